"""The message contract (rootlang/studio/messages.py) holds for what the server really sends:
every HTTP reply and WebSocket message of a session, checked against its type."""

from __future__ import annotations

import json
from typing import Any

import aiohttp

from rootlang.jstypes import problems
from rootlang.studio import messages as m

from .conftest import PROGRAMS, RunningStudio
from .test_server import with_session


async def _reply(response: aiohttp.ClientResponse, hint: Any) -> dict[str, Any]:
    data: dict[str, Any] = await response.json()
    assert problems(data, hint) == []
    return data


def test_every_http_reply_has_its_contract_type(studio: RunningStudio) -> None:
    text = (PROGRAMS / "square.root").read_text(encoding="utf-8")

    async def check(session: aiohttp.ClientSession) -> None:
        await _reply(await session.get("/api/setup", params={"language": "nl"}), m.SetupReply)
        read = await _reply(await session.get("/api/program?name=square.root"), m.ProgramReply)
        blocks = await _reply(await session.post("/api/blocks", json={"text": text, "name": ""}),
                              m.BlocksReply)  # fmt: skip
        broken = await session.post(
            "/api/blocks", json={"text": "when started\n  move", "name": ""}
        )
        assert (await _reply(broken, m.BlocksReply))["diagnostics"]
        back = {"workspace": blocks["workspace"], "name": "square.root"}
        await _reply(await session.post("/api/text", json=back), m.TextReply)
        saved = {"name": "square.root", "text": read["text"], "layout": {"top": {}}}
        await _reply(await session.put("/api/program", json=saved), m.SavedReply)
        await _reply(await session.post("/api/program", json={"name": "new.root"}), m.SavedReply)
        renamed = {"old": "new.root", "new": "newer.root"}
        await _reply(await session.post("/api/rename", json=renamed), m.RenamedReply)
        refused = await session.get("/api/program?name=../x.root")
        assert refused.status == 400
        await _reply(refused, m.ErrorsReply)

    with_session(studio, check)


def test_every_websocket_message_has_its_contract_type(studio: RunningStudio) -> None:
    text = 'when started\n    marker down\n    light green\n    move 10 cm\n    say "hi"\n'

    async def check(session: aiohttp.ClientSession) -> None:
        base = str(session._base_url).rstrip("/")
        seen: set[str] = set()
        async with session.ws_connect("/ws", origin=base) as socket:
            await socket.send_str("{not json")
            run: m.RunMessage = {"type": "run", "name": "square.root", "text": text,
                                 "world": "", "speed": 10, "robot": None}  # fmt: skip
            await socket.send_json(run)
            async for message in socket:
                data = json.loads(message.data)
                assert problems(data, m.ToPage) == [], data["type"]
                seen.add(data["type"])
                if data["type"] == "ended":
                    break
        # (and "watch", five times a second, if the run lasts long enough on a busy machine)
        assert seen - {"watch"} == {"error", "started", "frame", "ended"}

    with_session(studio, check)


def test_the_check_finds_what_breaks_the_contract() -> None:
    frame = {"type": "frame", "t": 1.0, "ink": [], "running": {"main": 2}, "printed": [],
             "said": [], "notes": [], "happened": [], "sent_at": 0.0, "n": 1}  # fmt: skip
    assert problems(frame, m.ToPage) == []
    assert problems({**frame, "running": {"main": "2"}}, m.ToPage)
    assert problems({**frame, "extra": 1}, m.FrameMessage) == [
        "message: `extra` is not in FrameMessage"
    ]
    assert problems({k: v for k, v in frame.items() if k != "t"}, m.FrameMessage) == [
        "message: no `t`"
    ]
