"""Packets from the simulated robot reach the host at the moment they were sent, in order, and
after whatever else was already due then (the transport hands them over at once only when the
virtual clock says nothing else is ready or due)."""

from __future__ import annotations

import asyncio
from dataclasses import replace
from pathlib import Path

import pytest

from rootlang.checks import load_checked
from rootlang.protocol import encode
from rootlang.runtime.clock import VirtualClock, WallClock
from rootlang.sim.robot import SENSE_MS, VirtualRobot
from rootlang.sim.simulate import simulate
from rootlang.sim.transport import SimTransport
from rootlang.sim.world import parse_world
from rootlang.testing.files import world_for

GALLERY = Path(__file__).parents[2] / "programs"

STRIPES = """
[robot]
x = 1000
y = 300
""" + "".join(
    f"""
[[mat]]
shape = "line"
points = [[700, {y}], [1300, {y}]]
width = 4
color = "black"
"""
    for y in range(400, 1000, 25)
)


PROGRAM = """\
when started
    move 40 cm
    turn left 90 degrees
    move 10 cm

when color black seen
    light red
    wait 0.05 seconds
    light off
"""


def test_each_packet_arrives_when_the_robot_sent_it_and_in_order() -> None:
    clock = VirtualClock()
    robot = VirtualRobot(parse_world(STRIPES, "stripes.toml"))
    transport = SimTransport(robot, clock)
    got: list[tuple[int, bytes]] = []

    async def host() -> None:
        await transport.connect(lambda data: got.append((round(clock.now() * 1000), data)), print)
        await transport.send(encode("drive_distance", {"distance": 600}, 1))
        await clock.sleep(8)
        await transport.disconnect()

    clock.run(host())
    sent = [(record.t_ms, record.data) for record in robot.packet_log if record.direction == "<-"]
    assert len(sent) > 20  # colour events for the stripes, and the drive's answer
    assert [data for _, data in got] == [data for _, data in sent]
    for (arrived, _), (sent_ms, _) in zip(got, sent, strict=True):
        assert sent_ms <= arrived <= sent_ms + SENSE_MS  # the world moves on at least so often


def test_handing_packets_over_at_once_changes_nothing(monkeypatch: pytest.MonkeyPatch) -> None:
    world = parse_world(STRIPES, "stripes.toml")
    checked = load_checked(PROGRAM, "stripes.root", world.robot.model)
    at_once, _ = simulate(checked.program, world, source=PROGRAM)
    monkeypatch.setattr(VirtualClock, "nothing_else_now", lambda self: False)
    queued, _ = simulate(checked.program, world, source=PROGRAM)
    assert at_once.trace.text() == queued.trace.text()
    assert at_once.trace.text().count("color_sensor_event") > 20


def test_the_clock_knows_when_nothing_else_is_ready_or_due() -> None:
    clock = VirtualClock()
    seen: list[bool] = []

    async def main() -> None:
        loop = asyncio.get_running_loop()
        seen.append(clock.nothing_else_now())  # only this task runs
        loop.call_soon(lambda: None)
        seen.append(clock.nothing_else_now())  # a callback is ready
        await asyncio.sleep(0)
        loop.call_later(0, lambda: None)
        seen.append(clock.nothing_else_now())  # a timer is due now
        await asyncio.sleep(0)
        await asyncio.sleep(0)  # (the timer's callback ran in the turn this task woke in)
        later = loop.call_later(1, lambda: None)
        seen.append(clock.nothing_else_now())  # a timer due later does not count
        later.cancel()
        seen.append(clock.nothing_else_now())  # a cancelled first timer: say no, to be safe

    clock.run(main())
    assert seen == [True, False, False, True, False]
    assert WallClock().nothing_else_now() is False


@pytest.mark.parametrize("program", ["bump_and_turn.root", "light_seeker.root"])
def test_looking_ahead_changes_nothing(monkeypatch: pytest.MonkeyPatch, program: str) -> None:
    # a timer's turn runs the robot's later wake-ups too, while nothing else can run first:
    # the trace, and every packet with its time, are those of one turn of the loop per wake-up
    source = (GALLERY / program).read_text(encoding="utf-8")
    world = replace(world_for(GALLERY / program, source), time_limit=40)
    checked = load_checked(source, program, world.robot.model)

    def run() -> tuple[str, list[str]]:
        robot = VirtualRobot(world)
        result, _ = simulate(checked.program, world, source=source, robot=robot)
        return result.trace.text(), [str(record) for record in robot.packet_log]

    ahead = run()
    monkeypatch.setattr(VirtualClock, "quiet_until", lambda self: None)
    one_by_one = run()
    assert ahead == one_by_one
    assert len(ahead[1]) > 20
