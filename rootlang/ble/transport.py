"""The bleak transport: 20-byte packets to and from one robot over Bluetooth Low Energy.

Connecting follows the spec's order: connect (no pairing), read Device Information (serial,
firmware, hardware; the firmware gives the protocol version), subscribe to TX, and only then
let the runtime send. Writes go to RX with response by default (the robot acknowledges each
one); without response they are paced, because then the host must leave the robot time to
process each packet. A disconnect nobody asked for (robot switched off, out of range) reaches
the runtime once, through ``on_disconnect``, in plain words.
"""

from __future__ import annotations

import asyncio
import contextlib
from typing import TYPE_CHECKING

from rootlang.ble.advertisement import RobotSeen
from rootlang.ble.backend import SYSTEM_BLUETOOTH, BleBackend
from rootlang.ble.profile import (
    DEVICE_INFORMATION_SERVICE,
    FIRMWARE_VERSION,
    HARDWARE_VERSION,
    RX,
    SERIAL_NUMBER,
    TX,
    UART_SERVICE,
)
from rootlang.diagnostics import RootlangError
from rootlang.protocol import PACKET_BYTES, protocol_version_for
from rootlang.protocol.fields import text_from_bytes
from rootlang.robots import RobotModel
from rootlang.runtime.clock import Clock, WallClock
from rootlang.runtime.transport import (
    USUAL_PROTOCOL,
    DisconnectHandler,
    PacketHandler,
    RobotInfo,
    Transport,
)

if TYPE_CHECKING:
    from bleak import BleakClient
    from bleak.backends.characteristic import BleakGATTCharacteristic
    from bleak.backends.device import BLEDevice

CONNECT_TIMEOUT = 20.0
"""Seconds to connect and read the robot's details; bleak's own default (30 s) feels hung."""
WRITE_TIMEOUT = 5.0
"""Seconds a robot may take to acknowledge one packet before we call it unresponsive."""
UNACKNOWLEDGED_WRITE_GAP = 0.015
"""Seconds between writes without response, so the robot can process each packet first."""

LOST_CONNECTION = (
    "the Bluetooth connection dropped (the robot was switched off or went out of range)"
)


