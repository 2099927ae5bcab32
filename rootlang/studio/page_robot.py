"""A robot whose Bluetooth link is the pupil's own page (Web Bluetooth); the runtime stays here.

A Chromebook can't run Python, and one laptop's adapter holds 5–7 robots, so in a class each
page links its own robot (``static/robot_link.js``) and relays packets: a run on "my robot" is
the very run every other run is (runtime, scheduler, robot client, trace) on a
:class:`PageTransport`, whose packets travel worker → server → WebSocket → page → the robot's
RX characteristic, and whose robot's notifications come back the same way.

The page keeps the robot safe by itself (it stops it when anything drops: see the timing rules
below and ``docs/studio.md``), so it needs the Stop and Reset packet before any run
— and the packets that make a robot show it is the one linked. Both are made here, from the
protocol's table (:func:`link_packets`): the page never builds a packet itself.
"""

from __future__ import annotations

import asyncio
import contextlib
import itertools
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from rootlang.ble.naming import here_i_am
from rootlang.ble.profile import (
    DEVICE_INFORMATION_SERVICE,
    FIRMWARE_VERSION,
    HARDWARE_VERSION,
    MANUFACTURER_ID,
    ROOT_IDENTIFIER_SERVICE,
    RX,
    SERIAL_NUMBER,
    TX,
    UART_SERVICE,
)
from rootlang.diagnostics import RootlangError
from rootlang.protocol import (
    PACKET_BYTES,
    Packet,
    PacketError,
    decode,
    encode,
    protocol_version_for,
)
from rootlang.robots import RobotModel
from rootlang.runtime.stops import StoppedBy, StopReason
from rootlang.runtime.transport import (
    USUAL_PROTOCOL,
    DisconnectHandler,
    LinkLost,
    PacketHandler,
    RobotInfo,
    Transport,
)
from rootlang.studio.messages import BluetoothProfile, LinkFigures, RobotLinkMessage

PAGE_LINK = "page"
"""A run message's ``link`` that asks for the page's own robot."""

WRITE_TIMEOUT_S = 5.0
"""As the bleak transport's: a packet unacknowledged this long means the robot or page is gone."""
SILENCE_S = 1.0
"""The page stops a moving robot when the studio has said nothing this long (frames come ~25 a
second during a run, so a second of silence is a studio or network gone, not a slow one)."""
HIDDEN_S = 5.0
"""The page stops its robot when it has been hidden this long (another tab, a closed lid)."""
STOP_GRACE_S = 3.0
"""After the page's Stop, `when stopped` scripts have 2 s; a run not ended by then is cut."""
WEB_BLUETOOTH: BluetoothProfile = {
    "identifier": ROOT_IDENTIFIER_SERVICE,  # what the browser's chooser filters on ...
    "company": MANUFACTURER_ID,  # ... or iRobot's manufacturer data (a Create 3 has it too)
    "uart": UART_SERVICE, "rx": RX, "tx": TX,
    "information": DEVICE_INFORMATION_SERVICE,
    "serial": SERIAL_NUMBER, "firmware": FIRMWARE_VERSION, "hardware": HARDWARE_VERSION,
}  # fmt: skip
"""The robots' GATT as the page needs it (from :mod:`rootlang.ble.profile`, the one table)."""
MAX_KEPT = 100_000  # round trips kept for a run's figures (a long run keeps its first ones)
FIELD_CHARS = 64  # a robot's name and its Device Information strings are far shorter


_MOVES = frozenset(("drive_distance", "rotate_angle", "drive_arc", "navigate_to_position"))
_SPEEDS = {"set_wheel_speeds": ("left", "right"), "set_left_wheel_speed": ("left",),
           "set_right_wheel_speed": ("right",)}  # fmt: skip
_STOPS = frozenset(("stop_and_reset",))


