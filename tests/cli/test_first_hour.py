"""A class's first hour, as a teacher meets it: worlds by name from any folder, commands that
take files and folders alike, a trace a child can read, and `--json` a script can trust."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from rootlang.cli import main
from rootlang.sim.world import BUILT_IN_WORLDS

GALLERY = Path(__file__).parents[2] / "programs"
SQUARE = "when started\n    repeat 4\n        move 10 cm\n        turn right 90 degrees\n"


@pytest.fixture
def class_folder(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """An empty folder of the teacher's, far from rootlang's own files."""
    monkeypatch.chdir(tmp_path)
    return tmp_path


def out_of(capsys: pytest.CaptureFixture[str]) -> str:
    return capsys.readouterr().out


# --- 1. worlds by name, from anywhere ----------------------------------------------------------


def test_every_built_in_world_is_found_by_name_from_an_empty_folder(
    class_folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (class_folder / "hello.root").write_text(SQUARE, encoding="utf-8")
    names = sorted(path.stem for path in BUILT_IN_WORLDS.glob("*.toml"))
    assert {"arena", "color_mat", "line_mat"} <= set(names)
    for name in names:
        assert main(["sim", "hello.root", "--world", name, "--json"]) in (0, 1), name
        assert json.loads(out_of(capsys))["world"], name


def test_the_world_line_names_a_built_in_world_and_the_folder_s_own_comes_first(
    class_folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (class_folder / "hello.root").write_text("# world: arena\n" + SQUARE, encoding="utf-8")
    assert main(["sim", "hello.root", "--json"]) == 0
    assert json.loads(out_of(capsys))["world"] == "arena"
    (class_folder / "worlds").mkdir()
    (class_folder / "worlds" / "arena.toml").write_text('name = "our arena"\n', "utf-8")
    assert main(["sim", "hello.root", "--json"]) == 0
    assert json.loads(out_of(capsys))["world"] == "our arena"
    assert main(["sim", "hello.root", "--world", "arena", "--json"]) == 0
    assert json.loads(out_of(capsys))["world"] == "our arena"


def test_gallery_programs_copied_away_still_find_their_worlds(
    class_folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """The gallery's `# world: worlds/arena.toml` lines keep working without a worlds folder."""
    shutil.copy(GALLERY / "bump_and_turn.root", class_folder)
    assert main(["sim", "bump_and_turn.root", "--json"]) == 0
    assert json.loads(out_of(capsys))["world"] == "arena"


