"""Files are safe and the class never waits for one child, over real HTTP with real conversion
worker processes: a Save over a file changed since it was opened is refused, every Save keeps
the versions before it, long programs open (as text only past the blocks' limit), and a huge or
slow request stalls nobody else."""

from __future__ import annotations

import asyncio
import json
import sys
import time
from collections.abc import Awaitable, Callable
from pathlib import Path
from typing import Any

import aiohttp
from aiohttp.test_utils import TestServer

from rootlang.blocks import to_text
from rootlang.studio.conversions import MOST_BLOCK_LINES
from rootlang.studio.folder import HISTORY, KEPT_VERSIONS, ClassFolder, version_of
from rootlang.studio.pool import ConversionPool
from rootlang.studio.server import STUDIO, make_app

from .conftest import RunningStudio

Check = Callable[[aiohttp.ClientSession], Awaitable[None]]
SQUARE = "when started\n    repeat 4\n        move 10 cm\n        turn right 90 degrees\n"


def with_session(studio: RunningStudio, check: Check) -> None:
    async def main() -> None:
        async with aiohttp.ClientSession(studio.address) as session:
            await check(session)

    asyncio.run(main())


async def deep_json(reply: aiohttp.ClientResponse) -> Any:
    """A reply's JSON, nested as deep as Blockly nests a long script (a browser reads it as
    it is; Python's json module needs room for it)."""
    text = await reply.text()
    limit = sys.getrecursionlimit()
    sys.setrecursionlimit(max(limit, 50_000))
    try:
        return json.loads(text)
    finally:
        sys.setrecursionlimit(limit)


def long_program(statements: int) -> str:
    body = ["    move 10 cm  # forward", "    turn right 90 degrees", '    say "hi"'] * statements
    return "when started\n" + "\n".join(body[:statements]) + "\n"


# ---- Save: versions and history ------------------------------------------------------------


def test_a_save_over_a_file_changed_since_it_was_opened_is_refused(
    studio: RunningStudio,
) -> None:
    path = studio.folder / "square.root"

    async def check(session: aiohttp.ClientSession) -> None:
        opened = await (await session.get("/api/program", params={"name": "square.root"})).json()
        assert opened["version"] == version_of(path.read_text(encoding="utf-8"))
        other = await (await session.get("/api/program", params={"name": "square.root"})).json()
        # another tab saves first ...
        first = await session.put("/api/program", json={
            "name": "square.root", "text": SQUARE, "version": other["version"]})  # fmt: skip
        assert first.status == 200
        # ... so this one, opened before that, may not write over it
        mine = "when started\n    move 99 cm\n"
        refused = await session.put("/api/program", json={
            "name": "square.root", "text": mine, "version": opened["version"]})  # fmt: skip
        assert refused.status == 409
        assert (await refused.json())["errors"][0]["code"] == "E819"
        assert path.read_text(encoding="utf-8") == SQUARE
        # a pupil who edits the file on disk meanwhile is just another writer
        path.write_text("when started\n    move 1 cm\n", encoding="utf-8")
        newer = (await first.json())["version"]
        again = await session.put("/api/program", json={
            "name": "square.root", "text": mine, "version": newer})  # fmt: skip
        assert again.status == 409
        # opened again, it saves
        fresh = await (await session.get("/api/program", params={"name": "square.root"})).json()
        saved = await session.put("/api/program", json={
            "name": "square.root", "text": mine, "version": fresh["version"]})  # fmt: skip
        assert saved.status == 200 and (await saved.json())["version"] == version_of(mine)
        assert path.read_text(encoding="utf-8") == mine

    with_session(studio, check)


