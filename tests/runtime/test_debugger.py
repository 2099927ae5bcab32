"""Pausing, stepping and looking inside a run (rootlang.runtime.debugger): a step goes to the
next statement of any script in the scheduler's order, a pause says where every script is and
what the values are, and pausing changes nothing the run does."""

from __future__ import annotations

import json
import textwrap
from functools import cache
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rootlang import ast
from rootlang.app import session
from rootlang.runtime.debugger import Debugger, Go, NameWatch, Pause
from rootlang.wording.language import ENGLISH, Languages

PROGRAMS = Path(__file__).resolve().parents[2] / "programs"
SLOW = {"line_follower.root"}  # seconds of busy physics a run: its pauses would cost minutes
GALLERY = sorted(p.name for p in PROGRAMS.glob("*.root") if p.name not in SLOW)


def _load(source: str, name: str = "test.root") -> session.Program:
    text = textwrap.dedent(source).strip("\n") + "\n"
    return session.load(name, source=text, world=None, on_robot=False)


def _run(program: session.Program, debugger: Debugger | None = None) -> dict[str, object]:
    """What a run did that a pause must not change: its trace, drawing, sounds and end."""
    result, recording = session.simulate(
        program.checked, program.world, source=program.source, debugger=debugger
    )
    return {
        "end": result.end,
        "trace": result.trace.text(),
        "recording": recording.to_json(),
        "printed": result.printed,
        "time": result.sim_time_s,
    }


def _stepping(program: session.Program, steps: int, **options: object) -> list[Pause]:
    """The pauses of a run paused as ``options`` say and stepped ``steps`` times after."""
    pauses: list[Pause] = []

    def on_pause(pause: Pause) -> Go:
        pauses.append(pause)
        return Go.STEP if len(pauses) <= steps else Go.RESUME

    _run(program, Debugger(on_pause, **options))  # type: ignore[arg-type]
    return pauses


def _next(pause: Pause) -> tuple[str, int]:
    [place] = [place for place in pause.places if place.state == "next"]
    return place.name, place.line


def test_a_step_goes_to_the_next_statement_of_any_script_so_two_scripts_take_turns() -> None:
    program = _load("""
        when started
            wait 1 second
            print "a"
        when started
            wait 0.5 seconds
            print "b"
    """)
    pauses = _stepping(program, 3, step=True)
    assert [_next(pause) for pause in pauses] == [
        ("when started", 2), ("when started", 5), ("when started", 6), ("when started", 3),
    ]  # fmt: skip
    assert [round(pause.watch.time_s, 3) for pause in pauses] == [0.0, 0.0, 0.5, 1.0]
    assert [place.state for place in pauses[2].places] == ["running", "next"]


def test_a_paused_run_says_where_each_script_is_in_words() -> None:
    program = _load("""
        when started
            turn right 90 degrees
        when started
            wait 0.2 seconds
            print "x"
        when bumped
            print "ouch"
    """)
    [pause] = _stepping(program, 0, breakpoints={5})
    words = [place.words(ENGLISH) for place in pause.places]
    assert words == [
        "`when started`: waiting for `turn right 90 degrees` to end (line 2)",
        '`when started`: about to do `print "x"` (line 5)',
        "`when bumped`: not running, waiting for its event",
    ]
    spans = [place.to_json()["span"] for place in pause.places]
    assert spans[1] == [5, 5, 5, 14]
    dutch = Languages(chosen="nl")
    assert pause.places[0].words(dutch).startswith("`wanneer gestart`: wacht tot `")


def test_the_watch_has_variables_parameters_loops_messages_and_the_note() -> None:
    program = _load("""
        when started
            set speed to 5
            send "go" and wait
        when message "go" received
            square 20 cm
        to square size
            repeat 4
                play note A4 for 1 second
                move size
    """)
    [pause] = _stepping(program, 0, pause_at=3.5)
    watch = pause.watch
    assert pause.reason == "time"
    assert [(v.name, v.shown, v.script) for v in watch.variables] == [
        ("speed", "5", "1:when started")
    ]
    [call] = watch.calls
    assert (call.procedure, [(p.name, p.shown) for p in call.parameters]) == (
        "square", [("size", "20 cm")]
    )  # fmt: skip
    [loop] = watch.loops
    assert (loop.line, loop.round, loop.count) == (7, 2, 4)
    [sent] = watch.messages
    assert (sent.message, sent.by, sent.waiting) == ("go", "1:when started", True)
    assert watch.note == "play 440 Hz for 1000 ms"
    assert "`square` is running with size = 20 cm" in pause.lines(ENGLISH)
    data = json.loads(json.dumps(pause.to_json(ENGLISH)))
    assert data["watch"]["loops"] == [
        {"script": '2:when message "go" received', "line": 7, "round": 2, "count": 4}
    ]
    assert data["places"][1]["words"].startswith('`when message "go" received`: waiting for')


