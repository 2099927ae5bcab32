"""The pupil's own robot over Web Bluetooth, in real headless Chromium: the studio's page links
a robot through its real ``navigator.bluetooth`` (choose, connect, Device Information,
subscribe, write), Chromium's DevTools ``BluetoothEmulation`` plays the adapter, and the
simulator's virtual robot on the wall clock answers (:mod:`rootlang.testing.web_bluetooth`).
The one seam: the robot's notifications reach the page through ``robot_link.js``'s
``emulatedNotification`` (the emulation can't send one); everything else is real.

Each test runs on one event loop driven by a wall clock: Playwright's async API, the emulated
adapter and the virtual robots (whose time is the clock's)."""

from __future__ import annotations

import asyncio
import contextlib
import json
from collections.abc import Awaitable, Callable
from pathlib import Path
from typing import Any

import pytest

import rootlang
from rootlang.runtime.clock import WallClock
from rootlang.sim.world import Stimulus
from rootlang.studio.tls import studio_certificate
from rootlang.testing.web_bluetooth import (
    CHROMIUM_FLAGS,
    EmulatedCentral,
    EmulatedRobot,
    answer_chooser,
)

from .browser import CHROMIUM, CHROMIUM_ARGS
from .conftest import RunningStudio
from .test_page_robot import assert_golden_pose

pytestmark = pytest.mark.skipif(
    not CHROMIUM.exists(), reason="needs Debian's chromium at /usr/bin/chromium"
)
async_api = pytest.importorskip("playwright.async_api")

Scenario = Callable[["Lab"], Awaitable[None]]
ROBOT_A, ROBOT_B = "0A:0B:0C:0D:0E:07", "0A:0B:0C:0D:0E:08"
STUDIO_STRINGS = Path(rootlang.__file__).parent / "locale" / "studio.json"


class Lab:
    """A browser with Web Bluetooth and an emulated adapter, pages on the studio."""

    def __init__(self, browser: Any, central: EmulatedCentral, address: str) -> None:
        self.browser = browser
        self.central = central
        self.address = address
        self.pages: list[Any] = []
        self.errors: list[str] = []

    async def page(self, name: str = "square.root", address: str = "", language: str = "") -> Any:
        page = await self.browser.new_page(viewport={"width": 1400, "height": 850})
        page.on("pageerror", lambda error: self.errors.append(str(error)))
        spoken = f"&language={language}" if language else ""
        await page.goto(f"{address or self.address}/?open={name}{spoken}")
        await wait_state(page, "ready", "yes")
        await wait_state(page, "open", name)
        self.pages.append(page)
        return page

    async def link(self, page: Any, robot: EmulatedRobot) -> None:
        """The pupil presses Connect a robot and picks ``robot`` in the chooser."""
        await answer_chooser(page, robot)
        await page.click("#connect-robot")
        await wait_state(page, "robotLinked", robot.name)


async def wait_state(page: Any, key: str, value: str, timeout_ms: int = 60000) -> None:
    await page.wait_for_function(
        "([key, value]) => document.getElementById('state').dataset[key] === value",
        arg=[key, value], timeout=timeout_ms,
    )  # fmt: skip


async def state(page: Any) -> dict[str, str]:
    found: dict[str, str] = await page.eval_on_selector("#state", "e => ({...e.dataset})")
    return found


async def run(page: Any) -> None:
    await page.click("#run")
    await wait_state(page, "running", "yes")


async def ended(page: Any, timeout_ms: int = 60000) -> str:
    await page.wait_for_function(
        "() => (document.getElementById('state').dataset.ended || '') !== ''", timeout=timeout_ms
    )
    return (await state(page))["ended"]


async def safe_stops(page: Any) -> list[str]:
    stops: list[str] = await page.evaluate(
        "() => import('/static/robot_link.js').then(m => m.currentLink()?.safeStops ?? [])"
    )
    return stops


