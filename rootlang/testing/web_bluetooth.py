"""Robots for a real Chromium's Web Bluetooth: its DevTools ``BluetoothEmulation`` domain,
answered by the simulator's virtual robot on the wall clock (as ``rootlang.ble.virtual`` answers
bleak over bumble).

Chromium's emulation replaces the browser's Bluetooth adapter: :class:`EmulatedCentral` turns
it on (a browser-wide CDP session) and adds :class:`EmulatedRobot` peripherals with the Root's
GATT services from :data:`rootlang.ble.profile.ROOT_PROFILE`. The page's real
``navigator.bluetooth`` then chooses one (the chooser is answered through the page's
``DeviceAccess`` domain: :func:`answer_chooser`), connects, discovers, reads the Device
Information, subscribes to TX and writes to RX; each operation arrives here as an event and is
answered with ``simulate...Response``. Each packet written to RX goes to the virtual robot.

The emulation has no way to send a notification to the page, so the robot's packets are handed
to the page's one test seam, ``robot_link.js``'s ``emulatedNotification`` (documented there),
in order; from there they take the path a real notification takes.

Needs Playwright's async API (the ``test`` extra) and a Chromium with the domain (121+; tested
on 156). Web Bluetooth on Linux needs ``--enable-features=WebBluetooth`` (:data:`CHROMIUM_FLAGS`).
"""

from __future__ import annotations

import asyncio
import base64
import contextlib
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from rootlang.ble.profile import (
    FIRMWARE_VERSION,
    HARDWARE_VERSION,
    MANUFACTURER_ID,
    ROOT_PROFILE,
    RX,
    SERIAL_NUMBER,
    TX,
    UART_SERVICE,
)
from rootlang.protocol import Packet, PacketError, decode
from rootlang.robots import RobotModel
from rootlang.runtime.clock import Clock
from rootlang.sim.robot import VirtualRobot
from rootlang.sim.transport import SimTransport
from rootlang.sim.world import World

CHROMIUM_FLAGS = ("--enable-features=WebBluetooth",)
CLIENT_CONFIGURATION = "00002902-0000-1000-8000-00805f9b34fb"
"""The descriptor a notifying characteristic needs before Chromium lets a page subscribe."""
SUCCESS = 0
SEAM = "hex => import('/static/robot_link.js').then(link => link.emulatedNotification(hex))"
_PROPERTIES = {"read": "read", "write": "write", "write-without-response": "writeWithoutResponse",
               "notify": "notify", "indicate": "indicate"}  # fmt: skip

CDPSession = Any  # playwright.async_api.CDPSession (an optional dependency)
Page = Any  # playwright.async_api.Page


@dataclass
class EmulatedRobot:
    """One virtual robot behind the emulated adapter; ``written`` keeps every packet the page
    wrote to it, in order."""

    address: str
    name: str
    clock: Clock
    model: RobotModel = RobotModel.RT1
    world: World | None = None
    written: list[bytes] = field(default_factory=list)
    page: Page | None = None  # the page whose link chose it (where its notifications go)
    subscribed: bool = False

    def __post_init__(self) -> None:
        self.robot = VirtualRobot(self.world, model=self.model)
        self.robot.name = self.name
        self.brain = SimTransport(self.robot, self.clock)
        self.firmware = "G.5.4" if self.model is RobotModel.CREATE3 else "3.0.1"
        self.serial = f"{self.model.value}-{self.address[-2:]}"
        self._outbox: asyncio.Queue[bytes] = asyncio.Queue()
        self._sender: asyncio.Task[None] | None = None
        self.notified = 0

    @property
    def strings(self) -> dict[str, bytes]:
        return {SERIAL_NUMBER: self.serial.encode(), FIRMWARE_VERSION: self.firmware.encode(),
                HARDWARE_VERSION: b"1.0"}  # fmt: skip

    async def start(self) -> None:
        await self.brain.connect(self._outbox.put_nowait, lambda reason: None)
        self._sender = asyncio.ensure_future(self._notify_page())

    async def stop(self) -> None:
        if self._sender is not None:
            self._sender.cancel()
            with contextlib.suppress(asyncio.CancelledError):
                await self._sender
        await self.brain.disconnect()

    async def _notify_page(self) -> None:
        """The robot's packets, in order, to the page's seam (dropped while nobody listens, as
        a real robot's notifications are)."""
        while True:
            packet = await self._outbox.get()
            if self.page is None or not self.subscribed:
                continue
            with contextlib.suppress(Exception):  # the page is gone: nothing hears it
                if await self.page.evaluate(SEAM, packet.hex()):
                    self.notified += 1

    async def received(self, packet: bytes) -> None:
        self.written.append(packet)
        await self.brain.send(packet)

    def written_names(self, since: int = 0) -> list[str]:
        """The names (the protocol table's) of the packets written to it, from ``since`` on."""
        return [packet_name(packet) for packet in self.written[since:]]


def packet_name(packet: bytes) -> str:
    try:
        decoded = decode(packet, sender="host")
    except PacketError as error:
        return f"bad packet ({error})"
    return decoded.name if isinstance(decoded, Packet) else "unknown"


