"""A robot's Bluetooth face on bumble: the Root GATT services and advertisement.

:class:`RobotPeripheral` serves the profile in :data:`rootlang.ble.profile.ROOT_PROFILE`: Device
Information strings, Robot State, UART RX (write, write without response) and TX (notify,
indicate). Each packet written to RX goes to ``on_packet``; :meth:`send` delivers a packet to
every host subscribed to TX, in order. Whatever produces and consumes the packets (the
simulator's virtual robot, see :mod:`rootlang.ble.virtual.robot`) is not this module's business.

It advertises like a Root (:func:`rootlang.ble.advertisement.advertising_data`) while no host is
connected, and again after the host leaves; a new :class:`RobotState` (a touch, a bump, the
battery) updates the advertisement, which is how "touch the robot you want" works.
"""

from __future__ import annotations

import asyncio
import contextlib
from collections.abc import Awaitable, Callable, Coroutine
from dataclasses import dataclass
from typing import Any

from bumble import gatt, hci
from bumble.att import Attribute
from bumble.core import BaseBumbleError
from bumble.device import Connection, Device

from rootlang.ble.advertisement import advertising_data
from rootlang.ble.profile import (
    FIRMWARE_VERSION,
    HARDWARE_VERSION,
    MANUFACTURER,
    ROBOT_STATE,
    ROOT_PROFILE,
    RX,
    SERIAL_NUMBER,
    TX,
    RobotState,
)
from rootlang.robots import RobotModel

TEST_ADVERTISING_INTERVAL_MS = 20.0
"""bumble's default is 1 s, which makes every scan wait; real robots advertise far faster."""
PROBE_EVERY_SECONDS = 1.0
LINK_TIMEOUT_SECONDS = 4.0
"""Chosen, as a BLE link's supervision timeout (4 s is common): a host that answers nothing
for this long has gone, and the robot ends the link (:meth:`RobotPeripheral._supervise`)."""

_PROPERTY_FLAGS: dict[str, gatt.Characteristic.Properties] = {
    "read": gatt.Characteristic.Properties.READ,
    "write": gatt.Characteristic.Properties.WRITE,
    "write-without-response": gatt.Characteristic.Properties.WRITE_WITHOUT_RESPONSE,
    "notify": gatt.Characteristic.Properties.NOTIFY,
    "indicate": gatt.Characteristic.Properties.INDICATE,
}


@dataclass(frozen=True)
class RobotIdentity:
    """What the robot's Device Information service and advertisement say about it."""

    name: str = "Virtual Root"
    model: RobotModel = RobotModel.RT1
    serial: str = "RT1000000001"
    firmware: str = "2.7"
    hardware: str = "1.0"
    manufacturer: str = "iRobot"

    @classmethod
    def for_model(cls, model: RobotModel, name: str, number: int = 1) -> RobotIdentity:
        firmware = "G.5" if model is RobotModel.CREATE3 else "2.7"
        return cls(name, model, f"{model.value}{number:09d}", firmware)


