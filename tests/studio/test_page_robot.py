"""A run on the page's own robot, at the server's edge: a stand-in for the page's link module
(``static/robot_link.js``, tested in Chromium in ``test_web_bluetooth.py``) speaks the studio's
WebSocket messages and relays each packet to the simulator's virtual robot on the wall clock, as
the page relays them to a Root. The runtime, worker and server are the real ones."""

from __future__ import annotations

import asyncio
import json
from typing import Any

import aiohttp
import pytest

from rootlang.messages import MESSAGES
from rootlang.protocol import decode, encode
from rootlang.runtime.clock import WallClock
from rootlang.runtime.stops import StoppedBy, StopReason
from rootlang.runtime.transport import LinkLost
from rootlang.sim.robot import VirtualRobot
from rootlang.sim.transport import SimTransport
from rootlang.studio.page_robot import PageRobot, PageTransport, link_packets, motion_of
from rootlang.wording.catalogue import translations
from rootlang.wording.language import ENGLISH

from .conftest import PROGRAMS, RunningStudio
from .test_server import _time_limit, golden_world_pose, with_session

ROBOT = {"type": "robot_linked", "name": "Root-07", "serial": "RT1-0007", "firmware": "3.0.1",
         "hardware": "1.0"}  # fmt: skip


class PageStandIn:
    """The page's side of the link: writes each packet to the robot, says it did, relays the
    robot's packets back; the packets it wrote are kept."""

    def __init__(self, socket: aiohttp.ClientWebSocketResponse[bool], clock: WallClock) -> None:
        self.socket = socket
        self.robot = VirtualRobot()
        self.brain = SimTransport(self.robot, clock)
        self.written: list[bytes] = []
        self.link: dict[str, Any] = {}
        self._sending: set[asyncio.Future[None]] = set()

    async def link_robot(self) -> None:
        await self.brain.connect(self._notify, lambda reason: None)
        await self.socket.send_json(ROBOT)
        self.link = await self.socket.receive_json(timeout=10)
        assert self.link["type"] == "robot_link"

    def _notify(self, packet: bytes) -> None:
        sending = asyncio.ensure_future(
            self.socket.send_json({"type": "robot_notify", "data": packet.hex()})
        )
        self._sending.add(sending)
        sending.add_done_callback(self._sending.discard)

    async def relay_until_ended(self, *, cut_after: int = 0) -> dict[str, Any]:
        """Relays until the run ends (``cut_after`` packets: the robot's link drops)."""
        async with _time_limit(60):
            async for message in self.socket:
                data = json.loads(message.data)
                if data["type"] == "robot_packet":
                    packet = bytes.fromhex(data["data"])
                    assert data["moves"] == motion_of(packet)
                    if cut_after and len(self.written) == cut_after:
                        await self.socket.send_json({"type": "robot_lost"})
                        continue
                    self.written.append(packet)
                    await self.brain.send(packet)
                    await self.socket.send_json({"type": "robot_written", "n": data["n"]})
                elif data["type"] == "ended":
                    return dict(data)
                elif data["type"] == "error":
                    raise AssertionError(data["message"])
        raise AssertionError("the run never ended")


def assert_golden_pose(robot: VirtualRobot, name: str) -> None:
    """Where the robot ended, as the golden file (a simulated run) says, to the mm and degree
    (in real time the last step falls a little differently)."""
    final = robot.finish().final_frame
    assert final is not None
    x, y, heading = golden_world_pose(name)
    assert abs(final.x_mm - x) <= 1 and abs(final.y_mm - y) <= 1, (final, x, y)
    assert abs((final.heading_deg - heading + 180) % 360 - 180) <= 1, (final, heading)


def run_on_page(
    studio: RunningStudio, name: str, **options: Any
) -> tuple[PageStandIn, dict[str, Any]]:
    found: list[Any] = []
    clock = WallClock()  # the virtual robot's time: the wall's, as a robot's is

    async def main() -> None:
        async with aiohttp.ClientSession(studio.address) as session:
            await check(session)

    async def check(session: aiohttp.ClientSession) -> None:
        async with session.ws_connect("/ws", origin=studio.address) as socket:
            page = PageStandIn(socket, clock)
            await page.link_robot()
            text = (PROGRAMS / name).read_text(encoding="utf-8")
            await socket.send_json({"type": "run", "name": name, "text": text, "speed": 1,
                                    "link": "page"})  # fmt: skip
            ended = await page.relay_until_ended(**options)
            await page.brain.disconnect()
            found.extend([page, ended])

    clock.run(main())
    return found[0], found[1]


def test_a_square_on_the_pages_robot_reaches_the_golden_pose(studio: RunningStudio) -> None:
    page, ended = run_on_page(studio, "square.root")
    assert ended["end"] == "finished", (ended["error"], ended["trace"])
    assert_golden_pose(page.robot, "square.root")
    assert ended["trace"] and "Root RT1" in "\n".join(ended["trace"])
    assert decode(page.written[-1], sender="host").name in ("stop_and_reset", "get_position")


