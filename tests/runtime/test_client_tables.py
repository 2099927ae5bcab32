"""The robot client keeps no table of commands of its own: how each command behaves is its row
of the packet table (``rootlang/protocol/behaviour.py``), and the client names no packet."""

from __future__ import annotations

import ast
from pathlib import Path

from rootlang.protocol import PACKETS
from rootlang.protocol.behaviour import WhenSilent
from rootlang.runtime import client

PACKET_NAMES = {packet.name for packet in PACKETS}


def test_the_client_names_no_packet() -> None:
    tree = ast.parse(Path(client.__file__).read_text(encoding="utf-8"))
    named = {
        node.value
        for node in ast.walk(tree)
        if isinstance(node, ast.Constant) and isinstance(node.value, str)
    }
    assert named & PACKET_NAMES == set()


def test_a_movement_judged_by_the_pose_says_its_way_and_its_end() -> None:
    judged = [p for p in PACKETS if p.behaviour.when_silent is WhenSilent.BY_POSE]
    assert {p.name for p in judged} >= {"drive_distance", "rotate_angle", "drive_arc"}
    for packet in judged:
        assert packet.response is not None, packet.name
        assert packet.behaviour.takes is not None, packet.name
        assert packet.behaviour.ends_at is not None, packet.name
        assert packet.behaviour.moves, packet.name
