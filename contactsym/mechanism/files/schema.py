"""Scene files' schema and caps: the tables and keys a file may have and the kind of each value
(:data:`SCHEMA`), and the caps on a file's size (:class:`Limits`, raised by :func:`file_limits`).

Examples
--------
>>> SCHEMA["contacts"].required
('gap', 'reaction')
>>> Limits().max_contacts
6
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import AbstractContextManager, contextmanager
from contextvars import ContextVar
from dataclasses import dataclass, fields
from types import MappingProxyType

from ...errors import SceneError
from ...validate import shorten

__all__ = ["SCHEMA", "Limits", "TableSchema", "file_limits", "limits_in_force"]


@dataclass(frozen=True)
class TableSchema:
    """The keys of one table and the kind of each value.

    ``keys`` maps a fixed key to its kind; a table of free names (``[parameters]``) has
    ``keys = None`` and gives the kind of every entry as ``entries``. Kinds: ``formula``
    (text in quotes or a number), ``names`` (a list of names), ``pair`` (two formulas),
    ``formulas`` (a list of formulas), ``bool``, ``text``, ``label`` (the scene's name), ``name`` (a name declared elsewhere in
    the file), ``new name`` (a name this key declares), ``table`` and ``tables`` (a table, an
    array of tables), ``law``, ``number``, ``numbers`` (a pair of numbers), ``entry`` (read
    by the table's own rules). In a spatial file (``dimensions = 3``, see
    :mod:`contactsym.mechanism.files.spatial`) a ``pair`` is three formulas (x, y, z), a body's
    ``inertia`` is its tensor in its frame (three principal moments or six entries xx, yy, zz,
    xy, yz, zx), and a gap may be a table ``{point, normal, distance}``.
    """

    keys: MappingProxyType | None
    required: tuple[str, ...] = ()
    entries: str = "entry"

    @property
    def allowed(self) -> tuple[str, ...]:
        return tuple(self.keys or ())


def _table(required=(), **keys) -> TableSchema:
    return TableSchema(MappingProxyType(keys), tuple(required))


def _free(entries: str) -> TableSchema:
    return TableSchema(None, (), entries)


#: The schema of a scene file: every table (``""`` is the document), its keys and their kinds.
#:
#: >>> from contactsym.mechanism.files import SCHEMA
#: >>> SCHEMA[''].required
#: ('scene',)
SCHEMA = MappingProxyType(
    {
        "": _table(
            ("scene",),
            scene="table",
            parameters="table",
            intervals="table",
            functions="table",
            accelerations="table",
            energy="table",
            points="table",
            masses="tables",
            bodies="tables",
            loads="tables",
            contacts="tables",
            at="table",
            presentation="table",
            count_presentation="table",
            figures="table",
            frames="table",
            values="table",
        ),
        "scene": _table(
            ("coordinates",),
            name="label",
            description="text",
            coordinates="names",
            solve_for="formula",
            dimensions="number",
        ),
        "parameters": _free("entry"),
        "parameters.entry": _table((), assume="text", symbol="text", interval="pair"),
        "intervals": _free("pair"),
        "functions": _free("names"),
        "accelerations": _free("formula"),
        "energy": _table((), kinetic="formula", potential="formula"),
        "points": _free("entry"),
        "points.entry": _table((), position="pair", body="name", angle="formula", frame="name", offset="pair"),
        "masses": _table(("point", "mass"), point="name", mass="formula"),
        "bodies": _table(
            ("point", "mass", "inertia"), point="name", angle="formula", frame="name", mass="formula", inertia="formula"
        ),
        "loads": _table((), point="name", force="pair", angle="formula", frame="name", moment="formula"),
        "contacts": _table(
            ("gap", "reaction"), gap="formula", reaction="new name", unilateral="bool", law="law", friction="table"
        ),
        "contacts.gap": _table(("point", "normal"), point="name", normal="pair", distance="formula"),
        "contacts.friction": _table(("direction",), mu="formula", viscous="formula", point="name", direction="entry"),
        "at": _free("formula"),
        "presentation": _free("formula"),
        "count_presentation": _free("formula"),
        "figures": _table(
            ("x", "y", "x_range", "y_range"), x="name", y="name", x_range="numbers", y_range="numbers", values="table"
        ),
        "figures.values": _free("number"),
        "frames": _free("entry"),
        "frames.entry": _table(
            (),
            body_fixed="text",
            space_fixed="text",
            angles="formulas",
            euler_parameters="formulas",
            relative_to="name",
        ),
        "values": _free("formula"),
    }
)


@dataclass(frozen=True)
class Limits:
    """Caps on the size of a scene file, so that a file beyond them is refused in a moment.

    Pass ``limits=Limits(max_contacts=8)`` to :func:`~contactsym.mechanism.files.reader.load_scene`
    or :func:`~contactsym.mechanism.files.reader.read_scene` to read a larger scene, or raise caps
    for every read inside a block with :func:`file_limits`; on the command line,
    ``contactsym --limit max_contacts=8 ...`` (each field by its name). The formulas have their own
    caps, in :mod:`contactsym.parse` (``--limit max_degree=64`` raises one of those). A file cannot
    raise its own caps: they guard against the file.

    Examples
    --------
    >>> from contactsym.mechanism.files import SceneFileError, read_scene
    >>> text = ('[scene]\\ncoordinates = ["x", "y"]\\n[accelerations]\\nx = "N_1"\\ny = "N_2"\\n'
    ...         '[[contacts]]\\ngap = "x"\\nreaction = "N_1"\\n[[contacts]]\\ngap = "y"\\nreaction = "N_2"\\n')
    >>> read_scene(text, "two.toml").k
    2
    >>> try:
    ...     read_scene(text, "two.toml", limits=Limits(max_contacts=1))
    ... except SceneFileError as error:
    ...     print(str(error).split(";")[0])
    two.toml:1: 2 contacts, more than the cap of 1 (Limits.max_contacts)
    """

    #: Largest file, in bytes.
    max_bytes: int = 1_000_000
    #: Most generalized coordinates.
    max_coordinates: int = 12
    #: Most ``[[contacts]]``.
    max_contacts: int = 6
    #: Most ``[points]``.
    max_points: int = 64
    #: Most ``[[masses]]``, ``[[bodies]]`` and ``[[loads]]`` together.
    max_items: int = 64
    #: Most declared names (parameters, functions, intervals).
    max_names: int = 200

    def __post_init__(self):
        for cap in fields(self):
            value = getattr(self, cap.name)
            if isinstance(value, bool) or not isinstance(value, int) or value < 1:
                raise SceneError(f"Limits({cap.name}={shorten(value)}): a cap is a whole number >= 1.")


#: The caps :func:`file_limits` put in force, or None for the defaults (or what the caller passes).
_IN_FORCE: ContextVar = ContextVar("contactsym_file_limits", default=None)


def file_limits(limits: Limits) -> AbstractContextManager[None]:
    """``limits`` in force for every scene file read inside the block that is not given its own
    (``load_scene(path)`` without ``limits=``): what ``contactsym --limit max_contacts=8`` does.

    Examples
    --------
    >>> from contactsym.mechanism.files import read_scene
    >>> text = ('[scene]\\ncoordinates = ["x", "y"]\\n[accelerations]\\nx = "N_1"\\ny = "N_2"\\n'
    ...         '[[contacts]]\\ngap = "x"\\nreaction = "N_1"\\n[[contacts]]\\ngap = "y"\\nreaction = "N_2"\\n')
    >>> with file_limits(Limits(max_contacts=1)):
    ...     try:
    ...         read_scene(text, "two.toml")
    ...     except SceneError as error:
    ...         print(str(error).split(";")[0])
    two.toml:1: 2 contacts, more than the cap of 1 (Limits.max_contacts)
    """
    if not isinstance(limits, Limits):
        raise SceneError(f"file_limits takes a contactsym.mechanism.files.Limits, not {shorten(limits)}.")
    return _in_force(limits)  # checked now, in force when the block is entered


@contextmanager
def _in_force(limits: Limits) -> Iterator[None]:
    token = _IN_FORCE.set(limits)
    try:
        yield
    finally:
        _IN_FORCE.reset(token)


def limits_in_force(limits: Limits) -> Limits:
    """``limits``, or those of an enclosing :func:`file_limits` where ``limits`` are the defaults."""
    raised = _IN_FORCE.get()
    return raised if raised is not None and limits == Limits() else limits
