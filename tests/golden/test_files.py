"""Program files: where golden files live, finding programs, and the world a program names."""

from __future__ import annotations

from pathlib import Path

import pytest

from rootlang.app.files import find_programs, named_world, world_for
from rootlang.diagnostics import RootlangError
from rootlang.testing import golden_path
from rootlang.testing.produce import produce


def test_the_golden_file_is_next_to_the_program() -> None:
    assert golden_path(Path("class/spiral.root")) == Path("class/spiral.golden")


def test_programs_are_found_sorted_once_each_and_not_in_hidden_folders(tmp_path: Path) -> None:
    for name in ["b.root", "a.root", "sub/c.root", ".git/d.root", "notes.txt"]:
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text("", encoding="utf-8")
    found = find_programs([tmp_path, tmp_path / "a.root"])
    assert found == [tmp_path / "a.root", tmp_path / "b.root", tmp_path / "sub" / "c.root"]
    with pytest.raises(RootlangError, match=r"programs end in \.root"):
        find_programs([tmp_path / "notes.txt"])


def test_the_world_line_is_read_from_the_opening_comments_only(tmp_path: Path) -> None:
    (tmp_path / "worlds").mkdir()
    (tmp_path / "worlds" / "small.toml").write_text('name = "small"\n', encoding="utf-8")
    program = tmp_path / "p.root"
    source = "# p.root: a test\n#  World:  worlds/small.toml\nwhen started\n    move 1 cm\n"
    assert named_world(program, source) == tmp_path / "worlds" / "small.toml"
    assert world_for(program, source).name == "small"
    later = "when started\n    move 1 cm\n# world: worlds/small.toml\n"
    assert named_world(program, later) is None
    assert world_for(program, later).name == "default"


def test_a_missing_world_is_reported_on_its_line(tmp_path: Path) -> None:
    program = tmp_path / "lost.root"
    program.write_text("# world: nowhere.toml\nwhen started\n    move 1 cm\n", encoding="utf-8")
    produced = produce(program)
    assert produced.end == "check"
    assert produced.text.startswith("lost.root, line 1:\n        # world: nowhere.toml\n")
    assert "I can't find the world nowhere.toml" in produced.text
