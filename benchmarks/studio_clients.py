"""A class at once: browsers running gallery programs live in the studio in real time, while
others edit (a conversion every 0.3 s each), one opens a 0.9 MB program, and one a 2,000-line one.

Run: ``.venv/bin/python benchmarks/studio_clients.py [--clients 30] [--seconds 20]`` (runs only),
or ``... --clients 10 --editors 30`` (the class editing: aim conversion p95 <= 300 ms, every live
stream >= 20 frames a second with no gap over 250 ms; opening a 2,000-line program: blocks in
<= 2 s; a 0.9 MB program stalls nobody else).

Starts ``rootlang studio`` (a separate process, as a teacher would) on a free port on 127.0.0.1
over a copy of the gallery, then opens one WebSocket per client and starts every run at once at
real-time speed (each in its own worker process). Every client stops its run with the nose
button after ``--seconds`` (or when it ends by itself). For every frame received it measures:

- **lag**: how far the stream is behind real time — (wall time since the stream's first frame)
  minus (run time since that frame), clamped at 0;
- **transit**: from the worker sending the frame to the client receiving it.

Prints the p50/p95/max of both over all frames, the frames per second per stream, and the
server's CPU time. Aim (issue: a class on a LAN): frame lag p95 <= 100 ms on a 2-core machine.

With ``--editors N``, N more pupils edit at once: each changes its program a little every
0.3 s and asks for blocks (``/api/blocks``), then for the text of those blocks (``/api/text``),
as the page does; every conversion's time is measured. A second into the run one more pupil
opens a 0.9 MB program (it is answered as text only, or stopped at its limit), and after the
run a 2,000-line program is opened alone (its blocks and its text, the time the page waits).
Each stream's largest gap between two frames is measured too, and its frames a second while it
streams (from its first frame to its last), apart from the wait for its first frame (the run's
start: its worker process forked, its program loaded, its world made), printed on its own.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import shutil
import statistics
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

import aiohttp
from studio_process import served_studio  # (this folder's: the script's own is on sys.path)

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
    gap: float = 0.0  # the longest wait between two frames
    streaming: float = 0.0  # from the first frame to the last
    first_after: float = 0.0  # from asking for the run to its first frame
    started_after: float = 0.0  # ... to the worker saying the run has started


EDIT_EVERY_S = 0.3


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
        last = 0.0
        stopped = False
        began = time.monotonic()
        async for message in socket:
            data = json.loads(message.data)
            now = time.monotonic()
            if data["type"] == "frame":
                stream.frames += 1
                stream.transits.append(max(0.0, time.time() - data["sent_at"]))
                if first is not None and not stopped:
                    stream.gap = max(stream.gap, now - last)
                    stream.streaming = now - first[0]
                last = now
                if first is None:
                    first = (now, data["t"])
                    stream.first_after = now - began
                stream.lags.append(max(0.0, (now - first[0]) - (data["t"] - first[1])))
                if not stopped and now - began > seconds:
                    stopped = True
                    await socket.send_json({"type": "stop"})
            elif data["type"] == "started" and not stream.started_after:
                stream.started_after = now - began
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


async def editor(address: str, program: str, seconds: float, start: asyncio.Event) -> list[float]:
    """A pupil editing: every 0.3 s a change, its blocks, and the text of those blocks."""
    text = (GALLERY / f"{program}.root").read_text(encoding="utf-8")
    times: list[float] = []
    async with aiohttp.ClientSession(address) as session:
        await start.wait()
        began = time.monotonic()
        edit = 0
        while time.monotonic() - began < seconds:
            edit += 1
            changed = text + f'\nwhen message "e{edit}" received\n    move {edit} cm\n'
            asked = time.monotonic()
            reply = await session.post("/api/blocks", json={"text": changed, "name": "e.root"})
            workspace = (await reply.json())["workspace"]
            times.append(time.monotonic() - asked)
            asked = time.monotonic()
            reply = await session.post("/api/text", json={"workspace": workspace, "name": "e.root"})
            assert reply.status == 200, await reply.text()
            await reply.read()
            times.append(time.monotonic() - asked)
            await asyncio.sleep(max(0.0, EDIT_EVERY_S - (time.monotonic() - asked)))
    return times


def long_program(lines: int) -> str:
    body = ["    move 10 cm  # forward", "    turn right 90 degrees", '    say "hi"',
            "    set x to x + 1", "    play note C4 for 0.1 seconds"]  # fmt: skip
    return "when started\n" + "\n".join((body * (lines // len(body) + 1))[: lines - 1]) + "\n"


async def open_huge(address: str, start: asyncio.Event) -> tuple[int, float, str]:
    """One pupil opens a 0.9 MB program a second into the class's work."""
    text = long_program(40_000)[:900_000]
    text = text[: text.rindex("\n") + 1]
    async with aiohttp.ClientSession(address) as session:
        await start.wait()
        await asyncio.sleep(1.0)
        asked = time.monotonic()
        reply = await session.post("/api/blocks", json={"text": text, "name": "huge.root"})
        data = await reply.json()
        answer = (data.get("text_only") or (data.get("errors") or [{}])[0]).get("code", "blocks")
        return reply.status, time.monotonic() - asked, answer


