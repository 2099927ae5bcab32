"""Packets from the simulated robot reach the host at the moment they were sent, in order, and
after whatever else was already due then (the transport hands them over at once only when the
virtual clock says nothing else is ready or due)."""

from __future__ import annotations

import asyncio
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path

import pytest

from rootlang.app.files import world_for
from rootlang.app.session import simulate
from rootlang.checks import load_checked
from rootlang.protocol import encode
from rootlang.runtime.clock import VirtualClock, WallClock
from rootlang.runtime.faults import Fault, FaultRates, FaultyTransport
from rootlang.runtime.scheduler import run as run_program_sync
from rootlang.sim.robot import SENSE_MS, VirtualRobot
from rootlang.sim.transport import SimTransport
from rootlang.sim.world import parse_world

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
    # (after running ahead the transport knows nothing else is ready without asking: no
    # running ahead either, so every packet is queued)
    monkeypatch.setattr(VirtualClock, "run_ahead", lambda self, delay: False)
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
        seen.append(clock.nothing_else_now())  # nor a cancelled one (all others are later)
        loop.call_later(0, lambda: None).cancel()
        seen.append(clock.nothing_else_now())  # a cancelled first timer due now: say no, to be
        # safe (another behind it may be due now too)
        await asyncio.sleep(0)
        loop.stop()
        seen.append(clock.nothing_else_now())  # the loop ends after this turn: nothing runs
        # after it, as one given to call_soon would

    clock.run(main())
    assert seen == [True, False, False, True, True, False, False]
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

    ran_ahead: list[bool] = []
    run_ahead = VirtualClock.run_ahead

    def counted(self: VirtualClock, delay: float) -> bool:
        ran_ahead.append(run_ahead(self, delay))
        return ran_ahead[-1]

    monkeypatch.setattr(VirtualClock, "run_ahead", counted)
    ahead = run()
    assert ran_ahead.count(True) > 20  # (else both runs would be one by one)
    monkeypatch.setattr(VirtualClock, "run_ahead", lambda self, delay: False)
    one_by_one = run()
    assert ahead == one_by_one
    assert len(ahead[1]) > 20


def _drive_over_stripes(
    on_packet: Callable[[SimTransport, bytes], None] = lambda transport, data: None,
) -> tuple[VirtualClock, VirtualRobot, SimTransport]:
    """Drive 60 cm across the stripes; ``on_packet`` sees each packet as it is handed over."""
    clock = VirtualClock()
    robot = VirtualRobot(parse_world(STRIPES, "stripes.toml"))
    transport = SimTransport(robot, clock)

    async def host() -> None:
        await transport.connect(lambda data: on_packet(transport, data), print)
        await transport.send(encode("drive_distance", {"distance": 600}, 1))
        await clock.sleep(8)
        await transport.disconnect()

    clock.run(host())
    return clock, robot, transport


def test_a_turn_runs_ahead_through_the_wake_ups_while_nothing_else_can_run(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    ticks: list[float] = []  # the loop's turns for the robot, and when
    tick = SimTransport._tick

    def counted(self: SimTransport) -> None:
        ticks.append(self.clock.now())
        tick(self)

    monkeypatch.setattr(SimTransport, "_tick", counted)
    _, robot, _ = _drive_over_stripes()
    moments = {record.t_ms for record in robot.packet_log if record.direction == "<-"}
    assert len(moments) > 20
    assert len(ticks) <= 10  # a turn at most every simulated second (LOOK_AHEAD_S)
    ticks.clear()
    monkeypatch.setattr(VirtualClock, "run_ahead", lambda self, delay: False)
    _drive_over_stripes()
    assert len(ticks) > len(moments)  # one turn per 40 ms wake-up


def test_a_timer_set_while_packets_are_handed_over_comes_after_the_wake_up_due_with_it() -> None:
    # as if the wake-up's timer had been set before the hand-over: the robot has caught up
    # when a timer the host sets for that very moment fires
    lagging: list[tuple[float, float]] = []

    def set_timer_for_the_next_wake_up(transport: SimTransport, data: bytes) -> None:
        robot, clock = transport.robot, transport.clock
        wakeup = robot.next_wakeup()
        if wakeup is None:
            return
        due = max(wakeup, robot.time + robot.step_ms / 1000)  # the transport's own sums
        delay = max(0.0, due - clock.now())  # (connected at 0: robot time is clock time)

        def fired() -> None:
            if robot.time < due - 1e-9:
                lagging.append((robot.time, due))

        asyncio.get_running_loop().call_later(delay, fired)

    _, robot, _ = _drive_over_stripes(set_timer_for_the_next_wake_up)
    assert sum(record.direction == "<-" for record in robot.packet_log) > 20
    assert lagging == []


def test_running_ahead_behind_a_faulty_link_changes_nothing(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # delayed packets set timers while packets are handed over: the order must still hold
    world = parse_world(STRIPES, "stripes.toml")
    checked = load_checked(PROGRAM, "stripes.root", world.robot.model)

    def run() -> tuple[str, list[str]]:
        clock = VirtualClock()
        robot = VirtualRobot(world)
        rates = FaultRates(rate=0.3, faults=(Fault.DELAY, Fault.DUPLICATE))
        link = FaultyTransport(SimTransport(robot, clock), clock, seed=3, to_host=rates)
        result = run_program_sync(checked, link, clock, source=PROGRAM, time_limit=20)
        return result.trace.text(), [str(record) for record in robot.packet_log]

    ahead = run()
    monkeypatch.setattr(VirtualClock, "run_ahead", lambda self, delay: False)
    assert run() == ahead
    assert ahead[0].count("color_sensor_event") > 20
