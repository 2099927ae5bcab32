"""First-hour defects a child meets: a translation that runs as it is, world names as a child
types them, a `check` that sums up, and message headers in the child's language."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest

from rootlang.cli import main

SQUARE = "when started\n    repeat 4\n        move 10 cm\n        turn right 90 degrees\n"


@pytest.fixture
def folder(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Path]:
    monkeypatch.chdir(tmp_path)
    yield tmp_path


def test_a_translation_names_its_language_and_runs_as_it_is(
    folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (folder / "square.root").write_text(SQUARE, encoding="utf-8")
    assert main(["translate", "square.root", "--to", "fr", "-o", "carre.root"]) == 0
    translated = (folder / "carre.root").read_text(encoding="utf-8")
    assert translated.startswith("# language: fr\nquand démarré\n")
    assert main(["sim", "carre.root"]) == 0
    assert "la fin : tous les scripts ont fini" in capsys.readouterr().out  # in French too


def test_a_word_written_another_way_still_translates(
    folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (folder / "pen.root").write_text("when started\n    pen down\n    stop   moving\n", "utf-8")
    assert main(["translate", "pen.root", "--to", "de"]) == 0  # `pen` reads back as `marker`
    assert "halte an" in capsys.readouterr().out


def test_a_name_that_is_a_word_of_the_new_language_is_named_on_its_line(
    folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (folder / "si.root").write_text("when started\n    set si to 5\n    move si cm\n", "utf-8")
    assert main(["translate", "si.root", "--to", "es"]) == 1
    err = capsys.readouterr().err
    assert "line 2:" in err and "the name `si`" in err


def test_world_names_are_case_insensitive_and_a_typo_gets_did_you_mean(
    folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (folder / "a.root").write_text("# world: Arena\n" + SQUARE, encoding="utf-8")
    assert main(["sim", "a.root", "--world", "LINE_MAT"]) == 0
    assert main(["check", "a.root"]) == 0
    capsys.readouterr()
    (folder / "b.root").write_text("# world: arean\n" + SQUARE, encoding="utf-8")
    assert main(["check", "b.root"]) == 1  # `check` says what `sim` would refuse
    err = capsys.readouterr().err
    assert "b.root, line 1:" in err and 'Did you mean "arena"?' in err
    assert main(["sim", "a.root", "--world", "lin_mat"]) == 1
    assert 'Did you mean "line_mat"?' in capsys.readouterr().err


def test_check_ends_with_a_summary_when_there_are_mistakes(
    folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (folder / "a.root").write_text("when started\n    mve 10 cm\n    jump\n", encoding="utf-8")
    (folder / "b.root").write_text(SQUARE, encoding="utf-8")
    assert main(["check", "a.root", "b.root"]) == 1
    assert capsys.readouterr().out == "Mistakes: 2. Warnings: 0. Programs checked: 2.\n"


def test_the_header_of_a_message_is_in_the_childs_language(
    folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (folder / "a.root").write_text("# language: nl\nwanneer gestart\n    bewg 10 cm\n", "utf-8")
    assert main(["check", "a.root"]) == 1
    shown = capsys.readouterr()
    assert "a.root, regel 3:" in shown.err and "Fouten: 1." in shown.out


def test_no_mistakes_is_said_in_the_childs_language(
    folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (folder / "a.root").write_text("# language: nl\nwanneer gestart\n    beweeg 10 cm\n", "utf-8")
    assert main(["check", "a.root"]) == 0
    assert capsys.readouterr().out == "Geen fouten gevonden. Programma's nagekeken: 1.\n"


@pytest.mark.parametrize(
    ("line", "said"),
    [
        ("play sweep from 200 Hz to 800 Hz for 2 seconds volume 500 %",
         "The volume can be 0 % to 100 %, not 500 %."),
        ("play note C4 for 100 seconds",
         "The duration can be 0 seconds to 65.535 seconds, not 100 seconds."),
        ("set gravity compensation on 200 %",
         "The gravity compensation can be 0 % to 100 %, not 200 %."),
    ],
)  # fmt: skip
def test_a_value_out_of_range_is_said_in_the_childs_units(
    folder: Path, capsys: pytest.CaptureFixture[str], line: str, said: str
) -> None:
    (folder / "loud.root").write_text(f"when started\n    {line}\n", encoding="utf-8")
    assert main(["sim", "loud.root"]) == 1
    err = capsys.readouterr().err
    assert said in err and "decipercent" not in err and "1275" not in err


def test_round_and_mod_work_as_in_scratch(folder: Path, capsys: pytest.CaptureFixture[str]) -> None:
    program = "when started\n    print round 2.5, round -2.5, -7 mod 3, 7 mod -3, 7 mod 3\n"
    (folder / "numbers.root").write_text(program, encoding="utf-8")
    assert main(["sim", "numbers.root"]) == 0
    assert 'print "3 -2 2 -2 1"' in capsys.readouterr().out


def test_the_childs_view_tells_a_command_cut_short_and_which_line_cut_it(
    folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    program = (Path(__file__).parents[2] / "programs" / "interrupted.root").read_text("utf-8")
    (folder / "cut.root").write_text(program, encoding="utf-8")
    assert main(["sim", "cut.root"]) == 0
    out = capsys.readouterr().out
    assert "line 4: move 50 cm — stopped after 0.7 s: line 13 started a new one" in out
    assert "line 9: play note C4 for 5 seconds — stopped after 2.2 s: line 14 started" in out


def test_the_childs_view_tells_how_long_the_robot_pushed_against_a_wall(
    folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    program = (
        "# world: arena\nwhen started\n    drive 5 cm/s\n    wait 20 seconds\n    stop moving\n"
    )
    (folder / "wall.root").write_text(program, encoding="utf-8")
    assert main(["sim", "wall.root"]) == 0
    lines = capsys.readouterr().out.splitlines()
    pushed = [line for line in lines if "the robot pushed against something for" in line]
    assert len(pushed) == 1 and pushed[0].split()[0] == "15.4", lines


def test_a_stall_handled_at_once_is_told_as_a_bump_never_for_0_0_s(
    folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    programs = Path(__file__).parents[2] / "programs"
    program = (programs / "stalled.root").read_text("utf-8")
    (folder / "stalled.root").write_text(program.replace("worlds/low_battery.toml", "low_battery"))
    assert main(["sim", "stalled.root"]) == 0
    out = capsys.readouterr().out
    assert "the robot ran into something and its wheels got stuck" in out
    assert " 0.0 s" not in out.replace("   0.0 s  line", "")  # (times at the left are times)


@pytest.mark.parametrize(
    ("world", "said"),
    [('name = "x"\n[[walls\n', "I can't read the world file bad.toml"),
     ('size = "big"\n', "In the world file bad.toml")],
)  # fmt: skip
def test_check_reports_a_world_file_that_sim_would_refuse_on_its_line(
    folder: Path, capsys: pytest.CaptureFixture[str], world: str, said: str
) -> None:
    (folder / "bad.toml").write_text(world, encoding="utf-8")
    (folder / "w.root").write_text("# world: bad.toml\nwhen started\n    move 1 cm\n", "utf-8")
    assert main(["sim", "w.root"]) != 0
    refused = capsys.readouterr().err
    assert main(["check", "w.root"]) == 1
    err = capsys.readouterr().err
    assert said in refused and said in err and "w.root, line 1:" in err, err
