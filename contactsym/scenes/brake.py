"""§6, (6.1)-(6.4), Fig. 2: a rotating disc braked by two identical pads.

The pads' inward normals n1, n2 make n1 . n2 = -cos(alpha) (pads at angle alpha to
each other). The disc turns clockwise, so at pad j its surface slides along z x n_j
and Coulomb friction mu |N_j| opposes that. The gaps q_j = n_j . r are minus the pad
deformations; external forces press the disc on the pads, so the contacts are
unilateral with N_j > 0.
"""

from __future__ import annotations

import sympy as sp
from sympy.physics.mechanics import Lagrangian as lagrangian_of
from sympy.physics.mechanics import RigidBody, dynamicsymbols, inertia

from ..laws import Coulomb
from ..lyapunov_form import first_lyapunov_polynomial
from ..scene import Contact, Scene
from ._planar import planar_body


def build() -> Scene:
    x, y, theta = dynamicsymbols("x y theta")
    m, J, r, mu, alpha = sp.symbols("m J r mu alpha", positive=True)
    Fx, Fy = sp.symbols("F_x F_y", real=True)
    N1, N2 = sp.symbols("N_1 N_2", real=True)
    O, disc, centre = planar_body(x, y, theta, "D")
    normals = [O.y, -sp.sin(alpha) * O.x - sp.cos(alpha) * O.y]  # n1 . n2 = -cos(alpha)
    contacts = []
    for j, (n, N) in enumerate(zip(normals, (N1, N2)), 1):
        spot = centre.locatenew(f"P_{j}", -r * n)
        spot.v2pt_theory(centre, O, disc)
        sliding = O.z.cross(n)  # surface velocity direction for a clockwise disc
        gap = n.dot(x * O.x + y * O.y)
        contacts.append(Contact(coordinate=gap, reaction=N, friction=Coulomb(mu, sliding, spot), unilateral=True))
    body = RigidBody("disc", centre, disc, m, (inertia(disc, 0, 0, J), centre))
    F1, F2 = sp.symbols("F_1 F_2", real=True)
    presentation = {Fy: F1, Fx: -(F2 + sp.cos(alpha) * F1) / sp.sin(alpha)}  # F_j = n_j . F
    return Scene.from_lagrangian(
        lagrangian_of(O, body),
        [x, y, theta],
        contacts,
        loads=[(centre, Fx * O.x + Fy * O.y)],
        frame=O,
        name="brake",
        presentation=presentation,
        positive=(sp.sin(alpha),),  # 0 < alpha < pi
        solve_for=mu,
        description="(6.1)-(6.4): disc braked by two pads at angle alpha",
    )


LAW_DERIVATIVES = ("Phi_u", "Phi_v", "Phi_uu", "Phi_uv", "Phi_vv", "Psi_u", "Psi_v", "Psi_uu", "Psi_uv", "Psi_vv")


def squeal_direction(derivatives=LAW_DERIVATIVES) -> tuple[sp.Expr, sp.Expr]:
    """(Phi*, l1): the Hopf line and the first Lyapunov coefficient at alpha = 90 deg, identical pads.

    The special case Phi_j = Phi, Psi_j = Psi (< 0), and each law's derivatives at (u*, 0) equal
    for both pads (``Phi_u`` = dPhi/du, ``Psi_uv`` = d^2 Psi/du dv, ...; those not in
    ``derivatives`` are 0). Phi* solves the pipeline's Hopf condition Delta_3 = 0; l1 is
    :attr:`Stability.first_lyapunov` on that line, reduced by
    :func:`contactsym.lyapunov_form.first_lyapunov_polynomial` to a quadratic polynomial in the
    derivatives with coefficients rational in m, mu, Psi. The normalization (``<q, q> = 1`` in
    (u, v)) only adds a positive factor: l1 < 0 is a soft squeal (supercritical), l1 > 0 a jump
    with hysteresis (subcritical). About 15 s for all ten derivatives.

    Examples
    --------
    >>> Phi_line, l1 = squeal_direction(["Phi_uu"])
    >>> Phi_line
    -Psi**2*(mu**2 + 1)/(m*mu**2)
    >>> l1
    -Phi_uu*m*mu**3*(3*mu**2 + 5)/(4*(mu**2 + 1)*(mu**2 + 4)*(Psi**2*mu**2 + Psi**2 + mu**2))
    """
    stability = build().stability()
    P = {str(s): s for s in stability.linearization.scene.parameters}
    Phi, Psi = sp.Symbol("Phi", negative=True), sp.Symbol("Psi", negative=True)
    at = {P["alpha"]: sp.pi / 2, P["Phi_1"]: Phi, P["Phi_2"]: Phi, P["Psi_1"]: Psi, P["Psi_2"]: Psi}
    delta = next(c.lhs for c in sp.And.make_args(stability.hopf) if isinstance(c, sp.Eq))
    (Phi_line,) = sp.solve(sp.factor(delta.subs(at)), Phi)
    Phi_line = sp.factor(Phi_line)
    at.update({P["Phi_1"]: Phi_line, P["Phi_2"]: Phi_line})
    for j in (1, 2):
        for name in LAW_DERIVATIVES:
            law, order = name.split("_")
            at[sp.Symbol(f"{law}_{j}_{order}", real=True)] = sp.Symbol(name, real=True) if name in derivatives else 0
    return Phi_line, first_lyapunov_polynomial(stability, at)
