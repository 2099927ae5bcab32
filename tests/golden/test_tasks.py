"""Tasks that check themselves: a task folder, and each kind of check run for real (child
processes of the golden runner) on right and wrong programs, told in plain words."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from rootlang.diagnostics import RootlangError, diagnostic
from rootlang.testing.golden import Ending
from rootlang.testing.produce import produce
from rootlang.testing.reports import junit_xml, report_text
from rootlang.testing.tasks import CheckJob, Task, check_programs, find_tasks, load_task
from rootlang.wording.language import ENGLISH, Languages

PROGRAMS = Path(__file__).resolve().parents[2] / "programs"
SQUARE = (PROGRAMS / "square.root").read_text(encoding="utf-8")


def make_task(folder: Path, settings: str = "", name: str = "square") -> Task:
    task = folder / name
    task.mkdir(parents=True)
    shutil.copy(PROGRAMS / "square.golden", task / f"{name}.golden")
    (task / f"{name}.root").write_text("when started\n", encoding="utf-8")
    if settings:
        (task / "task.toml").write_text(settings, encoding="utf-8")
    return load_task(task)


def said(task: Task, *texts: str, languages: Languages = ENGLISH) -> list[str]:
    jobs = [CheckJob(task, f"p{n}/{task.program}", text) for n, text in enumerate(texts)]
    return [checked.said.shown(languages) for checked in check_programs(jobs, workers=2)]


def test_a_task_folder_and_its_settings(tmp_path: Path) -> None:
    task = make_task(tmp_path, 'title = "A square"\ncheck = "pose"\ntolerance_mm = 5\n')
    assert (task.title, task.check, task.tolerance_mm, task.world) == ("A square", "pose", 5, None)
    arena = make_task(tmp_path, 'world = "arena"\n', name="walls")
    assert arena.world is not None and arena.world.name == "arena.toml"
    (tmp_path / "half").mkdir()  # a folder being made is not (yet) a task
    assert [t.name for t in find_tasks(tmp_path)] == ["square", "walls"]
    for settings, code in (('check = "roughly"\n', "E841"), ("tolerance_mm = -1\n", "E841"),
                           ("title = \n", "E841"), ('world = "../../etc"\n', "E616")):  # fmt: skip
        (tmp_path / "bad").mkdir()
        shutil.copy(PROGRAMS / "square.golden", tmp_path / "bad" / "bad.golden")
        (tmp_path / "bad" / "bad.root").write_text("when started\n", encoding="utf-8")
        (tmp_path / "bad" / "task.toml").write_text(settings, encoding="utf-8")
        with pytest.raises(RootlangError) as raised:
            load_task(tmp_path / "bad")
        assert raised.value.diagnostics[0].code == code
        shutil.rmtree(tmp_path / "bad")
    with pytest.raises(RootlangError) as raised:
        load_task(tmp_path / "half")
    assert raised.value.diagnostics[0].code == "E840"


def test_the_ending_is_data_and_reads_the_same_from_golden_text() -> None:
    # a run gives its ending as data; a task's target is read from its golden file: the two
    # agree, eraser strokes left out (whiteboard.root erases too)
    square = Ending.read((PROGRAMS / "square.golden").read_text(encoding="utf-8"))
    assert square.pose == (1000, 1000, 90)
    assert square.strokes == (((1000, 1000), (1000, 1100), (1100, 1100), (1100, 1000),
                               (1000, 1000)),)  # fmt: skip
    for name in ("square", "whiteboard", "flower"):
        produced = produce(PROGRAMS / f"{name}.root")
        assert produced.ending is not None and produced.ending.pose is not None
        assert produced.ending == Ending.read(produced.text), name


def test_pose_and_drawing_say_the_first_difference(tmp_path: Path) -> None:
    task = make_task(tmp_path)
    told = said(
        task,
        SQUARE,
        SQUARE.replace("say", "print"),  # another right program: its trace differs
        SQUARE.replace("repeat 4", "repeat 3"),
        "when started\n    marker down\n    move 10 cm\n",
        SQUARE.replace("turn right", "turn left"),
        "when started\n    turn left 90 degrees\n",
        "when started\n    mvoe 10 cm\n",
        "when started\n    move 10 cm / 0\n",
    )
    assert told == [
        "Well done: your robot did it!",
        "Well done: your robot did it!",
        "Your robot ended 10 cm right of the target.",
        "Your robot ended 10 cm above the target.",
        "Your drawing misses the target's line at x 110 cm, y 110 cm: the nearest line you drew "
        "is 10 cm away.",
        "Your robot ended in the right place, but turned 90° away from the way it should face.",
        "Your program has mistakes to fix first (they are marked in the text).",
        "Your program stopped with an error on line 2. Run it to see the error.",
    ]


def test_a_drawing_task_ignores_where_the_robot_ends_but_not_extra_lines(tmp_path: Path) -> None:
    task = make_task(tmp_path, 'check = "drawing"\n')
    extra = SQUARE.replace("    marker up\n", "    move 20 cm\n    marker up\n")
    moved_on = SQUARE + "    move 50 cm\n"  # the drawing is done; then the robot drives on
    assert said(task, moved_on, extra) == [
        "Well done: your robot did it!",
        "Your robot drew a line where the target has none, at x 100 cm, y 120 cm (10 cm from "
        "the target's lines).",
    ]


def test_a_golden_task_is_rootlang_tests_comparison(tmp_path: Path) -> None:
    task = make_task(tmp_path, 'check = "golden"\n')
    other = SQUARE.replace('say "done"', 'say "done!"')
    results = check_programs([CheckJob(task, "a/square.root", SQUARE),
                              CheckJob(task, "b/square.root", other)])  # fmt: skip
    assert [r.passed for r in results] == [True, False]
    assert results[1].said.english == (
        "Your robot ended in the right place, but did it differently from the target, from line "
        "8 of your program on."
    )
    assert results[1].result.first_difference.startswith("line ")
    csv = report_text([r.result for r in results], ".csv")
    assert "a/square.root,passed,True" in csv and "b/square.root,failed,False" in csv
    assert 'failures="1"' in junit_xml([r.result for r in results])


def test_the_world_is_the_tasks_not_the_programs_own(tmp_path: Path) -> None:
    task = make_task(tmp_path)
    cheat = "# world: worlds/../../x.toml\n" + SQUARE  # its own world line is never read
    assert said(task, cheat) == ["Well done: your robot did it!"]


def test_a_check_speaks_the_pupils_language(tmp_path: Path) -> None:
    """What a check found is kept as data, and said in the language of whoever asks."""
    task = make_task(tmp_path)
    wrong = SQUARE.replace("repeat 4", "repeat 3")
    told = {
        "nl": "Je robot eindigde 10 cm rechts van het doel.",
        "de": "Dein Roboter hat 10 cm rechts neben dem Ziel angehalten.",
    }
    (checked,) = check_programs([CheckJob(task, f"p/{task.program}", wrong)])
    for language, words in told.items():
        assert checked.said.shown(Languages(page=language)) == words


def test_an_endless_program_is_stopped_at_the_cpu_limit(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from rootlang.app.sandbox import Limits
    from rootlang.testing import tasks

    monkeypatch.setattr(tasks, "CHECK_LIMITS", Limits(cpu_seconds=1.0, memory_mb=256))
    folder = make_task(tmp_path).folder  # its world: a day of simulated time
    (folder / "long.toml").write_text("time_limit = 100000\n", encoding="utf-8")
    (folder / "task.toml").write_text('world = "long.toml"\n', encoding="utf-8")
    task = load_task(folder)
    assert task.world == folder / "long.toml"
    busy = "when started\n    forever\n        set x to 1\n"
    told = said(task, busy)
    assert told == [diagnostic("E611", limit="1 s").english]
