"""A bleak backend over bumble's central role: bleak's real API on a BLE stack with no radio.

bleak lets a caller plug in backend classes (``BleakScanner(backend=...)``,
``BleakClient(backend=...)``). These two drive a powered-on bumble :class:`Device` instead of the
operating system: scanning reports bumble's advertisements as bleak's ``AdvertisementData``;
the client connects, discovers the GATT database into bleak's service collection, reads, writes
(with and without response), subscribes, and reports a disconnect it did not ask for.

Used by the tests (over bumble's in-process link to the virtual robot) and by ``--transport`` on
the command line (over any bumble HCI transport, e.g. a USB dongle).
"""

from __future__ import annotations

import asyncio
import contextlib
import uuid
from collections.abc import Callable
from typing import Any, ClassVar

from bleak.args import SizedBuffer
from bleak.assigned_numbers import CHARACTERISTIC_PROPERTIES, CharacteristicPropertyName
from bleak.backends.characteristic import BleakGATTCharacteristic
from bleak.backends.client import BaseBleakClient, NotifyCallback
from bleak.backends.descriptor import BleakGATTDescriptor
from bleak.backends.device import BLEDevice
from bleak.backends.scanner import AdvertisementData, BaseBleakScanner
from bleak.backends.service import BleakGATTService, BleakGATTServiceCollection
from bleak.exc import BleakDeviceNotFoundError, BleakError
from bumble import core, hci
from bumble.device import Advertisement, Connection, Device, Peer
from bumble.gatt_client import CharacteristicProxy

from rootlang.ble.backend import BleBackend

_ATT_HEADER = 3  # bytes of an ATT write command that are not the value


class BumbleCentral:
    """A bumble device acting as the computer's Bluetooth, offered to bleak as a backend."""

    def __init__(self, device: Device, description: str = "a bumble Bluetooth stack") -> None:
        self.device = device
        scanner = type("BumbleScanner", (BumbleScanner,), {"central": self})
        client = type("BumbleClient", (BumbleClient,), {"central": self})
        self.backend = BleBackend(scanner=scanner, client=client, description=description)


class BumbleScanner(BaseBleakScanner):
    central: ClassVar[BumbleCentral]

    def __init__(
        self,
        detection_callback: Any,
        service_uuids: list[str] | None,
        scanning_mode: str = "active",
        **_platform_options: Any,
    ) -> None:
        super().__init__(detection_callback, service_uuids)
        self._active = scanning_mode == "active"

    async def start(self) -> None:
        self.seen_devices = {}
        device = self.central.device
        device.on(device.EVENT_ADVERTISEMENT, self._on_advertisement)
        await device.start_scanning(active=self._active, filter_duplicates=False)

    async def stop(self) -> None:
        device = self.central.device
        device.remove_listener(device.EVENT_ADVERTISEMENT, self._on_advertisement)
        if device.is_scanning:
            await device.stop_scanning()

    def _on_advertisement(self, advertisement: Advertisement) -> None:
        data = _bleak_advertisement_data(advertisement)
        if not self.is_allowed_uuid(data.service_uuids):
            return
        address = str(advertisement.address).split("/", 1)[0]
        found = self.create_or_update_device(
            address, address, data.local_name, advertisement.address, data
        )
        self.call_detection_callbacks(found, data)


def _bleak_advertisement_data(advertisement: Advertisement) -> AdvertisementData:
    kinds = core.AdvertisingData.Type
    name: str | None = None
    manufacturer: dict[int, bytes] = {}
    service_data: dict[str, bytes] = {}
    uuids: list[str] = []
    tx_power: int | None = None
    for kind, value in advertisement.data.ad_structures:
        if kind in (kinds.COMPLETE_LOCAL_NAME, kinds.SHORTENED_LOCAL_NAME):
            name = value.decode("utf-8", errors="replace")
        elif kind == kinds.MANUFACTURER_SPECIFIC_DATA and len(value) >= 2:
            manufacturer[int.from_bytes(value[:2], "little")] = bytes(value[2:])
        elif kind in _UUID_LISTS:
            size = _UUID_LISTS[kind]
            chunks = (value[i : i + size] for i in range(0, len(value) - size + 1, size))
            uuids.extend(_uuid_string(chunk) for chunk in chunks)
        elif kind in _SERVICE_DATA:
            size = _SERVICE_DATA[kind]
            service_data[_uuid_string(value[:size])] = bytes(value[size:])
        elif kind == kinds.TX_POWER_LEVEL and value:
            tx_power = int.from_bytes(value[:1], "little", signed=True)
    return AdvertisementData(
        local_name=name,
        manufacturer_data=manufacturer,
        service_data=service_data,
        service_uuids=list(dict.fromkeys(uuids)),
        tx_power=tx_power,
        rssi=advertisement.rssi,
        platform_data=(advertisement,),
    )


_UUID_LISTS: dict[int, int] = {0x02: 2, 0x03: 2, 0x04: 4, 0x05: 4, 0x06: 16, 0x07: 16}
_SERVICE_DATA: dict[int, int] = {0x16: 2, 0x20: 4, 0x21: 16}


def _uuid_string(little_endian: bytes) -> str:
    """An over-the-air UUID (16, 32 or 128 bits, least significant byte first), bleak-style."""
    if len(little_endian) == 16:
        return str(uuid.UUID(bytes=bytes(little_endian[::-1])))
    return f"{int.from_bytes(little_endian, 'little'):08x}-0000-1000-8000-00805f9b34fb"


