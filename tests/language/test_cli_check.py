"""`rootlang check`: exit codes, rendered errors, --json, --robot, missing files."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from rootlang.cli import main


def write(folder: Path, name: str, text: str) -> str:
    path = folder / name
    path.write_text(text, encoding="utf-8")
    return str(path)


def test_clean_file_exits_0(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = write(tmp_path, "ok.root", "when started\n    move 10 cm\n")
    assert main(["check", path]) == 0
    assert "No mistakes" in capsys.readouterr().out


def test_errors_exit_1_with_caret(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = write(tmp_path, "bad.root", "when started\n    mve 10 cm\n")
    assert main(["check", path]) == 1
    err = capsys.readouterr().err
    assert "bad.root, line 2:\n            mve 10 cm\n            ^^^\n" in err
    assert 'Did you mean "move"?' in err and "Traceback" not in err


def test_json_lists_every_mistake(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    first = write(tmp_path, "a.root", "when started\n    move 10\n    turn left 90\n")
    second = write(tmp_path, "b.root", "when started\n    move 1 cm\n")
    assert main(["check", "--json", first, second]) == 1
    found = json.loads(capsys.readouterr().out)
    assert [(item["file"], item["line"], item["column"], item["code"]) for item in found] == [
        (first, 2, 10, "E108"),
        (first, 3, 15, "E108"),
    ]
    assert {"end_line", "end_column", "message"} <= set(found[0])


def test_robot_warnings_do_not_fail(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = write(tmp_path, "c.root", "when color red seen\n    stop moving\n")
    assert main(["check", "--robot", "RT0", "--json", path]) == 0
    (warning,) = json.loads(capsys.readouterr().out)
    assert warning["code"] == "W101" and "Root RT0 has no colour sensor" in warning["message"]
    assert main(["check", "--robot", "RT1", path]) == 0


def test_missing_file(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["check", str(tmp_path / "nope.root")]) == 1
    assert "I can't find the file" in capsys.readouterr().err
