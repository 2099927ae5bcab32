"""Where bumble devices get their controller: an in-process link, or a real HCI transport.

:class:`VirtualRadio` is bumble's in-process link (no radio, no kernel Bluetooth): every device
on it gets its own virtual controller and sees the others' advertisements and connections.
:func:`open_hci_device` opens a device on any bumble transport name (``usb:0``,
``tcp-client:127.0.0.1:6402``, ...), for a dongle or a virtual controller outside this process.
"""

from __future__ import annotations

import contextlib
import itertools
from collections.abc import AsyncIterator

from bumble.controller import Controller
from bumble.device import Device
from bumble.hci import Address
from bumble.host import Host
from bumble.link import LocalLink
from bumble.transport import open_transport
from bumble.transport.common import AsyncPipeSink

from rootlang.ble.virtual.central import BumbleCentral
from rootlang.diagnostics import RootlangError
from rootlang.runtime.clock import Clock
from rootlang.runtime.transport import Transport


class VirtualRadio:
    """bumble's in-process link; create it inside the event loop that will use it."""

    def __init__(self) -> None:
        self.link = LocalLink()  # type: ignore[no-untyped-call]
        self._numbers = itertools.count(1)

    def device(self, name: str) -> Device:
        """A new device with its own controller on the link (static random address)."""
        number = next(self._numbers)
        address = f"F0:00:00:00:{number >> 8:02X}:{number & 0xFF:02X}"
        controller = Controller(name, link=self.link, public_address=address)
        return Device(
            name=name, address=Address(address), host=Host(controller, AsyncPipeSink(controller))
        )

    async def central(self) -> BumbleCentral:
        """The host's side: a powered-on device offered to bleak as a backend."""
        device = self.device("rootlang host")
        await device.power_on()
        return BumbleCentral(device, "bumble's in-process virtual link")


_HOST_ADDRESS = "F0:F0:F0:F0:F0:01"
_ROBOT_ADDRESS = "F0:F0:F0:F0:F0:02"


@contextlib.asynccontextmanager
async def open_hci_device(spec: str, name: str, *, robot: bool = False) -> AsyncIterator[Device]:
    """A bumble device on the HCI transport ``spec`` (E409 if it can't be opened)."""
    try:
        transport = await open_transport(spec)
    except Exception as error:  # bumble raises many kinds for a transport it can't open
        reason = str(error) or type(error).__name__
        raise RootlangError.of("E409", spec=spec, reason=reason) from error
    async with transport:
        address = Address(_ROBOT_ADDRESS if robot else _HOST_ADDRESS)
        yield Device.with_hci(name, address, transport.source, transport.sink)


@contextlib.asynccontextmanager
async def hci_central(spec: str) -> AsyncIterator[BumbleCentral]:
    async with open_hci_device(spec, "rootlang host") as device:
        await device.power_on()
        yield BumbleCentral(device, f"bumble on {spec}")


@contextlib.asynccontextmanager
async def in_process_classroom(
    brain: Transport | None = None, name: str = "Virtual Root", clock: Clock | None = None
) -> AsyncIterator[BumbleCentral]:
    """A host and one virtual robot on one in-process link: Bluetooth with no radio at all."""
    from rootlang.ble.virtual.bridge import BleBridge
    from rootlang.ble.virtual.robot import simulated_robot

    radio = VirtualRadio()
    central = await radio.central()
    bridge = BleBridge(
        radio.device(name),
        brain or simulated_robot(name=name, clock=clock),
        name=name,
        scan_response_in_advertisement=True,
    )
    await bridge.start()
    try:
        yield central
    finally:
        await bridge.stop()
