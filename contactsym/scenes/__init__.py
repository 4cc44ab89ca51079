"""Built-in scenes: the paper's four examples and mechanisms beyond it, written at the level of mechanics."""

from __future__ import annotations

import difflib
from dataclasses import dataclass
from importlib import import_module

import sympy as sp

from ..arguments import checked
from ..errors import SceneError
from ..validate import scene_name, shorten

__all__ = ["scene", "scene_names", "scene_description", "paper_name", "paper_knowledge", "SpecialCase", "DEFAULT_SCENE"]

_MODULES = {
    "sliding-point": "sliding_point",
    "painleve-klein-rod": "painleve_klein_rod",
    "painleve-klein-guides": "painleve_klein_guides",
    "brake": "brake",
    "double-pendulum-tip": "double_pendulum_tip",
    "painleve-rod": "painleve_rod",
    "two-leg-block": "two_leg_block",
    "painleve-rod-3d": "painleve_rod_3d",
    "stool-3d": "stool_3d",
}

#: The scene that ``contactsym`` shows when no scene is named.
#:
#: >>> from contactsym import DEFAULT_SCENE, scene
#: >>> scene(DEFAULT_SCENE).name
#: 'brake'
DEFAULT_SCENE = "brake"

_built: dict = {}


def scene_names() -> list[str]:
    """Names of the built-in scenes.

    Examples
    --------
    >>> scene_names()
    ['sliding-point', 'painleve-klein-rod', 'painleve-klein-guides', 'brake', 'double-pendulum-tip', 'painleve-rod', 'two-leg-block', 'painleve-rod-3d', 'stool-3d']
    """
    return list(_MODULES)


def scene_description(name: str) -> str:
    """One line on the built-in scene ``name``, read from its module without building the scene.

    ``contactsym list`` prints these; building every scene for it took seconds (the spatial rod's
    Lagrange equations alone about two). The text is the built scene's ``description`` (tested).

    Examples
    --------
    >>> scene_description("brake")
    '(6.1)-(6.4): disc braked by two pads at angle alpha'
    >>> scene_description("brake") == scene("brake").description
    True
    """
    return import_module(f".{_MODULES[_known(name)]}", __name__).DESCRIPTION


def _known(name: str) -> str:
    """``name`` when it is a built-in scene's, else a SceneError that suggests the closest one."""
    name = scene_name(name)
    if name not in _MODULES:
        close = difflib.get_close_matches(name, _MODULES, n=1)
        hint = f"did you mean '{close[0]}'? " if close else ""
        raise SceneError(f"unknown scene {shorten(name)}; {hint}Known scenes: {', '.join(_MODULES)}.")
    return name


def scene(name: str):
    """A built-in scene by name (built once, then shared; scenes are immutable).

    Examples
    --------
    >>> scene("brake")
    <Scene 'brake': 3 coordinates, k = 2 contacts>
    >>> scene("break")
    Traceback (most recent call last):
    ...
    contactsym.errors.SceneError: unknown scene 'break'; did you mean 'brake'? Known scenes: sliding-point, painleve-klein-rod, painleve-klein-guides, brake, double-pendulum-tip, painleve-rod, two-leg-block, painleve-rod-3d, stool-3d.
    """
    name = _known(name)
    if name not in _built:
        _built[name] = import_module(f".{_MODULES[name]}", __name__).build()
    return _built[name]


@checked
def paper_name(scene) -> str | None:
    """The built-in name of ``scene`` when it is the built-in scene object itself, else None.

    Output that belongs to the paper's scenes (equation numbers, errata, figures) is chosen
    by this test of identity, so a user's scene that shares a built-in name gets none of it.

    Examples
    --------
    >>> paper_name(scene("brake"))
    'brake'
    >>> from contactsym.mechanism.files.reader import load_scene
    >>> from pathlib import Path
    >>> paper_name(load_scene(Path(__file__).parents[2] / "examples" / "brake.toml")) is None
    True
    """
    name = getattr(scene, "name", None)
    return name if isinstance(name, str) and _built.get(name) is scene else None


@checked
def paper_knowledge(scene, attribute: str, default=None):
    """What the paper says about the built-in ``scene``: ``attribute`` of the scene's own module.

    Scene knowledge (equation numbers, count presentation, figures with captions, special
    cases) lives in ``scenes/<name>.py``. Output code asks for it here with the Scene object,
    never with a name, so a user's scene gets ``default`` even when it shares a built-in name.

    The attributes a scene module may define:

    - ``EQUATIONS``: ``{formula key: (paper equation numbers, note)}``;
    - ``COUNT_EQUATIONS``: ``((word in a count region's name, paper numbers), ...)``;
    - ``figures(scene, directory, *, resolution, dpi)``: ``[(PNG path, LaTeX caption), ...]``;
    - ``special_cases(scene)``: a list of :class:`SpecialCase`.
    - ``PORTRAIT_VALUES``: numbers for the phase portrait of a one-contact scene.

    Examples
    --------
    >>> paper_knowledge(scene("brake"), "no such attribute", "none here")
    'none here'
    >>> from contactsym.mechanism.files.reader import load_scene
    >>> from pathlib import Path
    >>> own = load_scene(Path(__file__).parents[2] / "examples" / "brake.toml")
    >>> paper_knowledge(own, "special_cases") is None
    True
    """
    name = paper_name(scene)
    if name is None:
        return default
    return getattr(import_module(f".{_MODULES[name]}", __name__), attribute, default)


@checked
@dataclass(frozen=True)
class SpecialCase:
    r"""One of the paper's special cases of a scene, derived from the scene's stages.

    Printed as ``intro`` followed by the display ``lhs relation rhs`` tagged with ``paper``.

    Examples
    --------
    >>> case = SpecialCase("With $x = 0$:", "special", "", "", sp.Symbol("y") > 0, ("6.4",))
    >>> case.paper
    ('6.4',)
    """

    intro: str  # LaTeX sentence before the formula
    key: str
    lhs: str  # LaTeX of the left side, "" for a condition standing alone
    relation: str  # LaTeX of the relation, "" for a condition
    rhs: sp.Basic
    paper: tuple = ()
    note: str = ""
