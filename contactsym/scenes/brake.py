"""§6, (6.1)-(6.4), Fig. 2: a rotating disc braked by two identical pads.

The pads' inward normals n1, n2 make n1 . n2 = -cos(alpha) (pads at angle alpha to
each other). The disc turns clockwise, so at pad j its surface slides along z x n_j
and Coulomb friction mu ``|N_j|`` opposes that. The gaps q_j = n_j . r are minus the pad
deformations; external forces press the disc on the pads, so the contacts are
unilateral with N_j > 0.
"""

from __future__ import annotations

from pathlib import Path

import sympy as sp
from sympy.physics.mechanics import Lagrangian as lagrangian_of
from sympy.physics.mechanics import RigidBody, dynamicsymbols, inertia

from ..errors import SceneError
from ..laws import Coulomb
from ..lyapunov.polynomial import first_lyapunov_polynomial
from ..mechanism.scene import Contact, Scene
from ..plotting import brake_hopf_data, brake_hopf_plot, brake_map_data, brake_map_plot, save_figure
from ..printing.latex_output import tex
from ..stages.regions import closed_form
from . import SpecialCase
from ._planar import planar_body

#: The paper's numbers of this example, by formula key (see :func:`contactsym.scenes.paper_knowledge`).
EQUATIONS = {
    "contact accelerations": (("6.1",), ""),
    "A": (("6.2",), ""),
    "stable for every law": (("6.3",), "with equality allowed: erratum 12"),
    "Hopf line": ((), "for Phi_j = Phi, Psi_j = Psi, alpha = 90 deg it is (6.4), with the mass: erratum 13"),
    "hopf frequency": ((), "the frequency after (6.4), with the mass: erratum 14"),
}


#: What ``contactsym list`` prints for the built-in scene (read without building it).
DESCRIPTION = "(6.1)-(6.4): disc braked by two pads at angle alpha"


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
        equations=EQUATIONS,
        presentation=presentation,
        positive=(sp.sin(alpha),),  # 0 < alpha < pi
        solve_for=mu,
        description=DESCRIPTION,
    )


#: The special case's common law: Phi_j = Phi, Psi_j = Psi at both pads.
PHI, PSI = sp.Symbol("Phi", negative=True), sp.Symbol("Psi", negative=True)


def special_cases(scene) -> list[SpecialCase]:
    r"""The paper's special case (6.4): alpha = 90 deg, equal laws Phi_j = Phi, Psi_j = Psi.

    Derived from the scene's Hurwitz conditions with these values substituted, and, when
    its boundary (the Hopf line) is one equation in Phi, the frequency on it.

    Examples
    --------
    >>> import contactsym as cs
    >>> stable, omega = special_cases(cs.scene("brake"))
    >>> stable.rhs, stable.paper
    (-Phi*m*mu**2 < Psi**2*(mu**2 + 1), ('6.4',))
    >>> omega.lhs, omega.rhs
    ('\\omega', -Psi*(mu**2 + 1)/(m*mu))
    """
    return list(_special(scene)[0])


_SPECIAL: dict = {}


def _special(scene) -> tuple[list[SpecialCase], sp.Expr | None]:
    """(the special cases, Phi on the Hopf line or None): derived once per scene object, then shared."""
    if id(scene) not in _SPECIAL:
        _SPECIAL[id(scene)] = (scene, _derive_special_cases(scene))  # the scene kept: its id stays its own
    return _SPECIAL[id(scene)][1]


def _equal_pads(scene) -> dict:
    """The substitution of the special case: alpha = 90 deg, Phi_j = Phi, Psi_j = Psi."""
    fast = scene.fast_subsystem()
    alpha = next(s for s in scene.parameters if s.name == "alpha")
    return {**dict.fromkeys(fast.Phi, PHI), **dict.fromkeys(fast.Psi, PSI), alpha: sp.pi / 2}


def _derive_special_cases(scene) -> tuple[list[SpecialCase], sp.Expr | None]:
    st, equal = scene.stability(), _equal_pads(scene)
    stable = closed_form(sp.And(*[sp.Gt(h.subs(equal), 0) for h in st.hurwitz]), scene)
    intro = r"With $\Phi_j = \Phi$, $\Psi_j = \Psi$ and $\alpha = 90^\circ$ the Hurwitz conditions reduce to"
    cases = [SpecialCase(intro, "special", "", "", stable, ("6.4",), "with the mass m: erratum 13")]
    line = closed_form(st.hopf.subs(equal), scene)
    solved = sp.solve(line, PHI, dict=True) if isinstance(line, sp.Equality) else []
    if len(solved) != 1:
        return cases, None
    Phi_line = sp.factor(solved[0][PHI])
    omega = sp.factor(sp.sqrt(sp.factor(st.routh_hurwitz.omega_squared.subs(equal).subs(PHI, Phi_line))))
    on_line = "and on its boundary, a Hopf bifurcation, the frequency in the stretched time is"
    cases.append(SpecialCase(on_line, "hopf frequency", r"\omega", "=", omega, (), "erratum 14"))
    return cases, Phi_line


