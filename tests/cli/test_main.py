"""`rootlang` as a new user meets it: Ctrl-C at any moment, names that need quoting."""

from __future__ import annotations

import argparse
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import pytest

import rootlang.cli
from rootlang.cli import main


def test_ctrl_c_while_starting_up_exits_130_without_traceback(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    # Ctrl-C pressed while the subcommand is still being imported or the arguments parsed
    def interrupted(command: str | None = None) -> argparse.ArgumentParser:
        raise KeyboardInterrupt

    monkeypatch.setattr(rootlang.cli, "build_parser", interrupted)
    assert _exit_status(["sim", "square.root"]) == 130
    assert capsys.readouterr().err.strip() == "Stopped (Ctrl-C)."


def test_ctrl_c_while_a_command_runs_exits_130(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    import rootlang.cli.packet as packet_command

    def interrupted(args: argparse.Namespace) -> int:
        raise KeyboardInterrupt

    monkeypatch.setattr(packet_command, "run", interrupted)
    assert _exit_status(["packet", "list"]) == 130
    assert capsys.readouterr().err.strip() == "Stopped (Ctrl-C)."


def _exit_status(argv: list[str]) -> int:
    try:
        return main(argv)
    except KeyboardInterrupt:  # reaching here is the bug: Python would print a traceback
        pytest.fail("Ctrl-C escaped from main()")


def test_the_language_can_come_before_the_command(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    program = tmp_path / "hallo.root"
    program.write_text("wanneer gestart\n    beweeg 1 cm\n", encoding="utf-8")
    assert main(["--language", "nl", "check", str(program)]) == 0
    assert main(["check", str(program), "--language", "nl"]) == 0


def test_new_with_a_space_shows_a_command_that_can_be_pasted(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.chdir(tmp_path)
    assert main(["new", "my dance"]) == 0
    assert "rootlang sim 'my dance.root' --svg 'my dance.svg'" in capsys.readouterr().out
    assert "`rootlang sim 'my dance.root'`" in (tmp_path / "my dance.root").read_text()


def test_a_program_named_without_root_is_found(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "hello.root").write_text("when started\n    move 1 cm\n", encoding="utf-8")
    assert main(["check", "hello"]) == 0
    assert main(["check", "bye"]) == 1
    assert "I can't find the file bye." in capsys.readouterr().err


@pytest.mark.parametrize(
    ("command", "make", "says"),
    [
        ("run", lambda path: path.mkdir(), "is a folder, not a program"),
        ("check", lambda path: path.mkdir(), "I found no .root programs in"),
        ("check", lambda path: path.write_bytes(b"\xff\xfe move"), "isn't plain text"),
    ],
)
def test_what_is_not_a_program_is_named_in_plain_words(
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    command: str,
    make: Callable[[Path], object],
    says: str,
) -> None:
    make(tmp_path / "odd.root")
    assert main([command, str(tmp_path / "odd.root")]) == 1
    err = capsys.readouterr().err
    assert says in err
    assert "Errno" not in err and "codec" not in err


def test_warnings_before_a_run_name_the_program_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "pen.root").write_text("when started\n    marker down\n", encoding="utf-8")
    main(["sim", "pen.root", "--robot", "Create3"])
    err = capsys.readouterr().err
    assert "pen.root, line 2:\n" in err and "warning: Create 3 can't use the marker" in err
    assert "<program>" not in err


def test_run_says_how_to_stop_a_program_that_waits_for_events(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    pytest.importorskip("bumble")  # the virtual robot over a real BLE stack
    program = tmp_path / "short.root"
    program.write_text("when started\n    move 1 cm\n", encoding="utf-8")
    assert main(["run", str(program), "--transport", "virtual"]) == 0
    assert "To stop the program, press the robot's nose button" in capsys.readouterr().err


def test_test_in_a_folder_without_programs_says_this_folder(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.chdir(tmp_path)
    assert main(["test"]) == 1
    assert "I found no .root programs in this folder." in capsys.readouterr().err


@pytest.mark.skipif(sys.platform == "win32", reason="the golden runner needs fork")
def test_pytest_rootlang_names_programs_without_a_golden_file(tmp_path: Path) -> None:
    (tmp_path / "ana.root").write_text("when started\n    move 1 cm\n", encoding="utf-8")
    ran = subprocess.run(
        [sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "--rootlang"],
        cwd=tmp_path, capture_output=True, text=True, timeout=120,
    )  # fmt: skip
    assert "not tested: ana.root: There is no golden file ana.golden yet." in ran.stdout


@pytest.mark.parametrize("name", ["", "   "])
def test_a_robot_cannot_be_renamed_to_nothing(
    name: str, capsys: pytest.CaptureFixture[str]
) -> None:
    # refused before looking for a robot: no Bluetooth needed
    assert main(["robot", "rename", name]) == 1
    assert "can't be a robot's name: it is empty" in capsys.readouterr().err


@pytest.mark.skipif(sys.platform == "win32", reason="the golden runner needs fork")
def test_rootlang_test_names_a_file_that_is_not_text_in_plain_words(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "odd.root").write_bytes(b"\xff\xfe move")
    assert main(["test", "--update", "odd.root"]) == 0
    golden = (tmp_path / "odd.golden").read_text(encoding="utf-8")
    assert "odd.root isn't plain text" in golden and "codec" not in golden
