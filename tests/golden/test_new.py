"""`rootlang new NAME` writes a starter program that passes the checks, and never overwrites."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from rootlang.app.files import starter
from rootlang.checks import load_checked
from rootlang.cli import main
from rootlang.locale.keywords import LANGUAGES


def test_new_writes_a_starter_program_that_passes_the_checks(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    assert main(["new", "dance"]) == 0
    source = (tmp_path / "dance.root").read_text(encoding="utf-8")
    assert source.startswith("# dance.root: ")
    checked = load_checked(source, "dance.root")
    assert not checked.warnings
    assert "rootlang sim dance.root" in capsys.readouterr().out


def test_new_keeps_a_root_suffix_and_refuses_to_overwrite(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    target = tmp_path / "mine.root"
    assert main(["new", str(target)]) == 0
    target.write_text("# my own work\n", encoding="utf-8")
    assert main(["new", str(target)]) == 1
    assert "already exists" in capsys.readouterr().err
    assert target.read_text(encoding="utf-8") == "# my own work\n"


def test_new_in_a_missing_folder_says_so(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["new", str(tmp_path / "no-such-folder" / "x")]) == 1
    assert "There is no folder" in capsys.readouterr().err


def test_the_starter_ends_by_itself_soon(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """A first program that idles to the time limit looks broken: the starter must finish."""
    monkeypatch.chdir(tmp_path)
    assert main(["new", "hello"]) == 0
    capsys.readouterr()
    assert main(["sim", "hello", "--json"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert summary["end"] == "finished"
    assert summary["sim_time_s"] < 20
    assert summary["said"] == ["I drew a square"]


@pytest.mark.parametrize("language", [language for language in LANGUAGES if language != "en"])
def test_the_starter_is_wholly_in_its_language(language: str) -> None:
    """Every line is in the language: the keywords, the first comment and what the robot says
    (only the `# language:` line, which says so, is rootlang's own); and it passes the checks."""
    english = starter("dans", "dans.root", None).splitlines()
    text = starter("dans", "dans.root", language)
    lines = text.splitlines()
    assert lines.pop(1) == f"# language: {language}"
    assert len(lines) == len(english)
    same = [line for line, theirs in zip(lines, english, strict=True) if line == theirs]
    assert same == []
    assert "dans.root" in lines[0] and lines[0].startswith("# dans.root")
    checked = load_checked(text, "dans.root")
    assert not checked.warnings
