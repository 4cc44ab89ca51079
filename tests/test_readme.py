"""The README is the front door and the guides (docs/guides/) hold the rest: their quick start and
examples must stay true, and so must every result they state (verdicts in the examples'
comments, regions and numbers in their prose).

Each check reads the stated result out of README.md or a guide and compares it with what the
code gives, so it fails when either drifts. Every Python block of the README and the guides runs."""

import math
import re
from functools import cache
from pathlib import Path

import sympy as sp
from sympy.parsing.sympy_parser import implicit_multiplication_application, parse_expr, standard_transformations

import contactsym as cs
from contactsym.cli import main as command_line
from contactsym.scenes import scene_names

ROOT = Path(__file__).resolve().parents[1]
README = (ROOT / "README.md").read_text()
GUIDES = sorted((ROOT / "docs" / "guides").glob("*.md"))
#: The README and the guides, the text whose statements the tests check.
TEXT = "\n".join([README, *(path.read_text() for path in GUIDES)])


def fenced_blocks(language: str = "", text: str = TEXT) -> list[str]:
    return re.findall(rf"```{language}\n(.*?)```", text, flags=re.S)


def quick_start_commands() -> list[str]:
    section = README.split("## Quick start", 1)[1]
    block = re.search(r"```\n(.*?)```", section, flags=re.S).group(1)
    return [line for line in block.splitlines() if line.strip()]


def stated(pattern: str, text: str = TEXT) -> re.Match:
    """The statement of the README or a guide matching ``pattern`` (a space matches any run of white space)."""
    match = re.search(pattern.replace(" ", r"\s+"), text, flags=re.M)
    assert match, f"README.md and docs/guides/ no longer state {pattern!r}: update this test with it"
    return match


def math_of(text: str, symbols) -> sp.Expr:
    """A formula as the README writes it in prose (juxtaposition multiplies), in the given symbols."""
    names = {str(s): s for s in symbols}
    transformations = standard_transformations + (implicit_multiplication_application,)
    return parse_expr(text, local_dict=names, transformations=transformations)


@cache
def run(block: str) -> dict:
    """Run a Python block of the README in a namespace of its own (once per test process)."""
    namespace: dict = {}
    exec(compile(block, "README.md", "exec"), namespace)
    return namespace


def example(containing: str) -> tuple[str, dict]:
    """The Python block that contains ``containing`` and the namespace it leaves."""
    found = [block for block in fenced_blocks("python") if containing in block]
    assert len(found) == 1, f"README.md and the guides have {len(found)} Python blocks containing {containing!r}"
    return found[0], run(found[0])


def test_quick_start_has_two_commands_and_ci_runs_the_second():
    install_and_run, install_and_test = quick_start_commands()
    assert "pip install ." in install_and_run and "contactsym" in install_and_run
    assert '".[test]"' in install_and_test and "pytest" in install_and_test
    ci_lines = [line for line in (ROOT / ".ci" / "run").read_text().splitlines() if line.strip()]
    assert ci_lines[-1] == install_and_test


def test_python_examples_run():
    blocks = fenced_blocks("python")
    assert len(blocks) >= 4 and all(isinstance(run(block), dict) for block in blocks)


def test_report_command_writes_what_the_quick_start_says(tmp_path, monkeypatch, capsys):
    # "writes a report for each built-in scene ... into `contactsym-report/<scene>/`: `report.tex`
    # ...; `figures/*.png`; and `conditions.json`. It prints a short summary of the conditions."
    folder = stated(r"into `([\w-]+)/<scene>/`: `report.tex`").group(1)
    stated(r"`figures/\*.png`; and `conditions.json`. It prints a short summary of the conditions.")
    monkeypatch.chdir(tmp_path)
    assert command_line(["report", "sliding-point", "--no-pdf"]) == 0
    written = tmp_path / folder / "sliding-point"
    assert (written / "report.tex").is_file() and (written / "conditions.json").is_file()
    assert list((written / "figures").glob("*.png"))
    assert "stable for every law: True" in capsys.readouterr().out


