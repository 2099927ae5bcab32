"""The packet reference in docs/ is the table, regenerated."""

from __future__ import annotations

from pathlib import Path

from rootlang.protocol import PACKETS
from rootlang.protocol.describe import markdown_reference

REFERENCE = Path(__file__).resolve().parents[2] / "docs" / "protocol-packets.md"


def test_reference_matches_the_table() -> None:
    assert REFERENCE.read_text(encoding="utf-8") == markdown_reference() + "\n", (
        "run: python -m rootlang.protocol.describe > docs/protocol-packets.md"
    )


def test_reference_lists_every_packet_and_the_errata() -> None:
    text = markdown_reference()
    for packet in PACKETS:
        assert f"### `{packet.name}`" in text
    assert text.count("Erratum:") == 3