def in_chromium(address: str, scenario: Scenario, *, flags: tuple[str, ...] = ()) -> None:
    """Runs ``scenario`` on one wall-clock loop with a fresh browser and emulated adapter."""
    clock = WallClock()

    async def main() -> None:
        async with async_api.async_playwright() as playwright:
            browser = await playwright.chromium.launch(
                executable_path=str(CHROMIUM), args=[*CHROMIUM_ARGS, *CHROMIUM_FLAGS, *flags]
            )
            central = await EmulatedCentral.start(browser, clock)
            lab = Lab(browser, central, address)
            try:
                await asyncio.wait_for(scenario(lab), 300)
            finally:
                await central.close()
                await browser.close()
            assert lab.errors == [], "the page's script failed"

    clock.run(main())


def test_a_square_on_an_emulated_robot_reaches_the_golden_pose(studio: RunningStudio) -> None:
    async def scenario(lab: Lab) -> None:
        robot = await lab.central.add_robot(ROBOT_A, "Root-07")
        page = await lab.page("square.root")
        await lab.link(page, robot)
        await wait_until(lambda: robot.written_names().count("play_note") == 3, 30)
        assert robot.written_names()[0] == "set_led_animation"  # "this one is mine"
        assert "Root-07" in await page.inner_text("#robot-name")
        await run(page)
        assert await ended(page) == "finished"
        trace = await page.text_content("#trace") or ""
        assert "line 5" in trace and "Root RT1" in trace
        assert_golden_pose(robot.robot, "square.root")
        assert robot.notified > 10  # the robot's answers reached the run through the page
        await wait_state(page, "robotConnected", "no")  # the run ended: stopped, link ended
        assert robot.written_names()[-1] == "stop_and_reset"

    in_chromium(studio.address, scenario)


class CuttableLink:
    """A TCP relay between the browser and the studio, to cut like a network that drops."""

    def __init__(self, target: str) -> None:
        host, port = target.removeprefix("http://").split(":")
        self.target = (host, int(port))
        self.streams: list[asyncio.StreamWriter] = []
        self.server: asyncio.AbstractServer | None = None
        self.flowing = asyncio.Event()
        self.flowing.set()

    async def start(self) -> str:
        self.server = await asyncio.start_server(self._relay, "127.0.0.1", 0)
        port = self.server.sockets[0].getsockname()[1]
        return f"http://127.0.0.1:{port}"

    async def _relay(self, reader: asyncio.StreamReader, writer: asyncio.StreamWriter) -> None:
        upstream_reader, upstream_writer = await asyncio.open_connection(*self.target)
        self.streams += [writer, upstream_writer]

        async def pipe(
            source: asyncio.StreamReader, sink: asyncio.StreamWriter, held: bool
        ) -> None:
            with contextlib.suppress(ConnectionError, OSError):
                while data := await source.read(65536):
                    if held:
                        await self.flowing.wait()
                    sink.write(data)
                    await sink.drain()
            sink.close()

        await asyncio.gather(
            pipe(reader, upstream_writer, False), pipe(upstream_reader, writer, True)
        )

    def cut(self) -> None:
        for stream in self.streams:
            stream.transport.abort()

    def close(self) -> None:
        """The studio gone for good: every connection cut, and no new one taken."""
        assert self.server is not None
        self.server.close()
        self.cut()

    def hold(self) -> None:
        """The studio goes quiet: nothing it says reaches the browser (the socket stays up, and
        what the page says still reaches the studio), until :meth:`release`."""
        self.flowing.clear()

    def release(self) -> None:
        self.flowing.set()


