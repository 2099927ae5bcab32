"""How fast the studio answers Pause and Step: from the page's message to the "paused" reply.

Run: ``.venv/bin/python benchmarks/studio_debug.py [--rounds 20] [--others 10] [--robot]``.

Starts ``rootlang studio`` (a separate process, as a teacher would) on a free port on 127.0.0.1
over a copy of the gallery. ``--others`` pages run gallery programs at real time meanwhile (a
class). One more page runs a program of two endless scripts (one drawing circles) at real time
and, ``--rounds`` times, presses Pause (while the robot draws), then Step three times, then
Resume; each answer's time is measured,
from sending the message to receiving ``paused`` (the worker paused, told where each script
is and every value, in the page's words); a Step's time less the run's own time to its next
statement (the simulated seconds between the two pauses, at speed 1). Prints p50/p95/max of
each (aim: p95 <= 100 ms). ``--robot``: the measured page runs on bumble's virtual robot over
Bluetooth (``--transport virtual``, needs ``rootlang[virtual]``), where a pause also stops the
robot's wheels and holds the run's time while the link goes on.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import shutil
import tempfile
import time
from pathlib import Path
from typing import Any

import aiohttp
from studio_process import served_studio  # (this folder's: the script's own is on sys.path)

GALLERY = Path(__file__).resolve().parents[1] / "programs"
OTHERS = ("square", "spiral", "star", "dance", "polygons", "tree", "bump_and_turn", "go_to")
STEPS = 3
CIRCLES = """\
when started
    marker down
    forever
        move 2 cm
        turn right 10 degrees

when started
    forever
        wait 0.3 seconds
        set beat to timer
"""  # two scripts that go on drawing until stopped, their statements short (steps are quick)


def percentile(values: list[float], fraction: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(fraction * len(ordered)))]


async def _paused(socket: aiohttp.ClientWebSocketResponse[bool]) -> dict[str, Any]:
    async for message in socket:
        data: dict[str, Any] = json.loads(message.data)
        if data["type"] == "paused":
            return data
        if data["type"] in ("ended", "error"):
            raise RuntimeError(f"the run ended before it paused: {data}")
    raise RuntimeError("the socket closed")


async def other_page(address: str, name: str, stop: asyncio.Event) -> None:
    """A pupil's run at real time, stopped when the measuring is done."""
    text = (GALLERY / f"{name}.root").read_text(encoding="utf-8")
    async with (
        aiohttp.ClientSession() as session,
        session.ws_connect(f"{address}/ws", origin=address) as socket,
    ):
        await socket.send_json({"type": "run", "name": f"{name}.root", "text": text,
                                "speed": 1})  # fmt: skip
        await stop.wait()
        await socket.send_json({"type": "stop"})


async def measure(
    address: str, rounds: int, others: int, robot: bool
) -> tuple[list[float], list[float]]:
    stop = asyncio.Event()
    pages = [
        asyncio.create_task(other_page(address, OTHERS[n % len(OTHERS)], stop))
        for n in range(others)
    ]
    pauses: list[float] = []
    steps: list[float] = []
    async with (
        aiohttp.ClientSession() as session,
        session.ws_connect(f"{address}/ws", origin=address) as socket,
    ):
        on = {"robot": ""} if robot else {}  # (a robot's first frame comes once it is linked)
        await socket.send_json({"type": "run", "name": "circles.root", "text": CIRCLES,
                                "speed": 1, **on})  # fmt: skip
        async for message in socket:  # its first values: the run has started
            if json.loads(message.data)["type"] == "watch":
                break
        for _ in range(rounds):
            await asyncio.sleep(0.5)  # the robot draws meanwhile
            sent = time.perf_counter()
            await socket.send_json({"type": "debug", "action": "pause"})
            paused = await _paused(socket)
            pauses.append(time.perf_counter() - sent)
            for _ in range(STEPS):
                sent = time.perf_counter()
                await socket.send_json({"type": "debug", "action": "step"})
                stepped = await _paused(socket)
                # the run's own time to its next statement (at speed 1) is not the answer's
                ran = stepped["watch"]["time_s"] - paused["watch"]["time_s"]
                steps.append(time.perf_counter() - sent - ran)
                paused = stepped
            await socket.send_json({"type": "debug", "action": "resume"})
        await socket.send_json({"type": "stop"})
    stop.set()
    await asyncio.gather(*pages, return_exceptions=True)
    return pauses, steps


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=20)
    parser.add_argument("--others", type=int, default=10, help="pages running meanwhile")
    parser.add_argument("--robot", action="store_true", help="on bumble's virtual robot")
    args = parser.parse_args()
    options = ("--transport", "virtual") if args.robot else ()
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch) / "class"
        shutil.copytree(GALLERY, folder)
        with served_studio(folder, *options) as (address, _):
            pauses, steps = asyncio.run(measure(address, args.rounds, args.others, args.robot))
    on = "on the virtual Bluetooth robot" if args.robot else "simulated"
    print(f"{os.cpu_count()} cores, {on}, {args.others} other runs at real time meanwhile")
    for what, times in (("Pause", pauses), ("Step", steps)):
        print(f"{what} -> paused: p50 {percentile(times, 0.5) * 1000:.0f} ms, "
              f"p95 {percentile(times, 0.95) * 1000:.0f} ms, max {max(times) * 1000:.0f} ms "
              f"({len(times)} times; aim: p95 <= 100 ms)")  # fmt: skip


if __name__ == "__main__":
    main()
