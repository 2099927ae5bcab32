"""The one small interface between the runtime and a robot: 20-byte packets both ways.

Implemented by the simulator (`rootlang.sim`), by bleak for real robots (`rootlang.ble`) and by
an in-memory loopback for tests (`rootlang.runtime.loopback`). A transport knows nothing of what
the packets mean; the robot client (`rootlang.runtime.client`) does.
"""

from __future__ import annotations

import abc
from collections.abc import Callable
from dataclasses import dataclass

from rootlang.robots import RobotModel
from rootlang.runtime.stops import StoppedBy

PacketHandler = Callable[[bytes], None]
"""Called with each 20-byte packet the robot sends, in arrival order, on the event loop."""

LinkLost = str | StoppedBy
"""Why a link dropped: a reason in the link's own plain words (a Bluetooth stack's), or one of
rootlang's own as data (the studio ended a page's link), said in the reader's language."""

DisconnectHandler = Callable[[LinkLost], None]
"""Called once, with why, when the link drops without being asked to."""


USUAL_PROTOCOL: tuple[int, int] = (1, 3)
"""What a robot is taken to speak until it says otherwise: Root firmware 2.x, the usual robot."""


@dataclass(frozen=True)
class RobotInfo:
    """What a robot tells about itself when the link opens."""

    model: RobotModel
    name: str
    serial: str = ""
    firmware: str = ""
    hardware: str = ""
    protocol_version: tuple[int, int] = USUAL_PROTOCOL


class Transport(abc.ABC):
    """Something that exchanges 20-byte packets with one robot."""

    acknowledges_writes: bool = False
    """True when ``send`` returns only once the robot has the packet (a Bluetooth write with
    response): a packet can't then be lost on its way, so none is sent twice to be safe."""

    @abc.abstractmethod
    async def connect(
        self, on_packet: PacketHandler, on_disconnect: DisconnectHandler
    ) -> RobotInfo:
        """Open the link; from now on every packet from the robot goes to ``on_packet``."""

    @abc.abstractmethod
    async def send(self, packet: bytes) -> None:
        """Deliver one 20-byte packet to the robot."""

    @abc.abstractmethod
    async def disconnect(self) -> None:
        """Close the link; safe to call twice, and after the robot has gone."""
