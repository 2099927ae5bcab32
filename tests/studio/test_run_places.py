"""The studio's runs and the machine (docs/studio.md, "A class on a network"): starting a run
never holds up the server, and a cap on runs at once for the computer and for each pupil —
over real HTTP, real WebSockets and real worker processes."""

from __future__ import annotations

import asyncio
import json
import os
import signal
import threading
import time
from collections.abc import Callable
from multiprocessing.process import BaseProcess
from pathlib import Path
from typing import Any

import aiohttp
import pytest

from rootlang.studio import runs

from .conftest import RunningStudio
from .test_server import alive_workers, with_session

DRIVE = "when started\n    forever\n        move 10 cm\n        turn right 90 degrees\n"
HELD_AT_MOST_S = 60.0  # (a hang's bound: the test lets the start go on long before)


class HeldStarts:
    """Starting a worker process waits until the test lets it go on, as on a computer busy with
    30 starting at once: what the studio does meanwhile is seen, however fast the machine."""

    def __init__(self) -> None:
        self.begun = threading.Event()  # a start is under way (and held)
        self.go_on = threading.Event()
        self.started: list[BaseProcess] = []  # the processes started, in order


@pytest.fixture
def held_starts(monkeypatch: pytest.MonkeyPatch) -> HeldStarts:
    held = HeldStarts()
    start = runs.start_process

    def slowly(target: Callable[..., None], args: tuple[Any, ...]) -> BaseProcess:
        held.begun.set()
        held.go_on.wait(HELD_AT_MOST_S)
        held.started.append(start(target, args))
        return held.started[-1]

    monkeypatch.setattr(runs, "start_process", slowly)
    return held


async def _begun(held: HeldStarts) -> None:
    """Until a start is under way (it is held there)."""
    assert await asyncio.to_thread(held.begun.wait, HELD_AT_MOST_S), "no run was started"


async def _next(socket: aiohttp.ClientWebSocketResponse[bool], kind: str) -> dict[str, Any]:
    async for message in socket:
        data: dict[str, Any] = json.loads(message.data)
        if data["type"] == kind:
            return data
    raise AssertionError(f"the socket closed before a {kind!r} message")


def test_a_run_whose_process_starts_slowly_holds_up_no_other_page(
    studio: RunningStudio, held_starts: HeldStarts
) -> None:
    async def check(session: aiohttp.ClientSession) -> None:
        async with (
            session.ws_connect("/ws", origin=studio.address) as runner,
            session.ws_connect("/ws", origin=studio.address) as other,
        ):
            await runner.send_json({"type": "run", "name": "d.root", "text": DRIVE})
            await _begun(held_starts)
            await other.send_str('{"type": "fly"}')  # any message: its answer is the server's
            # answered while the start is held (a server that waited for it: never, until
            # the hang's bound)
            assert (await other.receive_json(timeout=HELD_AT_MOST_S / 2))["type"] == "error"
            assert not held_starts.started
            held_starts.go_on.set()
            await asyncio.wait_for(_next(runner, "started"), 30)
            await runner.send_json({"type": "stop"})
            ended = await asyncio.wait_for(_next(runner, "ended"), 30)
            assert ended["end"] == "stopped"

    with_session(studio, check)


def test_a_run_stopped_while_its_process_starts_ends_and_leaves_no_process(
    studio: RunningStudio, held_starts: HeldStarts
) -> None:
    async def check(session: aiohttp.ClientSession) -> None:
        async with session.ws_connect("/ws", origin=studio.address) as runner:
            await runner.send_json({"type": "run", "name": "d.root", "text": DRIVE})
            await _begun(held_starts)  # its process is starting as the page goes
        held_starts.go_on.set()
        deadline = time.monotonic() + 30  # (a hang's bound)
        while not held_starts.started:
            assert time.monotonic() < deadline, "the run's process never started"
            await asyncio.sleep(0.1)
        while held_starts.started[0].is_alive():
            assert time.monotonic() < deadline, "the run's process outlived its page"
            await asyncio.sleep(0.1)

    with_session(studio, check)


# --- places for runs: a cap on runs at once, for the computer and for each pupil ----------------

SHORT = "when started\n    move 20 cm\n"  # a few seconds at 1×


async def _follow(
    socket: aiohttp.ClientWebSocketResponse[bool], name: str, events: list[tuple[str, str]]
) -> list[dict[str, Any]]:
    """Every message of a run until it ends; each waiting, start and end noted in ``events``
    as it comes (the order of the whole class's events)."""
    seen = []
    async for message in socket:
        data: dict[str, Any] = json.loads(message.data)
        if data["type"] in ("waiting", "started", "ended", "error"):
            events.append((name, data["type"]))
            seen.append(data)
        if data["type"] in ("ended", "error"):
            break
    return seen


