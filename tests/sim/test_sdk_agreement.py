"""The virtual robot checked against what iRobot's own Python SDK and the spec expect of a robot."""

from __future__ import annotations

import struct

import pytest

from rootlang.protocol import PacketError, crc8, decode, spec
from rootlang.robots import RobotModel

from .helpers import PLAIN, make_robot


def _raw(name: str, packet_id: int, *values: int) -> bytes:
    """A command packet built by hand, as the SDK builds it (no range check)."""
    command = spec(name)
    body = struct.pack(">BBB", int(command.device), command.command, packet_id)
    body += struct.pack(">" + "i" * len(values), *values)
    body = body.ljust(19, b"\0")
    return body + bytes([crc8(body)])


@pytest.mark.parametrize(("model", "top"), [(RobotModel.RT1, 100), (RobotModel.CREATE3, 306)])
def test_wheel_speeds_beyond_the_range_are_clamped_and_noted(model: RobotModel, top: int) -> None:
    robot, host = make_robot(PLAIN, model)
    data = _raw("set_wheel_speeds", 1, 500, -40)  # the SDK sends up to 500 mm/s
    with pytest.raises(PacketError):
        decode(data, "host", robot=model)  # beyond this model's range ...
    robot.write(data)  # ... yet the robot drives on, at its top speed
    host.wait(2.0)
    assert robot.ignored == []
    note = f"set_wheel_speeds #1: clamped to {model.display_name}'s range (left 500 -> {top} mm/s)"
    assert robot.packet_log[0].note == note
    assert [e.text for e in robot.recording.events] == [note]
    x, y, _ = robot.world_pose
    assert x != 1500 or y != 1500  # it moved


def test_one_wheel_speed_beyond_the_range_is_clamped_too() -> None:
    robot, host = make_robot(PLAIN)
    robot.write(_raw("set_right_wheel_speed", 1, -250))
    host.wait(1.0)
    assert "right -250 -> -100 mm/s" in robot.packet_log[0].note
    assert robot.pose[2] != 900  # it turns on its left wheel


def test_a_damaged_wheel_speed_packet_is_still_dropped() -> None:
    robot, host = make_robot(PLAIN)
    data = bytearray(_raw("set_wheel_speeds", 1, 500, 500))
    data[19] ^= 0xFF
    robot.write(bytes(data))
    host.wait(1.0)
    assert robot.packet_log[0].note.startswith("dropped:")
    assert robot.pose == (0, 0, 900)


def test_an_ignored_packet_names_the_protocol_only_when_the_version_is_why() -> None:
    robot, host = make_robot(PLAIN)  # a Root RT1 speaks protocol 1.3
    host.send("dock")  # Create 3 only: no protocol version would help
    host.send("navigate_to_position", x=100, y=100, heading=-1)  # needs 1.4
    lacks, too_old = robot.ignored
    assert lacks == "dock: not supported by Root RT1 (no Root RT1 has it)"
    assert "protocol" not in lacks
    assert (
        too_old == "navigate_to_position: not supported by Root RT1's protocol 1.3 (it needs 1.4)"
    )


def test_the_battery_event_comes_when_it_has_dropped_by_more_than_ten_points() -> None:
    # 93.75 % a minute drains exactly 1/16 point every 40 ms sensing: 40.0 exactly at 6.4 s
    world = PLAIN.replace("heading = 90", "heading = 90\nbattery = 50\nbattery_drain = 93.75")
    _, host = make_robot(world)
    host.send("set_wheel_speeds", left=50, right=-50)  # spinning in place counts as driving
    host.wait(6.42)
    assert host.ask("get_battery_level")["percent"] == 40
    assert host.events("battery_level_event") == []  # down by exactly 10: not more than 10
    host.wait(0.05)
    (event,) = host.events("battery_level_event")
    assert event["timestamp"] == 6440 and event["percent"] == 40
