"""The robot client over the loopback robot, in virtual time."""

from __future__ import annotations

import asyncio
from collections.abc import Awaitable, Callable
from typing import TypeVar

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rootlang.diagnostics import RootlangError, Span
from rootlang.protocol import BumperState, Packet, encode
from rootlang.robots import RobotModel
from rootlang.runtime.client import (
    MOTION_ATTEMPTS,
    READ_ATTEMPTS,
    Origin,
    Pose,
    RobotClient,
    early_check_seconds,
    timeout_for,
)
from rootlang.runtime.clock import VirtualClock
from rootlang.runtime.loopback import LoopbackRobot
from rootlang.runtime.trace import Outcome, Trace
from rootlang.runtime.transport import LinkLost

T = TypeVar("T")
HERE = Origin("1:when started", Span(3, 5, 3, 14))


def on_robot(
    test: Callable[[RobotClient, LoopbackRobot], Awaitable[T]],
    model: RobotModel = RobotModel.RT1,
    **robot_options: object,
) -> tuple[T, RobotClient, LoopbackRobot]:
    clock = VirtualClock()
    robot = LoopbackRobot(clock, model=model, **robot_options)  # type: ignore[arg-type]
    client = RobotClient(robot, clock, Trace(clock.now))

    async def main() -> T:
        await client.connect()
        return await test(client, robot)

    return clock.run(main()), client, robot


def test_commands_use_the_host_id_counter_and_get_their_own_answers() -> None:
    async def test(client: RobotClient, robot: LoopbackRobot) -> list[int]:
        first = await client.command("drive_distance", {"distance": 100}, HERE)
        second = await client.command("rotate_angle", {"angle": 900}, HERE)
        assert first is not None and second is not None
        assert (first.name, first["y"]) == ("drive_distance_response", 100)
        assert second["heading"] == 0  # turned right from 90 degrees
        return [item.packet.id for item in robot.received]

    ids, client, robot = on_robot(test)
    assert ids == [0, 1, 2]  # id 0 (which a robot always obeys, repeated or not) does nothing
    assert robot.received[0].packet.name == "enable_events"
    assert not robot.received[0].packet["devices"]
    assert client.stats.responses == 2
    assert client.state.pose.y_mm == 100


def test_a_pose_answer_sets_the_pose_and_the_trace_shows_it() -> None:
    async def test(client: RobotClient, robot: LoopbackRobot) -> None:
        await client.command("drive_distance", {"distance": -25}, HERE, trace_text="move")
        await client.command("rotate_angle", {"angle": -1355}, HERE, trace_text="turn")

    _, client, _ = on_robot(test)
    assert client.state.pose == Pose(0.0, -25.0, 225.5)  # (in decidegrees: 900 + 1355)
    shown = [line[line.index("[") :] for line in client.trace.text().splitlines()]
    assert shown == ["[x 0 mm, y -25 mm, heading 90°]", "[x 0 mm, y -25 mm, heading 226°]"]


def test_a_command_that_is_never_answered_names_the_command_and_line() -> None:
    async def test(client: RobotClient, robot: LoopbackRobot) -> float:
        with pytest.raises(RootlangError) as caught:
            await client.command("drive_distance", {"distance": 40}, HERE, trace_text="move 40 mm")
        diagnostic = caught.value.diagnostics[0]
        assert diagnostic.code == "E203"
        assert diagnostic.span.line == 3
        assert "move 40 mm" in diagnostic.english
        return client.clock.now()

    waited, client, robot = on_robot(test, drop={"drive_distance"})
    # The robot never moved, so the movement can't have arrived: it is sent again, then given up.
    # Each try waits only as long as a robot at a usual speed needs, then reads the pose.
    once = early_check_seconds("drive_distance", {"distance": 40})
    assert once < timeout_for("drive_distance", {"distance": 40})
    assert waited == pytest.approx(MOTION_ATTEMPTS * once)
    assert robot.names_received().count("drive_distance") == MOTION_ATTEMPTS
    assert client.trace.of_kind("command")[0].outcome is Outcome.FAILED


