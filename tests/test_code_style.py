"""The code base and its tests stay ruff- and mypy-clean: these run as part of the test suite."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def _tool(name: str) -> list[str]:
    if shutil.which(name) is None and not (Path(sys.executable).parent / name).exists():
        pytest.skip(f"{name} is not installed (pip install -e '.[test]')")
    return [sys.executable, "-m", name]


def test_ruff_is_clean() -> None:
    result = subprocess.run(
        [*_tool("ruff"), "check", "rootlang", "tests", "benchmarks", "scripts"],
        cwd=ROOT,
        capture_output=True,
        text=True,
    )
    assert result.returncode == 0, result.stdout + result.stderr


def test_ruff_format_is_applied() -> None:
    result = subprocess.run(
        [*_tool("ruff"), "format", "--check", "rootlang", "tests", "benchmarks", "scripts"],
        cwd=ROOT, capture_output=True, text=True,
    )  # fmt: skip
    assert result.returncode == 0, result.stdout + result.stderr


def test_mypy_is_clean() -> None:
    result = subprocess.run([*_tool("mypy")], cwd=ROOT, capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr


def test_the_tests_are_type_checked_as_the_package_is() -> None:
    result = subprocess.run(
        [*_tool("mypy"), "--strict", "tests"], cwd=ROOT, capture_output=True, text=True
    )
    assert result.returncode == 0, result.stdout + result.stderr


# A node type added to the syntax tree and left out of a handler: a statement, an expression
# and a robot event, each put into its union in rootlang/ast.py (what the recipe in
# docs/architecture.md says to do), with no case for it anywhere.
NEW_NODES = {
    "AnyStatement = (\n": "Honk(Statement)",
    "AnyExpression = (\n": "Echo(Expression)",
    "RobotEvent = (\n": "Squeak(Event)",
}
NODE_CLASS = (
    "@dataclass(frozen=True, eq=False, repr=False, slots=True)\nclass {}:\n    x: int\n\n\n"
)
HANDLERS = ("checks.py", "runtime/interpreter.py", "runtime/scheduler.py", "formatting.py")


def test_mypy_rejects_a_node_that_nobody_handles(tmp_path: Path) -> None:
    source = (ROOT / "rootlang" / "ast.py").read_text(encoding="utf-8")
    for union, node in NEW_NODES.items():
        name = node.split("(")[0]
        assert union in source
        source = source.replace(union, f"{NODE_CLASS.format(node)}{union}    {name}\n    | ", 1)
    shadow = tmp_path / "ast.py"
    shadow.write_text(source, encoding="utf-8")
    result = subprocess.run(
        [*_tool("mypy"), "--shadow-file", "rootlang/ast.py", str(shadow),
         "--cache-dir", str(tmp_path / "cache"), "--follow-imports", "silent", "rootlang/ast.py",
         *(f"rootlang/{handler}" for handler in HANDLERS)],
        cwd=ROOT, capture_output=True, text=True,
    )  # fmt: skip
    unhandled = sorted(
        line.split(":")[0] + " " + line.split('incompatible type "')[1].split('"')[0]
        for line in result.stdout.splitlines()
        if '"assert_never" has incompatible type' in line
    )
    assert unhandled == [
        "rootlang/checks.py Echo",  # the checks: statements and expressions
        "rootlang/checks.py Honk",
        "rootlang/formatting.py Echo",  # the printer's expressions (statements: by their form)
        "rootlang/runtime/interpreter.py Echo",  # the runtime: statements and expressions
        "rootlang/runtime/interpreter.py Honk",
        "rootlang/runtime/scheduler.py Squeak",  # the edge test of a robot event
    ], result.stdout