def test_a_save_as_written_is_not_formatted(studio: RunningStudio) -> None:
    """A program too long to format in time is saved as the page has it (``as_written``);
    otherwise a Save writes the canonical form."""
    path = studio.folder / "loose.root"
    untidy = "when started\n    move   10 cm\n"

    async def check(session: aiohttp.ClientSession) -> None:
        for as_written, written in ((True, untidy), (False, "when started\n    move 10 cm\n")):
            reply = await session.put("/api/program", json={
                "name": "loose.root", "text": untidy, "as_written": as_written})  # fmt: skip
            assert reply.status == 200 and (await reply.json())["text"] == written
            assert path.read_text(encoding="utf-8") == written

    with_session(studio, check)


def test_every_save_keeps_the_version_before_it(studio: RunningStudio) -> None:
    path = studio.folder / "square.root"
    before = path.read_text(encoding="utf-8")

    async def check(session: aiohttp.ClientSession) -> None:
        reply = await session.put("/api/program", json={"name": "square.root", "text": SQUARE})
        assert reply.status == 200

    with_session(studio, check)
    kept = sorted((studio.folder / HISTORY / "square.root").glob("*.root"))
    assert [p.read_text(encoding="utf-8") for p in kept] == [before]
    listed = [p.name for p in ClassFolder(studio.folder).programs()]
    assert not any(HISTORY in name for name in listed)  # the history is no program


def test_the_history_keeps_the_last_versions_only_and_follows_a_rename(tmp_path: Path) -> None:
    now = [1_700_000_000.0]
    folder = ClassFolder(tmp_path, clock=lambda: now[0])
    folder.create("dance.root", "when started\n    move 0 cm\n")
    version = version_of(folder.read("dance.root"))
    for step in range(1, KEPT_VERSIONS + 6):
        now[0] += 1 if step % 3 else 0  # some Saves in the same second
        version = folder.save("dance.root", f"when started\n    move {step} cm\n", version)
    kept = folder.history("dance.root")
    assert len(kept) == KEPT_VERSIONS
    assert (
        kept[-1].read_text(encoding="utf-8") == f"when started\n    move {KEPT_VERSIONS + 4} cm\n"
    )
    assert len({p.name for p in kept}) == KEPT_VERSIONS
    folder.rename("dance.root", "disco.root")
    assert len(folder.history("disco.root")) == KEPT_VERSIONS
    assert folder.history("dance.root") == []


def test_a_history_folder_linking_out_of_the_class_folder_is_not_written(tmp_path: Path) -> None:
    outside = tmp_path / "outside"
    outside.mkdir()
    room = tmp_path / "class"
    room.mkdir()
    (room / HISTORY).symlink_to(outside)
    folder = ClassFolder(room)
    folder.create("a.root", "when started\n    move 1 cm\n")
    folder.save("a.root", "when started\n    move 2 cm\n", None)
    assert list(outside.iterdir()) == []
    assert folder.read("a.root") == "when started\n    move 2 cm\n"


# ---- long programs -----------------------------------------------------------------------------


def test_a_600_statement_program_opens_as_blocks_and_saves_itself(studio: RunningStudio) -> None:
    text = long_program(600)
    (studio.folder / "long.root").write_text(text, encoding="utf-8")

    async def check(session: aiohttp.ClientSession) -> None:
        opened = await (await session.get("/api/program", params={"name": "long.root"})).json()
        reply = await session.post(
            "/api/blocks", json={"text": opened["text"], "name": "long.root"}
        )
        assert reply.status == 200
        workspace = (await deep_json(reply))["workspace"]
        assert workspace is not None
        limit = sys.getrecursionlimit()
        sys.setrecursionlimit(max(limit, 50_000))
        try:
            assert to_text(workspace) == text
            body = json.dumps({"workspace": workspace, "name": "long.root"})
        finally:
            sys.setrecursionlimit(limit)
        back = await session.post(
            "/api/text", data=body, headers={"Content-Type": "application/json"}
        )
        assert back.status == 200 and (await deep_json(back))["text"] == text  # (its blocks too)
        saved = await session.put("/api/program", json={
            "name": "long.root", "text": text, "version": opened["version"]})  # fmt: skip
        assert saved.status == 200

    with_session(studio, check)
    assert (studio.folder / "long.root").read_text(encoding="utf-8") == text