def test_the_websocket_cut_mid_drive_makes_the_page_stop_the_robot(
    studio: RunningStudio,
) -> None:
    (studio.folder / "far.root").write_text(FAR, encoding="utf-8")

    async def scenario(lab: Lab) -> None:
        link = CuttableLink(studio.address)
        robot, page = await driving_far(lab, await link.start())
        await asyncio.sleep(0.5)
        before = len(robot.written)
        link.cut()
        await wait_until(lambda: "stop_and_reset" in robot.written_names(before), 30)
        assert await safe_stops(page) == ["socket"]
        await wait_state(page, "robotConnected", "no")
        moved = robot.robot.world_pose
        await asyncio.sleep(0.5)
        assert robot.robot.world_pose == moved, "the robot stopped"

    in_chromium(studio.address, scenario)


FAR = "when started\n    move 100 cm\n"  # 10 s of driving: long enough to cut in


async def driving_far(lab: Lab, address: str = "") -> tuple[EmulatedRobot, Any]:
    """A robot linked by a page, on its way through ``far.root``."""
    robot = await lab.central.add_robot(ROBOT_A, "Root-07")
    page = await lab.page("far.root", address=address)
    await lab.link(page, robot)
    await run(page)
    await wait_until(lambda: "drive_distance" in robot.written_names(), 60)
    return robot, page


async def wait_until(condition: Callable[[], bool], seconds: float) -> None:
    async def poll() -> None:
        while not condition():
            await asyncio.sleep(0.02)

    await asyncio.wait_for(poll(), seconds)


def test_a_quiet_studio_is_told_at_once_that_the_page_stopped_the_robot_and_why(
    studio: RunningStudio,
) -> None:
    """The studio goes quiet mid-drive: the page stops the robot after its second of silence
    and says so over the socket (still up) at once; the run ends with that reason, "stopped",
    not a lost link long after. (Nothing here is timed: the studio is held quiet until the
    robot is stopped, then the reason is read.)"""
    (studio.folder / "far.root").write_text(FAR, encoding="utf-8")

    async def scenario(lab: Lab) -> None:
        link = CuttableLink(studio.address)
        robot, page = await driving_far(lab, await link.start())
        before = len(robot.written)
        link.hold()
        await wait_until(lambda: "stop_and_reset" in robot.written_names(before), 30)
        assert await safe_stops(page) == ["silence"]
        link.release()
        assert await ended(page, 30000) == "stopped"
        said = "Stopped (this page stopped the robot: it heard nothing from the studio for 1 s)."
        assert await page.inner_text("#status") == said
        assert "The link was lost" not in await page.inner_text("#status")

    in_chromium(studio.address, scenario)


def test_a_robot_that_cant_be_reached_is_said_in_the_childs_words_and_language(
    studio: RunningStudio,
) -> None:
    """A robot the page finds but can't talk to (Chromium: "No Services matching UUID
    6e400001-... found in Device"): the page says it in the child's words, in Dutch."""

    async def scenario(lab: Lab) -> None:
        robot = await lab.central.add_robot(ROBOT_A, "Root-07", uart=False)
        page = await lab.page("square.root", language="nl")
        await answer_chooser(page, robot)
        await page.click("#connect-robot")
        await wait_state(page, "bluetoothProblem", "robot_unreachable")
        status = await page.inner_text("#status")
        assert status.startswith("Ik kan de robot niet bereiken."), status
        assert "UUID" not in status and "Device" not in status

    in_chromium(studio.address, scenario)


def test_a_studio_out_of_reach_is_said_in_the_pages_language(studio: RunningStudio) -> None:
    """The studio gone (stopped, the network down): what the page asks of it fails, and the
    page says so in the child's words and language, not the browser's "Failed to fetch"."""

    async def scenario(lab: Lab) -> None:
        link = CuttableLink(studio.address)
        address = await link.start()
        page = await lab.page("square.root", address=address, language="nl")
        link.close()
        await page.select_option("#world", "arena")  # (the stage of that world is asked for)
        await page.wait_for_function(
            "() => document.getElementById('status').className === 'error'", timeout=30000
        )
        status = await page.inner_text("#status")
        strings = json.loads(STUDIO_STRINGS.read_text(encoding="utf-8"))
        assert status == strings["nl"]["out_of_touch"]
        assert status.startswith("De studio is nu niet te bereiken.")
        assert "fetch" not in status

    in_chromium(studio.address, scenario)


