"""§5, (5.1)-(5.10): Painlevé–Klein system with a rigid rod and deformable guides.

A rod of length 2 l carries masses 1/2 at its ends (radius of inertia k = l) and
slides to the right between two guides 2 h apart, at angle phi to them. The local
deformations of the guides are q_{1,2} = h - l sin(phi) -/+ y. Loads: force (X, Y) at
the centre and moment M.
"""

from __future__ import annotations

import math
from pathlib import Path

import sympy as sp
from sympy.physics.mechanics import Lagrangian as lagrangian_of
from sympy.physics.mechanics import Particle, dynamicsymbols

from ..algebra.basic import SignSymbol
from ..laws import Coulomb
from ..mechanism.scene import Contact, Scene
from ..plotting import Fig1Data, fig1_data, fig1_plot, save_figure
from ._planar import planar_body

#: The paper's numbers of this example, by formula key (see :func:`contactsym.scenes.paper_knowledge`).
EQUATIONS = {
    "accelerations": (("5.1",), "with the moment M, erratum 10"),
    "contact accelerations": (("5.2",), ""),
    "equilibrium": (("5.3",), ""),
    "A": (("5.4",), ""),
    "det A": (("5.5",), ""),
    "stable for every law": (("5.6",), "corrected: erratum 11"),
    "unstable for every law": (("5.7",), ""),
}


#: What ``contactsym list`` prints for the built-in scene (read without building it).
DESCRIPTION = "(5.1)-(5.10): Painleve-Klein system, rigid rod, deformable guides"


def build() -> Scene:
    x, y, phi = dynamicsymbols("x y phi")
    l, h = sp.symbols("l h", positive=True)
    mu1, mu2 = sp.symbols("mu_1 mu_2", positive=True)
    X, Y, M = sp.symbols("X Y M", real=True)
    N1, N2 = sp.symbols("N_1 N_2", real=True)
    O, rod, centre = planar_body(x, y, phi)
    ends = []
    for name, side in (("P_1", 1), ("P_2", -1)):
        end = centre.locatenew(name, side * l * rod.x)
        end.v2pt_theory(centre, O, rod)
        ends.append(end)
    half = sp.Rational(1, 2)
    L = lagrangian_of(O, Particle("m_1", ends[0], half), Particle("m_2", ends[1], half))
    contacts = [
        Contact(coordinate=h - l * sp.sin(phi) - y, reaction=N1, friction=Coulomb(mu1, O.x, ends[0])),
        Contact(coordinate=h - l * sp.sin(phi) + y, reaction=N2, friction=Coulomb(mu2, O.x, ends[1])),
    ]
    kappa = sp.Symbol("kappa", positive=True)
    v1, v2 = sp.symbols("v_1 v_2", real=True)
    s1, s2 = SignSymbol("s_1"), SignSymbol("s_2")
    phi_ = sp.Symbol("phi", real=True)
    presentation = {
        mu1: s1 * v1 / kappa,  # v_j = (-1)^(j+1) kappa s_j mu_j  (5.4)
        mu2: -s2 * v2 / kappa,
        sp.sin(phi_): 1 / sp.sqrt(1 + kappa**2),  # kappa = cot(phi), 0 < phi < pi/2
        sp.cos(phi_): kappa / sp.sqrt(1 + kappa**2),
    }
    return Scene.from_lagrangian(
        L,
        [x, y, phi],
        contacts,
        loads=[(centre, X * O.x + Y * O.y), (rod, M * O.z)],
        frame=O,
        at={h: l * sp.sin(phi)},
        name="painleve-klein-guides",
        equations=EQUATIONS,
        presentation=presentation,
        positive=(sp.sin(phi), sp.cos(phi)),  # 0 < phi < pi/2
        description=DESCRIPTION,
        # counts of (5.3) do not depend on the signs s_j: the paper writes them with mu_j = |v_j|/kappa
        count_presentation={**presentation, mu1: sp.Abs(v1) / kappa, mu2: sp.Abs(v2) / kappa},
    )


#: Paper numbers of the count regions, by a word in the region's name.
COUNT_EQUATIONS = (("unique", ("5.8",)), ("none", ("5.10",)), ("two", ("5.10",)))


def figures(scene, directory: Path, *, resolution: int = 400, dpi: int = 150) -> list[tuple[Path, str]]:
    """Fig. 1a and 1b of the paper, derived: the (v1, v2) plane at phi = 60 and 45 degrees."""
    drawn = []
    for file, phi in (("fig1a_guides.png", sp.pi / 3), ("fig1b_guides.png", sp.pi / 4)):
        data = fig1_data(scene, phi, resolution=resolution)
        path = save_figure(
            directory / file, lambda f, data=data: fig1_plot(data, ax=f.add_subplot()), size=(6.0, 6.6), dpi=dpi
        )
        drawn.append((path, _fig1_caption(data)))
    return drawn


def _fig1_caption(data: Fig1Data) -> str:
    where = (
        "the unique square (5.8) lies inside the region stable for every law (5.9)"
        if data.panel == "a"
        else "part of the unique square (5.8) lies where stability depends on the contact law"
    )
    phi, threshold = (f"{math.degrees(float(angle)):.3g}" for angle in (data.phi, data.threshold))
    return (
        f"Fig. 1{data.panel}: the $(v_1, v_2)$ plane of the guides at $\\varphi = {phi}^\\circ$ "
        f"(threshold $\\arctan\\sqrt{{2}} \\approx {threshold}^\\circ$). Single hatching: stable for every "
        "contact law (5.6); double hatching: unstable for every law (5.7); dashed: the lines "
        "$\\pm v_1 \\pm v_2 = 2 \\kappa^2$ bounding the unique square (5.8), the sectors with two solutions or none "
        f"(5.10) and the half-strips with one or three. Here {where}."
    )