class EmulatedCentral:
    """Chromium's emulated Bluetooth adapter, powered on, with the robots added to it."""

    def __init__(self, session: CDPSession, clock: Clock) -> None:
        self.session = session
        self.clock = clock
        self.robots: dict[str, EmulatedRobot] = {}
        self._characteristics: dict[str, tuple[EmulatedRobot, str]] = {}
        self._events: asyncio.Queue[tuple[str, dict[str, Any]]] = asyncio.Queue()
        self._worker: asyncio.Task[None] | None = None

    @classmethod
    async def start(cls, browser: Any, clock: Clock) -> EmulatedCentral:
        session = await browser.new_browser_cdp_session()
        central = cls(session, clock)
        await session.send("BluetoothEmulation.enable", {"state": "powered-on",
                                                         "leSupported": True})  # fmt: skip
        for event in ("gattOperationReceived", "characteristicOperationReceived",
                      "descriptorOperationReceived"):  # fmt: skip
            session.on(f"BluetoothEmulation.{event}", central._queue(event))
        central._worker = asyncio.ensure_future(central._answer())
        return central

    def _queue(self, event: str) -> Callable[[dict[str, Any]], None]:
        return lambda params: self._events.put_nowait((event, params))

    async def close(self) -> None:
        if self._worker is not None:
            self._worker.cancel()
            with contextlib.suppress(asyncio.CancelledError):
                await self._worker
        for robot in self.robots.values():
            await robot.stop()
        with contextlib.suppress(Exception):  # the browser may be closed already
            await self.session.send("BluetoothEmulation.disable")

    async def add_robot(
        self, address: str, name: str, model: RobotModel = RobotModel.RT1,
        world: World | None = None, *, uart: bool = True,
    ) -> EmulatedRobot:  # fmt: skip
        """A robot in range (already known to the system, as Chromium's emulation offers);
        without its ``uart`` service, one the page finds but can't talk to (as Chromium says
        of a robot it can't reach: "No Services matching UUID ... found in Device")."""
        robot = EmulatedRobot(address, name, self.clock, model, world)
        code = base64.b64encode(model.value.encode()).decode()
        send = self.session.send
        await send("BluetoothEmulation.simulatePreconnectedPeripheral", {
            "address": address, "name": name,
            "manufacturerData": [{"key": MANUFACTURER_ID, "data": code}],
            "knownServiceUuids": [ROOT_PROFILE[0].uuid],
        })  # fmt: skip
        for service in ROOT_PROFILE:
            if service.uuid == UART_SERVICE and not uart:
                continue
            added = await send("BluetoothEmulation.addService",
                               {"address": address, "serviceUuid": service.uuid})  # fmt: skip
            for characteristic in service.characteristics:
                properties = {_PROPERTIES[p]: True for p in characteristic.properties}
                made = await send("BluetoothEmulation.addCharacteristic", {
                    "serviceId": added["serviceId"], "characteristicUuid": characteristic.uuid,
                    "properties": properties,
                })  # fmt: skip
                self._characteristics[made["characteristicId"]] = (robot, characteristic.uuid)
                if "notify" in characteristic.properties:
                    await send("BluetoothEmulation.addDescriptor", {
                        "characteristicId": made["characteristicId"],
                        "descriptorUuid": CLIENT_CONFIGURATION,
                    })  # fmt: skip
        await robot.start()
        self.robots[address] = robot
        return robot

    async def drop_link(self, robot: EmulatedRobot) -> None:
        """The robot switched off or out of range: Chromium's GATT disconnection."""
        robot.subscribed = False
        await self.session.send("BluetoothEmulation.simulateGATTDisconnection",
                                {"address": robot.address})  # fmt: skip

    async def _answer(self) -> None:
        while True:
            event, params = await self._events.get()
            with contextlib.suppress(Exception):  # a page that went away mid-operation
                await self._answer_one(event, params)

    async def _answer_one(self, event: str, params: dict[str, Any]) -> None:
        send = self.session.send
        if event == "gattOperationReceived":  # connection, discovery: both succeed
            await send("BluetoothEmulation.simulateGATTOperationResponse",
                       {"address": params["address"], "type": params["type"],
                        "code": SUCCESS})  # fmt: skip
        elif event == "descriptorOperationReceived":
            await send("BluetoothEmulation.simulateDescriptorOperationResponse",
                       {"descriptorId": params["descriptorId"], "type": params["type"],
                        "code": SUCCESS})  # fmt: skip
        else:
            await self._characteristic(params)

    async def _characteristic(self, params: dict[str, Any]) -> None:
        robot, uuid = self._characteristics[params["characteristicId"]]
        kind = params["type"]
        answer: dict[str, Any] = {"characteristicId": params["characteristicId"], "type": kind,
                                  "code": SUCCESS}  # fmt: skip
        if kind == "read":
            answer["data"] = base64.b64encode(robot.strings.get(uuid, b"")).decode()
        elif kind == "subscribe-to-notifications" and uuid == TX:
            robot.subscribed = True
        elif kind == "unsubscribe-from-notifications" and uuid == TX:
            robot.subscribed = False
        await self.session.send("BluetoothEmulation.simulateCharacteristicOperationResponse",
                                answer)  # fmt: skip
        if kind == "write" and uuid == RX:  # acknowledged, then obeyed (as a robot's BLE stack)
            await robot.received(base64.b64decode(params["data"]))


async def answer_chooser(page: Page, robot: EmulatedRobot) -> None:
    """The page's Bluetooth chooser picks ``robot`` (as a child clicking its name would);
    its notifications then go to ``page``."""
    session = await page.context.new_cdp_session(page)
    answered: set[str] = set()

    async def choose(params: dict[str, Any]) -> None:
        ids = [device["id"] for device in params["devices"]]
        if params["id"] in answered or robot.address not in ids:
            return  # (the chooser is told again as devices are found)
        answered.add(params["id"])
        robot.page = page
        await session.send("DeviceAccess.selectPrompt",
                           {"id": params["id"], "deviceId": robot.address})  # fmt: skip

    tasks: set[asyncio.Task[None]] = set()

    def prompted(params: dict[str, Any]) -> None:
        task = asyncio.ensure_future(choose(params))
        tasks.add(task)
        task.add_done_callback(tasks.discard)

    session.on("DeviceAccess.deviceRequestPrompted", prompted)
    await session.send("DeviceAccess.enable")
