"""Scene files, the second step: :func:`build_scene` makes the Scene of a :class:`SceneSpec` alone
(the mechanics, the contacts and every option, in one constructor call).

:func:`contactsym.mechanism.files.reader.read_spec` gives the spec; a spec is data, so it can also be
made, changed (``dataclasses.replace``) or compared before it is built.
"""

from __future__ import annotations

from ...errors import ContactsymError
from ...parse import ParseError
from ..scene import Scene
from .bodies import Plane, inertia_proved
from .contacts import build_contact
from .space import Space
from .spec import SceneSpec
from .toml_source import SceneFileError, shown

__all__ = ["build_scene"]


def build_scene(spec: SceneSpec) -> Scene:
    """The Scene of a spec: the mechanics, the contacts and every option, in one constructor call.

    Examples
    --------
    >>> from contactsym.mechanism.files import read_spec
    >>> spec = read_spec('[scene]\\nname = "drop"\\ncoordinates = ["y"]\\n[accelerations]\\ny = "N - 1"\\n'
    ...                  '[[contacts]]\\ngap = "y"\\nreaction = "N"\\n', "a.toml")
    >>> scene = build_scene(spec)
    >>> scene.name, scene.k, scene.accelerations
    ('drop', 1, {y(t): N - 1})
    >>> try:
    ...     build_scene("drop.toml")
    ... except SceneFileError as error:
    ...     print(error)
    build_scene takes a SceneSpec (from read_spec), not 'drop.toml'.
    """
    if not isinstance(spec, SceneSpec):
        raise SceneFileError(f"build_scene takes a SceneSpec (from read_spec), not {shown(spec)}.")
    plane = Plane(spec.points) if spec.lagrangian and spec.space is None else None
    plane = Space(spec.space) if spec.space is not None else plane
    contacts = [build_contact(c, plane, spec.source, spec.eps) for c in spec.contacts]
    presentation = dict(spec.presentation)
    count_presentation = None
    if spec.count_presentation is not None:
        count_presentation = {**presentation, **dict(spec.count_presentation)}
    options = dict(
        name=spec.name,
        description=spec.description,
        at=dict(spec.at),
        presentation=presentation,
        positive=spec.positive,
        solve_for=spec.solve_for,
        count_presentation=count_presentation,
        figure_plan=spec.figures,
        # a parameter called ydot stays a parameter, apart from the frozen rate of y; one printed as a
        # coordinate (symbol = "theta") is that frozen coordinate, for [at]
        parameters=[p.symbol for p in spec.parameters if str(p.symbol) not in {c.name for c in spec.coordinates}],
    )
    if spec.lagrangian and spec.space is None and inertia_proved(spec):  # by the bodies' structure: no check
        options["inertia"] = "proved"
    coordinates = [c.symbol for c in spec.coordinates]
    try:
        if spec.lagrangian:
            L, loads = plane.lagrangian(spec)
            built = Scene.from_lagrangian(L, coordinates, contacts, loads=loads, frame=plane.frame, **options)
        else:
            built = Scene.from_accelerations(coordinates, list(spec.accelerations), contacts, **options)
        return built.with_values(dict(spec.values)) if spec.values else built
    except (SceneFileError, ParseError):
        raise
    except ContactsymError as error:  # the API's own message, from the file
        if getattr(error, "contact", None) is not None:  # about one contact: placed at its gap or friction
            contact = spec.contacts[error.contact]
            line = contact.gap_line if error.key == "gap" and contact.gap_line else contact.friction.line
            raise SceneFileError(f"{spec.source}:{line}: {str(error).rstrip('.')}.") from None
        raise type(error)(f"{spec.source}: {error}") from None