def test_built_in_scenes_are_the_ones_the_readme_names(capsys):
    # "the paper's four and five mechanisms beyond it"; the Use example names them all
    paper, beyond = stated(r"the paper's (\w+) and (\w+) mechanisms beyond it").groups()
    words = {"three": 3, "four": 4, "five": 5}
    block, _ = example("s.fast_subsystem()")
    first = stated(r's = cs.scene\("([\w-]+)"\)\s*# also: ([^\n]*)\n\s*# ([^\n]*)', block)
    named = [first.group(1)] + re.split(r",\s*", (first.group(2) + " " + first.group(3)).strip(" ,"))
    assert sorted(named) == sorted(scene_names())
    assert command_line(["list"]) == 0  # `contactsym list  # the built-in scenes`
    listed = dict(line.split(None, 1) for line in capsys.readouterr().out.splitlines())
    assert sorted(listed) == sorted(scene_names())
    from_the_paper = [name for name, description in listed.items() if re.match(r"\(\d\.\d+\)", description)]
    assert (len(from_the_paper), len(listed) - len(from_the_paper)) == (words[paper], words[beyond])
    # "examples/ states each built-in scene this way (examples/<name>.toml)"
    stated(r"`examples/` states each built-in scene this way \(`examples/<name>.toml`\)")
    assert all((ROOT / "examples" / f"{name}.toml").is_file() for name in scene_names())


def test_attributes_named_in_the_examples_comments_exist():
    # `lin = s.linearization()  # .A (4.3) .jacobian (4.5) ...`: each .name is an attribute of lin
    checked = 0
    for block in fenced_blocks("python"):
        target = None
        for line in block.splitlines():
            assignment = re.match(r"(\w+) = [^#]*#(.*)", line)
            continuation = re.match(r"\s+#(.*)", line)
            if assignment:
                target, comment = assignment.groups()
            elif continuation and target:
                comment = continuation.group(1)
            else:
                target = None
                continue
            for attribute in re.findall(r"(?:^|\s)\.(\w+)", comment):
                assert hasattr(run(block)[target], attribute), (target, attribute)
                checked += 1
    assert checked >= 10


def test_presented_jacobian_is_in_the_stated_variables():
    block, namespace = example("s.present(lin.A)")
    names = stated(r"s.present\(lin.A\)\s+# in the paper's variables ([^\n]+)", block).group(1)
    free = {str(s) for s in namespace["s"].present(namespace["lin"].A).free_symbols}
    assert set(re.split(r",\s*", names.strip())) <= free


def test_own_system_verdict_is_the_stated_one():
    block, namespace = example("cs.Scene.from_accelerations")
    expression, verdict, proposition = stated(r"^(\S+)\s+# (True|False): Proposition (\d)", block).groups()
    assert eval(expression, namespace) == {"True": sp.true, "False": sp.false}[verdict]
    propositions = namespace["s"].stability().propositions
    assert any(n.startswith(f"Proposition {proposition} ") and c == sp.true for n, c in propositions.items())


def test_hopf_direction_and_amplitude_law_are_the_stated_ones():
    block, namespace = example("numerics.hopf_point")
    direction = stated(r"^h.direction, .*# '(\w+)': reaction amplitudes ~ sqrt\(distance / \|l1\|\)", block)
    h = namespace["h"]
    assert h.direction == direction.group(1)
    assert (h.l1 < 0) == (direction.group(1) == "supercritical")
    # amplitude ~ sqrt(distance): four times as far past the line, twice the amplitude
    ratio = h.amplitude(h.value * 1.04) / h.amplitude(h.value * 1.01)
    assert all(math.isclose(r, 2, rel_tol=1e-6) for r in ratio)


def test_double_pendulum_jacobian_is_the_stated_formula_of_the_stated_size():
    block, namespace = example("Particle(")
    size, formula = stated(r"# (\d+) operations, in multiple angles:\n# ([^\n]*)", block).groups()
    A = namespace["A"]
    assert sp.count_ops(A) == int(size)
    printed = math_of(formula, A.free_symbols)
    assert sp.expand(sp.expand_trig(sp.together(A - printed))) == 0
    # the same number in the prose on symengine ("... against 27 in A")
    assert stated(r"against (\d+) in A").group(1) == size


