"""Going back in time (rootlang.runtime.timeline): what a run's recording shows at time t is what
the run paused at t shows (`rootlang sim --until t`): every script's place, the values, the
readings and the note, and the robot where the run's world recording has it; recording changes
nothing the run does; and the page's pieces of a moment make the same lines."""

from __future__ import annotations

import math
from functools import cache
from pathlib import Path
from typing import Any

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from rootlang.app import session
from rootlang.runtime.client import Pose
from rootlang.runtime.debugger import Debugger, Go, Pause, pose_words
from rootlang.runtime.timeline import Timeline
from rootlang.sim.recording import Recording
from rootlang.sim.robot import VirtualRobot
from rootlang.studio.clock import ScaledWallClock
from rootlang.wording.language import ENGLISH

PROGRAMS = Path(__file__).resolve().parents[2] / "programs"
# quick ones, between them: two scripts at once, messages, loops, notes, sensors, a drawing
GALLERY = ("square.root", "dance.root", "bumpers.root", "flower.root", "countdown.root",
           "messages.root", "color_sorter.root", "shared_variables.root")  # fmt: skip
TIE_MS = 2  # a moment this near a change: which comes first is a matter of the loop's order
NEAR_MM = 5.0  # a paused run's pose is the robot's last reckoning: a sensor reading ago at most
NEAR_DEGREES = 10.0


def _program(name: str) -> session.Program:
    return session.load(str(PROGRAMS / name), world=None, on_robot=False)


@cache
def _recorded(name: str) -> tuple[Timeline, Recording, str]:
    """The run with its timeline, its world recording, and its trace."""
    program = _program(name)
    assert program.world is not None
    timeline = Timeline()
    robot = VirtualRobot(program.world, keep_history=True)
    session.keep_moments(robot, timeline)
    result, recording = session.simulate(
        program.checked, source=program.source, robot=robot,
        debugger=Debugger(recorder=timeline), on_trace=timeline.seen,
    )  # fmt: skip
    return timeline, recording, result.trace.text()


def _paused_at(name: str, seconds: float) -> Pause | None:
    program = _program(name)
    pauses: list[Pause] = []

    def stop_there(pause: Pause) -> Go:
        pauses.append(pause)
        return Go.STOP

    debugger = Debugger(stop_there, pause_at=seconds)
    session.simulate(program.checked, program.world, source=program.source, debugger=debugger)
    return pauses[0] if pauses else None


def _recorded_pose(recording: Recording, time_ms: float) -> Pose:
    """Where the world recording has the robot at ``time_ms`` (between its frames), counted
    as the robot counts it: from where it started, facing +y (the page does the same)."""
    frames = recording.frames
    before = max(i for i, frame in enumerate(frames) if frame.t_ms <= time_ms)
    a, b = frames[before], frames[min(before + 1, len(frames) - 1)]
    part = 0.0 if b.t_ms == a.t_ms else min(1.0, (time_ms - a.t_ms) / (b.t_ms - a.t_ms))
    turned = ((b.heading_deg - a.heading_deg) % 360 + 540) % 360 - 180
    x, y = a.x_mm + (b.x_mm - a.x_mm) * part, a.y_mm + (b.y_mm - a.y_mm) * part
    start = frames[0]
    turn = math.radians(90 - start.heading_deg)
    dx, dy = x - start.x_mm, y - start.y_mm
    return Pose(
        dx * math.cos(turn) - dy * math.sin(turn),
        dx * math.sin(turn) + dy * math.cos(turn),
        a.heading_deg + turned * part + 90 - start.heading_deg,
    )


def _changes_ms(timeline: Timeline) -> list[float]:
    sounds = [
        t for sound in timeline.sounds for t in (sound.time_ms, sound.end_ms) if t is not None
    ]
    changes = timeline.program.times + timeline.robot.times + timeline.poses.times
    return [*(t * 1000 for t in changes), *sounds]


def test_recording_a_run_changes_nothing_it_does() -> None:
    for name in ("square.root", "dance.root"):
        program = _program(name)
        result, recording = session.simulate(program.checked, program.world, source=program.source)
        _timeline, recorded, trace = _recorded(name)
        assert trace == result.trace.text()
        assert recorded.to_json() == recording.to_json()


