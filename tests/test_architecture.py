"""The import graph of contactsym, read with ``ast``: no cycle, latex a leaf, the stages below the scene.

Every import counts, also one inside a function; only ``if TYPE_CHECKING:`` blocks are left out
(they never run). An import inside a function is allowed for a heavy optional module, or with a
comment saying why.
"""

import ast
import pathlib
from dataclasses import dataclass

import pytest

import contactsym

PACKAGE = pathlib.Path(contactsym.__file__).parent

#: The pipeline's stages: computed from the previous stage, never from what is built on them.
STAGES = ("regularize", "fast", "equilibria", "linear", "hurwitz", "stability", "regions", "counts")

#: What the stages are below: the scene and its registry, output and numerics.
ABOVE_THE_STAGES = ("scene", "scenes", "plotting", "report", "numerics")

#: Heavy optional modules that may be imported where first needed, without a comment.
HEAVY = ("matplotlib", "scipy.optimize", "dask", "xarray")


@dataclass(frozen=True)
class Import:
    source: str  # the importing module, e.g. "contactsym.fast"
    target: str  # the imported module ("contactsym.latex", or an outside one: "matplotlib.pyplot")
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


def _graph() -> dict[str, set[str]]:
    """contactsym module -> the contactsym modules it imports (anywhere in it)."""
    return {
        module: {i.target for i in imports if i.target in MODULES and i.target != module}
        for module, imports in IMPORTS.items()
    }


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
    stability = {(i.target, i.in_function) for i in IMPORTS["contactsym.stability"]}
    assert ("contactsym.robustness", True) in stability  # imported where first needed
    assert ("contactsym.linear", False) in stability
    assert all(i.line > 0 for i in IMPORTS["contactsym.stability"])
    assert any(i.target == "contactsym.scenes" for i in IMPORTS["contactsym.scenefile"])


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
    assert _is_leaf("contactsym.latex")
    assert not _is_leaf("contactsym.fast")


def _is_leaf(module: str) -> bool:
    """A module that imports no contactsym module but ``errors``: importing it can close no cycle."""
    return {i.target for i in IMPORTS[module] if i.target in MODULES} <= {"contactsym.errors"}


@pytest.mark.parametrize("stage", STAGES)
def test_stages_never_import_what_is_built_on_them(stage):
    above = {f"contactsym.{name}" for name in ABOVE_THE_STAGES}
    wrong = [
        f"line {i.line}: {i.target}"
        for i in IMPORTS[f"contactsym.{stage}"]
        if i.target in above or any(i.target.startswith(f"{name}.") for name in above)
    ]
    assert not wrong, f"contactsym.{stage} imports " + "; ".join(wrong)


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
