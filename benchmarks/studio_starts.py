"""30 pupils press Run at once: does the studio's server keep serving while their runs start?

Run: ``.venv/bin/python benchmarks/studio_starts.py [--pupils 30]``.

Serves a class (``rootlang studio --class``) in this process, with a probe on the server's
event loop that wakes every 10 ms and notes how late it woke (the loop's lag: how long
something held the loop). Each pupil (their own cookies) opens the run socket, presses Run (a
drawing at real time) and at once sends their program to be turned into blocks, as the page
does. It prints the loop's lag while the runs start (aim: no wait over 100 ms that is the
server's own; on a computer busy with other work, the operating system's waits count too),
each pupil's first change answered, and each run's start as its page is told.
"""

from __future__ import annotations

import argparse
import asyncio
import contextlib
import os
import statistics
import tempfile
import threading
import time
from pathlib import Path

import aiohttp

from rootlang.studio.classroom import Classroom
from rootlang.studio.folder import ClassFolder
from rootlang.studio.server import serve

LOAD_BEFORE = os.getloadavg()[0]
GALLERY = Path(__file__).resolve().parents[1] / "programs"
DRAWING = "when started\n    repeat 600\n        move 1 cm\n        turn right 3 degrees\n"


class Studio:
    """The studio served in a thread of this process, with the probe on its loop."""

    def __init__(self, folder: Path) -> None:
        self.address = ""
        self.lags: list[tuple[float, float]] = []  # when, how late the probe woke
        self._ready = threading.Event()
        self._loop = asyncio.new_event_loop()
        self._task: asyncio.Task[None] | None = None
        classroom = Classroom(ClassFolder(folder))
        threading.Thread(target=self._serve, args=(folder, classroom), daemon=True).start()
        assert self._ready.wait(60), "the studio did not start"

    def _serve(self, folder: Path, classroom: Classroom) -> None:
        def ready(address: str) -> None:
            self.address = address.rstrip("/")
            self._ready.set()

        async def probe() -> None:
            while True:
                before = time.monotonic()
                await asyncio.sleep(0.01)
                self.lags.append((before, time.monotonic() - before - 0.01))

        self._loop.create_task(probe())
        self._task = self._loop.create_task(
            serve(ClassFolder(folder), "127.0.0.1", 0, ready, classroom=classroom)
        )
        with contextlib.suppress(asyncio.CancelledError):
            self._loop.run_until_complete(self._task)

    def stop(self) -> None:
        if self._task is not None:
            self._loop.call_soon_threadsafe(self._task.cancel)


async def pupil(address: str, n: int, text: str) -> tuple[float, float]:
    """Run, then the first change: how long the change took, and the run to start (infinite:
    its socket dropped first, as on a computer so busy that a heartbeat went unanswered)."""
    try:
        return await _pupil(address, n, text)
    except aiohttp.ClientError:
        return float("inf"), float("inf")


async def _pupil(address: str, n: int, text: str) -> tuple[float, float]:
    jar = aiohttp.CookieJar(unsafe=True)
    async with aiohttp.ClientSession(address, cookie_jar=jar, headers={"Origin": address}) as s:
        await s.post("/api/pupil", json={"name": f"pupil {n:02d}"})
        async with s.ws_connect("/ws") as socket:
            pressed = time.monotonic()
            await socket.send_json({"type": "run", "name": "draw.root", "text": DRAWING})
            await s.post("/api/blocks", json={"text": text, "name": "mine.root"})
            changed = time.monotonic() - pressed
            async for message in socket:
                if '"started"' in message.data[:40]:
                    return changed, time.monotonic() - pressed
    return changed, float("inf")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pupils", type=int, default=30)
    args = parser.parse_args()
    text = (GALLERY / "spiral.root").read_text("utf-8")
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch) / "class"
        folder.mkdir()
        studio = Studio(folder)
        time.sleep(3)  # the fork server and the conversion workers start with a class
        began = time.monotonic()
        results = asyncio.run(_all(studio.address, args.pupils, text))
        ended = time.monotonic()
        studio.stop()
    lags = sorted(lag for when, lag in studio.lags if began <= when <= ended)
    changes = sorted(change for change, _ in results)
    starts = sorted(start for _, start in results)

    def ms(value: float) -> str:
        return f"{value * 1000:.0f} ms"

    print(f"pupils: {args.pupils}, each pressing Run and sending a change at once; "
          f"{os.cpu_count()} cores, load average before {LOAD_BEFORE:.1f}")  # fmt: skip
    print(f"the server's loop, while the runs started ({ended - began:.1f} s): woke late by "
          f"p50 {ms(statistics.median(lags))}, max {ms(lags[-1])}; "
          f"{sum(1 for lag in lags if lag > 0.1)} waits over 100 ms, "
          f"{sum(lags):.1f} s late in all")  # fmt: skip
    print(f"each pupil's first change answered: p50 {ms(statistics.median(changes))}, "
          f"max {ms(changes[-1])}")  # fmt: skip
    print(f"each run started (its page told): p50 {ms(statistics.median(starts))}, "
          f"max {ms(starts[-1])}")  # fmt: skip


async def _all(address: str, count: int, text: str) -> list[tuple[float, float]]:
    return await asyncio.gather(*(pupil(address, n, text) for n in range(count)))


if __name__ == "__main__":
    main()