def test_a_program_too_long_for_blocks_opens_as_text_only(studio: RunningStudio) -> None:
    text = "when started\n" + "    stop moving\n" * (MOST_BLOCK_LINES + 9)  # (quick to check)

    async def check(session: aiohttp.ClientSession) -> None:
        reply = await session.post("/api/blocks", json={"text": text, "name": "huge.root"})
        assert reply.status == 200
        data = await reply.json()
        assert data["workspace"] is None
        assert data["text_only"]["code"] == "E817"
        assert str(MOST_BLOCK_LINES + 10) in data["text_only"]["message"]

    with_session(studio, check)


def test_a_workspace_nested_deeper_than_python_likes_is_answered(studio: RunningStudio) -> None:
    """Blockly nests each block in the one above it: 5,000 blocks in one script."""
    body: dict[str, Any] = {"type": "root_stop_moving"}
    for _ in range(5_000):
        body = {"type": "root_stop_moving", "next": {"block": body}}
    top = {"type": "root_when_started", "inputs": {"BODY": {"block": body}}}
    workspace = {"blocks": {"languageVersion": 0, "blocks": [top]}}

    limit = sys.getrecursionlimit()
    sys.setrecursionlimit(max(limit, 50_000))
    try:
        sent = json.dumps({"workspace": workspace, "name": "deep.root"})
    finally:
        sys.setrecursionlimit(limit)

    async def check(session: aiohttp.ClientSession) -> None:
        reply = await session.post(
            "/api/text", data=sent,
            headers={"Content-Type": "application/json"},
        )  # fmt: skip
        assert reply.status in (200, 400)
        data = await deep_json(reply)  # (the text's own blocks nest as deep)
        assert "text" in data or data["errors"][0]["code"].startswith(("E7", "E8"))

    with_session(studio, check)


# ---- nobody waits for one child ----------------------------------------------------------------


async def timed(session: aiohttp.ClientSession, text: str) -> float:
    began = time.monotonic()
    reply = await session.post("/api/blocks", json={"text": text, "name": "a.root"})
    assert reply.status == 200 and (await deep_json(reply))["workspace"] is not None
    return time.monotonic() - began


def test_a_huge_program_stalls_nobody_else(studio: RunningStudio) -> None:
    huge = long_program(40_000)  # about 0.9 MB (how it is answered: the test above)
    assert len(huge.encode()) > 800_000

    async def check(session: aiohttp.ClientSession) -> None:
        await timed(session, SQUARE)  # the workers are up
        big = asyncio.create_task(
            session.post("/api/blocks", json={"text": huge, "name": "h.root"})
        )
        await asyncio.sleep(0.3)  # it is being worked on
        for n in range(5):  # each answered while the huge one is still worked on, not after it
            await timed(session, SQUARE + f"    move {n} cm\n")
            assert not big.done()
        big.cancel()

    with_session(studio, check)


def test_a_request_past_its_time_limit_is_stopped_and_the_next_one_is_served(
    tmp_path: Path,
) -> None:
    async def main() -> None:
        app = make_app(ClassFolder(tmp_path))
        app[STUDIO].pool = ConversionPool(1, seconds=1.0)
        async with TestServer(app) as server:
            base = str(server.make_url("")).rstrip("/")
            async with aiohttp.ClientSession(base) as session:
                await timed(session, SQUARE)
                slow = long_program(35_000)  # about 3 s of work, under the 1 MB a request may be
                reply = await session.post("/api/blocks", json={"text": slow, "name": "s.root"})
                assert reply.status == 400
                error = (await reply.json())["errors"][0]
                assert error["code"] == "E818" and "1 second" in error["message"]
                assert await timed(session, SQUARE) < 5  # a fresh worker took its place

    asyncio.run(main())
