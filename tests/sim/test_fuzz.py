"""Whatever bytes a host sends, the virtual robot keeps going: no exception, no stuck clock."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rootlang.protocol import PACKETS, FieldType, Kind, PacketSpec, crc8, encode
from rootlang.robots import RobotModel
from rootlang.sim.robot import VirtualRobot
from rootlang.sim.world import default_world

COMMANDS = [p for p in PACKETS if p.kind is Kind.COMMAND]


def _packet(device: int, command: int, packet_id: int, payload: bytes) -> bytes:
    head = bytes([device, command, packet_id]) + payload
    return head + bytes([crc8(head)])


@st.composite
def packets(draw: st.DrawFn) -> bytes:
    spec = draw(st.sampled_from(COMMANDS))
    payload = draw(st.binary(min_size=16, max_size=16))
    return _packet(int(spec.device), spec.command, draw(st.integers(0, 255)), payload)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    model=st.sampled_from(list(RobotModel)),
    sent=st.lists(st.one_of(packets(), st.binary(min_size=0, max_size=24)), max_size=8),
)
def test_random_packets_never_break_the_robot(model: RobotModel, sent: list[bytes]) -> None:
    robot = VirtualRobot(default_world(), model=model)
    for data in sent:
        robot.write(data)
        robot.advance(0.3)
    robot.advance(2)
    assert robot.now_ms == 2000 + 300 * len(sent)
    assert len(robot.packet_log) >= len(sent)
    for answer in robot.read():
        assert len(answer) == 20 and crc8(answer[:19]) == answer[19]


def _extreme_fields(spec: PacketSpec, model: RobotModel, pick: int) -> dict[str, object]:
    """Every field of a command at one end of its range (``pick`` 0: lowest, -1: highest)."""
    fields: dict[str, object] = {}
    for field in spec.fields:
        if field.enum is not None:
            fields[field.name] = sorted(field.enum)[pick]
        elif field.type is FieldType.TEXT:
            fields[field.name] = "é" * (field.size // 2) if pick else ""
        elif field.type is FieldType.DEVICES:
            fields[field.name] = range(128) if pick else ()
        else:
            limits = field.range_for(model)
            assert limits is not None, field.name
            value = limits[pick]
            fields[field.name] = [value] * field.count if field.count > 1 else value
    return fields


@pytest.mark.parametrize("model", list(RobotModel), ids=lambda m: m.value)
@pytest.mark.parametrize("pick", [0, -1], ids=["lowest", "highest"])
def test_every_command_at_the_ends_of_its_ranges(model: RobotModel, pick: int) -> None:
    robot = VirtualRobot(default_world(), model=model)
    for number, spec in enumerate(COMMANDS, 1):
        if spec.name == "disconnect":
            continue
        robot.write(encode(spec.name, _extreme_fields(spec, model, pick), number, robot=model))
        robot.advance(0.5)
    robot.advance(5)
    assert robot.now_ms == 500 * (len(COMMANDS) - 1) + 5000
    assert all(len(answer) == 20 for answer in robot.read())
