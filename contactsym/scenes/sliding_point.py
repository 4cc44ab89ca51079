"""§1, (1.10)-(1.12): a point mass sliding on a rough line, pressed by a plane force.

The line is y = 0; the point slides to the right (x' > 0), so Coulomb friction
mu ``|N|`` acts along -x. The contact deforms with the Kelvin–Voigt law (1.11),
N = -2 b c y' - c^2 y with eps = 1/c.
"""

from __future__ import annotations

from pathlib import Path

import sympy as sp
from sympy.physics.mechanics import Lagrangian as lagrangian_of
from sympy.physics.mechanics import Particle, Point, ReferenceFrame, dynamicsymbols

from ..laws import Coulomb, KelvinVoigt
from ..mechanism.scene import Contact, Scene, t
from ..plotting import phase_portrait_caption, phase_portrait_data, phase_portrait_plot, save_figure

#: The paper's numbers of this example, by formula key (see :func:`contactsym.scenes.paper_knowledge`).
EQUATIONS = {
    "accelerations": (("1.10",), ""),
    "regularized": (("1.12",), ""),
    "fast": (("1.12",), "eps = 0 in (1.12)"),
    "law": (("1.11",), "Kelvin-Voigt law (1.11)"),
}


#: What ``contactsym list`` prints for the built-in scene (read without building it).
DESCRIPTION = "(1.10)-(1.12): a point sliding on a rough line, Kelvin-Voigt contact"


def build() -> Scene:
    x, y = dynamicsymbols("x y")
    m, mu, b = sp.symbols("m mu b", positive=True)
    N = sp.Symbol("N", real=True)
    X = sp.Function("X")(x, x.diff(t))
    Y = sp.Function("Y")(x, x.diff(t))
    frame = ReferenceFrame("O")
    origin = Point("O")
    origin.set_vel(frame, 0)
    point = origin.locatenew("P", x * frame.x + y * frame.y)
    point.set_vel(frame, x.diff(t) * frame.x + y.diff(t) * frame.y)
    contact = Contact(
        coordinate=y,
        reaction=N,
        compliance=KelvinVoigt(1, 2 * b),
        friction=Coulomb(mu, direction=frame.x, point=point),
    )
    return Scene.from_lagrangian(
        lagrangian_of(frame, Particle("P", point, m)),
        [x, y],
        [contact],
        loads=[(point, X * frame.x + Y * frame.y)],
        frame=frame,
        name="sliding-point",
        equations=EQUATIONS,
        description=DESCRIPTION,
    )


#: The numbers of the phase portrait (a load Y(x, xdot) by its function's name).
PORTRAIT_VALUES = {"m": 1.0, "b": 0.25, "Y": -1.0}


def figures(scene, directory: Path, *, resolution: int = 400, dpi: int = 150) -> list[tuple[Path, str]]:
    """The phase portrait of the fast subsystem (1.12): one stable equilibrium for the Kelvin–Voigt law."""
    portrait = phase_portrait_data(scene, extent=(3.0, 3.0), resolution=max(20, resolution // 8))
    path = save_figure(
        directory / "sliding_point_phase_portrait.png",
        lambda f: phase_portrait_plot(portrait, ax=f.add_subplot()),
        dpi=dpi,
    )
    return [(path, phase_portrait_caption(portrait))]