@pytest.mark.parametrize(
    ("language", "one", "two"),
    [("en", "1 mistake", "2 mistakes"), ("nl", "1 fout", "2 fouten"),
     ("es", "1 error", "2 errores"), ("fr", "1 erreur", "2 erreurs"),
     ("de", "1 Fehler", "2 Fehler")],
)  # fmt: skip
def test_counts_take_their_plural_form_in_every_language(
    studio: RunningStudio, language: str, one: str, two: str
) -> None:
    """ "1 mistakes" no more: a count's sentence (a teacher's card's mistakes, Stop every run,
    the loose blocks) has its form for one, by the language's plural rules."""

    async def scenario(lab: Lab) -> None:
        page = await lab.page("square.root", language=language)
        said = await page.evaluate("""() => import('/static/page.js').then(m => [
            m.words('mistakes', {count: 1}), m.words('mistakes', {count: 2}),
            m.words('stopped_all', {count: 1, seconds: '0.10'}),
            m.words('left_count', {count: 1}), m.words('left_count', {count: 2})])""")
        assert said[:2] == [one, two]
        strings = json.loads(STUDIO_STRINGS.read_text(encoding="utf-8"))[language]
        assert said[2] == strings["stopped_all_one"].format(count=1, seconds="0.10")
        assert said[3:] == [strings["left_count_one"].format(count=1),
                            strings["left_count"].format(count=2)]  # fmt: skip

    in_chromium(studio.address, scenario)


def test_a_gatt_disconnect_mid_run_ends_the_run_with_a_clear_message(
    studio: RunningStudio,
) -> None:
    (studio.folder / "far.root").write_text(FAR, encoding="utf-8")

    async def scenario(lab: Lab) -> None:
        robot, page = await driving_far(lab)
        await lab.central.drop_link(robot)
        assert await ended(page, 30000) == "disconnected"
        assert await page.inner_text("#status") == "The link was lost."
        output = await page.inner_text("#output")
        assert "The robot disconnected: the page's Bluetooth link to the robot dropped" in output

    in_chromium(studio.address, scenario)


def test_two_pages_with_two_robots_do_not_cross(studio: RunningStudio) -> None:
    (studio.folder / "turn.root").write_text(
        "when started\n    turn left 90 degrees\n", encoding="utf-8"
    )
    (studio.folder / "ahead.root").write_text("when started\n    move 5 cm\n", encoding="utf-8")

    async def scenario(lab: Lab) -> None:
        first = await lab.central.add_robot(ROBOT_A, "Root-07")
        second = await lab.central.add_robot(ROBOT_B, "Root-08")
        ahead, turn = await lab.page("ahead.root"), await lab.page("turn.root")
        await lab.link(ahead, first)
        await lab.link(turn, second)
        assert first.page is ahead and second.page is turn
        await asyncio.gather(run(ahead), run(turn))
        assert await ended(turn) == "finished" and await ended(ahead) == "finished"
        assert "drive_distance" in first.written_names()
        assert "rotate_angle" not in first.written_names()  # each program went to its robot
        assert "drive_distance" not in second.written_names()
        assert "rotate_angle" in second.written_names()
        moved, turned = first.robot.finish().final_frame, second.robot.finish().final_frame
        assert moved is not None and turned is not None
        start = first.robot.world.robot
        assert round(moved.x_mm - start.x) == 50 or round(moved.y_mm - start.y) == 50
        assert round(abs(turned.heading_deg - moved.heading_deg)) == 90

    in_chromium(studio.address, scenario)


