"""Pause, Step, Resume and breakpoints for a simulated run, over the studio's real WebSocket
and worker process: the run pauses at a breakpoint inside `repeat` with the loop's round and
a variable, steps through the scripts in the scheduler's order, and then ends as it would
have."""

from __future__ import annotations

import asyncio
import json
from typing import Any

import aiohttp
import pytest

from rootlang.app.session import Simulation, simulate
from rootlang.checks import load_checked
from rootlang.diagnostics import RootlangError
from rootlang.jstypes import problems
from rootlang.sim.world import default_world
from rootlang.studio.clock import ScaledWallClock
from rootlang.studio.debugging import RobotDebugging, breakpoint_lines, debug_request
from rootlang.studio.messages import PausedMessage, ResumedMessage, WatchMessage
from rootlang.wording.language import ENGLISH

from .conftest import RunningStudio
from .test_server import Socket, _time_limit, with_session

PROGRAM = """\
when started
    set size to 5 cm
    repeat 3
        move size
        change size by 1 cm
    print "done"

when started
    wait 0.5 seconds
    print "tick"
"""


async def _next(socket: Socket, *kinds: str) -> dict[str, Any]:
    """The next message of one of these kinds (frames in between are passed over)."""
    async for message in socket:
        data: dict[str, Any] = json.loads(message.data)
        if data["type"] in kinds:
            return data
        assert data["type"] != "error", data
    raise AssertionError(f"no {kinds} came")


def _where(paused: dict[str, Any]) -> list[tuple[str, int]]:
    return [(place["state"], place["line"]) for place in paused["places"]]


def test_a_breakpoint_in_a_loop_pauses_there_and_steps_go_in_the_schedulers_order(
    studio: RunningStudio,
) -> None:
    plain, _ = simulate(load_checked(PROGRAM, "d.root"), source=PROGRAM)
    never_paused = plain.pose
    assert never_paused is not None

    async def check(session: aiohttp.ClientSession) -> None:
        async with session.ws_connect("/ws", origin=studio.address) as socket:
            await socket.send_json({"type": "run", "name": "d.root", "text": PROGRAM,
                                    "speed": 0, "breakpoints": [4]})  # fmt: skip
            async with _time_limit(60):
                paused = await _next(socket, "paused")
                assert problems(paused, PausedMessage) == []  # the page's contract
                assert paused["reason"] == "breakpoint"
                assert _where(paused) == [("next", 4), ("starting", 9)]
                watch = paused["watch"]
                assert watch["loops"] == [
                    {"script": "1:when started", "line": 3, "round": 1, "count": 3}
                ]
                assert {"name": "size", "value": "5 cm", "script": "1:when started"} in (
                    watch["variables"]
                )
                words = paused["places"][0]["words"]
                assert words == "`when started`: about to do `move size` (line 4)"
                steps = []
                for _ in range(3):  # the other script's wait, its print at 0.5 s, then line 5
                    await socket.send_json({"type": "debug", "action": "step"})
                    resumed = await _next(socket, "resumed")
                    assert resumed["step"] is True and problems(resumed, ResumedMessage) == []
                    steps.append(await _next(socket, "paused"))
                assert [_where(step) for step in steps] == [
                    [("running", 4), ("next", 9)],
                    [("running", 4), ("next", 10)],
                    [("next", 5), ("finished", 0)],
                ]
                assert [step["watch"]["time_s"] for step in steps][1:] == [
                    0.5,
                    0.72,
                ]  # the move of 5 cm ends at 0.72 s
                await socket.send_json(
                    {"type": "debug", "action": "breakpoints", "breakpoints": []}
                )
                await socket.send_json({"type": "debug", "action": "resume"})
                ended = await _next(socket, "ended")
        assert ended["end"] == "finished" and ended["printed"] == ["tick", "done"]
        assert ended["pose"]["y_mm"] == round(never_paused.y_mm)  # 5 + 6 + 7 cm

    with_session(studio, check)


def test_the_values_come_live_and_pause_pauses_at_once_while_every_script_waits(
    studio: RunningStudio,
) -> None:
    text = 'when started\n    wait 20 seconds\n    print "late"\n'

    async def check(session: aiohttp.ClientSession) -> None:
        async with session.ws_connect("/ws", origin=studio.address) as socket:
            await socket.send_json({"type": "run", "name": "w.root", "text": text, "speed": 1})
            async with _time_limit(60):
                live = await _next(socket, "watch")  # the values as the run goes on
                assert problems(live, WatchMessage) == []
                assert _where(live) == [("running", 2)] and live["watch"]["time_s"] > 0
                await socket.send_json({"type": "debug", "action": "pause"})
                paused = await _next(socket, "paused")
                assert paused["reason"] == "pause" and _where(paused) == [("running", 2)]
                assert paused["watch"]["time_s"] < 2
                await socket.send_json({"type": "stimulus", "action": "nose"})  # Stop
                ended = await _next(socket, "ended")
        assert ended["end"] == "stopped" and ended["printed"] == []

    with_session(studio, check)