def test_a_breakpoint_in_a_loop_pauses_every_round() -> None:
    program = _load("""
        when started
            repeat 3
                move 5 cm
    """)
    pauses: list[Pause] = []

    def on_pause(pause: Pause) -> Go:
        pauses.append(pause)
        return Go.RESUME

    _run(program, Debugger(on_pause, breakpoints={3}))
    assert [(p.reason, p.watch.loops[0].round) for p in pauses] == [
        ("breakpoint", n) for n in (1, 2, 3)
    ]
    assert [round(p.watch.pose.y_mm / 10) for p in pauses] == [0, 5, 10]


def test_stop_at_a_time_ends_the_run_there_as_its_time_limit() -> None:
    program = _load("""
        when started
            forever
                move 10 cm
    """)
    seen: list[Pause] = []

    def on_pause(pause: Pause) -> Go:
        seen.append(pause)
        return Go.STOP

    ran = _run(program, Debugger(on_pause, pause_at=3.0))
    assert ran["end"] == "time_limit" and ran["time"] == pytest.approx(3.0, abs=0.01)
    assert [p.reason for p in seen] == ["time"]


def test_watched_names_are_told_each_time_they_change() -> None:
    program = _load("""
        when started
            set count to 0
            repeat 3
                change count by 1
                wait 1 second
    """)
    watching = NameWatch(("count",), ENGLISH)
    debugger = Debugger(watching=watching)
    _run(program, debugger)
    watching.look(debugger)
    assert [(line.time_ms, line.line, line.text) for line in watching.lines] == [
        (0, 2, "count is now 0"), (0, 4, "count is now 1"), (1000, 4, "count is now 2"),
        (2000, 4, "count is now 3"),
    ]  # fmt: skip


# ---- stepping changes nothing: the gallery, paused at generated points ----------------------


@cache
def _gallery_program(name: str) -> session.Program:
    return session.load(str(PROGRAMS / name), world=None, on_robot=False)


@cache
def _never_paused(name: str) -> dict[str, object]:
    return _run(_gallery_program(name))


@cache
def _lines_of(name: str) -> list[int]:
    program = _gallery_program(name).checked.program
    return sorted({n.span.line for n in ast.walk(program) if isinstance(n, ast.Statement)})


@pytest.mark.parametrize("name", GALLERY)
@settings(max_examples=2, derandomize=True, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])  # fmt: skip
@given(data=st.data())
def test_a_run_paused_stepped_and_resumed_does_what_a_run_never_paused_does(
    name: str, data: st.DataObject
) -> None:
    program = _gallery_program(name)
    plain = _never_paused(name)
    seconds = float(plain["time"])  # type: ignore[arg-type]
    pause_at = data.draw(st.none() | st.floats(0.0, max(seconds, 0.001)), label="pause at")
    breakpoint = data.draw(st.sampled_from(_lines_of(name)), label="breakpoint")
    steps = data.draw(st.integers(0, 6), label="steps after each pause")
    stop_breaking_after = data.draw(st.integers(1, 4), label="breakpoint pauses")
    counted = {"breakpoint": 0, "steps": 0}

    def on_pause(pause: Pause) -> Go:
        pause.lines(ENGLISH)  # looking inside changes nothing either
        if pause.reason == "breakpoint":
            counted["breakpoint"] += 1
            if counted["breakpoint"] >= stop_breaking_after:
                debugger.breakpoints = ()
        if pause.reason != "step":
            counted["steps"] = 0
        counted["steps"] += 1
        return Go.STEP if counted["steps"] <= steps else Go.RESUME

    debugger = Debugger(on_pause, breakpoints={breakpoint}, pause_at=pause_at)
    assert _run(program, debugger) == plain
