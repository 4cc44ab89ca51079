"""The import graph of contactsym, read with ``ast``: no cycle, latex a leaf, the stages below the scene.

Every import counts, also one inside a function; only ``if TYPE_CHECKING:`` blocks are left out
(they never run). An import inside a function is allowed for a heavy optional module, or with a
comment saying why.
"""

import ast
import pathlib
import re
from dataclasses import dataclass
from pathlib import Path

import pytest

import contactsym

PACKAGE = pathlib.Path(contactsym.__file__).parent

#: The subpackages below the scene: the stages and what they are computed with.
BELOW_THE_SCENE = ("stages", "counts", "algebra", "inequalities", "robustness", "lyapunov", "laws", "printing")

#: What the stages are below: the scene and its registry, output and numerics.
ABOVE_THE_STAGES = ("mechanism", "scenes", "plotting", "report", "numerics", "atlas", "cli", "command_line")

#: At most this many modules at the top level; the rest live in the subpackage of their domain.
TOP_LEVEL_LIMIT = 14

#: Heavy optional modules that may be imported where first needed, without a comment.
HEAVY = ("matplotlib", "scipy.optimize", "dask", "xarray")


@dataclass(frozen=True)
class Import:
    source: str  # the importing module, e.g. "contactsym.stages.fast"
    target: str  # the imported module ("contactsym.printing.latex_output", or an outside one: "matplotlib.pyplot")
    line: int
    in_function: bool
    commented: bool  # a comment on the import's line or on the line above


def _module_name(path: pathlib.Path) -> str:
    parts = ("contactsym", *path.relative_to(PACKAGE).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


MODULES = {_module_name(path): path for path in sorted(PACKAGE.rglob("*.py"))}


def _is_type_checking(node: ast.AST) -> bool:
    test = getattr(node, "test", None)
    return isinstance(node, ast.If) and (
        (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING")
        or (isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING")
    )


def _targets(module: str, node: ast.AST) -> list[str]:
    """The modules an import statement names; a name from a package counts as its submodule when it is one."""
    if isinstance(node, ast.Import):
        return [alias.name for alias in node.names]
    package = module if MODULES[module].name == "__init__.py" else module.rpartition(".")[0]
    if node.level:
        base = package.split(".")[: len(package.split(".")) - (node.level - 1)]
        origin = ".".join(base + ([node.module] if node.module else []))
    else:
        origin = node.module or ""
    return [f"{origin}.{a.name}" if f"{origin}.{a.name}" in MODULES else origin for a in node.names]


def _imports(module: str) -> list[Import]:
    path = MODULES[module]
    text = path.read_text()
    lines = text.splitlines()
    found = []

    def commented(line: int) -> bool:
        return "#" in lines[line - 1] or (line >= 2 and lines[line - 2].lstrip().startswith("#"))

    def visit(node: ast.AST, in_function: bool) -> None:
        for child in ast.iter_child_nodes(node):
            if _is_type_checking(child):
                for part in child.orelse:  # the else branch runs
                    visit(part, in_function)
                continue
            if isinstance(child, (ast.Import, ast.ImportFrom)):
                for target in dict.fromkeys(_targets(module, child)):
                    found.append(Import(module, target, child.lineno, in_function, commented(child.lineno)))
            visit(child, in_function or isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)))

    visit(ast.parse(text), False)
    return found


IMPORTS = {module: _imports(module) for module in MODULES}


def _packages_run_first(importer: str, target: str) -> set[str]:
    """The packages whose ``__init__`` runs when ``importer`` imports ``target``: the target's
    ancestors that do not already contain the importer. The root package is left out: it runs
    before any of its modules, so an edge to it closes no cycle that Python would meet."""
    parts = target.split(".")
    ancestors = {".".join(parts[:i]) for i in range(2, len(parts))}
    return {a for a in ancestors if a in MODULES and not (importer == a or importer.startswith(a + "."))}


def _graph() -> dict[str, set[str]]:
    """contactsym module -> the contactsym modules it imports (anywhere in it), and the packages
    whose ``__init__`` those imports run first (``numerics.hopf`` imported from outside runs
    ``numerics/__init__``)."""
    graph = {}
    for module, imports in IMPORTS.items():
        edges = {i.target for i in imports if i.target in MODULES and i.target != module}
        graph[module] = edges.union(*(_packages_run_first(module, t) for t in edges))
    return graph


def _cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one module (Tarjan's algorithm, iterative)."""
    index, low, stack, on_stack, components = {}, {}, [], set(), []
    for root in graph:
        if root in index:
            continue
        work = [(root, iter(sorted(graph[root])))]
        index[root] = low[root] = len(index)
        stack.append(root)
        on_stack.add(root)
        while work:
            node, successors = work[-1]
            for successor in successors:
                if successor not in index:
                    index[successor] = low[successor] = len(index)
                    stack.append(successor)
                    on_stack.add(successor)
                    work.append((successor, iter(sorted(graph[successor]))))
                    break
                if successor in on_stack:
                    low[node] = min(low[node], index[successor])
            else:
                work.pop()
                if work:
                    low[work[-1][0]] = min(low[work[-1][0]], low[node])
                if low[node] == index[node]:
                    component = []
                    while True:
                        member = stack.pop()
                        on_stack.discard(member)
                        component.append(member)
                        if member == node:
                            break
                    if len(component) > 1:
                        components.append(sorted(component))
    return components


def test_the_cycle_finder_finds_a_cycle_and_only_cycles():
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}, "e": set()}
    assert _cycles(graph) == [["a", "b", "c"]]
    assert _cycles({"a": {"b"}, "b": set()}) == []