def test_an_unknown_world_name_lists_the_worlds_there_are(
    class_folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (class_folder / "hello.root").write_text(SQUARE, encoding="utf-8")
    assert main(["sim", "hello.root", "--world", "nowhere"]) == 1
    err = capsys.readouterr().err
    assert "There is no world called nowhere" in err and "arena, color_mat" in err


# --- the `# world:` line: the caret under the path, and confined to the program's folder -----


def test_a_missing_world_puts_the_caret_under_the_path(
    class_folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (class_folder / "w.root").write_text("#  world: world\n" + SQUARE, encoding="utf-8")
    for command in ("check", "sim"):  # check says what sim would refuse
        assert main([command, "w.root"]) == 1
        err = capsys.readouterr().err
        assert "        #  world: world\n" + " " * 18 + "^^^^^\n" in err  # under the path
        assert "I can't find the world world" in err


@pytest.mark.parametrize(
    "named", ["/etc/passwd", "../../secret.toml", "worlds/../../secret.toml", "C:\\x.toml"]
)
def test_the_world_line_cannot_leave_the_program_s_folder(
    class_folder: Path, capsys: pytest.CaptureFixture[str], named: str
) -> None:
    inner = class_folder / "a" / "b"
    inner.mkdir(parents=True)
    (class_folder / "secret.toml").write_text('"the secret key" = 1\n', encoding="utf-8")
    (inner / "p.root").write_text(f"# world: {named}\n" + SQUARE, encoding="utf-8")
    assert main(["sim", str(inner / "p.root"), "--json"]) == 1
    answer = json.loads(out_of(capsys))
    assert [error["code"] for error in answer["errors"]] == ["E616"]
    assert answer["errors"][0]["column"] == len("# world: ") + 1
    shown = answer["errors"][0]["rendered"]
    assert "secret key" not in shown and "root:" not in shown


# --- 2. files and folders alike ---------------------------------------------------------------


def test_check_and_sim_take_this_folder_a_folder_or_a_bare_name(
    class_folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (class_folder / "hello.root").write_text(SQUARE, encoding="utf-8")
    (class_folder / "dance.root").write_text("when started\n    turn left 1 degree\n", "utf-8")
    assert main(["check"]) == 0
    assert "No mistakes found. Programs checked: 2." in out_of(capsys)
    for paths in (["."], [str(class_folder)], ["hello", "dance.root"]):
        assert main(["check", *paths]) == 0, paths
        assert main(["sim", *paths]) == 0, paths
        out = out_of(capsys)
        assert "== " in out and "the end: every script finished" in out, paths
    assert main(["sim", "hello"]) == 0
    assert "== " not in out_of(capsys)  # one program: no heading


def test_sim_of_a_folder_goes_on_after_a_program_with_mistakes(
    class_folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (class_folder / "a.root").write_text("when started\n    mvoe 1 cm\n", encoding="utf-8")
    (class_folder / "b.root").write_text(SQUARE, encoding="utf-8")
    assert main(["sim", "."]) == 1
    captured = capsys.readouterr()
    assert "a.root, line 2" in captured.err
    assert "== b.root ==" in captured.out and "the end: every script finished" in captured.out


def test_options_that_make_one_file_want_one_program(
    class_folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (class_folder / "a.root").write_text(SQUARE, encoding="utf-8")
    (class_folder / "b.root").write_text(SQUARE, encoding="utf-8")
    assert main(["sim", ".", "--svg", "x.svg"]) == 1
    assert "--svg is for one program, but this names 2" in capsys.readouterr().err
    assert not (class_folder / "x.svg").exists()


def test_an_empty_folder_says_so(class_folder: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["sim", "."]) == 1
    assert main(["check", "."]) == 1
    err = capsys.readouterr().err
    assert err.count("I found no .root programs in this folder.") == 2
    assert "Traceback" not in err and "ValueError" not in err


# --- 3. the child's view ----------------------------------------------------------------------


def test_the_flower_reads_as_the_program(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["sim", str(GALLERY / "flower.root")]) == 0
    lines = out_of(capsys).splitlines()
    assert len(lines) < 60
    assert lines[0].split() == ["0.0", "s", "line", "2", "when", "started"]
    assert lines[2].split()[2:] == [
        "line",
        "5",
        "arc",
        "right",
        "60",
        "degrees",
        "radius",
        "20",
        "cm",
    ]
    assert lines[-1].split()[2:] == ["the", "end:", "every", "script", "finished"]
    assert not any("colors=" in line or " ms " in line for line in lines)


def test_a_busy_loop_is_counted_not_listed(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["sim", str(GALLERY / "line_follower.root")]) == 0
    lines = out_of(capsys).splitlines()
    assert len(lines) < 60
    assert "drive 6 cm/s" in lines[1]
    assert "... 652 more times, until 6.5 s" in lines[2]
    assert lines[-1].endswith("stopped by stop all")


def test_a_go_to_done_as_turn_move_turn_is_one_line_not_repeats(
    capsys: pytest.CaptureFixture[str],
) -> None:
    """Without Navigate (Root RT1), `go to` is three commands on one line: the view shows the
    line once, as it ran once; a loop that runs a line again is still counted."""
    assert main(["sim", str(GALLERY / "go_to.root")]) == 0
    lines = out_of(capsys).splitlines()
    assert [line.split(None, 2)[2] for line in lines[2:4]] == [
        "line 4        go to x 20 cm y 10 cm",
        "line 5        go to x 20 cm y 30 cm facing 180 degrees",
    ]
    assert not any("more time" in line for line in lines)


def test_the_view_shows_what_was_said_and_printed_and_the_error(
    class_folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    program = 'when started\n    say "hi"\n    play note C4 for 0.1 seconds\n'
    program += '    set n to 0\n    print "n is", n\n    print 1 / n\n'
    (class_folder / "p.root").write_text(program, encoding="utf-8")
    assert main(["sim", "p.root"]) == 1
    shown = [line.split(None, 2)[2] for line in out_of(capsys).splitlines()]
    assert shown == [
        "line 1    when started",
        'line 2        say "hi"',
        "line 3        play note C4 for 0.1 seconds",
        'line 5        print "n is 0"',
        "line 6        error: I can't divide by zero.",
        "stopped by an error",
    ]


def test_full_trace_keeps_every_entry(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["sim", str(GALLERY / "flower.root"), "--full-trace"]) == 0
    lines = out_of(capsys).splitlines()
    assert len(lines) > 500
    assert sum("colors=" in line for line in lines) > 400
    assert "ended: finished (every script finished)" in lines[-1]


# --- 7. --json ----------------------------------------------------------------------------------


def test_json_pose_is_where_the_program_left_the_robot(
    class_folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    for ending, heading in (("turn left 90 degrees", 180.0), ("stop all", 90.0)):
        program = f"when started\n    move 10 cm\n    {ending}\n"
        (class_folder / "p.root").write_text(program, encoding="utf-8")
        assert main(["sim", "p.root", "--json"]) == 0
        pose = json.loads(out_of(capsys))["pose"]
        assert pose == {"x_mm": 0, "y_mm": 100, "heading_deg": heading}, ending


def test_json_answers_when_the_world_file_is_missing(
    class_folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (class_folder / "p.root").write_text("# world: gone.toml\n" + SQUARE, encoding="utf-8")
    assert main(["sim", "p.root", "--json"]) == 1
    answer = json.loads(out_of(capsys))
    assert answer["end"] == "mistakes" and answer["errors"][0]["code"] == "E607"


# --- 4. `rootlang run` shows the run -----------------------------------------------------------


def test_run_on_a_robot_shows_the_child_view_and_how_it_ended(
    class_folder: Path, capfd: pytest.CaptureFixture[str]
) -> None:
    pytest.importorskip("bumble")  # the virtual robot over a real BLE stack
    program = 'when started\n    move 1 cm\n    say "done"\n'
    (class_folder / "p.root").write_text(program, encoding="utf-8")
    assert main(["run", "p.root", "--transport", "virtual"]) == 0
    # (the program runs in a process of its own, which writes to the terminal itself)
    shown = [line.split(None, 2)[2] for line in capfd.readouterr().out.splitlines()]
    assert shown == [
        "line 1    when started",
        "line 2        move 1 cm",
        'line 3        say "done"',
        "the end: every script finished",
    ]


def test_realtime_shows_the_view_as_it_happens(
    class_folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (class_folder / "p.root").write_text('when started\n    move 1 cm\n    print "ok"\n', "utf-8")
    assert main(["sim", "p.root", "--realtime"]) == 0
    shown = [line.split(None, 2)[2] for line in out_of(capsys).splitlines()]
    assert shown == [
        "line 1    when started",
        "line 2        move 1 cm",
        'line 3        print "ok"',
        "the end: every script finished",
    ]


def test_the_view_spells_each_line_the_canonical_way(
    class_folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """However a child typed it, the view shows the line as `rootlang format` writes it."""
    program = "WHEN STARTED:\n  Set N To 2\n  While n > 0:\n"
    program += "    Play Note a4 For .2 Seconds  #beep\n    Change n By -1\n"
    (class_folder / "p.root").write_text(program, encoding="utf-8")
    assert main(["sim", "p.root"]) == 0
    shown = [line.split(None, 2)[2] for line in out_of(capsys).splitlines()]
    assert shown[:2] == ["line 1    when started", "line 4        play note A4 for 0.2 seconds"]