@dataclass(frozen=True)
class PageRobot:
    """What the page read from the robot it linked: its name and Device Information strings."""

    name: str
    serial: str = ""
    firmware: str = ""
    hardware: str = ""

    @classmethod
    def from_message(cls, message: dict[str, Any]) -> PageRobot:
        """From a page's ``robot_linked`` message (E806 for anything but short strings)."""
        values = {}
        for key in ("name", "serial", "firmware", "hardware"):
            value = message.get(key, "")
            if not isinstance(value, str) or len(value) > FIELD_CHARS:
                raise RootlangError.of(
                    "E806", reason=f"`{key}` must be text of at most {FIELD_CHARS} characters"
                )
            values[key] = value.strip()
        return cls(**values)

    @property
    def model(self) -> RobotModel:
        return RobotModel.from_details(self.serial, self.firmware)

    def info(self) -> RobotInfo:
        try:
            protocol = protocol_version_for(self.model, self.firmware)
        except RootlangError:
            protocol = USUAL_PROTOCOL  # an unreadable firmware version
        return RobotInfo(self.model, self.name, self.serial, self.firmware, self.hardware,
                         protocol)  # fmt: skip

    def describe(self) -> str:
        return f'{self.model.display_name} "{self.name or "?"}"'


def link_packets(robot: PageRobot) -> RobotLinkMessage:
    """What the page needs before any run: Stop and Reset (id 0: a robot always takes it,
    whatever its count) and the "here I am" light and chirp, from the protocol's table, with the
    timing rules it keeps by itself."""
    return {
        "type": "robot_link",
        "robot": robot.describe(),
        "stop": encode("stop_and_reset", {}, 0, robot.model).hex(),
        "hello": [packet.hex() for packet in here_i_am(robot.model)],
        "write_timeout_s": WRITE_TIMEOUT_S,
        "silence_s": SILENCE_S,
        "hidden_s": HIDDEN_S,
        "stop_grace_s": STOP_GRACE_S,
    }


def page_stop(why: object) -> StoppedBy:
    """What stopped a run when its page stopped the robot itself, from the page's
    ``robot_stopped`` (``why``: the rule that did; E806 for anything else)."""
    stops = {
        "silence": StoppedBy(StopReason.PAGE_STOPPED_QUIET, SILENCE_S),
        "hidden": StoppedBy(StopReason.PAGE_STOPPED_HIDDEN, HIDDEN_S),
        "stop": StoppedBy(StopReason.PAGE_STOPPED_LATE, STOP_GRACE_S),
        "pagehide": StoppedBy(StopReason.PAGE_CLOSED),
        "socket": StoppedBy(StopReason.PAGE_LOST_STUDIO),
    }
    if not isinstance(why, str) or why not in stops:
        raise RootlangError.of("E806", reason=f"`why` must be one of {', '.join(stops)}")
    return stops[why]


def motion_of(packet: bytes) -> bool | None:
    """Whether the robot is moving after ``packet`` (True), stopped by it (False), or neither
    changes (None) — what the page's watchdog needs to know, read from the protocol's table."""
    try:
        decoded = decode(packet, sender="host")
    except PacketError:
        return None
    if not isinstance(decoded, Packet):
        return None
    if decoded.name in _MOVES:
        return True
    if decoded.name in _STOPS:
        return False
    wheels = _SPEEDS.get(decoded.name)
    if wheels is None:
        return None
    moving = any(int(decoded.fields[wheel]) != 0 for wheel in wheels)
    return True if moving else (False if len(wheels) == 2 else None)


def packet_from_hex(data: object) -> bytes:
    """A robot's packet as the page relays it (40 hex digits); E806 for anything else."""
    if not isinstance(data, str) or len(data) != 2 * PACKET_BYTES:
        raise RootlangError.of("E806", reason=f"`data` must be {2 * PACKET_BYTES} hex digits")
    try:
        return bytes.fromhex(data)
    except ValueError:
        raise RootlangError.of("E806", reason="`data` must be hex digits") from None


Post = Callable[[str, object], None]
"""Sends one message towards the page (the worker's pipe to the server)."""


