"""Adventures: every built-in one's model solution passes its check and its starter fails with
a hint; the hints compare a run with the goal aspect by aspect, in a child's terms."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from rootlang.adventures import (
    BUILT_IN,
    SOLUTION,
    check_adventures,
    find_adventures,
    load_adventure,
)
from rootlang.adventures.hints import Step, Summary, hint, missing_parts
from rootlang.adventures.picture import goal_svg
from rootlang.blocks import pictures, to_workspace
from rootlang.diagnostics import RootlangError
from rootlang.locale.keywords import LANGUAGES
from rootlang.locale.translate import from_english
from rootlang.testing.produce import produce
from rootlang.testing.tasks import CheckJob
from rootlang.wording.language import ENGLISH, Languages

ADVENTURES = find_adventures()


def test_the_built_in_adventures_lead_through_the_three_levels() -> None:
    assert len(ADVENTURES) >= 12
    assert {adventure.level for adventure in ADVENTURES} == {1, 2, 3}
    assert [a.level for a in ADVENTURES] == sorted(a.level for a in ADVENTURES)
    made_of = {part for adventure in ADVENTURES for part in adventure.uses}
    assert made_of == {"repeat", "variable", "message", "procedure"}
    events = {event for adventure in ADVENTURES for event in adventure.wanted.events}
    assert any("bumped" in event for event in events)
    for adventure in ADVENTURES:  # in all five languages, with a picture of the goal
        assert set(adventure.titles) == set(adventure.goals) == set(LANGUAGES), adventure.name
        assert goal_svg(adventure.wanted, adventure.goal("nl")).startswith("<svg")


@pytest.mark.parametrize("adventure", [a for a in ADVENTURES if a.level == 1], ids=str)
def test_level_1_adventures_are_picture_blocks_only(adventure: object) -> None:
    from rootlang.adventures import Adventure

    assert isinstance(adventure, Adventure)
    for program in (adventure.task.starter, adventure.task.folder / SOLUTION):
        _, above = pictures.to_pictures(to_workspace(program.read_text(encoding="utf-8")))
        assert above == [], program


def test_each_solution_passes_and_each_starter_fails_with_a_hint() -> None:
    jobs, which = [], []
    for adventure in ADVENTURES:
        for program in (adventure.task.folder / SOLUTION, adventure.task.starter):
            jobs.append(CheckJob(adventure.task, program.name, program.read_text("utf-8")))
            which.append(adventure)
    results = check_adventures(which, jobs, workers=2)
    for job, checked in zip(jobs, results, strict=True):
        if job.who == SOLUTION:
            assert checked.passed, (job.task.name, checked.said.english)
        else:  # a hint from the goal (V3xx), or the drawing's V051: never "well done"
            assert not checked.passed, job.task.name
            assert checked.said.code.startswith("V3") or checked.said.code == "V051"
    told = {job.task.name: c.said.english for job, c in zip(jobs, results, strict=True)
            if job.who != SOLUTION}  # fmt: skip
    assert told["01-go-forward"] == (
        "Your robot stopped 30 cm short: the goal's robot drives 30 cm further."
    )
    assert told["04-draw-a-square"] == "Your drawing has 3 sides, but the goal's has 4."


def summary(**changed: object) -> Summary:
    square = tuple(Step(x, y, 0, True) for x, y in ((0, 150), (150, 150), (150, 0), (0, 0)))
    base = {"events": (), "track": square, "turns": (-90.0,) * 4, "sides": 4, "drew": True,
            "lights": ("red",), "notes": 1, "said": ("hi",)}  # fmt: skip
    return Summary(**{**base, **changed})  # type: ignore[arg-type]


@pytest.mark.parametrize(
    ("run", "code", "english"),
    [
        ({"events": ()}, "V300", "The goal's robot does something `when bumped`, but yours"),
        ({"events": ("when bumped", 'when message "hi" received')}, None, ""),
        ({"drew": False, "sides": 0}, "V051", "Your robot drew nothing"),
        ({"sides": 3}, "V303", "Your drawing has 3 sides, but the goal's has 4."),
        ({"turns": ()}, "V301", "Your robot never turns"),
        ({"turns": (-90.0,) * 3}, "V304", "Your robot turned 3 times"),
        ({"turns": (-90.0, 90.0, -90.0, -90.0)}, "V305", "At turn 2, your robot turned left"),
        ({"turns": (-90.0, -60.0, -90.0, -90.0)}, "V307", "At turn 2, your robot turned less"),
        ({"track": (Step(0, 100, 90, True),)}, "V309", "Your robot stopped 50 cm short"),
        ({"track": (Step(0, 1000, 90, True),)}, "V310", "Your robot went 40 cm too far"),
        ({"lights": ()}, "V311", "The goal's robot lights up red, but yours never does."),
        ({"lights": ("blue",)}, "V312", "Your robot lit up blue, but the goal's robot lights"),
        ({"notes": 3}, "V313", "Your robot played 3 notes, but the goal's robot plays 1."),
        ({"said": ()}, "V314", "Your robot said 0 things"),
        ({"said": ("ho",)}, "V315", 'Thing number 1 your robot said, "ho", is not'),
    ],
)
def test_a_hint_tells_the_first_difference(
    run: dict[str, object], code: str | None, english: str
) -> None:
    goal = summary(events=("when bumped",))
    if code is None:  # (a message the goal's robot answers, and the run's does not)
        goal, run, code, english = (
            summary(**run),
            {"events": ("when bumped",)},
            "V302",
            ('The goal\'s robot does something when the message "hi" comes'),
        )
    changed = {"events": ("when bumped",), **run}
    if "track" in run:
        changed["sides"], changed["turns"] = 4, goal.turns
    told = hint(goal, summary(**changed))
    assert told is not None and told.code == code
    assert told.english.startswith(english)
    assert told.shown(Languages(chosen="nl")) != told.english  # (told in the child's language)


def test_a_run_is_read_from_its_golden_text(tmp_path: Path) -> None:
    """Names with words of the trace in them, and lines the golden text counts as repeats."""
    program = tmp_path / "tricky.root"
    program.write_text(
        'when started\n    send "go start now"\n    say "a @3 run x"\n'
        "    repeat 5\n        play note C4 for 0.1 seconds\n\n"
        'when message "go start now" received\n    light on red\n    move 10 cm\n',
        encoding="utf-8",
    )
    produced = produce(program)
    assert "more times" in produced.text  # (the notes are counted, not written out)
    run = Summary.of(produced.text)
    assert run.events == ('when message "go start now" received',)
    assert (run.said, run.notes, run.lights) == (("a @3 run x",), 5, ("red",))
    assert [(step.x, step.y) for step in run.track] == [(0, 100)]


@pytest.mark.parametrize("language", ["nl", "de"])
def test_a_program_in_another_language_passes_too(language: str) -> None:
    events = [a for a in ADVENTURES if a.name in ("06-bump-and-ring", "10-send-a-message")]
    jobs = [
        CheckJob(a.task, "x", f"# language: {language}\n"
                 + from_english((a.task.folder / SOLUTION).read_text("utf-8"), language))
        for a in events
    ]  # fmt: skip
    assert [c.passed for c in check_adventures(events, jobs, workers=2)] == [True, True]


def test_a_side_drawn_again_is_the_same_side() -> None:
    square = ((0, 0), (0, 150), (150, 150), (150, 0), (0, 0))
    drawn = "drawing: 1 stroke\n  marker #000000 3 mm from 0 ms:\n    " + " ".join(
        f"({x},{y})" for x, y in square * 3
    )
    assert Summary.of(drawn).sides == 4  # (round the square three times: still 4 sides)


def test_a_run_doing_more_than_the_goal_is_no_difference() -> None:
    goal = summary()
    assert hint(goal, summary(events=("when touched",), lights=("red", "blue"))) is None


def test_a_run_and_its_golden_text_are_read_the_same_way() -> None:
    square = find_adventures()[3]
    wanted = square.wanted
    assert wanted.sides == 4 and len(wanted.turns) == 4 and wanted.drew
    assert round(wanted.path_mm) == 600


def test_what_a_program_is_made_of() -> None:
    plain = "when started\n    move 10 cm\n"
    assert missing_parts(plain, ["repeat"]).code == "V318"  # type: ignore[union-attr]
    assert missing_parts(plain, ["variable"]).code == "V317"  # type: ignore[union-attr]
    assert missing_parts(plain, ["message"]).code == "V319"  # type: ignore[union-attr]
    unused = "to hop\n    move 1 cm\n\nwhen started\n    move 10 cm\n"
    assert missing_parts(unused, ["procedure"]).code == "V316"  # type: ignore[union-attr]
    used = unused + "    hop\n"
    assert missing_parts(used, ["procedure"]) is None
    assert missing_parts("when started\n    move (\n", ["repeat"]) is None  # (its mistakes first)


def test_a_teachers_adventure_is_a_folder(tmp_path: Path) -> None:
    mine = tmp_path / "01-go-forward"
    shutil.copytree(BUILT_IN / "01-go-forward", mine)
    (mine / "adventure.toml").write_text('level = 2\n[title]\nen = "Mine"\n[goal]\nen = "Go"\n')
    found = {a.name: a for a in find_adventures(tmp_path)}
    assert found["01-go-forward"].title("fr") == "Mine" and found["01-go-forward"].level == 2
    assert len(found) == len(ADVENTURES)  # (it replaced the built-in one of its name)
    (mine / "adventure.toml").write_text("level = 4\n")
    with pytest.raises(RootlangError) as refused:
        load_adventure(mine)
    assert refused.value.diagnostics[0].code == "E850"
    assert "level must be 1, 2 or 3" in refused.value.diagnostics[0].shown(ENGLISH)