class RobotPeripheral:
    """A bumble device that looks, to any BLE host, like a Root robot."""

    def __init__(
        self,
        device: Device,
        identity: RobotIdentity,
        on_packet: Callable[[bytes], Awaitable[None] | None],
        *,
        scan_response_in_advertisement: bool = False,
        advertising_interval_ms: float = TEST_ADVERTISING_INTERVAL_MS,
    ) -> None:
        self.device = device
        self.identity = identity
        self.on_packet = on_packet
        self.on_host_connected: Callable[[], None] = lambda: None
        self.on_host_gone: Callable[[], None] = lambda: None
        self.state = RobotState()
        self.connection: Connection | None = None
        # bumble's in-process link delivers no scan responses: there, advertise both in one.
        self._merge_scan_response = scan_response_in_advertisement
        self._interval = advertising_interval_ms
        self._outbox: asyncio.Queue[bytes] = asyncio.Queue()
        self._sender: asyncio.Task[None] | None = None
        self._background: set[asyncio.Task[None]] = set()
        self._supervisor: asyncio.Task[None] | None = None
        self.host_answered = 0
        """How many times a host has answered the robot's question (:meth:`_supervise`)."""
        self._tx = self._build_gatt()

    def _build_gatt(self) -> gatt.Characteristic[bytes]:
        strings = {
            SERIAL_NUMBER: self.identity.serial,
            FIRMWARE_VERSION: self.identity.firmware,
            HARDWARE_VERSION: self.identity.hardware,
            MANUFACTURER: self.identity.manufacturer,
        }
        characteristics: dict[str, gatt.Characteristic[bytes]] = {}
        services = []
        for service_spec in ROOT_PROFILE:
            for spec in service_spec.characteristics:
                flags = gatt.Characteristic.Properties(0)
                for name in spec.properties:
                    flags |= _PROPERTY_FLAGS[name]
                characteristics[spec.uuid] = gatt.Characteristic(
                    spec.uuid, flags, self._permissions(flags), self._value_of(spec.uuid, strings)
                )
            services.append(
                gatt.Service(
                    service_spec.uuid,
                    [characteristics[spec.uuid] for spec in service_spec.characteristics],
                )
            )
        self.device.add_services(services)
        return characteristics[TX]

    @staticmethod
    def _permissions(flags: gatt.Characteristic.Properties) -> Attribute.Permissions:
        properties = gatt.Characteristic.Properties
        permissions = Attribute.Permissions(0)
        if flags & (properties.READ | properties.NOTIFY | properties.INDICATE):
            permissions |= Attribute.Permissions.READABLE
        if flags & (properties.WRITE | properties.WRITE_WITHOUT_RESPONSE):
            permissions |= Attribute.Permissions.WRITEABLE
        return permissions

    def _value_of(
        self, uuid: str, strings: dict[str, str]
    ) -> bytes | gatt.CharacteristicValue[bytes]:
        if uuid in strings:
            return strings[uuid].encode()
        if uuid == ROBOT_STATE:
            return gatt.CharacteristicValue(read=lambda _connection: self.state.to_bytes())
        if uuid == RX:
            return gatt.CharacteristicValue(write=lambda _connection, value: self._received(value))
        return b""

    async def _received(self, value: bytes) -> None:
        answer = self.on_packet(bytes(value))
        if answer is not None:  # a robot busy with the packet acknowledges the write after
            await answer

    async def start(self) -> None:
        """Power on, then advertise until a host connects."""
        self.device.on(self.device.EVENT_CONNECTION, self._on_connection)
        await self.device.power_on()
        self._sender = asyncio.get_running_loop().create_task(self._send_in_order())
        await self._advertise()

    async def stop(self) -> None:
        if self._supervisor is not None:
            self._supervisor.cancel()
            self._supervisor = None
        if self._sender is not None:
            self._sender.cancel()
            with contextlib.suppress(asyncio.CancelledError):
                await self._sender
            self._sender = None
        with contextlib.suppress(BaseBumbleError):
            await self.device.stop_advertising()
        await self.drop_connection()

    async def _advertise(self) -> None:
        advertising, scan_response = advertising_data(
            self.identity.name, self.identity.model, self.state
        )
        if self._merge_scan_response:
            advertising, scan_response = advertising + scan_response, b""
        await self.device.start_advertising(
            advertising_data=advertising,
            scan_response_data=scan_response,
            advertising_interval_min=self._interval,
            advertising_interval_max=self._interval,
            own_address_type=hci.OwnAddressType.RANDOM,
        )

    async def update_state(self, state: RobotState) -> None:
        """A touch, bump or battery change: readable now, advertised while no host is connected."""
        if state == self.state:
            return
        self.state = state
        if self.connection is None:
            await self._advertise()

    def in_background(self, work: Coroutine[Any, Any, None]) -> None:
        """Run ``work`` soon; a BLE stack that has gone meanwhile is not an error."""

        async def quietly() -> None:
            with contextlib.suppress(BaseBumbleError, ConnectionError):
                await work

        task = asyncio.get_running_loop().create_task(quietly())
        self._background.add(task)
        task.add_done_callback(self._background.discard)

    def _on_connection(self, connection: Connection) -> None:
        self.connection = connection
        connection.on(connection.EVENT_DISCONNECTION, self._on_disconnection)
        self._supervisor = asyncio.get_running_loop().create_task(self._supervise(connection))
        self.on_host_connected()

    def _on_disconnection(self, _reason: int) -> None:
        self.connection = None
        if self._supervisor is not None:
            self._supervisor.cancel()
            self._supervisor = None
        self.on_host_gone()
        if self.device.powered_on:
            self.in_background(self._advertise())

    async def _supervise(self, connection: Connection) -> None:
        """A real robot's link drops when its host's radio stops answering, and the robot
        stops (the link's supervision timeout). A virtual link never drops by itself, and a
        host whose process was killed (``kill -9`` of ``rootlang run``) can leave its
        controller holding the link: so every :data:`PROBE_EVERY_SECONDS` the robot asks the
        host for its device name, which every BLE host answers (an error says "here" too);
        no answer within :data:`LINK_TIMEOUT_SECONDS`, and the robot ends the link, which
        stops it (``on_host_gone``)."""
        while True:
            await asyncio.sleep(PROBE_EVERY_SECONDS)
            asked = connection.gatt_client.read_characteristics_by_uuid(
                gatt.GATT_DEVICE_NAME_CHARACTERISTIC, None
            )
            try:
                await asyncio.wait_for(asked, LINK_TIMEOUT_SECONDS)
            except asyncio.TimeoutError:
                break
            except BaseBumbleError:
                pass  # an answer all the same: the host is there
            self.host_answered += 1
        self.in_background(self.drop_connection())

    def send(self, packet: bytes) -> None:
        """Queue a packet for TX; packets arrive in the order they were sent."""
        self._outbox.put_nowait(bytes(packet))

    async def _send_in_order(self) -> None:
        while True:
            packet = await self._outbox.get()
            if self.connection is None:
                continue  # nobody listening: a real robot drops it too
            with contextlib.suppress(BaseBumbleError):
                await self.device.notify_subscribers(self._tx, packet)
                await self.device.indicate_subscribers(self._tx, packet)

    async def drop_connection(self) -> None:
        """The robot ends the link (switched off, out of range): the host sees a disconnect."""
        connection = self.connection
        if connection is not None:
            with contextlib.suppress(BaseBumbleError):
                await connection.disconnect()
