"""The packets published with the spec encode and decode exactly."""

from __future__ import annotations

import csv
from pathlib import Path

import pytest

from rootlang.protocol import Packet, crc8, decode, encode

DATA = Path(__file__).parent / "data"


def _vectors() -> list[tuple[str, dict[str, int], str]]:
    lines = [
        line
        for line in (DATA / "protocol_vectors.tsv").read_text().splitlines()
        if line and not line.startswith("#")
    ]
    rows = list(csv.DictReader(lines, delimiter="\t"))
    assert rows, "no vectors read"
    result = []
    for row in rows:
        fields = {k: int(v) for k, v in (pair.split("=") for pair in row["fields"].split())}
        result.append((row["meaning"], fields, row["hex"]))
    return result


VECTORS = _vectors()


def test_crc8_check_value() -> None:
    assert crc8(b"123456789") == 0xF4


@pytest.mark.parametrize(("meaning", "fields", "hex_bytes"), VECTORS)
def test_vector_encodes_exactly(meaning: str, fields: dict[str, int], hex_bytes: str) -> None:
    assert "device 1, command 4" in meaning
    assert encode("set_wheel_speeds", fields, packet_id=0).hex() == hex_bytes


@pytest.mark.parametrize(("meaning", "fields", "hex_bytes"), VECTORS)
def test_vector_decodes_exactly(meaning: str, fields: dict[str, int], hex_bytes: str) -> None:
    packet = decode(bytes.fromhex(hex_bytes), sender="host")
    assert isinstance(packet, Packet)
    assert packet.name == "set_wheel_speeds"
    assert packet.id == 0
    assert dict(packet.fields) == fields
    assert packet.encode().hex() == hex_bytes