def test_the_import_reader_sees_imports_in_functions_and_skips_type_checking_blocks():
    stability = {(i.target, i.in_function) for i in IMPORTS["contactsym.stages.stability"]}
    assert ("contactsym.robustness.classify", True) in stability  # imported where first needed
    assert ("contactsym.stages.linear", False) in stability
    assert all(i.line > 0 for i in IMPORTS["contactsym.stages.stability"])
    assert any(i.target == "contactsym.scenes" for i in IMPORTS["contactsym.mechanism.files.reader"])


def test_no_import_cycle_among_contactsym_modules():
    graph = _graph()
    found = []
    for component in _cycles(graph):
        members = set(component)
        edges = sorted(f"{a} -> {b}" for a in component for b in graph[a] & members)
        found.append(f"{len(component)} modules: " + ", ".join(edges))
    assert not found, "import cycles:\n" + "\n".join(found)


def test_latex_is_a_leaf():
    """latex.py prints; each stage says what its formulas are, so the printer imports no stage."""
    assert _is_leaf("contactsym.printing.latex_output")
    assert not _is_leaf("contactsym.stages.fast")


def _contactsym_imports(module: str) -> set[str]:
    return {i.target for i in IMPORTS[module] if i.target in MODULES} - {"contactsym.errors"}


def _is_leaf(module: str) -> bool:
    """A module that imports no contactsym module but ``errors`` and modules that import nothing else
    (the printer's ``printing.shared``): importing it can close no cycle."""
    return all(not _contactsym_imports(target) for target in _contactsym_imports(module))


def test_the_graph_sees_the_edge_to_a_parent_package():
    graph = _graph()
    assert "contactsym.stages" in graph["contactsym.mechanism.equation_numbers"]  # it imports contactsym.stages.fast
    assert "contactsym.numerics" not in graph["contactsym.numerics.hopf"]  # its own package is running
    assert _cycles(
        {**graph, "contactsym.stages.fast": graph["contactsym.stages.fast"] | {"contactsym.mechanism.equation_numbers"}}
    )


