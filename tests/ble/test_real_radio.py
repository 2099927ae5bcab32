"""With a real radio and a robot switched on nearby: the same code over the system's Bluetooth.

Skipped unless ROOTLANG_REAL_ROBOT names a robot in range (e.g. ROOTLANG_REAL_ROBOT=Rooty):
this machine, and CI, have no Bluetooth radio (no /dev/vhci, no AF_BLUETOOTH, no BlueZ).
"""

from __future__ import annotations

import asyncio
import os

import pytest

from rootlang.ble.select import choose_robot
from rootlang.ble.transport import BleakTransport

ROBOT = os.environ.get("ROOTLANG_REAL_ROBOT", "")

pytestmark = pytest.mark.skipif(
    not ROBOT,
    reason="needs a Bluetooth radio and a robot in range: set ROOTLANG_REAL_ROBOT=<robot name>",
)


def test_a_real_robot_is_found_connected_and_identified() -> None:
    async def main() -> None:
        chosen = await choose_robot(ROBOT, timeout=15)
        transport = BleakTransport(chosen.device, chosen.robot)
        info = await transport.connect(lambda _packet: None, lambda _reason: None)
        try:
            assert info.firmware and info.serial
            assert info.protocol_version >= (1, 0)
        finally:
            await transport.disconnect()

    asyncio.run(main())
