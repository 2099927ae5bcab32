"""Files a person names on the command line that can't be read or written: a message in plain
words and exit 1, never "Something went wrong inside rootlang" (E699) nor Python's
``[Errno 2] ...`` text."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from rootlang.cli import main

PROGRAM = "when started\n    move 10 cm\n"


def _program(folder: Path, text: str = PROGRAM) -> Path:
    path = folder / "p.root"
    path.write_text(text, encoding="utf-8")
    return path


def _said(capsys: pytest.CaptureFixture[str], *args: str) -> tuple[int, str]:
    status = main(list(args))
    captured = capsys.readouterr()
    return status, captured.err


@pytest.mark.parametrize("where", ["missing/out.root", "."])
def test_translate_into_a_missing_folder_or_onto_a_folder(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], where: str
) -> None:
    status, said = _said(capsys, "translate", str(_program(tmp_path)), "--to", "nl",
                         "-o", str(tmp_path / where))  # fmt: skip
    assert status == 1
    assert said.startswith(f"I can't write {tmp_path / where}: ")
    assert "went wrong" not in said and "Errno" not in said


@pytest.mark.parametrize("kind", ["svg", "png", "html"])
def test_a_picture_onto_a_folder_says_so_without_python_words(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], kind: str
) -> None:
    status, said = _said(capsys, "sim", str(_program(tmp_path)), f"--{kind}", str(tmp_path))
    assert status == 1
    assert said.strip() == f"I can't write the picture {tmp_path}: it is a folder."


def test_a_world_file_that_is_not_text(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    world = tmp_path / "w.toml"
    world.write_bytes(b"\xb5\xff\x00 not text")
    status, said = _said(capsys, "sim", str(_program(tmp_path)), "--world", str(world))
    assert status == 1
    assert said.strip() == f"I can't read the world file {world}: it isn't plain text (UTF-8)."


def test_blocks_from_a_file_that_is_not_text(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    workspace = tmp_path / "w.json"
    workspace.write_bytes(b"\xbd\xff\x00{")
    status, said = _said(capsys, "--language", "nl", "blocks", "--to-text", str(workspace))
    assert status == 1
    assert said.strip() == f"Ik kan {workspace} niet lezen: het is geen gewone tekst (UTF-8)."


def test_format_that_cannot_replace_the_file_leaves_it_and_says_so(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """The only mock here: the tests may run as root, who may write any file, so the refusal
    a pupil's read-only file gives is made by ``os.replace`` raising as the system would."""
    program = _program(tmp_path, "WHEN started\n  move 10 cm\n")

    def refuse(source: str, target: str) -> None:
        raise PermissionError(1, "Operation not permitted", source, None, target)

    monkeypatch.setattr(os, "replace", refuse)
    status, said = _said(capsys, "format", str(program))
    assert status == 1
    assert said.strip() == f"I can't write {program}: I'm not allowed to (no permission)."
    assert program.read_text(encoding="utf-8") == "WHEN started\n  move 10 cm\n"
    assert [path.name for path in tmp_path.iterdir()] == ["p.root"]  # no temporary file left