def test_the_https_studio_trusted_by_its_spki_drives_an_emulated_robot(
    class_folder: Path, tmp_path: Path
) -> None:
    certificate = studio_certificate("", tmp_path / "tls")
    studio = RunningStudio(class_folder, tls=certificate).start()
    (class_folder / "hop.root").write_text("when started\n    move 2 cm\n", encoding="utf-8")
    spki = f"--ignore-certificate-errors-spki-list={certificate.spki_sha256}"

    async def scenario(lab: Lab) -> None:
        robot = await lab.central.add_robot(ROBOT_A, "Root-07")
        page = await lab.page("hop.root")
        assert await page.evaluate("() => window.isSecureContext && 'bluetooth' in navigator")
        await lab.link(page, robot)
        await run(page)
        assert await ended(page) == "finished"
        assert "drive_distance" in robot.written_names()
        await wait_state(page, "robotConnected", "no")  # stopped, and the link ended
        before = len(robot.written)
        await run(page)  # the next run links again by itself, without the chooser
        assert await ended(page) == "finished"
        assert "drive_distance" in robot.written_names(before)

    try:
        assert studio.address.startswith("https://")
        in_chromium(studio.address, scenario, flags=(spki,))
    finally:
        studio.stop()


def test_without_web_bluetooth_the_page_says_so_in_its_language(studio: RunningStudio) -> None:
    clock = WallClock()

    async def main() -> None:
        async with async_api.async_playwright() as playwright:
            # no WebBluetooth feature: as Firefox or Safari, navigator.bluetooth is missing
            browser = await playwright.chromium.launch(executable_path=str(CHROMIUM),
                                                       args=CHROMIUM_ARGS)  # fmt: skip
            page = await browser.new_page()
            await page.goto(f"{studio.address}/?open=square.root&language=nl")
            await wait_state(page, "ready", "yes")
            assert (await state(page)).get("bluetooth") == "browser"
            told = await page.inner_text("#robot-help")
            assert "simulator" in told and "Chrome" in told and "Firefox" in told
            assert await page.is_disabled("#connect-robot")
            await browser.close()

    clock.run(main())


def test_stop_and_a_hidden_tab_stop_the_robot(studio: RunningStudio) -> None:
    """Stop: the run stops the robot (Stop and Reset) and ends; a tab hidden too long: the page
    stops the robot itself and the run. (Headless Chromium never hides a tab: the page is told
    it is hidden the way a browser tells it, a ``visibilitychange`` with ``document.hidden``.)"""
    (studio.folder / "far.root").write_text(FAR, encoding="utf-8")

    async def scenario(lab: Lab) -> None:
        robot, page = await driving_far(lab)
        before = len(robot.written)
        await page.click("#stop")
        assert await ended(page, 30000) == "stopped"
        assert "stop_and_reset" in robot.written_names(before)
        assert await safe_stops(page) == ["ended"]  # the run stopped it; the page only made sure
        await run(page)
        await wait_until(lambda: robot.written_names().count("drive_distance") == 2, 60)
        hidden_at = asyncio.get_running_loop().time()
        await page.evaluate("""() => {
            Object.defineProperty(document, "hidden", {value: true, configurable: true});
            document.dispatchEvent(new Event("visibilitychange"));
        }""")
        assert await ended(page, 30000) == "stopped"
        assert (await safe_stops(page))[-1] == "hidden"
        assert asyncio.get_running_loop().time() - hidden_at >= 5.0  # the rule: 5 s hidden
        assert robot.written_names()[-1] == "stop_and_reset"

    in_chromium(studio.address, scenario)


