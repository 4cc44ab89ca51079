"""Scene files: a mechanical system written in TOML as on paper, read into a
:class:`~contactsym.Scene` (every error names the file, the line and the fix).
"""

from .bodies import COMPLIANCE_LAWS, PlaneMixin
from .contacts import ContactsMixin
from .reader import FigurePlan, load_scene, read_scene, scene_or_file
from .toml_source import SceneFileError, TomlSource, shown

__all__ = [
    "COMPLIANCE_LAWS",
    "ContactsMixin",
    "FigurePlan",
    "PlaneMixin",
    "SceneFileError",
    "TomlSource",
    "load_scene",
    "read_scene",
    "scene_or_file",
    "shown",
]
