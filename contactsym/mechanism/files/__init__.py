"""Scene files: a mechanical system written in TOML as on paper, read into a
:class:`~contactsym.Scene` (every error names the file, the line and the fix).

:func:`read_spec` reads a file into a frozen :class:`SceneSpec` (checked against
:data:`SCHEMA`), :func:`build_scene` builds the Scene from the spec; :func:`load_scene`
and :func:`read_scene` do both.
"""

from .contacts import COMPLIANCE_LAWS, LawKind
from .reader import LIMITS, build_scene, load_scene, read_scene, read_spec, scene_or_file
from .spec import SCHEMA, FigurePlan, Limits, SceneSpec, file_limits
from .toml_source import SceneFileError, TomlSource, shown

__all__ = [
    "COMPLIANCE_LAWS",
    "LIMITS",
    "SCHEMA",
    "FigurePlan",
    "LawKind",
    "Limits",
    "SceneFileError",
    "SceneSpec",
    "TomlSource",
    "build_scene",
    "file_limits",
    "load_scene",
    "read_scene",
    "read_spec",
    "scene_or_file",
    "shown",
]