def test_a_page_that_is_not_secure_says_so_and_the_flag_makes_it_secure(
    class_folder: Path,
) -> None:
    """A plain-http studio reached by a LAN name is not a secure context: no Web Bluetooth,
    and the page says the studio needs https (or a browser policy); Chrome's
    ``unsafely-treat-insecure-origin-as-secure`` (the policy's flag) gives it back."""
    # a name for this computer, as a Chromebook would use (given with --allow-host, as a
    # name the studio can't find among its own)
    studio = RunningStudio(class_folder, host="0.0.0.0", allow_hosts=("studio.test",)).start()
    port = studio.address.rsplit(":", 1)[1]
    lan = f"http://studio.test:{port}"
    resolve = "--host-resolver-rules=MAP studio.test 127.0.0.1"
    clock = WallClock()

    async def look(*flags: str) -> tuple[str, str]:
        async with async_api.async_playwright() as playwright:
            browser = await playwright.chromium.launch(
                executable_path=str(CHROMIUM),
                args=[*CHROMIUM_ARGS, *CHROMIUM_FLAGS, resolve, *flags],
            )
            page = await browser.new_page()
            await page.goto(f"{lan}/?open=square.root")
            await wait_state(page, "ready", "yes")
            found = (await state(page)).get("bluetooth", ""), await page.inner_text("#robot-help")
            await browser.close()
            return found

    try:
        missing, told = clock.run(look())
        assert missing == "insecure" and "--https" in told and "simulator" in told
        allowed, _ = clock.run(look(f"--unsafely-treat-insecure-origin-as-secure={lan}"))
        assert allowed == "yes"
    finally:
        studio.stop()


def test_pause_stops_the_pupils_robot_and_step_finishes_the_move_from_where_it_stood(
    studio: RunningStudio,
) -> None:
    """The debugger's buttons, pressed, on the page's own robot: Pause stops it at once (the
    wheels to 0, through the page's link) and the Watch shows where the robot says it is and
    its touch sensor pressed meanwhile;
    Step finishes the move from there and stops at the next line; Resume ends the run with
    the robot 40 cm from its start, not more."""
    (studio.folder / "cut.root").write_text(CUT, encoding="utf-8")

    async def scenario(lab: Lab) -> None:
        robot = await lab.central.add_robot(ROBOT_A, "Root-07")
        page = await lab.page("cut.root")
        await lab.link(page, robot)
        start = robot.robot.world_pose
        await run(page)
        await wait_until(lambda: "drive_distance" in robot.written_names(), 60)
        await wait_until(lambda: _gone_mm(robot, start) > 50, 30)  # on its way
        before = len(robot.written)
        await page.click("#pause")
        await wait_state(page, "paused", "2")
        await wait_until(lambda: "set_wheel_speeds" in robot.written_names(before), 30)
        await wait_until(robot.robot.devices.motors.resting, 30)  # stopped, mid-move
        cut = _gone_mm(robot, start)
        assert 50 < cut < 380, cut
        watched = await page.wait_for_function(
            """() => {
                const lines = document.getElementById('watch-lines').textContent;
                const y = /y (-?[0-9.]+) cm/.exec(lines);
                return y && Number(y[1]) > 5 ? Number(y[1]) : null;
            }""",
            timeout=30000,
        )  # the robot's own word of where it stopped (as it began to brake)
        assert cut - 30 <= await watched.json_value() * 10 <= cut + 1
        robot.brain.stimulate(Stimulus(0.0, "touch", ("front left",), duration=3.0))
        await page.wait_for_function(  # the robot's touch sensor, as it tells it, while paused
            "() => document.getElementById('watch-lines').textContent"
            ".includes('Touched: front left.')",
            timeout=30000,
        )  # fmt: skip
        await page.click("#step")
        await wait_state(page, "paused", "3")
        assert abs(_gone_mm(robot, start) - 400) <= 5  # the move finished from where it stood
        await page.click("#resume")
        assert await ended(page) == "finished"
        assert "there" in (await page.text_content("#output") or "")
        assert abs(_gone_mm(robot, start) - 400) <= 5

    in_chromium(studio.address, scenario)


CUT = 'when started\n    move 40 cm\n    print "there"\n'


def _gone_mm(robot: EmulatedRobot, start: Any) -> float:
    """How far the robot is from where it started, in its world."""
    now = robot.robot.world_pose
    return float(((now[0] - start[0]) ** 2 + (now[1] - start[1]) ** 2) ** 0.5)