def _below_the_scene(module: str) -> bool:
    return any(module == f"contactsym.{p}" or module.startswith(f"contactsym.{p}.") for p in BELOW_THE_SCENE)


@pytest.mark.parametrize("module", sorted(m for m in MODULES if _below_the_scene(m)))
def test_stages_never_import_what_is_built_on_them(module):
    above = {f"contactsym.{name}" for name in ABOVE_THE_STAGES}
    wrong = [
        f"line {i.line}: {i.target}"
        for i in IMPORTS[module]
        if i.target in above or any(i.target.startswith(f"{name}.") for name in above)
    ]
    assert not wrong, f"{module} imports " + "; ".join(wrong)


def test_few_modules_at_the_top_level():
    top = sorted(p.name for p in PACKAGE.glob("*.py") if p.name != "__main__.py")
    assert len(top) <= TOP_LEVEL_LIMIT, f"{len(top)} modules at the top level: {top}"


def _submodules(package: str) -> list[str]:
    return [m for m in MODULES if m.rpartition(".")[0] == package and not m.endswith("__main__")]


@pytest.mark.parametrize("package", sorted(m for m in MODULES if MODULES[m].name == "__init__.py"))
def test_no_name_shadows_a_module(package):
    """``contactsym.numerics.integrate`` must be the module, not a function of the same name."""
    import importlib
    import types

    wrong = []
    for sub in _submodules(package):
        importlib.import_module(sub)
        value = getattr(importlib.import_module(package), sub.rpartition(".")[2])
        if not isinstance(value, types.ModuleType) or value.__name__ != sub:
            wrong.append(f"{sub} is {type(value).__name__}")
    assert not wrong, f"names in {package} shadow its modules: {wrong}"


@pytest.mark.parametrize("module", sorted(MODULES))
def test_imports_inside_functions_are_heavy_or_explained(module):
    unexplained = [
        f"line {i.line}: {i.target}"
        for i in IMPORTS[module]
        if i.in_function and not i.commented and not any(i.target == h or i.target.startswith(h + ".") for h in HEAVY)
    ]
    assert not unexplained, f"{module} imports inside functions without a comment saying why: {unexplained}"


def test_architecture_page_lists_every_module_and_no_stale_one():
    """docs/architecture.md, the page a new maintainer reads first, has one line per module."""
    page = (PACKAGE.parent / "docs" / "architecture.md").read_text()
    listed = {line.split("`")[1] for line in page.splitlines() if line.startswith("- `") and line.count("`") >= 2}
    files = {str(path.relative_to(PACKAGE)) for path in PACKAGE.rglob("*.py") if path.name != "__main__.py"}
    assert files - listed == set(), f"modules missing from docs/architecture.md: {sorted(files - listed)}"
    stale = {name for name in listed - files if name.endswith(".py") and not name.startswith("tests/")}
    assert not stale, f"docs/architecture.md lists modules that do not exist: {sorted(stale)}"


# --- interfaces, not private names ---------------------------------------------------------------


def _is_private(name: str) -> bool:
    return name.startswith("_") and not name.startswith("__")


def _unit(module: str) -> str:
    """The subpackage a module belongs to (``contactsym.numerics`` for ``contactsym.numerics.hopf``);
    a module at the top level is a unit of its own."""
    parts = module.split(".")
    if len(parts) == 1:
        return module
    if len(parts) == 2 and (module not in MODULES or MODULES[module].name != "__init__.py"):
        return module
    return ".".join(parts[:2])


