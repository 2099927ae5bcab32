"""Which bleak backend to use: the computer's own Bluetooth, or another stack plugged in.

bleak picks the platform's backend (BlueZ, CoreBluetooth, WinRT) unless it is given classes with
``backend=``; rootlang passes these through, so the same scanner and transport run over bumble
in tests (``rootlang.ble.virtual``) and over a USB dongle with ``--transport``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from bleak.backends.client import BaseBleakClient
    from bleak.backends.scanner import BaseBleakScanner


@dataclass(frozen=True)
class BleBackend:
    """bleak backend classes; ``None`` means the platform's own."""

    scanner: type[BaseBleakScanner] | None = None
    client: type[BaseBleakClient] | None = None
    description: str = "this computer's Bluetooth"


SYSTEM_BLUETOOTH = BleBackend()
