"""`rootlang format`: canonical text in place, --check, stdin, and files left alone on mistakes."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path


def rootlang(*args: str, stdin: str | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "rootlang", *args], input=stdin,
                          capture_output=True, text=True, check=False)  # fmt: skip


MESSY = "WHEN Started:\n  Move FORWARD 10cm   #go\n  forever\n    turn left 90°\n"
TIDY = "when started\n    move forward 10 cm  # go\n    repeat forever\n        turn left 90°\n"


def test_format_rewrites_the_file_and_a_second_run_changes_nothing(tmp_path: Path) -> None:
    program = tmp_path / "messy.root"
    program.write_text(MESSY)
    first = rootlang("format", str(program))
    assert first.returncode == 0 and program.read_text() == TIDY
    assert "formatted" in first.stdout
    second = rootlang("format", "--check", str(program))
    assert second.returncode == 0


def test_check_changes_nothing_and_exits_1(tmp_path: Path) -> None:
    program = tmp_path / "messy.root"
    program.write_text(MESSY)
    done = rootlang("format", "--check", str(program))
    assert done.returncode == 1 and program.read_text() == MESSY
    assert "would be changed by `rootlang format`" in done.stderr


def test_stdin_in_stdout_out() -> None:
    done = rootlang("format", "-", stdin=MESSY)
    assert done.returncode == 0 and done.stdout == TIDY


def test_a_program_with_mistakes_is_left_as_it_is(tmp_path: Path) -> None:
    program = tmp_path / "broken.root"
    program.write_text("when started\n    mvoe 10 cm cm\n")
    done = rootlang("format", str(program))
    assert done.returncode == 1 and program.read_text() == "when started\n    mvoe 10 cm cm\n"
    assert "line 2" in done.stderr and "Traceback" not in done.stderr