def figures(scene, directory: Path, *, resolution: int = 400, dpi: int = 150) -> list[tuple[Path, str]]:
    """The (alpha, mu) map (6.3) and the Hopf line of the special case (6.4)."""
    plane = brake_map_data(scene, resolution=resolution)
    hopf = brake_hopf_data(scene, resolution=resolution)
    bound = tex(plane.regions["stable for every law"].condition)
    return [
        (
            save_figure(
                directory / "brake_alpha_mu.png",
                lambda f: brake_map_plot(plane, ax=f.add_subplot()),
                size=(6.5, 4.5),
                dpi=dpi,
            ),
            rf"The brake in the $(\alpha, \mu)$ plane: stable for every contact law where ${bound}$ (6.3); "
            "beyond that curve stability depends on the contact law (a Hopf bifurcation, brake squeal, is possible).",
        ),
        (
            save_figure(
                directory / "brake_hopf.png",
                lambda f: brake_hopf_plot(hopf, ax=f.add_subplot()),
                size=(6.5, 4.8),
                dpi=dpi,
            ),
            rf"The brake at $\alpha = 90^\circ$ with $\Phi_j = \Phi$, $\Psi_j = \Psi$: asymptotically stable where "
            rf"${tex(hopf.stable.condition)}$ ((6.4) with the mass $m$), unstable beyond the Hopf line "
            rf"${tex(hopf.hopf.condition)}$, on which the squeal frequency is $\omega = {tex(hopf.frequency)}$ "
            "(stretched time).",
        ),
    ]


#: The law's derivatives at (u*, 0) that enter l1 (``Phi_uv`` = d^2 Phi / du dv, ...).
LAW_DERIVATIVES = ("Phi_u", "Phi_v", "Phi_uu", "Phi_uv", "Phi_vv", "Psi_u", "Psi_v", "Psi_uu", "Psi_uv", "Psi_vv")


def squeal_direction(scene, derivatives=LAW_DERIVATIVES) -> tuple[sp.Expr, sp.Expr]:
    """(Phi*, l1): the Hopf line and the first Lyapunov coefficient at alpha = 90 deg, identical pads.

    The special case Phi_j = Phi, Psi_j = Psi (< 0), and each law's derivatives at (u*, 0) equal
    for both pads (``Phi_u`` = dPhi/du, ``Psi_uv`` = d^2 Psi/du dv, ...; those not in
    ``derivatives`` are 0). Phi* is the Hopf line of :func:`special_cases`; l1 is
    :attr:`Stability.first_lyapunov` on that line, reduced by
    :func:`contactsym.lyapunov.polynomial.first_lyapunov_polynomial` to a quadratic polynomial in the
    derivatives with coefficients rational in m, mu, Psi. The normalization (``<q, q> = 1`` in
    (u, v)) only adds a positive factor: l1 < 0 is a soft squeal (supercritical), l1 > 0 a jump
    with hysteresis (subcritical). About 15 s for all ten derivatives.

    Examples
    --------
    >>> import contactsym as cs
    >>> Phi_line, l1 = squeal_direction(cs.scene("brake"), ["Phi_uu"])
    >>> Phi_line
    -Psi**2*(mu**2 + 1)/(m*mu**2)
    >>> l1
    -Phi_uu*m*mu**3*(3*mu**2 + 5)/(4*(mu**2 + 1)*(mu**2 + 4)*(Psi**2*mu**2 + Psi**2 + mu**2))
    """
    Phi_line = _special(scene)[1]
    if Phi_line is None:
        raise SceneError("this brake has no Hopf line in Phi at alpha = 90 deg with equal pads.")
    at = {**_equal_pads(scene), **{Phi_j: Phi_line for Phi_j in scene.fast_subsystem().Phi}}
    for j in (1, 2):
        for name in LAW_DERIVATIVES:
            law, order = name.split("_")
            at[sp.Symbol(f"{law}_{j}_{order}", real=True)] = sp.Symbol(name, real=True) if name in derivatives else 0
    return Phi_line, first_lyapunov_polynomial(scene.stability(), at)