def test_the_robots_link_dropping_ends_the_run_with_its_reason(studio: RunningStudio) -> None:
    _, ended = run_on_page(studio, "square.root", cut_after=6)
    assert ended["end"] == "disconnected"
    assert ended["stopped_by"] == "the page's Bluetooth link to the robot dropped"
    assert ended["error"]["code"] == "E207"


def test_a_run_on_the_pages_robot_needs_one_linked(studio: RunningStudio) -> None:
    async def check(session: aiohttp.ClientSession) -> None:
        async with session.ws_connect("/ws", origin=studio.address) as socket:
            await socket.send_json({"type": "run", "name": "a.root", "link": "page",
                                    "text": "when started\n    move 1 cm\n"})  # fmt: skip
            reply = await socket.receive_json(timeout=10)
            assert reply["type"] == "error" and reply["code"] == "E816"

    with_session(studio, check)


@pytest.mark.parametrize(
    "message",
    [{"type": "robot_linked", "name": 7}, {"type": "robot_linked", "name": "x" * 65},
     {"type": "robot_teleport"}],
)  # fmt: skip
def test_bad_link_messages_get_an_error(studio: RunningStudio, message: dict[str, Any]) -> None:
    async def check(session: aiohttp.ClientSession) -> None:
        async with session.ws_connect("/ws", origin=studio.address) as socket:
            await socket.send_json(message)
            reply = await socket.receive_json(timeout=10)
            assert reply["type"] == "error" and reply["code"] == "E806"

    with_session(studio, check)


def test_the_link_packets_come_from_the_protocol_table() -> None:
    robot = PageRobot.from_message(ROBOT)
    link = link_packets(robot)
    assert decode(bytes.fromhex(link["stop"]), sender="host").name == "stop_and_reset"
    names = [decode(bytes.fromhex(p), sender="host").name for p in link["hello"]]
    assert names[0] == "set_led_animation" and set(names[1:]) == {"play_note"}
    assert link["silence_s"] > 0 and link["hidden_s"] > 0


@pytest.mark.parametrize(
    ("name", "fields", "moves"),
    [("set_wheel_speeds", {"left": 0, "right": 0}, False),
     ("set_wheel_speeds", {"left": 10, "right": 0}, True),
     ("set_left_wheel_speed", {"left": 0}, None),
     ("drive_distance", {"distance": 100}, True),
     ("stop_and_reset", {}, False),
     ("set_led_animation", {"state": 1, "red": 1, "green": 2, "blue": 3}, None)],
)  # fmt: skip
def test_which_packets_set_the_robot_moving(
    name: str, fields: dict[str, int], moves: object
) -> None:
    assert motion_of(encode(name, fields, 5)) is moves


def test_models_and_protocols_come_from_the_device_information() -> None:
    create = PageRobot("Create-01", serial="", firmware="G.5.4").info()
    assert create.model.value == "Ci3" and create.protocol_version >= (1, 4)
    assert PageRobot("R", serial="RT0123", firmware="1.0").info().model.value == "RT0"


def test_a_link_that_is_gone_fails_the_packet_waiting_on_it() -> None:
    sent: list[tuple[str, object]] = []
    lost: list[LinkLost] = []
    transport = PageTransport(PageRobot("R"), lambda kind, data: sent.append((kind, data)))

    async def main() -> None:
        await transport.connect(lambda packet: None, lost.append)
        waiting = asyncio.ensure_future(transport.send(encode("stop_and_reset", {}, 1)))
        await asyncio.sleep(0)
        transport.lost("gone")
        with pytest.raises(ConnectionError):
            await waiting
        with pytest.raises(ConnectionError):
            await transport.send(encode("stop_and_reset", {}, 2))

    asyncio.run(main())
    assert lost == ["gone"] and sent[0][0] == "robot_packet"


def test_the_studios_own_reason_for_ending_a_link_reaches_the_run_as_data() -> None:
    """The server hands a run's worker why it ended a page's link as data, not words to be
    read back: the run is stopped by that reason, said in the page's language."""
    lost: list[LinkLost] = []
    transport = PageTransport(PageRobot("R"), lambda kind, data: None)
    dropped = StoppedBy(StopReason.PAGE_LINK_DROPPED)

    async def main() -> None:
        await transport.connect(lambda packet: None, lost.append)
        transport.lost(StoppedBy.from_json(dropped.to_json()) or "")  # as the pipe carries it

    asyncio.run(main())
    assert lost == [dropped]
    said = StoppedBy.link(lost[0]).shown(ENGLISH.for_page("nl"))
    assert said == translations("nl")["V031"] != MESSAGES["V031"]
