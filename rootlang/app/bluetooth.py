"""Which Bluetooth: the computer's own, or bumble on an HCI transport, or bumble's virtual
robot in this process (the spec ``virtual``): what ``rootlang scan``/``run``/``robot`` and the
studio's robot runs share.

A spec is an HCI transport (a USB dongle ``usb:0``, a virtual controller
``tcp-client:127.0.0.1:6402``); ``virtual`` starts a simulated robot inside this process, on
bumble's virtual link, so the whole Bluetooth path can be tried with no robot and no radio.
"""

from __future__ import annotations

import contextlib
from collections.abc import AsyncIterator

from rootlang.ble.backend import SYSTEM_BLUETOOTH, BleBackend
from rootlang.diagnostics import RootlangError
from rootlang.runtime.clock import Clock

IN_PROCESS = "virtual"


@contextlib.asynccontextmanager
async def bluetooth(spec: str | None, clock: Clock) -> AsyncIterator[BleBackend]:
    """The bleak backend to use while inside the block (``clock`` runs the loop)."""
    if spec is None:
        yield SYSTEM_BLUETOOTH
        return
    try:
        from rootlang.ble.virtual import radio  # bumble: the `virtual` extra, maybe missing
    except ImportError as error:
        raise RootlangError.of("E408") from error
    if spec == IN_PROCESS:
        async with radio.in_process_classroom(clock=clock) as central:
            yield central.backend
        return
    async with radio.hci_central(spec) as central:
        yield central.backend
