"""The pupil's page as its robot's link: packet round trips and how fast the page stops a robot.

Run: ``.venv/bin/python benchmarks/web_bluetooth_link.py [--repeats 3]`` (needs
/usr/bin/chromium and the ``test`` extra's Playwright).

Starts ``rootlang studio`` as a teacher would (a process of its own, 127.0.0.1, a free port),
then headless Chromium with Web Bluetooth whose adapter is Chromium's DevTools emulation,
answered by the simulator's virtual robot (:mod:`rootlang.testing.web_bluetooth`). A page
links the robot through its real ``navigator.bluetooth`` and runs programs on it. Measured:

- **relay round trip**: the runtime sends a packet → worker → studio → WebSocket → page →
  robot's RX (a write with response) → the page says so → studio → worker (the run's own
  figures, ``link`` in its outcome); a program of 200 light changes, nothing but packets;
- **robot write** at the page: ``writeValueWithResponse`` alone (here: Chromium's emulation,
  answered over DevTools by Python); **page ↔ studio** = relay − robot write (medians);
- **stop on a lost studio**: a robot driving; the studio process is frozen (SIGSTOP: no
  frames, no close) → the page's silence watchdog writes Stop and Reset; time until it reaches
  the robot (bound: 1 s + one 250 ms check);
- **stop on a dropped WebSocket**: the studio process killed (SIGKILL: its sockets closed by
  the system) → the page writes Stop and Reset; time until it reaches the robot.

On real hardware add the BLE connection interval (7.5–50 ms a write) to the robot write.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import re
import signal
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

from playwright.async_api import async_playwright

from rootlang.runtime.clock import WallClock
from rootlang.testing.web_bluetooth import CHROMIUM_FLAGS, EmulatedCentral, answer_chooser

CHROMIUM = "/usr/bin/chromium"
ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", *CHROMIUM_FLAGS]
LIGHTS = "when started\n    repeat 100\n        light green\n        light red\n"
DRIVE = "when started\n    move 100 cm\n"


def start_studio(folder: Path) -> tuple[subprocess.Popen[str], str]:
    server = subprocess.Popen(
        [sys.executable, "-m", "rootlang", "studio", str(folder), "--port", "0", "--no-browser"],
        stdout=subprocess.PIPE, text=True,
    )  # fmt: skip
    assert server.stdout is not None
    found = re.search(r"http://[\d.]+:\d+", server.stdout.readline())
    assert found, "the studio did not say where it serves"
    return server, found.group(0)


async def wait_state(page: Any, key: str, value: str, timeout_ms: int = 30000) -> None:
    await page.wait_for_function(
        "([key, value]) => document.getElementById('state').dataset[key] === value",
        arg=[key, value], timeout=timeout_ms,
    )  # fmt: skip


async def linked_page(
    browser: Any, central: EmulatedCentral, address: str, name: str, on_frame: Any = None
) -> Any:
    robot = await central.add_robot(f"0A:0B:0C:0D:{len(central.robots):02X}:07", "Root-07")
    page = await browser.new_page()
    if on_frame is not None:
        page.on("websocket", lambda socket: socket.on("framereceived", on_frame))
    await page.goto(f"{address}/?open={name}")
    await wait_state(page, "ready", "yes")
    await answer_chooser(page, robot)
    await page.click("#connect-robot")
    await wait_state(page, "robotLinked", "Root-07")
    page.robot = robot
    return page


async def relay_figures(browser: Any, central: EmulatedCentral, address: str) -> dict[str, Any]:
    outcome: asyncio.Future[dict[str, Any]] = asyncio.get_running_loop().create_future()

    def frame(payload: str | bytes) -> None:
        data = json.loads(payload)
        if data.get("type") == "ended" and not outcome.done():
            outcome.set_result(data)

    page = await linked_page(browser, central, address, "lights.root", frame)
    await page.click("#run")
    ended = await asyncio.wait_for(outcome, 120)
    writes: list[float] = await page.evaluate(
        "() => import('/static/robot_link.js').then(m => m.currentLink().writeTimes)"
    )
    await page.close()
    return {"link": ended.get("link", {}), "end": ended["end"], "writes": writes}


async def stop_after(
    browser: Any, central: EmulatedCentral, address: str, server: subprocess.Popen[str],
    how: signal.Signals,
) -> float:  # fmt: skip
    """Seconds from the studio frozen or killed (mid-drive) to Stop and Reset at the robot."""
    page = await linked_page(browser, central, address, "drive.root")
    robot = page.robot
    await page.click("#run")
    while "drive_distance" not in robot.written_names():
        await asyncio.sleep(0.01)
    await asyncio.sleep(0.3)
    before = len(robot.written)
    started = time.monotonic()
    os.kill(server.pid, how)
    while "stop_and_reset" not in robot.written_names(before):
        await asyncio.sleep(0.005)
        if time.monotonic() - started > 10:
            raise AssertionError("the robot was not stopped within 10 s")
    took = time.monotonic() - started
    if how == signal.SIGSTOP:
        os.kill(server.pid, signal.SIGCONT)
    await page.close()
    return took


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    clock = WallClock()
    relays: list[dict[str, Any]] = []
    silences: list[float] = []
    drops: list[float] = []

    async def measure() -> None:
        async with async_playwright() as playwright:
            browser = await playwright.chromium.launch(executable_path=CHROMIUM, args=ARGS)
            with tempfile.TemporaryDirectory() as scratch:
                folder = Path(scratch)
                (folder / "lights.root").write_text(LIGHTS, encoding="utf-8")
                (folder / "drive.root").write_text(DRIVE, encoding="utf-8")
                for _ in range(args.repeats):
                    for how, found in ((None, relays), (signal.SIGSTOP, silences),
                                       (signal.SIGKILL, drops)):  # fmt: skip
                        server, address = start_studio(folder)
                        # (Chromium ends the emulation when the page that used it closes)
                        central = await EmulatedCentral.start(browser, clock)
                        try:
                            if how is None:
                                found.append(await relay_figures(browser, central, address))
                            else:
                                found.append(await stop_after(browser, central, address,
                                                              server, how))  # fmt: skip
                        finally:
                            if server.poll() is None:
                                os.kill(server.pid, signal.SIGCONT)
                                server.terminate()
                            server.wait(10)
                            await central.close()
            await browser.close()

    clock.run(measure())
    medians = [r["link"]["median_ms"] for r in relays]
    p95s = [r["link"]["p95_ms"] for r in relays]
    writes = [statistics.median(r["writes"]) for r in relays]
    print(
        f"{os.cpu_count()} cores, {args.repeats} repeats; runs ended: "
        f"{sorted({r['end'] for r in relays})}; {relays[0]['link']['packets']} packets a run"
    )
    print(
        f"relay round trip (runtime -> page -> robot -> runtime): median "
        f"{min(medians):.1f}-{max(medians):.1f} ms, p95 {min(p95s):.1f}-{max(p95s):.1f} ms"
    )
    print(
        f"robot write at the page (emulated adapter): median {min(writes):.1f}-{max(writes):.1f} ms"
    )
    between = [m - w for m, w in zip(medians, writes, strict=True)]
    print(f"page <-> studio (relay - write): median {min(between):.1f}-{max(between):.1f} ms")
    print(
        f"studio frozen mid-drive -> Stop and Reset at the robot: "
        f"{min(silences):.2f}-{max(silences):.2f} s (bound 1.25 s)"
    )
    print(
        f"studio killed mid-drive -> Stop and Reset at the robot: "
        f"{min(drops) * 1000:.0f}-{max(drops) * 1000:.0f} ms"
    )


if __name__ == "__main__":
    main()