def test_past_the_cap_runs_wait_their_turn_and_each_starts_as_a_place_frees(
    class_folder: Path,
) -> None:
    studio = RunningStudio(class_folder, limits=runs.ClassLimits(runs=2)).start()
    events: list[tuple[str, str]] = []

    async def one(session: aiohttp.ClientSession, n: int) -> list[dict[str, Any]]:
        language = {"language": "nl"} if n == 4 else {}
        async with session.ws_connect("/ws", origin=studio.address, params=language) as socket:
            await asyncio.sleep(0.1 * n)  # (all sent long before the first two end)
            await socket.send_json({"type": "run", "name": f"r{n}.root", "text": SHORT})
            return await asyncio.wait_for(_follow(socket, f"r{n}", events), 120)

    async def check(session: aiohttp.ClientSession) -> None:
        told = await asyncio.gather(*(one(session, n) for n in range(5)))
        assert [seen[-1]["type"] for seen in told] == ["ended"] * 5
        assert all(seen[-1]["end"] == "finished" for seen in told), told
        live = most = 0
        for _, kind in events:  # never more than two at once, as the server told the pages
            live += {"started": 1, "ended": -1}.get(kind, 0)
            most = max(most, live)
        assert most == 2, events
        places = {}  # each waiting run's first place in the queue
        for n, seen in enumerate(told):
            waits = [m for m in seen if m["type"] == "waiting"]
            assert bool(waits) == (n >= 2), (n, seen)  # the first two ran at once
            if waits:
                places[f"r{n}"] = waits[0]["place"]
                assert [m["type"] for m in seen][-2:] == ["started", "ended"]
        assert sorted(places.values()) == [1, 2, 3]
        dutch = next(m for m in told[4] if m["type"] == "waiting")
        place = dutch["place"]
        assert dutch["message"] == f"Wachten op een vrije plek… (nummer {place} in de rij)"

    try:
        with_session(studio, check)
    finally:
        studio.stop()


def test_a_pupil_who_runs_again_replaces_their_own_run_going_or_waiting(tmp_path: Path) -> None:
    from rootlang.studio.classroom import Classroom
    from rootlang.studio.folder import ClassFolder

    folder = tmp_path / "class"
    folder.mkdir()
    classroom = Classroom(ClassFolder(folder), "123456")
    studio = RunningStudio(folder, classroom=classroom, limits=runs.ClassLimits(runs=1)).start()

    async def pupil(client: aiohttp.ClientSession, name: str) -> None:
        assert (await client.post("/api/pupil", json={"name": name})).status == 200

    def browser() -> aiohttp.ClientSession:
        jar = aiohttp.CookieJar(unsafe=True)
        return aiohttp.ClientSession(studio.address, cookie_jar=jar,
                                     headers={"Origin": studio.address})  # fmt: skip

    async def check() -> None:
        async with browser() as anna, browser() as ben:
            await pupil(anna, "Anna")
            await pupil(ben, "Ben")
            async with (
                anna.ws_connect("/ws") as anna_tab,
                anna.ws_connect("/ws") as anna_other_tab,
                ben.ws_connect("/ws") as ben_tab,
                ben.ws_connect("/ws") as ben_other_tab,
            ):
                await anna_tab.send_json({"type": "run", "name": "a.root", "text": DRIVE})
                assert (await asyncio.wait_for(_next(anna_tab, "started"), 60))["stage"]
                await ben_tab.send_json({"type": "run", "name": "b.root", "text": DRIVE})
                assert (await ben_tab.receive_json(timeout=10))["place"] == 1
                # the teacher sees whose run waits, and whose runs
                ben_run, anna_run = classroom.pupils["ben"].run, classroom.pupils["anna"].run
                assert ben_run is not None and ben_run["waiting"] == 1
                assert anna_run is not None and anna_run["waiting"] == 0
                # Ben runs again in his other tab: his waiting run is replaced, not stacked
                await ben_other_tab.send_json({"type": "run", "name": "b.root", "text": SHORT})
                replaced = await asyncio.wait_for(_next(ben_tab, "ended"), 10)
                assert replaced["end"] == "stopped" and replaced["stopped_by"] == "your new run"
                assert (await ben_other_tab.receive_json(timeout=10))["place"] == 1
                # Anna runs again in her other tab: her run going is replaced, and Ben's
                # waiting one, first in line, gets the place it frees
                await anna_other_tab.send_json({"type": "run", "name": "a.root", "text": DRIVE})
                replaced = await asyncio.wait_for(_next(anna_tab, "ended"), 10)
                assert replaced["stopped_by"] == "your new run"
                assert (await anna_other_tab.receive_json(timeout=10))["place"] == 1
                await asyncio.wait_for(_next(ben_other_tab, "started"), 60)
                assert (await asyncio.wait_for(_next(ben_other_tab, "ended"), 60))["end"] == (
                    "finished"
                )
                await asyncio.wait_for(_next(anna_other_tab, "started"), 60)
                await anna_other_tab.send_json({"type": "stop"})
                assert (await asyncio.wait_for(_next(anna_other_tab, "ended"), 30))["end"] == (
                    "stopped"
                )

    try:
        asyncio.run(check())
    finally:
        studio.stop()


