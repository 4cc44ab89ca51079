"""The README is the front door: its quick start and its examples must stay true."""

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
README = (ROOT / "README.md").read_text()


def fenced_blocks(language: str = "") -> list[str]:
    return re.findall(rf"```{language}\n(.*?)```", README, flags=re.S)


def quick_start_commands() -> list[str]:
    section = README.split("## Quick start", 1)[1]
    block = re.search(r"```\n(.*?)```", section, flags=re.S).group(1)
    return [line for line in block.splitlines() if line.strip()]


def test_quick_start_has_two_commands_and_ci_runs_the_second():
    install_and_run, install_and_test = quick_start_commands()
    assert "pip install ." in install_and_run and "contactsym" in install_and_run
    assert '".[test]"' in install_and_test and "pytest" in install_and_test
    ci_lines = [line for line in (ROOT / ".ci" / "run").read_text().splitlines() if line.strip()]
    assert ci_lines[-1] == install_and_test


def test_python_examples_run():
    for block in fenced_blocks("python"):
        exec(compile(block, "README.md", "exec"), {})
