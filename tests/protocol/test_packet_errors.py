"""Bad packets never crash and are never silently accepted."""

from __future__ import annotations

import json

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rootlang.protocol import (
    PACKETS,
    BumperState,
    Packet,
    PacketError,
    Sender,
    SensorColor,
    UnknownPacket,
    crc8,
    decode,
    encode,
    interpretations,
    make_packet,
    spec,
)
from rootlang.robots import RobotModel

GOOD = bytes.fromhex("01040000000064000000640000000000000000d1")


def with_crc(body: bytes) -> bytes:
    assert len(body) == 19
    return body + bytes([crc8(body)])


def known(data: bytes, sender: Sender) -> Packet:
    packet = decode(data, sender)
    assert isinstance(packet, Packet)
    return packet


def code_of(error: pytest.ExceptionInfo[PacketError]) -> str:
    return error.value.diagnostics[0].code


@pytest.mark.parametrize("length", [0, 1, 19, 21, 40])
def test_wrong_length_is_refused(length: int) -> None:
    data = (GOOD * 2)[:length]
    with pytest.raises(PacketError) as caught:
        decode(data, "host")
    assert code_of(caught) == "E501"
    assert str(length) in str(caught.value)


@pytest.mark.parametrize("bit", range(160))
def test_any_single_bit_flip_fails_the_crc(bit: int) -> None:
    damaged = bytearray(GOOD)
    damaged[bit // 8] ^= 1 << (bit % 8)
    with pytest.raises(PacketError) as caught:
        decode(bytes(damaged), "host")
    assert code_of(caught) == "E502"


def test_unknown_device_or_command_decodes_as_unknown_packet() -> None:
    data = with_crc(bytes([42, 7, 9]) + bytes(range(16)))
    packet = decode(data, "robot")
    assert isinstance(packet, UnknownPacket)
    assert (packet.device, packet.command, packet.id) == (42, 7, 9)
    assert packet.payload == bytes(range(16))
    assert "device 42" in str(packet)
    # Known device, unknown command; and a command number only the other side sends.
    assert isinstance(decode(with_crc(bytes([1, 99, 0]) + bytes(16)), "host"), UnknownPacket)
    bumper_event = encode("bumper_event", {"timestamp": 1, "state": BumperState.LEFT})
    assert isinstance(decode(bumper_event, "host"), UnknownPacket)


def test_sender_must_be_robot_or_host() -> None:
    with pytest.raises(ValueError, match="sender"):
        decode(GOOD, "robots")  # type: ignore[arg-type]


def test_decode_accepts_bytearray_and_memoryview() -> None:
    assert isinstance(decode(bytearray(GOOD), "host"), Packet)
    assert isinstance(decode(memoryview(GOOD), "host"), Packet)


def test_out_of_range_value_names_field_value_and_range() -> None:
    with pytest.raises(PacketError) as caught:
        encode("set_wheel_speeds", {"left": 150, "right": 0})
    assert str(caught.value) == "E504: set_wheel_speeds: left must be -100 to 100, not 150."


def test_robot_specific_range() -> None:
    fast = {"left": 306, "right": -306}
    encoded = encode("set_wheel_speeds", fast, robot=RobotModel.CREATE3)
    decoded = decode(encoded, "host", RobotModel.CREATE3)
    assert isinstance(decoded, Packet) and dict(decoded.fields) == fast
    for robot in (None, RobotModel.RT1):
        with pytest.raises(PacketError, match="-100 to 100"):
            encode("set_wheel_speeds", fast, robot=robot)
        with pytest.raises(PacketError, match="-100 to 100"):
            decode(encoded, "host", robot)


@pytest.mark.parametrize("value", [1.5, "10", True, None, [1]])
def test_integer_fields_refuse_other_types(value: object) -> None:
    with pytest.raises(PacketError) as caught:
        encode("drive_distance", {"distance": value})
    assert code_of(caught) == "E504"


def test_missing_and_unknown_fields() -> None:
    with pytest.raises(PacketError) as caught:
        encode("set_wheel_speeds", {"left": 1})
    assert code_of(caught) == "E506" and "right" in str(caught.value)
    with pytest.raises(PacketError) as caught:
        encode("set_wheel_speeds", {"left": 1, "rigth": 2})
    assert code_of(caught) == "E505" and 'Did you mean "right"' in str(caught.value)
    with pytest.raises(PacketError) as caught:
        encode("set_wheel_speeds", {"left": 1, "right": 2, "speed": 3})
    assert code_of(caught) == "E505"
    with pytest.raises(PacketError) as caught:
        encode("get_name", {"name": "x"})
    assert code_of(caught) == "E505"


def test_unknown_packet_name_suggests_close_names() -> None:
    with pytest.raises(PacketError) as caught:
        spec("drive_distanse")
    assert code_of(caught) == "E503" and '"drive_distance"' in str(caught.value)
    with pytest.raises(PacketError, match="drive_arc"):
        encode("drive")


@pytest.mark.parametrize("packet_id", [-1, 256, 1.0, "1"])
def test_packet_id_must_be_a_byte(packet_id: object) -> None:
    with pytest.raises(PacketError) as caught:
        encode("stop_and_reset", {}, packet_id)  # type: ignore[arg-type]
    assert code_of(caught) == "E507"


def test_text_longer_than_16_bytes_is_refused_not_cut() -> None:
    assert known(encode("say_phrase", {"phrase": "x" * 16}), "host")["phrase"] == "x" * 16
    for too_long in ("x" * 17, "é" * 9):  # 17 and 18 bytes of UTF-8
        with pytest.raises(PacketError, match="at most 16 bytes"):
            encode("say_phrase", {"phrase": too_long})
    with pytest.raises(PacketError):
        encode("say_phrase", {"phrase": "a\0b"})


def test_serial_number_is_12_bytes() -> None:
    encode("get_serial_number_response", {"serial": "RT0123456789"})
    with pytest.raises(PacketError):
        encode("get_serial_number_response", {"serial": "RT01234567890"})


def test_decoded_text_stops_at_null_and_survives_bad_utf8() -> None:
    body = bytes([5, 4, 0]) + b"hi\0junk" + bytes(9)
    assert known(with_crc(body), "host")["phrase"] == "hi"
    body = bytes([0, 2, 3]) + b"\xff\xfeok" + bytes(12)
    assert known(with_crc(body), "robot")["name"] == "\ufffd\ufffdok"


def test_colour_nibbles_5_to_15_read_as_white() -> None:
    body = bytes([4, 2, 1]) + bytes([0x01, 0x23, 0x45, 0x67, 0x89, 0xAB, 0xCD, 0xEF]) + bytes(8)
    colors = known(with_crc(body), "robot")["colors"]
    assert colors[:5] == tuple(SensorColor(n) for n in range(5))
    assert colors[5:16] == (SensorColor.WHITE,) * 11
    assert len(colors) == 32


def test_packed_ir_values_unpack_as_the_spec_draws_them() -> None:
    msb = bytes([0x12, 0x34, 0x56, 0x78, 0x9A, 0xBC, 0xDE])
    lsn = bytes([0x12, 0x34, 0x56, 0x7F])  # sensor 6's partner nibble (F) is undefined
    body = bytes([11, 0, 3]) + (1000).to_bytes(4, "big") + bytes([0b101]) + msb + lsn
    packet = known(with_crc(body), "robot")
    assert packet["sensors"] == (0x121, 0x342, 0x563, 0x784, 0x9A5, 0xBC6, 0xDE7)
    assert packet["state"] == 0b101 and packet["timestamp"] == 1000


def test_device_bitfield_bit_order() -> None:
    raw = encode("enable_events", {"devices": {0, 12, 127}})
    assert raw[3] == 0x80  # device 127 is bit 7 of byte 3
    assert raw[18] == 0x01  # device 0 is bit 0 of byte 18
    assert raw[17] == 0x10  # device 12 is bit 4 of byte 17
    assert known(raw, "host")["devices"] == frozenset({0, 12, 127})
    with pytest.raises(PacketError):
        encode("enable_events", {"devices": {128}})


def test_decoded_value_out_of_range_is_refused_with_the_packet_named() -> None:
    body = bytes([1, 8, 77]) + bytes(4) + bytes(8) + (3600).to_bytes(2, "big") + bytes(2)
    with pytest.raises(PacketError) as caught:
        decode(with_crc(body), "robot")
    assert "heading" in str(caught.value) and "3600" in str(caught.value)
    assert caught.value.spec is not None and caught.value.spec.name == "drive_distance_response"
    assert caught.value.packet_id == 77


def test_decoded_value_outside_an_enum_is_refused() -> None:
    body = bytes([12, 0, 1]) + bytes(4) + bytes([0x20]) + bytes(11)
    with pytest.raises(PacketError, match="state"):
        decode(with_crc(body), "robot")


def test_interpretations_prefer_readings_with_zero_padding() -> None:
    command = encode("drive_distance", {"distance": 100}, 4)
    # ... which is also a response at timestamp 100 at the origin: both readings fit.
    assert [p.name for p in interpretations(command)] == [
        "drive_distance",
        "drive_distance_response",
    ]
    assert [
        p.name
        for p in interpretations(
            encode("bumper_event", {"timestamp": 3, "state": BumperState.BOTH})
        )
    ] == ["bumper_event"]
    response = encode(
        "drive_distance_response", {"timestamp": 7, "x": 1, "y": 2, "heading": 900}, 4
    )
    assert [p.name for p in interpretations(response)] == ["drive_distance_response"]
    both = encode("get_name", {}, 1)  # an empty name response is all zeros too
    assert [p.name for p in interpretations(both)] == ["get_name", "get_name_response"]
    with pytest.raises(PacketError) as caught:
        interpretations(with_crc(bytes([42, 0, 0]) + bytes(16)))
    assert code_of(caught) == "E509"


def test_make_packet_checks_at_once() -> None:
    packet = make_packet("drive_distance", 3, distance=-50)
    assert packet.key == (1, 8, 3)
    assert str(packet) == "drive_distance #3 distance=-50 mm"
    with pytest.raises(PacketError):
        make_packet("drive_distance", 3, distance=2**31)


@settings(max_examples=300, derandomize=True, deadline=None)
@given(
    body=st.binary(min_size=19, max_size=19),
    sender=st.sampled_from(["robot", "host"]),
    known_header=st.booleans(),
)
def test_any_bytes_with_a_good_crc_decode_or_fail_cleanly(
    body: bytes, sender: Sender, known_header: bool
) -> None:
    if known_header:  # aim at real packets so their fields, not just the header, get fuzzed
        row = PACKETS[body[0] % len(PACKETS)]
        body = bytes([row.device, row.command]) + body[2:]
        sender = row.sender
    try:
        packet = decode(with_crc(body), sender)
    except PacketError as error:
        assert error.diagnostics[0].code == "E504"
        return
    assert isinstance(packet, (Packet, UnknownPacket))
    str(packet)
    json.dumps(packet.to_json())