async def open_long(address: str, lines: int) -> tuple[float, float, int, str]:
    """Open a program alone: its blocks, then the text of those blocks (as the page does when
    the first block moves); seconds each, and the workspace's size."""
    text = long_program(lines)
    async with aiohttp.ClientSession(address) as session:
        asked = time.monotonic()
        reply = await session.post("/api/blocks", json={"text": text, "name": "long.root"})
        body = await reply.read()
        to_blocks = time.monotonic() - asked
        sys.setrecursionlimit(100_000)  # Blockly nests a script's blocks one in the next
        workspace = json.loads(body)["workspace"]
        assert workspace is not None, body[:300]
        asked = time.monotonic()
        reply = await session.post(
            "/api/text", data=json.dumps({"workspace": workspace, "name": "long.root"}),
            headers={"Content-Type": "application/json"},
        )  # fmt: skip
        answer = await reply.json()
        back = time.monotonic() - asked
        if reply.status != 200:
            return to_blocks, back, len(body), answer["errors"][0]["code"]
        return to_blocks, back, len(body), "same text" if answer["text"] == text else "OTHER TEXT"


async def measure(
    address: str, clients: int, seconds: float, editors: int
) -> tuple[list[Stream], list[float], tuple[int, float, str] | None]:
    start = asyncio.Event()
    tasks = [
        asyncio.create_task(client(address, PROGRAMS[n % len(PROGRAMS)], seconds, start))
        for n in range(clients)
    ]
    editing = [
        asyncio.create_task(editor(address, PROGRAMS[n % len(PROGRAMS)], seconds, start))
        for n in range(editors)
    ]
    huge = asyncio.create_task(open_huge(address, start)) if editors else None
    await asyncio.sleep(1.0)  # every socket open first, then every run starts at once
    start.set()
    streams = await asyncio.gather(*tasks)
    times = [t for each in await asyncio.gather(*editing) for t in each]
    return streams, times, (await huge) if huge is not None else None


def cpu_seconds(pid: int) -> float:
    """User + system CPU time of a process and its finished children (Linux /proc)."""
    try:
        fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    except OSError:
        return float("nan")
    ticks = sum(int(value) for value in fields[11:15])
    return ticks / os.sysconf("SC_CLK_TCK")


def tree_cpu_seconds(pid: int) -> float:
    """:func:`cpu_seconds` of a process and of every process below it still running (the fork
    server's, with the children it has started and seen end)."""
    below: dict[int, list[int]] = {}
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            parent = int(stat.read_text().rsplit(")", 1)[1].split()[1])
        except (OSError, ValueError, IndexError):
            continue
        below.setdefault(parent, []).append(int(stat.parent.name))
    total, waiting = 0.0, [pid]
    while waiting:
        one = waiting.pop()
        used = cpu_seconds(one)
        total += 0.0 if used != used else used  # (nan: it ended meanwhile)
        waiting.extend(below.get(one, []))
    return total


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--clients", type=int, default=30)
    parser.add_argument("--seconds", type=float, default=20.0)
    parser.add_argument("--editors", type=int, default=0, help="pupils editing meanwhile")
    parser.add_argument("--long", type=int, default=2_000, help="lines of the long program")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch) / "class"
        shutil.copytree(GALLERY, folder)
        with served_studio(folder) as (address, server):
            cpu_before, wall_before = cpu_seconds(server.pid), time.monotonic()
            streams, times, huge = asyncio.run(
                measure(address, args.clients, args.seconds, args.editors)
            )
            cpu = cpu_seconds(server.pid) - cpu_before
            wall = time.monotonic() - wall_before
            opened = asyncio.run(open_long(address, args.long)) if args.editors else None
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
    live = [stream for stream in streams if stream.streaming > 1.0]
    if live:
        # a stream's frames a second while it streams (the worker's beat, and the way to the
        # page); then counting the wait for its first frame too (the run's start)
        beats = [(stream.frames - 1) / stream.streaming for stream in live]
        print(f"slowest stream: {min(beats):.1f} frames a second while streaming (median "
              f"{statistics.median(beats):.1f}); largest gap between two frames: "
              f"{max(stream.gap for stream in live) * 1000:.0f} ms "
              f"(aim: >= 20 a second, no gap over 250 ms)")  # fmt: skip
        slowest = min(stream.frames / max(stream.seconds, 1e-9) for stream in live)
        starts = [stream.started_after for stream in live]
        waits = [stream.first_after for stream in live]
        print(f"runs started after: p50 {percentile(starts, 0.5):.2f} s, max {max(starts):.2f} s; "
              f"first frame after: p50 {percentile(waits, 0.5):.2f} s, max {max(waits):.2f} s; "
              f"counting that wait: slowest {slowest:.1f} frames a second")  # fmt: skip
    if times:
        print(f"conversions by {args.editors} pupils editing: {len(times)}, "
              f"p50 {percentile(times, 0.5) * 1000:.0f} ms, "
              f"p95 {percentile(times, 0.95) * 1000:.0f} ms, max {max(times) * 1000:.0f} ms "
              f"(aim: p95 <= 300 ms)")  # fmt: skip
    if huge is not None:
        status, seconds, answer = huge
        print(f"a 0.9 MB program opened meanwhile: HTTP {status} ({answer}) after {seconds:.1f} s")
    if opened is not None:
        to_blocks, to_text, size, answer = opened
        print(f"opening a {args.long:,}-line program: blocks in {to_blocks:.2f} s "
              f"({size / 1e6:.1f} MB of workspace), their text in {to_text:.2f} s ({answer}) "
              f"(aim: blocks in <= 2 s)")  # fmt: skip
    print(f"load average at the end: {os.getloadavg()[0]:.1f} (other work on the machine)")


if __name__ == "__main__":
    main()
