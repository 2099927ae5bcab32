"""A class at once: 30 browsers each running a gallery program live in the studio, in real time.

Run: ``.venv/bin/python benchmarks/studio_clients.py [--clients 30] [--seconds 20]``.

Starts ``rootlang studio`` (a separate process, as a teacher would) on a free port on 127.0.0.1
over a copy of the gallery, then opens one WebSocket per client and starts every run at once at
real-time speed (each in its own worker process). Every client stops its run with the nose
button after ``--seconds`` (or when it ends by itself). For every frame received it measures:

- **lag**: how far the stream is behind real time — (wall time since the stream's first frame)
  minus (run time since that frame), clamped at 0;
- **transit**: from the worker sending the frame to the client receiving it.

Prints the p50/p95/max of both over all frames, the frames per second per stream, and the
server's CPU time. Aim (issue: a class on a LAN): frame lag p95 <= 100 ms on a 2-core machine.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

import aiohttp

GALLERY = Path(__file__).resolve().parents[1] / "programs"
# Gallery programs that move and draw, and end by themselves or run on (stopped after --seconds)
PROGRAMS = ("square", "flower", "spiral", "star", "dance", "polygons", "tree", "countdown",
            "bump_and_turn", "line_follower", "color_sorter", "go_to")  # fmt: skip


@dataclass
class Stream:
    program: str
    lags: list[float] = field(default_factory=list)
    transits: list[float] = field(default_factory=list)
    frames: int = 0
    seconds: float = 0.0
    end: str = ""


async def client(address: str, program: str, seconds: float, start: asyncio.Event) -> Stream:
    stream = Stream(program)
    text = (GALLERY / f"{program}.root").read_text(encoding="utf-8")
    async with (
        aiohttp.ClientSession() as session,
        session.ws_connect(f"{address}/ws", origin=address) as socket,
    ):
        await start.wait()
        await socket.send_json({"type": "run", "name": f"{program}.root", "text": text, "speed": 1})
        first: tuple[float, float] | None = None
        stopped = False
        began = time.monotonic()
        async for message in socket:
            data = json.loads(message.data)
            now = time.monotonic()
            if data["type"] == "frame":
                stream.frames += 1
                stream.transits.append(max(0.0, time.time() - data["sent_at"]))
                if first is None:
                    first = (now, data["t"])
                stream.lags.append(max(0.0, (now - first[0]) - (data["t"] - first[1])))
                if not stopped and now - began > seconds:
                    stopped = True
                    await socket.send_json({"type": "stop"})
            elif data["type"] == "ended":
                stream.end = data["end"]
                break
            elif data["type"] == "error":
                stream.end = "error: " + data["message"]
                break
        stream.seconds = time.monotonic() - began
    return stream


def percentile(values: list[float], fraction: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, round(fraction * (len(ordered) - 1)))] if ordered else 0.0


async def measure(address: str, clients: int, seconds: float) -> list[Stream]:
    start = asyncio.Event()
    tasks = [
        asyncio.create_task(client(address, PROGRAMS[n % len(PROGRAMS)], seconds, start))
        for n in range(clients)
    ]
    await asyncio.sleep(1.0)  # every socket open first, then every run starts at once
    start.set()
    return await asyncio.gather(*tasks)


def cpu_seconds(pid: int) -> float:
    """User + system CPU time of a process and its finished children (Linux /proc)."""
    try:
        fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    except OSError:
        return float("nan")
    ticks = sum(int(value) for value in fields[11:15])
    return ticks / os.sysconf("SC_CLK_TCK")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--clients", type=int, default=30)
    parser.add_argument("--seconds", type=float, default=20.0)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch) / "class"
        shutil.copytree(GALLERY, folder)
        server = subprocess.Popen(
            [sys.executable, "-m", "rootlang", "studio", str(folder), "--port", "0",
             "--no-browser"],
            stdout=subprocess.PIPE, text=True,
        )  # fmt: skip
        try:
            assert server.stdout is not None
            found = re.search(r"http://[\d.]+:\d+", server.stdout.readline())
            assert found, "the studio did not say where it serves"
            address = found.group(0)
            cpu_before, wall_before = cpu_seconds(server.pid), time.monotonic()
            streams = asyncio.run(measure(address, args.clients, args.seconds))
            cpu = cpu_seconds(server.pid) - cpu_before
            wall = time.monotonic() - wall_before
        finally:
            server.terminate()
            server.wait(10)
    lags = [lag for stream in streams for lag in stream.lags]
    transits = [transit for stream in streams for transit in stream.transits]
    rates = [stream.frames / stream.seconds for stream in streams if stream.seconds]
    ends: dict[str, int] = {}
    for stream in streams:
        ends[stream.end] = ends.get(stream.end, 0) + 1
    print(f"clients: {len(streams)} at real time, {os.cpu_count()} cores, {wall:.1f} s wall")
    print(f"runs ended: {', '.join(f'{end} {count}' for end, count in sorted(ends.items()))}")
    print(f"frames: {len(lags)}, {statistics.median(rates):.1f} a second per stream (median)")
    print(f"frame lag behind real time: p50 {percentile(lags, 0.5) * 1000:.0f} ms, "
          f"p95 {percentile(lags, 0.95) * 1000:.0f} ms, max {max(lags) * 1000:.0f} ms "
          f"(aim: p95 <= 100 ms)")  # fmt: skip
    print(f"frame transit worker -> client: p50 {percentile(transits, 0.5) * 1000:.0f} ms, "
          f"p95 {percentile(transits, 0.95) * 1000:.0f} ms")  # fmt: skip
    print(f"server process CPU: {cpu:.1f} s ({cpu / wall * 100:.0f}% of one core)")


if __name__ == "__main__":
    main()
