"""`rootlang format`: canonical text in place, --check, stdin, and files left alone on mistakes."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from rootlang.wording.catalogue import message
from rootlang.wording.language import Languages


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


@pytest.mark.parametrize(
    ("language", "said"),
    [("en", "Files formatted: 1."), ("nl", "Bestanden opgemaakt: 1."),
     ("es", "Archivos ordenados: 1."), ("fr", "Fichiers mis en forme : 1."),
     ("de", "Dateien formatiert: 1.")],
)  # fmt: skip
def test_what_format_and_new_say_is_in_the_childs_language(
    tmp_path: Path, language: str, said: str
) -> None:
    """`new` and `format` speak --language (they spoke only English, whatever was chosen)."""
    made = rootlang("--language", language, "new", str(tmp_path / "mine"))
    assert made.returncode == 0
    first_line = made.stdout.splitlines()[0]
    assert first_line == message("V060", {"path": str(tmp_path / "mine.root"),
                                          "picture": str(tmp_path / "mine.svg")},
                                 Languages(chosen=language))  # fmt: skip
    program = tmp_path / "messy.root"
    program.write_text(MESSY)
    done = rootlang("--language", language, "format", str(program))
    assert done.returncode == 0 and said in done.stdout.splitlines()[-1]
    assert done.stdout.splitlines()[0] == message("V061", {"path": str(program)},
                                                  Languages(chosen=language))  # fmt: skip