class BumbleClient(BaseBleakClient):
    central: ClassVar[BumbleCentral]

    def __init__(
        self,
        address_or_ble_device: BLEDevice | str,
        *,
        disconnected_callback: Callable[[], None] | None,
        timeout: float,
        **_platform_options: Any,
    ) -> None:
        super().__init__(
            address_or_ble_device, disconnected_callback=disconnected_callback, timeout=timeout
        )
        details = getattr(address_or_ble_device, "details", None)
        self._peer_address: hci.Address = (
            details if isinstance(details, hci.Address) else hci.Address(self.address)
        )
        self._connection: Connection | None = None
        self._peer: Peer | None = None
        self._closing = False

    @property
    def name(self) -> str:
        return self.address

    @property
    def mtu_size(self) -> int:
        return self._peer.gatt_client.mtu if self._peer else 23

    @property
    def is_connected(self) -> bool:
        return self._connection is not None

    async def connect(self, pair: bool, **kwargs: Any) -> None:
        device = self.central.device
        try:
            connection = await device.connect(
                self._peer_address,
                transport=core.PhysicalTransport.LE,
                timeout=kwargs.get("timeout", self._timeout),
            )
        except core.TimeoutError as error:
            raise BleakDeviceNotFoundError(self.address, str(error)) from error
        except core.BaseBumbleError as error:
            raise BleakError(f"could not connect to {self.address}: {error}") from error
        self._connection = connection
        connection.on(connection.EVENT_DISCONNECTION, self._on_disconnection)
        self._peer = Peer(connection)
        self.services = await self._discover(self._peer)

    async def _discover(self, peer: Peer) -> BleakGATTServiceCollection:
        collection = BleakGATTServiceCollection()
        await peer.discover_services()
        for proxy in peer.services:
            service = BleakGATTService(proxy, proxy.handle, _full_uuid(proxy.uuid))
            collection.add_service(service)
            await proxy.discover_characteristics()
            for characteristic_proxy in proxy.characteristics:
                characteristic = BleakGATTCharacteristic(
                    characteristic_proxy,
                    characteristic_proxy.handle,
                    _full_uuid(characteristic_proxy.uuid),
                    _property_names(int(characteristic_proxy.properties)),
                    lambda: self.mtu_size - _ATT_HEADER,
                    service,
                )
                collection.add_characteristic(characteristic)
                await characteristic_proxy.discover_descriptors()
                for descriptor_proxy in characteristic_proxy.descriptors:
                    collection.add_descriptor(
                        BleakGATTDescriptor(
                            descriptor_proxy,
                            descriptor_proxy.handle,
                            _full_uuid(descriptor_proxy.type),
                            characteristic,
                        )
                    )
        return collection

    def _on_disconnection(self, _reason: int) -> None:
        self._connection = None
        self._peer = None
        self.services = None
        if not self._closing and self._disconnected_callback is not None:
            self._disconnected_callback()

    async def disconnect(self) -> None:
        connection = self._connection
        if connection is None:
            return
        self._closing = True
        try:
            gone = asyncio.get_running_loop().create_future()
            connection.once(connection.EVENT_DISCONNECTION, lambda _reason: gone.set_result(None))
            with contextlib.suppress(core.BaseBumbleError):
                await connection.disconnect()
            with contextlib.suppress(asyncio.TimeoutError):
                await asyncio.wait_for(gone, self._timeout)
        finally:
            self._connection = None
            self._peer = None
            self._closing = False

    async def pair(self, *args: Any, **kwargs: Any) -> None:
        raise BleakError("robots connect without pairing")

    async def unpair(self) -> None:
        raise BleakError("robots connect without pairing")

    def _require_peer(self) -> Peer:
        if self._peer is None:
            raise BleakError("not connected")
        return self._peer

    async def read_gatt_char(
        self, characteristic: BleakGATTCharacteristic, *, use_cached: bool = False, **kwargs: Any
    ) -> bytearray:
        return bytearray(await self._require_peer().read_value(characteristic.handle))

    async def read_gatt_descriptor(
        self, descriptor: BleakGATTDescriptor, *, use_cached: bool = False, **kwargs: Any
    ) -> bytearray:
        return bytearray(await self._require_peer().read_value(descriptor.handle))

    async def write_gatt_char(
        self, characteristic: BleakGATTCharacteristic, data: SizedBuffer, response: bool
    ) -> None:
        peer = self._require_peer()
        await peer.write_value(characteristic.handle, bytes(data), with_response=response)

    async def write_gatt_descriptor(
        self, descriptor: BleakGATTDescriptor, data: SizedBuffer
    ) -> None:
        await self._require_peer().write_value(descriptor.handle, bytes(data), with_response=True)

    async def start_notify(
        self, characteristic: BleakGATTCharacteristic, callback: NotifyCallback, **kwargs: Any
    ) -> None:
        proxy: CharacteristicProxy[bytes] = characteristic.obj
        await self._require_peer().subscribe(proxy, lambda value: callback(bytearray(value)))

    async def stop_notify(self, characteristic: BleakGATTCharacteristic) -> None:
        proxy: CharacteristicProxy[bytes] = characteristic.obj
        await self._require_peer().unsubscribe(proxy)


def _full_uuid(uuid: core.UUID) -> str:
    return _uuid_string(uuid.to_bytes(force_128=True))


def _property_names(flags: int) -> list[CharacteristicPropertyName]:
    return [name for bit, name in CHARACTERISTIC_PROPERTIES.items() if flags & bit]