class PageTransport(Transport):
    """The runtime's side of a page's link: ``post`` sends each packet towards the page; the
    worker hands back what the page reports (:meth:`written`, :meth:`notified`, :meth:`lost`).

    Each packet waits for the page's word that the robot took it (the page writes with
    response), so, as over bleak, no packet needs sending twice to be safe.
    """

    acknowledges_writes = True

    def __init__(
        self, robot: PageRobot, post: Post, write_timeout: float = WRITE_TIMEOUT_S
    ) -> None:
        self.robot = robot
        self._post = post
        self.write_timeout = write_timeout
        self._numbers = itertools.count(1)
        self._pending: dict[int, asyncio.Future[None]] = {}
        self._on_packet: PacketHandler | None = None
        self._on_disconnect: DisconnectHandler | None = None
        self._gone: LinkLost | None = None  # why the link is gone
        self._closing = False
        self.round_trips_s: list[float] = []  # packet sent -> the page says the robot has it
        self.stopped_by_page: StoppedBy | None = None  # the page stopped the robot itself

    async def connect(
        self, on_packet: PacketHandler, on_disconnect: DisconnectHandler
    ) -> RobotInfo:
        if self._gone is not None:
            raise RootlangError.of("E405", robot=self.robot.describe(), reason=self._gone)
        self._on_packet, self._on_disconnect = on_packet, on_disconnect
        return self.robot.info()

    async def send(self, packet: bytes) -> None:
        if len(packet) != PACKET_BYTES:
            raise ValueError(f"a packet is {PACKET_BYTES} bytes, got {len(packet)}")
        if self._gone is not None:
            raise ConnectionError(StoppedBy.link(self._gone).english())
        number = next(self._numbers)
        loop = asyncio.get_running_loop()
        sent_at = loop.time()
        written = loop.create_future()
        self._pending[number] = written
        self._post("robot_packet", {"n": number, "data": packet.hex(),
                                    "moves": motion_of(packet)})  # fmt: skip
        try:
            await asyncio.wait_for(written, self.write_timeout)
            if len(self.round_trips_s) < MAX_KEPT:
                self.round_trips_s.append(loop.time() - sent_at)
        except asyncio.TimeoutError as error:
            raise TimeoutError(
                f"it didn't acknowledge a packet within {self.write_timeout:g} seconds"
            ) from error
        finally:
            self._pending.pop(number, None)

    def written(self, number: int, error: str | None = None) -> None:
        """The page wrote packet ``number`` to the robot (or failed to: ``error``)."""
        future = self._pending.get(number)
        if future is None or future.done():
            return
        if error is None:
            future.set_result(None)
        else:
            future.set_exception(ConnectionError(error))

    def notified(self, packet: bytes) -> None:
        """A packet from the robot (its TX notification), relayed by the page."""
        if self._on_packet is not None and self._gone is None:
            self._on_packet(packet)

    def lost(self, reason: LinkLost) -> None:
        """The page's link to the robot is gone (a GATT disconnect, the page gone: the studio's
        reasons as data, :class:`~rootlang.runtime.stops.StoppedBy`)."""
        if self._gone is not None:
            return
        self._gone = reason
        for future in self._pending.values():
            if not future.done():
                future.set_exception(ConnectionError(StoppedBy.link(reason).english()))
        if self._on_disconnect is not None and not self._closing:
            self._on_disconnect(reason)

    def link_figures(self) -> LinkFigures:
        """How long packets took to reach the robot through the page, for the run's outcome."""
        times = sorted(self.round_trips_s)
        if not times:
            return {"packets": 0}

        def at(share: float) -> float:
            return round(times[min(len(times) - 1, int(share * len(times)))] * 1000, 2)

        return {"packets": len(times), "median_ms": at(0.5), "p95_ms": at(0.95), "max_ms": at(1.0)}

    async def disconnect(self) -> None:
        """The run is over: the page stops the robot and ends the link when it hears so."""
        self._closing = True
        with contextlib.suppress(Exception):
            self.lost("the run ended")
