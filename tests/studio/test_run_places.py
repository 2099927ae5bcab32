"""The studio's runs and the machine: starting a run never holds up the server (docs/studio.md,
"A class on a network"), over real HTTP and real WebSockets."""

from __future__ import annotations

import asyncio
import json
import time
from collections.abc import Callable
from multiprocessing.process import BaseProcess
from typing import Any

import aiohttp
import pytest

from rootlang.studio import runs

from .conftest import RunningStudio
from .test_server import alive_workers, with_session

SLOW_START_S = 1.5
DRIVE = "when started\n    forever\n        move 10 cm\n        turn right 90 degrees\n"


@pytest.fixture
def slow_starts(monkeypatch: pytest.MonkeyPatch) -> None:
    """Starting a worker process takes 1.5 s, as on a computer busy with 30 starting at once."""
    start = runs.start_process

    def slowly(target: Callable[..., None], args: tuple[Any, ...]) -> BaseProcess:
        time.sleep(SLOW_START_S)
        return start(target, args)

    monkeypatch.setattr(runs, "start_process", slowly)


async def _next(socket: aiohttp.ClientWebSocketResponse[bool], kind: str) -> dict[str, Any]:
    async for message in socket:
        data: dict[str, Any] = json.loads(message.data)
        if data["type"] == kind:
            return data
    raise AssertionError(f"the socket closed before a {kind!r} message")


def test_a_run_whose_process_starts_slowly_holds_up_no_other_page(
    studio: RunningStudio, slow_starts: None
) -> None:
    async def check(session: aiohttp.ClientSession) -> None:
        async with (
            session.ws_connect("/ws", origin=studio.address) as runner,
            session.ws_connect("/ws", origin=studio.address) as other,
        ):
            sent = time.monotonic()
            await runner.send_json({"type": "run", "name": "d.root", "text": DRIVE})
            await other.send_str('{"type": "fly"}')  # any message: its answer is the server's
            assert (await other.receive_json(timeout=10))["type"] == "error"
            answered = time.monotonic() - sent
            assert answered < SLOW_START_S / 2, f"the other page waited {answered:.2f} s"
            await asyncio.wait_for(_next(runner, "started"), 30)
            assert time.monotonic() - sent >= SLOW_START_S  # (the start was slow indeed)
            await runner.send_json({"type": "stop"})
            ended = await asyncio.wait_for(_next(runner, "ended"), 30)
            assert ended["end"] == "stopped"

    with_session(studio, check)


def test_a_run_stopped_while_its_process_starts_ends_and_leaves_no_process(
    studio: RunningStudio, slow_starts: None
) -> None:
    async def check(session: aiohttp.ClientSession) -> None:
        async with session.ws_connect("/ws", origin=studio.address) as runner:
            await runner.send_json({"type": "run", "name": "d.root", "text": DRIVE})
            await asyncio.sleep(0.2)  # (its process is starting)
        deadline = time.monotonic() + SLOW_START_S + 10
        await asyncio.sleep(SLOW_START_S)
        while alive_workers():
            assert time.monotonic() < deadline, "the run's process outlived its page"
            await asyncio.sleep(0.1)

    with_session(studio, check)
