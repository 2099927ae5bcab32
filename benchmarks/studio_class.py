"""A class with its teacher: 30 pupils typing and running at once, the teacher's page watching.

Run: ``.venv/bin/python benchmarks/studio_class.py [--pupils 30] [--seconds 20]``.

Starts ``rootlang studio --class`` (a separate process, as a teacher would) on a free port on
127.0.0.1 over a folder with one task (``square``), and reads the teacher's code it prints. Then
each pupil (their own cookies, as their own browser) types their name, opens the class socket,
starts a run of a gallery program at real time (each in its own worker process) and, every
``--edit-every`` seconds, changes their program the way the page does (``/api/blocks``, the
text→blocks sync, with a numbered comment). The teacher's page is one more client on
``/ws/teacher``. It measures:

- **teacher's page update**: from a pupil's change being sent to the teacher's page receiving
  it (every change of every pupil; aim: within 1 s);
- **Stop every run**: after ``--seconds``, the teacher's Stop; from pressing it to each pupil's
  page getting its run's end (aim: every run within 1 s), and the time the studio reports;
- **Check everyone**: the teacher checks the task for the whole class (each pupil's saved
  square.root, half of them right), the golden runner's child processes, one per core;
- the server's CPU time.
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
from studio_clients import cpu_seconds  # (this folder's: the script's own is on sys.path)

LOAD_BEFORE = os.getloadavg()[0]
GALLERY = Path(__file__).resolve().parents[1] / "programs"
PROGRAMS = ("spiral", "flower", "dance", "polygons", "line_follower", "color_sorter")
LONG = "when started\n    repeat 600\n        move 1 cm\n        turn right 3 degrees\n"


@dataclass
class Pupil:
    name: str
    session: aiohttp.ClientSession
    sent: dict[int, float] = field(default_factory=dict)  # edit number -> when sent
    answered: list[float] = field(default_factory=list)  # each change's request, answered
    answered_at: dict[int, float] = field(default_factory=dict)  # edit number -> when
    ended_at: float = 0.0
    started: asyncio.Event = field(default_factory=asyncio.Event)
    end: str = ""


def make_folder(folder: Path) -> None:
    task = folder / "_tasks" / "square"
    task.mkdir(parents=True)
    shutil.copy(GALLERY / "square.golden", task / "square.golden")
    (task / "square.root").write_text("# draw a square of 10 cm\nwhen started\n", "utf-8")


def browser(address: str) -> aiohttp.ClientSession:
    jar = aiohttp.CookieJar(unsafe=True)  # (cookies for 127.0.0.1)
    return aiohttp.ClientSession(address, cookie_jar=jar, headers={"Origin": address})


async def pupil_works(pupil: Pupil, n: int, stop_after: float, edit_every: float) -> None:
    session = pupil.session
    program = (GALLERY / f"{PROGRAMS[n % len(PROGRAMS)]}.root").read_text("utf-8")
    square = (GALLERY / "square.root").read_text("utf-8")
    saved = square if n % 2 == 0 else square.replace("repeat 4", "repeat 3")
    await session.put("/api/program", json={"name": "square.root", "text": saved})
    async with session.ws_connect("/ws/class"), session.ws_connect("/ws") as runs:
        await runs.send_json({"type": "run", "name": "long.root", "text": LONG, "speed": 1})
        watching = asyncio.create_task(watch_run(pupil, runs))  # its frames, as a page draws
        began, edit = time.monotonic(), 0
        while time.monotonic() - began < stop_after:
            edit += 1
            text = f"# edit {edit}\n{program}"
            sent = pupil.sent[edit] = time.monotonic()  # (the teacher's page may see it first)
            await session.post("/api/blocks", json={"text": text, "name": "mine.root"})
            pupil.answered_at[edit] = time.monotonic()
            pupil.answered.append(pupil.answered_at[edit] - sent)
            await asyncio.sleep(edit_every)
        await watching  # until the teacher's Stop ends the run


async def watch_run(pupil: Pupil, runs: aiohttp.ClientWebSocketResponse[bool]) -> None:
    async for message in runs:
        if '"started"' in message.data[:40]:
            pupil.started.set()
        if '"ended"' not in message.data:  # a frame: a page draws it; here it is not even read
            continue  # (30 pages' frames parsed in this one process would measure this process)
        data = json.loads(message.data)
        if data["type"] == "ended":
            pupil.ended_at, pupil.end = time.monotonic(), data["end"]
            break


async def teacher_watches(
    teacher: aiohttp.ClientSession,
    pupils: dict[str, Pupil],
    seen: list[tuple[float, float]],
    done: asyncio.Event,
) -> None:
    async with teacher.ws_connect("/ws/teacher") as socket:
        async for message in socket:
            now = time.monotonic()
            for one in json.loads(message.data).get("pupils", []):
                found = re.match(r"# edit (\d+)\n", one.get("text") or "")
                pupil = pupils.get(one["name"])
                if found and pupil is not None:
                    edit = int(found.group(1))
                    sent = pupil.sent.pop(edit, None)
                    if sent is not None:  # (and after the studio answered the change, if it had)
                        seen.append((now - sent, now - pupil.answered_at.get(edit, now)))
            if done.is_set():
                break


async def lesson(address: str, code: str, count: int, seconds: float, every: float) -> None:
    teacher = browser(address)
    await teacher.post("/api/teacher/login", json={"code": code})
    pupils: dict[str, Pupil] = {}
    for n in range(count):
        pupil = Pupil(f"pupil {n:02d}", browser(address))
        await pupil.session.post("/api/pupil", json={"name": pupil.name})
        pupils[pupil.name] = pupil
    seen: list[tuple[float, float]] = []
    done = asyncio.Event()
    watching = asyncio.create_task(teacher_watches(teacher, pupils, seen, done))
    await asyncio.sleep(0.5)
    working = [asyncio.create_task(pupil_works(p, n, seconds, every))
               for n, p in enumerate(pupils.values())]  # fmt: skip
    await asyncio.sleep(seconds + every + 0.5)
    # Stop stops the runs going on: on a busy computer a run may start later than this
    await asyncio.wait_for(asyncio.gather(*(p.started.wait() for p in pupils.values())), 120)
    pressed = time.monotonic()
    reply = await (await teacher.post("/api/teacher/stop")).json()
    answered = time.monotonic() - pressed
    await asyncio.wait_for(asyncio.gather(*working), 30)
    stops = [p.ended_at - pressed for p in pupils.values()]
    checking = time.monotonic()
    checked = await (await teacher.post("/api/teacher/check", json={"task": "square"})).json()
    check_seconds = time.monotonic() - checking
    done.set()
    watching.cancel()
    for pupil in pupils.values():
        await pupil.session.close()
    await teacher.close()

    def ms(value: float) -> str:
        return f"{value * 1000:.0f} ms"

    def spread(values: list[float]) -> str:
        ordered = sorted(values)
        p95 = ordered[min(len(ordered) - 1, round(0.95 * (len(ordered) - 1)))]
        return f"p50 {ms(statistics.median(ordered))}, p95 {ms(p95)}, max {ms(ordered[-1])}"

    lost = sum(len(p.sent) for p in pupils.values())
    print(f"pupils: {count}, each running at real time and changing their program every "
          f"{every:g} s for {seconds:g} s; {os.cpu_count()} cores, load average before "
          f"{LOAD_BEFORE:.1f} (other work on this computer slows every figure)")  # fmt: skip
    print(f"teacher's page update after a pupil's change: {spread([s[0] for s in seen])} over "
          f"{len(seen)} changes ({lost} superseded before a push) (aim: within 1 s)")  # fmt: skip
    print(f"  after the studio had the change (its answer to the pupil): "
          f"{spread([max(0.0, s[1]) for s in seen])}")  # fmt: skip
    answers = sorted(a for p in pupils.values() for a in p.answered)
    if os.environ.get("ROOTLANG_BENCH_DEBUG"):
        for index in range(max(len(p.answered) for p in pupils.values())):
            got = sorted(p.answered[index] for p in pupils.values() if len(p.answered) > index)
            print(f"  change {index + 1}: answered p50 {ms(got[len(got) // 2])}, max {ms(got[-1])}")
    print(f"  (the change's own request, text to blocks, answered: p50 "
          f"{ms(statistics.median(answers))}, max {ms(answers[-1])})")  # fmt: skip
    ends = {p.end for p in pupils.values()}
    print(f"Stop every run: {reply['stopped']} runs, the studio's answer after {ms(answered)} "
          f"(it reports {ms(reply['seconds'])}); each pupil's page told: p50 "
          f"{ms(statistics.median(stops))}, max {ms(max(stops))}; ends {sorted(ends)} "
          f"(aim: every run within 1 s)")  # fmt: skip
    results = checked["results"].values()
    passed = sum(1 for r in results if r["passed"])
    print(f"Check everyone: {len(results)} programs in {check_seconds:.1f} s "
          f"({passed} passed, as expected {(count + 1) // 2})")  # fmt: skip


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pupils", type=int, default=30)
    parser.add_argument("--seconds", type=float, default=20.0)
    parser.add_argument("--edit-every", type=float, default=1.0)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch) / "class"
        make_folder(folder)
        server = subprocess.Popen(
            [sys.executable, "-m", "rootlang", "studio", str(folder), "--class", "--port", "0",
             "--no-browser"],
            stdout=subprocess.PIPE, text=True,
        )  # fmt: skip
        try:
            assert server.stdout is not None
            address = re.search(r"http://[\d.]+:\d+", server.stdout.readline())
            code = re.search(r"code (\d+)", server.stdout.readline())
            assert address and code, "the studio did not say where it serves, or the code"
            cpu_before, wall_before = cpu_seconds(server.pid), time.monotonic()
            asyncio.run(lesson(address.group(0), code.group(1), args.pupils, args.seconds,
                               args.edit_every))  # fmt: skip
            cpu = cpu_seconds(server.pid) - cpu_before
            wall = time.monotonic() - wall_before
        finally:
            server.terminate()
            server.wait(10)
    print(f"server process CPU (itself, not its runs): {cpu:.1f} s "
          f"({cpu / wall * 100:.0f}% of one core over {wall:.0f} s)")  # fmt: skip


if __name__ == "__main__":
    main()