@pytest.mark.parametrize(
    "message",
    [{"action": "fly"}, {"action": "breakpoints", "breakpoints": "all"},
     {"action": "breakpoints", "breakpoints": [0]},
     {"action": "breakpoints", "breakpoints": [True]},
     {"action": "breakpoints", "breakpoints": list(range(1, 2000))}],
)  # fmt: skip
def test_a_bad_debug_message_is_refused(message: dict[str, Any]) -> None:
    with pytest.raises(RootlangError) as refused:
        debug_request(message)
    assert refused.value.diagnostics[0].code == "E806"


def test_breakpoints_are_lines_once_each() -> None:
    assert breakpoint_lines([7, 3, 7]) == (3, 7) and breakpoint_lines(None) == ()


# --- on a robot ---------------------------------------------------------------------------------

TAKING_TURNS = """\
when started
    light green
    light blue
    light red

when started
    light white
    light green
"""  # (each a command to the robot: a script waits for it, and the other takes its turn)


def test_steps_on_a_robot_take_the_scripts_in_turn_and_never_stop_the_run() -> None:
    """A robot's pause answered later (the run's loop goes on): each Step goes on to the next
    statement of any script, in the scheduler's order, and ends the run never (an answer once
    took a later pause's answer for its own and stopped the run). The simulated robot on a
    held wall clock stands in for the robot's link."""
    clock = ScaledWallClock(1.0)
    simulation = Simulation(default_world(), clock=clock)
    pauses: list[list[tuple[str, int]]] = []

    def send(kind: str, data: Any) -> None:
        if kind == "paused":
            pauses.append([(p["state"], p["line"]) for p in data["places"]])
            action = "step" if len(pauses) < 6 else "resume"
            asyncio.get_running_loop().call_soon(debugging.button, {"action": action})

    debugging = RobotDebugging(send, clock, ENGLISH)
    debugging.debugger.step = True
    checked = load_checked(TAKING_TURNS, "turns.root")
    result = clock.run(simulation.run(checked, source=TAKING_TURNS, debugger=debugging.debugger))
    assert result.end == "finished", result.stopped_by
    assert pauses == [
        [("next", 2), ("starting", 7)],
        [("running", 2), ("next", 7)],
        [("next", 3), ("running", 7)],
        [("running", 3), ("next", 8)],
        [("next", 4), ("running", 8)],
    ]


# --- on a robot over Bluetooth: bumble's virtual robot (rootlang[virtual]) ----------------------

ON_A_ROBOT = 'when started\n    move 30 cm\n    print "there"\n'


def test_pause_stops_a_robot_at_once_and_step_finishes_the_move_cut_short(
    robot_studio: RunningStudio,
) -> None:
    """Paused in the middle of `move 30 cm`, the robot stops where it is (the pose it answers
    is short of 30 cm) and its run's time stands still; Step finishes the move from there and
    pauses at the next statement; the robot ends at 30 cm, not further."""

    async def check(session: aiohttp.ClientSession) -> None:
        async with session.ws_connect("/ws", origin=robot_studio.address) as socket:
            await socket.send_json({"type": "run", "name": "r.root", "text": ON_A_ROBOT,
                                    "robot": ""})  # fmt: skip
            async with _time_limit(90):
                while (live := await _next(socket, "watch"))["watch"]["time_s"] < 1:
                    assert _where(live) == [("running", 2)], live  # on its way
                await socket.send_json({"type": "debug", "action": "pause"})
                paused = await _next(socket, "paused")
                assert paused["reason"] == "pause" and _where(paused) == [("running", 2)]
                while (live := await _next(socket, "watch"))["watch"]["pose"] == (
                    paused["watch"]["pose"]
                ):
                    pass  # (the move's answer, from where the pause stopped it, comes soon)
                cut = live["watch"]["pose"]["y_mm"]
                assert 20 < cut < 290, live  # stopped short of 30 cm
                assert live["watch"]["time_s"] == paused["watch"]["time_s"]  # time stands still
                await socket.send_json({"type": "debug", "action": "step"})
                assert (await _next(socket, "resumed"))["step"] is True
                stepped = await _next(socket, "paused")
                assert stepped["reason"] == "step" and _where(stepped) == [("next", 3)]
                assert abs(stepped["watch"]["pose"]["y_mm"] - 300) <= 5  # finished from there
                await socket.send_json({"type": "debug", "action": "resume"})
                ended = await _next(socket, "ended")
        assert ended["end"] == "finished" and ended["printed"] == ["there"], ended
        assert abs(ended["pose"]["y_mm"] - 300) <= 5

    with_session(robot_studio, check)
