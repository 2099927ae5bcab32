#!/usr/bin/env python3
"""The adventures' checks with a whole class checking at once (aim: each ≤ 2 s).

``rootlang studio --class`` is started as a teacher starts it; ``--pupils`` pupils (30) come
in, each starts an adventure (the built-in ones in turn, so every one is checked) and, all at
the same moment, presses Check: half of them on the adventure's model solution, half on its
starter (which fails with a hint). Printed: how long each pupil waited for their check's
answer (from pressing Check to the answer, as their page sees it), each adventure's worst,
and the CPU time the studio and its checks' children used (what does not depend on how busy
the computer is with other work: 30 checks of N ms each on 2 free cores take 15 N ms).
A second round does the same again (a class presses Check again and again).

    .venv/bin/python benchmarks/adventures.py [--pupils 30] [--rounds 2]
"""

from __future__ import annotations

import argparse
import asyncio
import os
import statistics
import tempfile
import time
from pathlib import Path

import aiohttp
from studio_clients import tree_cpu_seconds  # (this folder's: the script's own is on sys.path)
from studio_process import served_studio

from rootlang.adventures import SOLUTION, find_adventures

AIM_S = 2.0


def browser(address: str) -> aiohttp.ClientSession:
    jar = aiohttp.CookieJar(unsafe=True)  # (cookies for 127.0.0.1)
    return aiohttp.ClientSession(address, cookie_jar=jar, headers={"Origin": address})


async def check_once(
    session: aiohttp.ClientSession, program: str, text: str
) -> tuple[float, bool, str]:
    started = time.monotonic()
    async with session.post("/api/check", json={"name": program, "text": text}) as reply:
        answer = await reply.json()
    return time.monotonic() - started, bool(answer["passed"]), str(answer["said"])


async def lesson(address: str, pupils: int, rounds: int, studio: int) -> None:
    adventures = find_adventures()
    sessions = [browser(address) for _ in range(pupils)]
    jobs = []
    for n, session in enumerate(sessions):
        adventure = adventures[n % len(adventures)]
        await session.post("/api/pupil", json={"name": f"pupil {n + 1}"})
        reply = await (await session.post("/api/adventure", json={"name": adventure.name})).json()
        right = n % 2 == 0
        program = adventure.task.folder / SOLUTION if right else adventure.task.starter
        jobs.append((adventure.name, reply["program"], program.read_text("utf-8"), right))
    try:
        for round_number in range(1, rounds + 1):
            cpu_before = tree_cpu_seconds(studio)
            answers = await asyncio.gather(*(
                check_once(session, program, text)
                for session, (_, program, text, _) in zip(sessions, jobs, strict=True)
            ))  # fmt: skip
            cpu = tree_cpu_seconds(studio) - cpu_before
            waits = sorted(seconds for seconds, *_ in answers)
            expected = [right for *_, right in jobs]
            judged = sum(
                passed == right for (_, passed, _), right in zip(answers, expected, strict=True)
            )
            worst: dict[str, float] = {}
            for (seconds, passed, said), (name, *_, right) in zip(answers, jobs, strict=True):
                worst[name] = max(worst.get(name, 0.0), seconds)
                if passed != right:
                    print(f"  not as expected: {name} after {seconds:.2f} s: {said}")
            print(f"round {round_number}: {pupils} pupils pressed Check at once: answer after "
                  f"median {statistics.median(waits):.2f} s, p90 "
                  f"{waits[int(len(waits) * 0.9) - 1]:.2f} s, worst {waits[-1]:.2f} s; "
                  f"{judged}/{pupils} judged as expected; "
                  f"{sum(w <= AIM_S for w in waits)}/{pupils} within {AIM_S:.0f} s; "
                  f"CPU (the studio and its checks) {cpu:.2f} s, "
                  f"{cpu / pupils * 1000:.0f} ms a check")  # fmt: skip
            print(
                "  each adventure's worst: "
                + ", ".join(
                    f"{name.split('-', 1)[0]} {seconds:.2f} s" for name, seconds in worst.items()
                )
            )
    finally:
        for session in sessions:
            await session.close()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pupils", type=int, default=30)
    parser.add_argument("--rounds", type=int, default=2)
    args = parser.parse_args()
    print(f"{os.cpu_count()} cores; load average before: "
          f"{' '.join(f'{x:.1f}' for x in os.getloadavg())}")  # fmt: skip
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch) / "class"
        folder.mkdir()
        with served_studio(folder, "--class") as (address, server):
            asyncio.run(lesson(address, args.pupils, args.rounds, server.pid))


if __name__ == "__main__":
    main()