@settings(max_examples=40, derandomize=True, deadline=None)
@given(name=st.sampled_from(GALLERY), share=st.floats(0.0, 1.0))
def test_a_moment_of_the_recording_is_the_run_paused_then(name: str, share: float) -> None:
    timeline, recording, _trace = _recorded(name)
    seconds = round(share * timeline.end_s, 3)
    assume(all(abs(seconds * 1000 - t) > TIE_MS for t in _changes_ms(timeline)))
    assume(not any(start <= seconds <= end for start, end in timeline.busy))  # (kept less often)
    paused = _paused_at(name, seconds)
    assume(paused is not None)  # (it ended first: at its very end)
    assert paused is not None
    shown = timeline.at(seconds)
    assert [p.to_json() for p in shown.places] == [p.to_json() for p in paused.places]
    assert shown.watch == paused.watch
    assert shown.lines(ENGLISH) == paused.lines(ENGLISH)

    # the stage draws the world's robot then: where it reckoned it was (a reading ago), nearly
    pose = _recorded_pose(recording, seconds * 1000)
    assert math.dist(pose.place[:2], paused.watch.pose.place[:2]) <= NEAR_MM
    turned = (pose.heading_degrees - paused.watch.pose.heading_degrees + 180) % 360 - 180
    assert abs(turned) <= NEAR_DEGREES

    # the page's pieces of the moment (timeslider.js puts them together so)
    data: Any = timeline.to_json(ENGLISH)  # (JSON for the page: read as the page reads it)
    program = data["programs"][_step(data["program"], seconds)]
    robot = data["robots"][_step(data["robot"], seconds)]
    notes = [n for n in data["notes"] if n[0] <= round(seconds * 1000)]
    playing = (
        [notes[-1][2]] if notes and (notes[-1][1] is None or notes[-1][1] > seconds * 1000) else []
    )
    page = [place["words"] for place in program["places"]]
    page += [*program["values"], *robot, pose_words(shown.watch.pose, ENGLISH),
             *program["messages"], *playing]  # fmt: skip
    assert page == paused.lines(ENGLISH)[1:]


def _step(steps: tuple[list[int], list[int]], seconds: float) -> int:
    times, values = steps
    changed = [i for i, time_ms in enumerate(times) if time_ms < round(seconds * 1000)]
    return values[changed[-1] if changed else 0]


@pytest.mark.parametrize("name", ["square.root"])
def test_the_robot_at_5_s_is_where_sim_until_5_has_it(name: str) -> None:
    timeline, _recording, _trace = _recorded(name)
    paused = _paused_at(name, 5.0)
    assert paused is not None
    shown = timeline.at(5.0).lines(ENGLISH)
    assert shown == paused.lines(ENGLISH)
    assert shown[1] == "`when started`: waiting for `move 10 cm` to end (line 5)"
    assert "The robot is at x 10 cm, y 10 cm, heading 270°." in shown


BLINKING = """\
when started
    set blinks to 0
    repeat 6
        light green
        set blinks to blinks + 1
        wait 0.5 seconds
        light off
        wait 0.5 seconds
"""


@pytest.mark.parametrize("speed", [None, 4.0])  # as fast as it goes; a wall clock at 4x
def test_a_loop_waiting_half_a_second_a_round_is_kept_at_every_change(
    tmp_path: Path, speed: float | None
) -> None:
    """Half a second apart is not busy: each state is kept, the last before each wait too
    (though nothing else happens before the wait ends: the robot stands still)."""
    path = tmp_path / "blink.root"
    path.write_text(BLINKING, encoding="utf-8")
    program = _program(str(path))
    timeline = Timeline()
    clock = None if speed is None else ScaledWallClock(speed)
    simulation = session.Simulation(program.world, clock=clock)
    session.keep_moments(simulation.robot, timeline)
    debugger = Debugger(recorder=timeline)
    simulation.clock.run(
        simulation.run(program.checked, source=program.source, debugger=debugger,
                       on_trace=timeline.seen)
    )  # fmt: skip
    kept = [
        (place.line, [named.shown for named in state.variables])
        for state in timeline.program.values
        for place in state.places
    ]
    waits = [(line, blinks) for line, blinks in kept if line in (6, 8)]
    assert waits == [(line, [str(blink)]) for blink in range(1, 7) for line in (6, 8)], kept
    if speed is None:  # (on the wall clock, a busy computer moves the times)
        assert timeline.busy == []
        for blink in range(6):  # a quarter and three quarters into each round: each wait
            for part, line in ((0.25, 6), (0.75, 8)):
                moment = timeline.at(blink + part)
                assert [(place.line, place.state) for place in moment.places] == [(line, "running")]
                assert [named.shown for named in moment.watch.variables] == [str(blink + 1)]
