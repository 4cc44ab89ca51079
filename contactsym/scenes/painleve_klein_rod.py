"""§3, (3.5)-(3.9): Painlevé–Klein system with a deformable rod and rigid guides.

Two unit masses slide to the right on parallel rigid guides and are joined by a rod
at angle phi to the guides. The rod deforms along its length: delta is its
shortening, x1 - x2 = (2 l - delta) cos(phi), and R (R > 0: tension) is its force.
The guides are rigid, so their normal forces N1, N2 balance the vertical forces.
"""

from __future__ import annotations

from pathlib import Path

import sympy as sp
from sympy.physics.mechanics import ReferenceFrame, dynamicsymbols

from ..mechanism.scene import Contact, Scene
from ..plotting import (
    ROD_CASES,
    phase_portrait_caption,
    phase_portrait_data,
    phase_portrait_plot,
    rod_f_data,
    rod_f_plot,
    rod_portrait_values,
    save_figure,
)

#: The paper's numbers of this example, by formula key (``"key:detail"`` for one row).
EQUATIONS = {
    "accelerations:x_1": (("3.5",), ""),
    "accelerations:delta": (("3.6",), "corrected: Y*_j = Y_j / sin(phi), erratum 1"),
    "f": (("3.6", "3.7"), "erratum 1"),
}


#: What ``contactsym list`` prints for the built-in scene (read without building it).
DESCRIPTION = "(3.5)-(3.9): Painleve-Klein system, deformable rod, rigid guides"


def build() -> Scene:
    x1, delta = dynamicsymbols("x_1 delta")
    phi, l = sp.symbols("phi l", positive=True)
    mu1, mu2 = sp.symbols("mu_1 mu_2", positive=True)
    X1, X2, Y1, Y2, R = sp.symbols("X_1 X_2 Y_1 Y_2 R", real=True)
    N1, N2 = sp.symbols("N_1 N_2", real=True)
    O = ReferenceFrame("O")
    rod = sp.cos(phi) * O.x + sp.sin(phi) * O.y  # from mass 2 to mass 1
    # Newton's law for each unit mass: loads, guide normal force, friction, rod force
    F1 = X1 * O.x + Y1 * O.y + N1 * O.y - mu1 * sp.Abs(N1) * O.x - R * rod
    F2 = X2 * O.x + Y2 * O.y + N2 * O.y - mu2 * sp.Abs(N2) * O.x + R * rod
    # rigid guides: no vertical acceleration, which fixes the normal forces
    normal = {N1: sp.solve(F1.dot(O.y), N1)[0], N2: sp.solve(F2.dot(O.y), N2)[0]}
    a1, a2 = (F.dot(O.x).subs(normal) for F in (F1, F2))
    # delta = 2 l - (x1 - x2)/cos(phi)
    delta_dd = -(a1 - a2) / sp.cos(phi)
    mu_p, mu_m = sp.symbols("mu_+ mu_-", real=True)
    Xs, Y1s, Y2s = sp.symbols("X^* Y^*_1 Y^*_2", real=True)
    presentation = {
        mu1: (mu_p + mu_m) * sp.cos(phi) / (2 * sp.sin(phi)),  # mu_pm = (mu_1 +- mu_2) tan(phi)
        mu2: (mu_p - mu_m) * sp.cos(phi) / (2 * sp.sin(phi)),
        X2: X1 + Xs * sp.cos(phi),
        Y1: Y1s * sp.sin(phi),
        Y2: Y2s * sp.sin(phi),
    }
    return Scene.from_accelerations(
        [x1, delta],
        [a1, sp.expand(delta_dd)],
        [Contact(coordinate=delta, reaction=R)],
        name="painleve-klein-rod",
        equations=EQUATIONS,
        presentation=presentation,
        positive=(sp.sin(phi), sp.cos(phi)),  # 0 < phi < pi/2
        description=DESCRIPTION,
    )


#: Paper numbers of the count regions, by a word in the region's name.
COUNT_EQUATIONS = (
    ("unique", ("3.8", "3.9")),
    ("three", ("3.9",)),
    ("cusp", ("3.9",)),
    ("none", ("3.8",)),
    ("fold", ("3.8",)),
)

#: The numbers of the phase portrait: the cusp of §3 at its first load.
PORTRAIT_VALUES = rod_portrait_values("cusp")

_CASES_CAPTION = (
    "$f(u)$ of the Painlev\\'e--Klein rod (3.6) in the three cases of \\S3: a unique stable root ((3.8), (3.9)), "
    "a fold with two roots or none (impact-type catastrophe), a cusp with one root or three; each panel's condition "
    "is its derived count region. Filled dots: stable roots ($f' > 0$); open dots: unstable."
)


def figures(scene, directory: Path, *, resolution: int = 400, dpi: int = 150) -> list[tuple[Path, str]]:
    """f(u) in the three cases of §3 side by side, and the phase portrait of the cusp."""

    def cases(figure):
        for i, case in enumerate(ROD_CASES, 1):
            rod_f_plot(rod_f_data(scene, case, points=max(50, resolution)), ax=figure.add_subplot(1, 3, i))
        figure.subplots_adjust(wspace=0.3)

    portrait = phase_portrait_data(scene, resolution=max(20, resolution // 8))
    return [
        (save_figure(directory / "rod_f_cases.png", cases, size=(15.0, 4.6), dpi=dpi), _CASES_CAPTION),
        (
            save_figure(
                directory / "rod_phase_portrait.png",
                lambda f: phase_portrait_plot(portrait, ax=f.add_subplot()),
                dpi=dpi,
            ),
            phase_portrait_caption(portrait),
        ),
    ]
