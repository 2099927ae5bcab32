"""What every simulated device sees of the robot (:class:`Context`), and what it offers it.

A device owns its state, its command handlers (:meth:`SimDevice.commands`, by packet name) and
its sensing. It never reaches into the robot or another device: it talks to the robot through
the small :class:`Context` below, and to another device only through that device's public
methods (handed to it when the robot is built).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Protocol

from rootlang.protocol import Packet
from rootlang.sim.models import ModelSpec
from rootlang.sim.physics import Physics
from rootlang.sim.recording import Recording
from rootlang.sim.world import World

Pose = tuple[float, float, float]  # world x, y (mm), heading (radians, counterclockwise)
Handler = Callable[[Packet], None]


class Context(Protocol):
    """The robot as its devices see it: the clock, sending, timers, the body and the world."""

    now_ms: int  # simulated milliseconds since power-on (devices only read it)
    world: World
    spec: ModelSpec
    physics: Physics  # the body: its pose, contacts and ray casts
    recording: Recording
    keep_history: bool  # False: keep no growing history (strokes' points, frames)
    picked_up: bool  # held in the air by a person (wheels spin freely, the floor is far)

    def respond(self, request: Packet, **fields: object) -> None:
        """Send the response to ``request`` now."""

    def event(self, name: str, **fields: object) -> None:
        """Send an event now (if the host enabled its device and the model has it)."""

    def ignore(self, why: str) -> None:
        """Record that a packet was not acted on, and why."""

    def happened(self, text: str) -> None:
        """Note something on the recording's timeline."""

    def at(self, t_ms: int, action: Callable[[], None]) -> int:
        """Run ``action`` at simulated time ``t_ms``; returns a number for :meth:`cancel`."""

    def cancel(self, timer: int) -> None: ...

    def record_frame(self, *, force: bool = False) -> None:
        """Take a frame of the recording (``force``: even if one was taken lately)."""

    def sense_floor(self) -> None:
        """Bring the marker's line and the colour sensors up to the body's pose now."""

    def stop_everything(self, *, respond: bool) -> None:
        """Stop the wheels, the sound and the marker (``respond``: answer what they were doing)."""

    def reset_origin(self) -> None:
        """Make the pose now the odometry's origin."""

    def end_connection(self, reason: str) -> None:
        """The robot ends the link itself."""


class SimDevice:
    """One device of the protocol on the simulated robot."""

    def __init__(self, robot: Context) -> None:
        self.robot = robot

    def commands(self) -> Mapping[str, Handler]:
        """The commands this device acts on, by packet name (none by default)."""
        return {}
