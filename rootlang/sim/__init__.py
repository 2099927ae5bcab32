"""The simulator: a virtual Root or Create 3 in a pymunk world that speaks the robot's packets.

- :mod:`rootlang.sim.world` — worlds (TOML files) as plain data;
- :mod:`rootlang.sim.robot` — :class:`VirtualRobot`, the packet-level virtual robot, made of
  :mod:`rootlang.sim.devices`, one class per protocol device (its firmware);
- :mod:`rootlang.sim.physics`, :mod:`~rootlang.sim.motion`, :mod:`~rootlang.sim.sensors`,
  :mod:`~rootlang.sim.models` — its body, its firmware's driving, its senses, its models;
- :mod:`rootlang.sim.transport` — :class:`SimTransport`, the robot on a clock;
- :mod:`rootlang.sim.recording` — what a run leaves for pictures and summaries;
- :mod:`rootlang.sim.render` — those pictures.

A program run in a world is wired in :mod:`rootlang.app.session` (``simulate()``).

Names are imported lazily, so reading a world file does not load pymunk.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from rootlang.sim.recording import Recording
    from rootlang.sim.robot import PacketRecord, VirtualRobot
    from rootlang.sim.transport import SimTransport
    from rootlang.sim.world import World, default_world, load_world, parse_world

_EXPORTS = {
    "PacketRecord": "robot",
    "Recording": "recording",
    "SimTransport": "transport",
    "VirtualRobot": "robot",
    "World": "world",
    "default_world": "world",
    "load_world": "world",
    "parse_world": "world",
}

__all__ = [
    "PacketRecord",
    "Recording",
    "SimTransport",
    "VirtualRobot",
    "World",
    "default_world",
    "load_world",
    "parse_world",
]


def __getattr__(name: str) -> Any:
    if name not in _EXPORTS:
        raise AttributeError(f"module 'rootlang.sim' has no attribute {name!r}")
    return getattr(importlib.import_module(f"rootlang.sim.{_EXPORTS[name]}"), name)