def _private_uses(module: str, tree: ast.AST) -> list[tuple[str, str, int]]:
    """(origin module, private name, line) for each ``from origin import _name`` in ``module``
    and each ``origin._name`` read through a module bound by an import."""
    found, bound = [], {}
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            for alias, target in zip(node.names, _targets(module, node)):
                if target.endswith("." + alias.name):  # a submodule: the name is bound to it
                    bound[alias.asname or alias.name] = target
                    origin = target.rpartition(".")[0]
                else:
                    origin = target
                if _is_private(alias.name):
                    found.append((origin, alias.name, node.lineno))
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.asname:
                    bound[alias.asname] = alias.name
    for node in ast.walk(tree):
        if (
            isinstance(node, ast.Attribute)
            and isinstance(node.value, ast.Name)
            and node.value.id in bound
            and _is_private(node.attr)
            and bound[node.value.id] in MODULES
        ):
            found.append((bound[node.value.id], node.attr, node.lineno))
    return found


def _private_imports_across(module: str, tree: ast.AST) -> list[str]:
    return [
        f"line {line}: {origin}.{name}"
        for origin, name, line in _private_uses(module, tree)
        if origin.startswith("contactsym") and _unit(origin) != _unit(module)
    ]


def test_the_private_import_finder_sees_names_and_attributes():
    plot = "contactsym.atlas.plot"
    assert _private_imports_across(plot, ast.parse("from ..plotting import _axes")) == [
        "line 1: contactsym.plotting._axes"
    ]
    assert _private_imports_across(plot, ast.parse("from .. import numerics\nnumerics._Values({}, {})")) == [
        "line 2: contactsym.numerics._Values"
    ]
    assert _private_imports_across(
        plot, ast.parse("from .grid import _axis\nfrom ..plotting import _axes as axes")
    ) == ["line 2: contactsym.plotting._axes"]
    assert (
        _private_imports_across(plot, ast.parse("from .grid import _axis\nfrom ..plotting import axes_or_current"))
        == []
    )
    assert _unit("contactsym.numerics.hopf") == _unit("contactsym.numerics") == "contactsym.numerics"
    assert _unit("contactsym.parse") != _unit("contactsym.validate")


@pytest.mark.parametrize("module", sorted(MODULES))
def test_no_private_name_is_imported_from_another_subpackage(module):
    """A subpackage's interface is its public names: ``_name`` is free to change inside its subpackage."""
    wrong = _private_imports_across(module, ast.parse(MODULES[module].read_text()))
    assert not wrong, f"{module} uses private names of other subpackages: {wrong}"


def _init_private_names(package: str, tree: ast.AST) -> list[str]:
    """Private names an ``__init__`` imports (or binds by ``import ... as _x``) or lists in ``__all__``;
    importing a private submodule of the package itself (``from . import _aliases``) re-exports nothing."""
    wrong = []
    for node in ast.iter_child_nodes(tree):
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            for alias in node.names:
                own_module = isinstance(node, ast.ImportFrom) and node.level == 1 and not node.module
                if own_module and f"{package}.{alias.name}" in MODULES and not alias.asname:
                    continue
                if _is_private(alias.name) or _is_private(alias.asname or ""):
                    wrong.append(f"line {node.lineno}: {alias.name}" + (f" as {alias.asname}" if alias.asname else ""))
        elif isinstance(node, ast.Assign) and any(isinstance(t, ast.Name) and t.id == "__all__" for t in node.targets):
            names = [e.value for e in getattr(node.value, "elts", []) if isinstance(e, ast.Constant)]
            wrong += [f"__all__ lists {name}" for name in names if _is_private(name)]
    return wrong


PACKAGES = sorted(m for m in MODULES if MODULES[m].name == "__init__.py")


def test_the_init_checker_sees_private_re_exports():
    assert _init_private_names("contactsym.numerics", ast.parse("from .codegen import _cached as _cached")) == [
        "line 1: _cached as _cached"
    ]
    assert _init_private_names("contactsym.numerics", ast.parse("from . import hopf as _hopf")) == [
        "line 1: hopf as _hopf"
    ]
    assert _init_private_names("contactsym.numerics", ast.parse('__all__ = ["decide", "_Values"]')) == [
        "__all__ lists _Values"
    ]
    assert _init_private_names("contactsym", ast.parse("from . import _aliases")) == []


