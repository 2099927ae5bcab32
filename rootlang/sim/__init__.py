"""The simulator: a virtual Root or Create 3 in a pymunk world that speaks the robot's packets.

- :mod:`rootlang.sim.world` — worlds (TOML files) as plain data;
- :mod:`rootlang.sim.recording` — what a run leaves for pictures and summaries.
"""

from __future__ import annotations

from rootlang.sim.recording import Recording
from rootlang.sim.world import World, default_world, load_world, parse_world

__all__ = ["Recording", "World", "default_world", "load_world", "parse_world"]
