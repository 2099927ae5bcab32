"""Colours may be given as bytes, one a sensor (the simulator's floor raster reads them so)."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rootlang.protocol import Packet, PacketError, decode, encode
from rootlang.protocol.enums import SensorColor


@settings(max_examples=50)
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
