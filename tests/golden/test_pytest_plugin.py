"""The pytest plugin: a teacher's folder of programs tested with plain `pytest`, only when asked."""

from __future__ import annotations

import subprocess
import sys
from importlib import metadata
from pathlib import Path

import pytest

PROGRAM = '# hello.root: says hello\nwhen started\n    say "hello"\n'

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="needs fork and resource")


def _pytest(folder: Path, *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "pytest", "-p", "no:cacheprovider", *args],
        cwd=folder,
        capture_output=True,
        text=True,
        timeout=120,
    )


def _write_golden_file(folder: Path) -> int:
    """``rootlang test --update hello.root`` in ``folder``: its exit code."""
    command = [sys.executable, "-m", "rootlang", "test", "--update", "hello.root"]
    return subprocess.run(command, cwd=folder, capture_output=True, text=True).returncode


def test_the_plugin_is_registered_for_pytest() -> None:
    plugins = {entry.name: entry.value for entry in metadata.entry_points(group="pytest11")}
    if "rootlang" not in plugins:
        pytest.skip("rootlang's entry points are not installed: pip install -e .")
    assert plugins["rootlang"] == "rootlang.testing.pytest_plugin"


def test_programs_with_golden_files_are_tested_only_when_asked(tmp_path: Path) -> None:
    (tmp_path / "hello.root").write_text(PROGRAM, encoding="utf-8")
    (tmp_path / "no_golden.root").write_text(PROGRAM, encoding="utf-8")
    off = _pytest(tmp_path)
    assert "no tests ran" in off.stdout, off.stdout + off.stderr

    updated = _pytest(tmp_path, "--rootlang", "--rootlang-update")
    assert "no tests ran" in updated.stdout  # a program without a golden file is not collected
    assert _write_golden_file(tmp_path) == 0

    passed = _pytest(tmp_path, "--rootlang", "-v")
    assert passed.returncode == 0, passed.stdout + passed.stderr
    assert "hello.root::hello.root PASSED" in passed.stdout

    (tmp_path / "hello.root").write_text(PROGRAM.replace('"hello"', '"goodbye"'), "utf-8")
    failed = _pytest(tmp_path, "-o", "rootlang=true")
    assert failed.returncode == 1
    assert "The first difference comes from line 3 of hello.root:" in failed.stdout
    assert "+++ this run" in failed.stdout


def test_rootlang_update_rewrites_golden_files_from_pytest(tmp_path: Path) -> None:
    program = tmp_path / "hello.root"
    program.write_text(PROGRAM, encoding="utf-8")
    assert _write_golden_file(tmp_path) == 0
    program.write_text(PROGRAM.replace('"hello"', '"goodbye"'), "utf-8")
    assert _pytest(tmp_path, "--rootlang").returncode == 1

    updated = _pytest(tmp_path, "--rootlang", "--rootlang-update")
    assert updated.returncode == 0, updated.stdout + updated.stderr
    assert "goodbye" in (tmp_path / "hello.golden").read_text(encoding="utf-8")
    assert _pytest(tmp_path, "--rootlang").returncode == 0
