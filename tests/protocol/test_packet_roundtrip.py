"""Every packet round-trips over its fields' full ranges, and values outside are refused."""

from __future__ import annotations

from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rootlang.protocol import (
    PACKETS,
    FieldSpec,
    FieldType,
    Packet,
    PacketError,
    PacketSpec,
    SensorColor,
    TouchSensors,
    decode,
    encode,
)
from rootlang.protocol.fields import ipv4_from_int
from rootlang.robots import RobotModel

ROBOTS: list[RobotModel | None] = [None, *RobotModel]


def _text(size: int) -> st.SearchStrategy[str]:
    letters = st.characters(codec="utf-8", exclude_characters="\0")
    return st.text(letters, max_size=size).filter(lambda s: len(s.encode("utf-8")) <= size)


def field_values(field: FieldSpec, robot: RobotModel | None) -> st.SearchStrategy[Any]:
    """Any value the field accepts, across its whole range."""
    if field.enum is not None:
        return st.sampled_from(list(field.enum))
    limits = field.range_for(robot)
    if field.type is FieldType.TEXT:
        return _text(field.size)
    if field.type is FieldType.DEVICES:
        return st.frozensets(st.integers(0, 127))
    if field.type is FieldType.IPV4:
        return st.integers(0, 2**32 - 1).map(ipv4_from_int)
    if field.type is FieldType.CHAR:
        return st.characters(max_codepoint=255)
    assert limits is not None
    number = st.integers(*limits)
    count = {FieldType.COLORS: 32, FieldType.PACKED_IR: 7, FieldType.UINT16_ARRAY: field.count}
    if field.type in count:
        return st.lists(number, min_size=count[field.type], max_size=count[field.type]).map(tuple)
    return number


def expected_after_decode(field: FieldSpec, value: Any) -> Any:
    """What decoding gives back: colour nibbles 5-15 read as white, touch bits as flags."""
    if field.type is FieldType.COLORS:
        return tuple(SensorColor(v) if v <= 4 else SensorColor.WHITE for v in value)
    if field.type is FieldType.HIGH_NIBBLE:
        return TouchSensors(value)
    return value


@pytest.mark.parametrize("packet", PACKETS, ids=lambda p: p.name)
@settings(max_examples=20, derandomize=True, deadline=None)
@given(data=st.data())
def test_round_trip(packet: PacketSpec, data: st.DataObject) -> None:
    robot = data.draw(st.sampled_from(ROBOTS), label="robot")
    values = data.draw(
        st.fixed_dictionaries({f.name: field_values(f, robot) for f in packet.fields}),
        label="fields",
    )
    packet_id = data.draw(st.integers(0, 255), label="id")
    raw = encode(packet.name, values, packet_id, robot)
    assert len(raw) == 20
    assert raw[:3] == bytes([packet.device, packet.command, packet_id])
    assert not any(raw[3 + packet.payload_size : 19]), "unused payload bytes must be zero"
    decoded = decode(raw, packet.sender, robot)
    assert isinstance(decoded, Packet)
    assert decoded.spec is packet
    assert decoded.id == packet_id
    assert dict(decoded.fields) == {
        f.name: expected_after_decode(f, values[f.name]) for f in packet.fields
    }
    assert decoded.encode(robot) == raw or packet.name == "color_sensor_event"


def _integer_fields() -> list[tuple[PacketSpec, FieldSpec]]:
    return [(p, f) for p in PACKETS for f in p.fields if f.range is not None]


def _valid_fields(packet: PacketSpec) -> dict[str, Any]:
    """Some valid value for every field (the minimum, the first choice, empty text ...)."""
    examples = {
        FieldType.TEXT: "",
        FieldType.DEVICES: frozenset(),
        FieldType.IPV4: "0.0.0.0",
        FieldType.CHAR: "d",
    }
    result: dict[str, Any] = {}
    for f in packet.fields:
        if f.enum is not None:
            result[f.name] = next(iter(f.enum))
        elif f.type in examples:
            result[f.name] = examples[f.type]
        else:
            assert f.range is not None
            count = {FieldType.COLORS: 32, FieldType.PACKED_IR: 7}.get(f.type, f.count)
            result[f.name] = f.range[0] if count == 1 else (f.range[0],) * count
    return result


@pytest.mark.parametrize(
    ("packet", "field"), _integer_fields(), ids=lambda x: getattr(x, "name", "")
)
def test_range_ends_encode_and_just_outside_is_refused(
    packet: PacketSpec, field: FieldSpec
) -> None:
    assert field.range is not None
    lo, hi = field.range
    count = {FieldType.COLORS: 32, FieldType.PACKED_IR: 7}.get(field.type, field.count)
    values = _valid_fields(packet)
    for good in (lo, hi):
        values[field.name] = good if count == 1 else (good,) * count
        decoded = decode(encode(packet.name, values), packet.sender)
        assert isinstance(decoded, Packet)
    for bad in (lo - 1, hi + 1):
        values[field.name] = bad if count == 1 else (bad,) * count
        with pytest.raises(PacketError) as caught:
            encode(packet.name, values)
        message = str(caught.value)
        assert caught.value.diagnostics[0].code == "E504"
        assert field.name in message and str(bad) in message
        assert f"{lo} to {hi}" in message


@pytest.mark.parametrize(
    "packet", [p for p in PACKETS if any(f.enum for f in p.fields)], ids=lambda p: p.name
)
def test_enumerated_fields_refuse_values_outside_the_enum(packet: PacketSpec) -> None:
    for field in packet.fields:
        if field.enum is None:
            continue
        values = _valid_fields(packet)
        outside = next(v for v in range(-128, 256) if v not in {int(m) for m in field.enum})
        values[field.name] = outside
        with pytest.raises(PacketError, match=field.name):
            encode(packet.name, values)
