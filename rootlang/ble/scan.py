"""Listening for robots: every advertisement carrying the Root Identifier service.

:class:`RobotScanner` wraps bleak's scanner (filtered by the Root Identifier service, so other
Bluetooth devices never show up) and turns each advertisement into a :class:`RobotSeen`.
:func:`scan` collects what is in range for a while, for ``rootlang scan``.
"""

from __future__ import annotations

import asyncio
import contextlib
from collections.abc import AsyncIterator
from contextlib import asynccontextmanager
from typing import TYPE_CHECKING

from rootlang.ble.advertisement import RobotSeen, is_robot, robot_seen
from rootlang.ble.backend import SYSTEM_BLUETOOTH, BleBackend
from rootlang.ble.profile import ROOT_IDENTIFIER_SERVICE
from rootlang.diagnostics import RootlangError

if TYPE_CHECKING:
    from bleak.backends.device import BLEDevice
    from bleak.backends.scanner import AdvertisementData


class RobotScanner:
    """Robots heard since scanning started: the latest advertisement of each, by address."""

    def __init__(self) -> None:
        self.robots: dict[str, RobotSeen] = {}
        self.devices: dict[str, BLEDevice] = {}
        self.heard: asyncio.Queue[RobotSeen] = asyncio.Queue()

    def _on_advertisement(self, device: BLEDevice, advertisement: AdvertisementData) -> None:
        if not is_robot(advertisement):
            return
        seen = robot_seen(device, advertisement)
        self.robots[seen.address] = seen
        self.devices[seen.address] = device
        self.heard.put_nowait(seen)

    async def heard_within(self, seconds: float) -> AsyncIterator[RobotSeen]:
        """Each advertisement heard from now until ``seconds`` have passed (loop time)."""
        loop = asyncio.get_running_loop()
        deadline = loop.time() + seconds
        while (remaining := deadline - loop.time()) > 0:
            try:
                yield await asyncio.wait_for(self.heard.get(), remaining)
            except asyncio.TimeoutError:
                return

    def in_range(self) -> list[RobotSeen]:
        """Strongest signal first, then by name, so the list reads the same each time."""
        return sorted(
            self.robots.values(), key=lambda robot: (-robot.rssi, robot.name, robot.address)
        )


@asynccontextmanager
async def scanning(backend: BleBackend = SYSTEM_BLUETOOTH) -> AsyncIterator[RobotScanner]:
    """Scan while inside the block; Bluetooth that is off or missing becomes E407."""
    from bleak import BleakScanner
    from bleak.exc import BleakError

    robots = RobotScanner()
    scanner = BleakScanner(
        robots._on_advertisement, [ROOT_IDENTIFIER_SERVICE], backend=backend.scanner
    )
    try:
        await scanner.start()
    except BleakError as error:
        raise RootlangError.of("E407", backend=backend.description, reason=str(error)) from error
    except OSError as error:  # e.g. Linux without the BlueZ service, or no adapter at all
        reason = f"no Bluetooth adapter or service answered ({error.strerror or error})"
        raise RootlangError.of("E407", backend=backend.description, reason=reason) from error
    try:
        yield robots
    finally:
        # The adapter may have gone away while scanning: then nothing is left to stop.
        with contextlib.suppress(BleakError, OSError):
            await scanner.stop()


async def scan(seconds: float, backend: BleBackend = SYSTEM_BLUETOOTH) -> list[RobotSeen]:
    """Every robot heard within ``seconds``."""
    async with scanning(backend) as robots:
        async for _ in robots.heard_within(seconds):
            pass
    return robots.in_range()