def test_a_newer_motion_command_interrupts_the_older_ones_wait() -> None:
    async def test(client: RobotClient, robot: LoopbackRobot) -> tuple[object, float]:
        long_move = asyncio.ensure_future(
            client.command("drive_distance", {"distance": 1000}, HERE)
        )
        await client.clock.sleep(1.0)
        await client.command("rotate_angle", {"angle": 900}, HERE)
        return await long_move, client.clock.now()

    (older, _), client, _ = on_robot(test)
    assert older is None  # interrupted: its wait ended at once
    entries = client.trace.of_kind("command")
    assert [entry.outcome for entry in entries] == [Outcome.INTERRUPTED, Outcome.DONE]
    assert entries[0].end_ms == 1000
    assert client.stats.interrupted == 1
    assert client.stats.late_responses == 0  # the robot's "finished" for it was expected
    assert client.state.pose.y_mm == pytest.approx(100, abs=1)


def test_commands_on_different_actuators_do_not_interrupt_each_other() -> None:
    async def test(client: RobotClient, robot: LoopbackRobot) -> None:
        await asyncio.gather(
            client.command("drive_distance", {"distance": 100}, HERE),
            client.command("play_note", {"frequency": 440, "duration": 500}, HERE),
        )

    _, client, _ = on_robot(test)
    assert [e.outcome for e in client.trace.of_kind("command")] == [Outcome.DONE, Outcome.DONE]


def test_corrupt_unknown_duplicate_and_late_packets_are_counted_and_ignored() -> None:
    async def test(client: RobotClient, robot: LoopbackRobot) -> None:
        good = encode("bumper_event", {"timestamp": 1, "state": BumperState.LEFT}, 0)
        robot.deliver(good[:19] + bytes([good[19] ^ 0xFF]))  # bad checksum
        robot.deliver(good[:10])  # too short
        unknown = bytearray(good)
        unknown[1] = 77  # no such command on the bumper device
        robot.deliver(encode_raw(bytes(unknown)))
        await client.command("drive_distance", {"distance": 10}, HERE)  # answered twice
        robot.answer_delay["get_battery_level"] = 60.0
        with pytest.raises(RootlangError):
            await client.read("get_battery_level", HERE, "read battery")
        await client.clock.sleep(60.0)  # the answers come, too late

    _, client, _ = on_robot(test, duplicate_answers=True)
    assert client.stats.corrupt_packets == 2
    assert client.stats.unknown_packets == 1
    assert client.stats.duplicates == 1 + READ_ATTEMPTS  # the second copy of every answer
    assert client.stats.late_responses == READ_ATTEMPTS  # a read is asked again, then given up
    assert client.stats.resent == READ_ATTEMPTS - 1
    assert client.state.bumpers is BumperState.NONE


def encode_raw(packet: bytes) -> bytes:
    """Re-seal a hand-edited packet with a correct checksum."""
    from rootlang.protocol import crc8

    return packet[:19] + bytes([crc8(packet[:19])])


def test_events_update_state_and_event_id_gaps_and_repeats_are_noticed() -> None:
    seen: list[tuple[str, BumperState, BumperState]] = []

    async def test(client: RobotClient, robot: LoopbackRobot) -> None:
        client.on_event = lambda packet, before, after: seen.append(
            (packet.name, before.bumpers, after.bumpers)
        )
        robot.emit("bumper_event", {"state": BumperState.LEFT}, packet_id=5)
        robot.emit("bumper_event", {"state": BumperState.LEFT}, packet_id=5)  # repeat
        robot.emit("bumper_event", {"state": BumperState.NONE}, packet_id=9)  # 3 lost
        await asyncio.sleep(0)

    _, client, _ = on_robot(test)
    assert seen == [
        ("bumper_event", BumperState.NONE, BumperState.LEFT),
        ("bumper_event", BumperState.LEFT, BumperState.NONE),
    ]
    assert client.stats.duplicates == 1
    assert client.stats.event_id_gaps == 1