class BleakTransport(Transport):
    """One robot over bleak; ``backend`` plugs in another stack (bumble in tests)."""

    def __init__(
        self,
        device: BLEDevice | str,
        robot: RobotSeen | None = None,
        *,
        backend: BleBackend = SYSTEM_BLUETOOTH,
        clock: Clock | None = None,
        write_with_response: bool = True,
        connect_timeout: float = CONNECT_TIMEOUT,
        write_timeout: float = WRITE_TIMEOUT,
    ) -> None:
        self.device = device
        self.robot = robot
        self.backend = backend
        self.clock = clock or WallClock()
        self.write_with_response = write_with_response
        self.acknowledges_writes = write_with_response  # the robot's BLE stack confirms each
        self.connect_timeout = connect_timeout
        self.write_timeout = write_timeout
        self.info: RobotInfo | None = None
        self._client: BleakClient | None = None
        self._rx: BleakGATTCharacteristic | None = None
        self._on_disconnect: DisconnectHandler | None = None
        self._closing = False
        self._lost = False
        self._next_write_at = 0.0

    @property
    def label(self) -> str:
        if self.robot is not None:
            return self.robot.describe()
        return str(getattr(self.device, "address", self.device))

    @property
    def is_connected(self) -> bool:
        return self._client is not None and self._client.is_connected and not self._lost

    async def connect(
        self, on_packet: PacketHandler, on_disconnect: DisconnectHandler
    ) -> RobotInfo:
        from bleak import BleakClient
        from bleak.exc import BleakError

        self._on_disconnect = on_disconnect
        self._closing = self._lost = False
        client = BleakClient(
            self.device,
            self._disconnected,
            # Only these two are used: resolving fewer services connects faster on macOS/Windows.
            services=[DEVICE_INFORMATION_SERVICE, UART_SERVICE],
            timeout=self.connect_timeout,
            backend=self.backend.client,
        )
        self._client = client
        try:
            await asyncio.wait_for(client.connect(), self.connect_timeout)
            info = await asyncio.wait_for(self._read_info(client), self.connect_timeout)
            self._rx = client.services.get_characteristic(RX)
            tx = client.services.get_characteristic(TX)
            if self._rx is None or tx is None:
                raise RootlangError.of("E406", robot=self.label, part="UART service (RX and TX)")
            # Subscribe before anything is sent: the robot only talks to subscribers.
            await client.start_notify(tx, lambda _sender, data: on_packet(bytes(data)))
        except asyncio.TimeoutError as error:
            await self._close_quietly()
            raise RootlangError.of(
                "E405", robot=self.label, reason=f"no answer within {self.connect_timeout:g} s"
            ) from error
        except (BleakError, OSError, EOFError) as error:
            await self._close_quietly()
            raise RootlangError.of(
                "E405", robot=self.label, reason=str(error) or type(error).__name__
            ) from error
        except BaseException:
            await self._close_quietly()
            raise
        self.info = info
        return info

    async def _read_info(self, client: BleakClient) -> RobotInfo:
        async def text(uuid: str) -> str:
            if client.services.get_characteristic(uuid) is None:
                return ""
            raw = await client.read_gatt_char(uuid)
            return text_from_bytes(bytes(raw)).strip()

        serial, firmware, hardware = [
            await text(uuid) for uuid in (SERIAL_NUMBER, FIRMWARE_VERSION, HARDWARE_VERSION)
        ]
        model = self._model(serial, firmware)
        try:
            protocol = protocol_version_for(model, firmware)
        except RootlangError:
            protocol = USUAL_PROTOCOL  # an unreadable firmware version
        name = self.robot.name if self.robot else ""
        return RobotInfo(model, name, serial, firmware, hardware, protocol)

    def _model(self, serial: str, firmware: str) -> RobotModel:
        """From the advertisement; failing that, the serial number's prefix or the firmware."""
        if self.robot is not None and self.robot.model is not None:
            return self.robot.model
        return RobotModel.from_details(serial, firmware)

    def _disconnected(self, _client: BleakClient) -> None:
        if self._closing or self._lost:
            return
        self._lost = True
        if self._on_disconnect is not None:
            self._on_disconnect(LOST_CONNECTION)

    async def send(self, packet: bytes) -> None:
        from bleak.exc import BleakError

        if len(packet) != PACKET_BYTES:
            raise ValueError(f"a packet is {PACKET_BYTES} bytes, got {len(packet)}")
        client, rx = self._client, self._rx
        if client is None or rx is None or not self.is_connected:
            raise ConnectionError(LOST_CONNECTION)
        try:
            if self.write_with_response:
                await asyncio.wait_for(
                    client.write_gatt_char(rx, packet, response=True), self.write_timeout
                )
            else:
                await self._pace()
                await client.write_gatt_char(rx, packet, response=False)
        except asyncio.TimeoutError as error:
            raise TimeoutError(
                f"it didn't acknowledge a packet within {self.write_timeout:g} seconds"
            ) from error
        except (BleakError, OSError, EOFError) as error:
            # The runtime reports this (E208) in its own words; say what happened in ours.
            raise ConnectionError(
                LOST_CONNECTION if not client.is_connected else str(error)
            ) from error

    async def _pace(self) -> None:
        # Loop time, the time clock.sleep counts in: the transport's clock need not be the one
        # running the loop (then its now() stays 0).
        now = asyncio.get_running_loop().time()
        if now < self._next_write_at:
            await self.clock.sleep(self._next_write_at - now)
            now = self._next_write_at
        self._next_write_at = now + UNACKNOWLEDGED_WRITE_GAP

    async def disconnect(self) -> None:
        self._closing = True
        await self._close_quietly()

    async def _close_quietly(self) -> None:
        """Close whatever is open; a robot that is already gone is not an error here."""
        from bleak.exc import BleakError

        client, self._client, self._rx = self._client, None, None
        if client is None:
            return
        self._closing = True
        with contextlib.suppress(BleakError, OSError, EOFError, asyncio.TimeoutError):
            await asyncio.wait_for(client.disconnect(), self.write_timeout)