def test_a_waiting_run_stops_at_once_and_a_full_queue_refuses_more(class_folder: Path) -> None:
    studio = RunningStudio(class_folder, limits=runs.ClassLimits(runs=1)).start()
    waiting = runs.WAITING_PER_PLACE

    async def check(session: aiohttp.ClientSession) -> None:
        sockets = [await session.ws_connect("/ws", origin=studio.address)
                   for _ in range(waiting + 2)]  # fmt: skip
        try:
            first, *others, refused = sockets
            await first.send_json({"type": "run", "name": "d.root", "text": DRIVE})
            for place, socket in enumerate(others, 1):
                await socket.send_json({"type": "run", "name": "d.root", "text": DRIVE})
                assert (await socket.receive_json(timeout=10))["place"] == place
            await refused.send_json({"type": "run", "name": "d.root", "text": DRIVE})
            assert (await refused.receive_json(timeout=10))["code"] == "E825"
            await others[0].send_json({"type": "stop"})  # Stop while it waits: it just ends
            ended = await others[0].receive_json(timeout=10)
            assert ended["type"] == "ended" and ended["stopped_by"] == "the Stop button"
            assert (await others[1].receive_json(timeout=10))["place"] == 1  # moved up
            await refused.send_json({"type": "run", "name": "d.root", "text": DRIVE})  # room now
            assert (await refused.receive_json(timeout=10))["place"] == waiting
        finally:
            for socket in sockets:
                await socket.close()
        while alive_workers():  # (closing the pages ended every run)
            await asyncio.sleep(0.1)

    try:
        with_session(studio, check)
    finally:
        studio.stop()


# --- a run on a robot: the link outlives the program (docs/runtime.md) ------------------------


def _children_of(pid: int) -> list[tuple[int, str]]:
    """The processes whose parent is ``pid``, each with what /proc says of it (Linux)."""
    found = []
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            text = stat.read_text()
        except OSError:  # (it ended meanwhile)
            continue
        name, fields = text.split("(", 1)[1].rsplit(")", 1)
        state, parent = fields.split()[:2]
        if int(parent) == pid:
            found.append((int(stat.parent.name), f"{name} ({state})"))
    return found


def _same_program(pid: int, other: int) -> bool:
    """Whether process ``other`` runs the same executable as ``pid`` (a forked Python, not a
    tool a library ran, nor a zombie, which has none)."""
    try:
        return os.readlink(f"/proc/{other}/exe") == os.readlink(f"/proc/{pid}/exe")
    except OSError:
        return False


@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="finds processes in /proc")
def test_a_killed_program_s_robot_is_stopped_and_its_page_told(robot_studio: RunningStudio) -> None:
    """The program's process of a run on the virtual robot (over bumble) is killed with
    SIGKILL mid-drive: the run's process, which holds the link, stops the robot — confirmed by
    the robot — and the page is told in the child's words."""
    drive = "when started\n    drive 10 cm/s\n    wait 30 seconds\n"

    async def check(session: aiohttp.ClientSession) -> None:
        earlier = alive_workers()  # (an earlier test's, still ending: not this run's)
        async with session.ws_connect("/ws", origin=robot_studio.address) as socket:
            await socket.send_json({"type": "run", "name": "d.root", "text": drive, "robot": ""})
            async for message in socket:  # until the robot drives (it was told on line 2)
                data = json.loads(message.data)
                assert data["type"] not in ("ended", "error"), data
                if data["type"] == "frame" and data["running"] and data["t"] > 0.5:
                    break
            # (the run's process: the new one with the program's process under it; others,
            # such as the lessons' checks started meanwhile, have none)
            new = [worker.pid for worker in alive_workers() if worker not in earlier]
            children = {pid: _children_of(pid) for pid in new if pid is not None}
            forked = [child for pid, of in children.items() for child, _ in of
                      if _same_program(pid, child)]  # fmt: skip
            assert len(forked) == 1, f"the new processes have these children: {children}"
            (program,) = forked
            os.kill(program, signal.SIGKILL)
            ended = await asyncio.wait_for(_next(socket, "ended"), 30)
        assert ended["end"] == "error" and ended["error"]["code"] == "E218", ended
        assert ended["error"]["message"] == (
            "The program stopped all of a sudden (SIGKILL), so I stopped the robot."
        )

    with_session(robot_studio, check)