def test_commands_are_gated_on_robot_model_and_protocol_version() -> None:
    async def test(client: RobotClient, robot: LoopbackRobot) -> list[str]:
        codes = []
        for name in ("dock", "navigate_to_position"):
            with pytest.raises(RootlangError) as caught:
                await client.command(name, {}, HERE, trace_text=name)
            codes.append(caught.value.diagnostics[0].english)
        return codes

    messages, _, robot = on_robot(test)
    assert messages == [
        "The Root RT1 can't do `dock`.",
        "The Root RT1 can't do `navigate_to_position`.",
    ]
    assert robot.received == []  # nothing was sent


def test_concurrent_reads_of_one_sensor_share_one_request() -> None:
    async def test(client: RobotClient, robot: LoopbackRobot) -> list[object]:
        reads = [client.read("get_battery_level", HERE, "battery") for _ in range(3)]
        packets = await asyncio.gather(*reads)
        return [packet["percent"] if packet else None for packet in packets]

    percents, client, robot = on_robot(
        test, readings={"get_battery_level": {"percent": 77, "voltage": 3900}}
    )
    assert percents == [77, 77, 77]
    assert robot.names_received() == ["enable_events", "get_battery_level"]
    assert client.state.battery_percent == 77


def test_a_lost_link_fails_the_commands_waiting_for_answers() -> None:
    reasons: list[LinkLost] = []

    async def test(client: RobotClient, robot: LoopbackRobot) -> str:
        client.on_disconnect = reasons.append
        waiting = asyncio.ensure_future(client.command("drive_distance", {"distance": 500}, HERE))
        await client.clock.sleep(0.5)
        robot.drop_link("switched off")
        with pytest.raises(RootlangError) as caught:
            await waiting
        return caught.value.diagnostics[0].code

    code, client, _ = on_robot(test)
    assert code == "E208"
    assert reasons == ["switched off"]
    assert not client.connected


def test_timeouts_grow_with_what_the_command_asks() -> None:
    assert timeout_for("drive_distance", {"distance": 2000}) > timeout_for(
        "drive_distance", {"distance": 100}
    )
    assert timeout_for("play_note", {"duration": 10_000}) > 10.0
    assert timeout_for("say_phrase", {"phrase": "hello there"}) > timeout_for(
        "say_phrase", {"phrase": "hi"}
    )


@settings(max_examples=60, deadline=None)
@given(st.lists(st.binary(min_size=0, max_size=24), max_size=8))
def test_any_bytes_from_the_robot_are_handled_or_counted_never_raised(
    junk: list[bytes],
) -> None:
    async def test(client: RobotClient, robot: LoopbackRobot) -> None:
        for data in junk:
            robot.deliver(data)
        await client.command("drive_distance", {"distance": 10}, HERE)  # still works

    _, client, _ = on_robot(test)
    stats = client.stats
    counted = (
        stats.corrupt_packets + stats.unknown_packets + stats.events + stats.duplicates
        + stats.late_responses + stats.responses
    )  # fmt: skip
    assert counted == len(junk) + 1  # every packet counted once, plus the real answer


def test_a_movement_whose_motor_stalls_ends_as_the_robot_reports_it_never_as_silence() -> None:
    # The robot got the move and is stuck against something (its pose stays where it started),
    # says so with a motor stall event, and its answer comes far too late: the move ends at
    # the stall's news, sent once, no E203 ("didn't answer") and no resend.
    async def test(client: RobotClient, robot: LoopbackRobot) -> float:
        def stall_soon(packet: Packet) -> None:
            if packet.name == "drive_distance":
                stall = {"motor": 0, "cause": 3}  # the left wheel, underspeed
                asyncio.get_running_loop().call_later(0.2, robot.emit, "motor_stall_event", stall)

        robot.on_send = stall_soon
        answer = await client.command("drive_distance", {"distance": 40}, HERE, trace_text="move")
        assert answer is None
        return client.clock.now()

    took, client, robot = on_robot(test, answer_delay={"drive_distance": 600.0})
    assert robot.names_received().count("drive_distance") == 1
    (move,) = client.trace.of_kind("command")[:1]
    assert move.outcome is Outcome.DONE and "stalled" in (move.detail or "")
    assert took < timeout_for("drive_distance", {"distance": 40})