def test_leaning_rod_file_and_its_stated_region(capsys):
    (toml,) = fenced_blocks("toml")
    stated(r"\(it is also\n?`examples/leaning-rod.toml`\)")
    path = ROOT / "examples" / "leaning-rod.toml"
    assert toml == path.read_text()
    region = stated(r"stable for every contact law where\n?([^,]*), the classical Painlevé bound").group(1)
    assert command_line(["conditions", str(path)]) == 0
    printed = re.search(r"^  stable for every law: (.*?)\s+\(", capsys.readouterr().out, flags=re.M).group(1)
    symbols = cs.load_scene(path).stability().robustly_stable.free_symbols
    ours, theirs = math_of(printed, symbols), math_of(region.strip(), symbols)
    assert type(ours) is type(theirs) and sp.expand(ours.lhs - ours.rhs - theirs.lhs + theirs.rhs) == 0


def test_notebook_table_lists_every_notebook_and_links_resolve():
    # "the tests execute all of them": the table is the whole list
    guide = (ROOT / "docs" / "guides" / "notebooks.md").read_text()
    listed = re.findall(r"^\| \[\w+\]\(\.\./notebooks/(\w+\.ipynb)\)", guide, flags=re.M)
    assert sorted(listed) == sorted(p.name for p in (ROOT / "notebooks").glob("*.ipynb"))
    for path in [ROOT / "README.md", *GUIDES]:
        links = re.findall(r"\]\(([^)#:]+\.(?:md|ipynb|toml|png))\)", path.read_text())
        missing = [link for link in links if not (path.parent / link).is_file()]
        assert not missing, f"{path.name} links to missing files: {missing}"


def benchmark_rows() -> dict[str, list[str]]:
    """The table of the saved `contactsym bench --quick` run: name -> its other columns."""
    rows = {}
    for line in (ROOT / "benchmarks" / "results" / "README.md").read_text().splitlines():
        cells = [c.strip() for c in line.strip("|").split("|")]
        if line.startswith("| ") and len(cells) == 7:
            rows[cells[0]] = cells[1:]
    return rows


# README prose about `contactsym bench --quick` -> (table row, column, scale to the README's unit)
BENCHMARK_CLAIMS = {
    r"10\^6 brake parameter points classified in (\d+) ms": ("classification", "ours_s", 1e3),
    r"(\d+) times faster than per-point eigenvalues": ("classification", "ratio", 1),
    r"reduced system ([\d.]+) times cheaper than the full one at eps = 1e-4": ("work-precision", "ratio", 1),
    r"analytic Jacobian (\d+) times fewer right-hand-side evaluations on the guides": (
        "analytic-jacobian-rhs/guides",
        "ratio",
        1,
    ),
    r"the four paper scenes derived from scratch in ([\d.]+) s": ("derivation/paper-scenes-total", "ours_s", 1),
    r"the 6-link chain from scene to stability in (\d+) s": ("scaling/chain n=6", "ours_s", 1),
    r"chain n = 3 in ([\d.]+) s": ("scaling/chain n=3", "ours_s", 1),
    r"n = 6 in (\d+) s": ("scaling/chain n=6", "ours_s", 1),
    r"the stepladder \(4 coordinates, 3 contacts\) in (\d+) s": ("scaling/stepladder", "ours_s", 1),
    r"LU solve \+ expand does not finish n = 3 in (\d+) s": ("scaling/chain n=3", "baseline_s", 1),
}
COLUMNS = ["ours_s", "baseline_s", "ratio", "error", "n", "notes"]


def test_benchmark_numbers_in_the_prose_are_those_of_the_saved_quick_run():
    rows = benchmark_rows()
    for pattern, (row, column, scale) in BENCHMARK_CLAIMS.items():
        text = stated(pattern).group(1)
        value = float(rows[row][COLUMNS.index(column)]) * scale
        last_digit = 10.0 ** -len(text.partition(".")[2])
        assert abs(value - float(text)) <= last_digit / 2 + 1e-9 * value, (pattern, value)
    stated(r"with no disagreement outside the certified band")
    assert float(rows["classification"][COLUMNS.index("error")]) == 0
    assert "did not finish in 20 s" in rows["scaling/chain n=3"][COLUMNS.index("notes")]
    stated(r"\(8,638 operations in the accelerations of 2 links, against 27 in A\)")
    assert re.search(r"ours: ops f \d+, A 27,", rows["scaling/chain n=2"][COLUMNS.index("notes")])
