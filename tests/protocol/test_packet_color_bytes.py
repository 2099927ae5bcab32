"""Colours may be given as bytes, one a sensor (the simulator's floor raster reads them so)."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rootlang.protocol import Packet, PacketError, decode, encode
from rootlang.protocol.enums import SensorColor
from rootlang.protocol.fields import colors_from_bytes


@settings(max_examples=50, deadline=None)
@given(st.lists(st.integers(0, 4), min_size=32, max_size=32), st.integers(0, 255))
def test_bytes_encode_as_the_same_colours_as_a_tuple(colors: list[int], packet_id: int) -> None:
    as_bytes = encode("color_sensor_event", {"colors": bytes(colors)}, packet_id)
    assert as_bytes == encode("color_sensor_event", {"colors": tuple(colors)}, packet_id)
    decoded = decode(as_bytes, "robot")
    assert isinstance(decoded, Packet)
    assert decoded["colors"] == tuple(SensorColor(c) for c in colors)


@pytest.mark.parametrize(
    "colors", [bytes(31), bytes(33), bytes([16] * 32), bytes([0] * 31 + [255]), "W" * 32]
)
def test_bytes_of_the_wrong_length_or_range_are_refused(colors: object) -> None:
    with pytest.raises(PacketError) as caught:
        encode("color_sensor_event", {"colors": colors})
    assert caught.value.diagnostics[0].code == "E504"


@settings(max_examples=200, deadline=None)
@given(st.lists(st.binary(min_size=16, max_size=16), min_size=1, max_size=5))
def test_colour_bytes_decode_nibble_by_nibble_the_first_sensor_high(packets: list[bytes]) -> None:
    # (decoding remembers the quarters it met: each is read again, and again from memory)
    for raw in packets + packets:
        nibbles = [nibble for byte in raw for nibble in (byte >> 4, byte & 15)]
        expected = tuple(SensorColor(n) if n <= 4 else SensorColor.WHITE for n in nibbles)
        assert colors_from_bytes(raw) == expected
