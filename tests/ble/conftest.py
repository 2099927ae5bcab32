"""A classroom with no radio: bumble's in-process link, virtual robots on it, bleak over bumble.

Everything below the test goes through bleak's public API (``BleakScanner``, ``BleakClient``)
with bumble's central role as the backend, over bumble's virtual link, to bumble peripherals
serving the Root GATT profile. Nothing is mocked; only the radio is missing.
"""

from __future__ import annotations

import asyncio
from collections.abc import Callable, Coroutine
from dataclasses import dataclass, field
from typing import Any, TypeVar

import pytest

pytest.importorskip(
    "bumble", reason="the virtual robot needs the optional extra: rootlang[virtual]"
)

from rootlang.ble.virtual.central import BumbleCentral
from rootlang.ble.virtual.peripheral import RobotIdentity, RobotPeripheral
from rootlang.ble.virtual.radio import VirtualRadio
from rootlang.robots import RobotModel

T = TypeVar("T")


def run(main: Callable[[], Coroutine[Any, Any, T]], seconds: float = 60.0) -> T:
    """Run one test's coroutine with a hard deadline, so a hang fails instead of stalling CI
    (far above what a test takes on a busy machine: never a speed)."""

    async def bounded() -> T:
        return await asyncio.wait_for(main(), seconds)

    return asyncio.run(bounded())


@dataclass
class PacketLog:
    """What a peripheral received on RX; it can answer each packet by echoing it on TX."""

    echo: bool = True
    received: list[bytes] = field(default_factory=list)
    peripheral: RobotPeripheral | None = None

    def __call__(self, packet: bytes) -> None:
        self.received.append(packet)
        if self.echo and self.peripheral is not None:
            self.peripheral.send(packet)


@dataclass
class Classroom:
    radio: VirtualRadio
    central: BumbleCentral
    robots: list[RobotPeripheral] = field(default_factory=list)
    logs: list[PacketLog] = field(default_factory=list)

    async def add_robot(
        self, name: str, model: RobotModel = RobotModel.RT1, *, echo: bool = True
    ) -> RobotPeripheral:
        log = PacketLog(echo=echo)
        identity = RobotIdentity.for_model(model, name, len(self.robots) + 1)
        robot = RobotPeripheral(
            self.radio.device(name), identity, log, scan_response_in_advertisement=True
        )
        log.peripheral = robot
        await robot.start()
        self.robots.append(robot)
        self.logs.append(log)
        return robot


async def classroom() -> Classroom:
    radio = VirtualRadio()
    return Classroom(radio, await radio.central())