@pytest.mark.parametrize("package", PACKAGES)
def test_no_init_re_exports_a_private_name(package):
    wrong = _init_private_names(package, ast.parse(MODULES[package].read_text()))
    assert not wrong, f"{package}/__init__.py imports or exports private names: {wrong}"


@pytest.mark.parametrize("package", PACKAGES)
def test_each_subpackage_has_all_and_its_names_exist(package):
    """``__all__`` is the subpackage's documented interface: present, and every name in it importable."""
    import importlib

    module = importlib.import_module(package)
    assert isinstance(getattr(module, "__all__", None), (list, tuple)), f"{package} has no __all__"
    missing = [name for name in module.__all__ if not hasattr(module, name)]
    assert not missing, f"{package}.__all__ names what it does not have: {missing}"


# --- the page against the tree, beyond the module list ----------------------------------------------

PAGE = (PACKAGE.parent / "docs" / "architecture.md").read_text()


def _scene_tags(page: str) -> dict[str, str]:
    """scene module -> its tag on the page: the registered name, or 'not registered'."""
    tags = {}
    for line in page.splitlines():
        if line.startswith("- `scenes/") and "__init__" not in line and "/_" not in line:
            module = line.split("`")[1]
            if "*not registered*" in line:
                tags[module] = "not registered"
            else:
                tags[module] = line.split("`")[3] if line.count("`") >= 4 else "untagged"
    return tags


def test_the_scene_tag_reader_reads_names_and_the_unregistered():
    page = "- `scenes/brake.py` (`brake`): §6\n- `scenes/stool.py` (*not registered*): k = 3\n- `scenes/_x.py`: a"
    assert _scene_tags(page) == {"scenes/brake.py": "brake", "scenes/stool.py": "not registered"}
    assert _scene_tags("- `scenes/stepladder.py`: Beyond the paper") == {"scenes/stepladder.py": "untagged"}


def test_every_built_in_scene_the_page_names_is_registered_and_every_registered_one_is_named():
    tags = _scene_tags(PAGE)
    assert "untagged" not in tags.values(), (
        f"scene modules without a tag: {[m for m, t in tags.items() if t == 'untagged']}"
    )
    registered = set(contactsym.scene_names())
    named = {tag for tag in tags.values() if tag != "not registered"}
    named |= set(re.findall(r"""scene\(["']([a-z-]+)["']\)""", PAGE))
    assert named <= registered, (
        f"docs/architecture.md names scenes that are not registered: {sorted(named - registered)}"
    )
    assert registered <= named, f"registered scenes the page does not tag: {sorted(registered - named)}"
    wrong = [m for m, tag in tags.items() if tag == "not registered" and Path(m).stem.replace("_", "-") in registered]
    assert not wrong, f"tagged not registered, but registered: {wrong}"


def _private_scene_reads(tree: ast.AST) -> list[str]:
    """``scene._x`` or ``self.scene._x``: a private attribute read on something named scene."""
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Attribute) and _is_private(node.attr):
            owner = node.value
            name = owner.id if isinstance(owner, ast.Name) else getattr(owner, "attr", "")
            if name == "scene":
                found.append(f"line {node.lineno}: {name}.{node.attr}")
    return found


def test_the_private_scene_read_finder_finds_one():
    assert _private_scene_reads(ast.parse("x = self.scene._stage(k, f)\ny = scene.cached(k, f)")) == [
        "line 1: scene._stage"
    ]


@pytest.mark.parametrize("module", sorted(m for m in MODULES if _below_the_scene(m)))
def test_no_stage_reads_a_private_attribute_of_the_scene(module):
    """The stages and counts use the scene's public interface (``scene.cached``, ``scene.fast_subsystem()``)."""
    wrong = _private_scene_reads(ast.parse(MODULES[module].read_text()))
    assert not wrong, f"{module} reads private attributes of a scene: {wrong}"
