"""Nothing a studio page receives names a file by the server's own path: a pupil (or anyone)
sees the names of their folder's files as the folder names them (``square.root``,
``worlds/bad.toml``), never ``/home/miss/class-5b/Anna/...`` nor where rootlang is installed —
in mistakes, a run's ending and What happened, the world's errors, the stage, a check, the
teacher's page and its exports. And a ``# world:`` line can't load a world through a link
leading out of the folder, as a program can't be opened through one."""

from __future__ import annotations

import asyncio
import json
from pathlib import Path

import aiohttp

import rootlang

from .conftest import RunningStudio
from .test_classroom import Client, browser, pupil, teacher
from .test_server import _time_limit

BAD_WORLDS = {
    "bad.toml": "time_limit = 5\ncolour = 3\n",  # E304: a key it does not know
    "broken.toml": "time_limit = = 5\n",  # E302: not TOML
    "wrong.toml": 'time_limit = "soon"\n',  # E303: not a number
}
WORLD_LINES = (
    "# world: worlds/bad.toml",
    "# world: worlds/broken.toml",
    "# world: wrong",
    "# world: nowhere",  # E607
    "# world: ../../outside.toml",  # E616
    "# world: arena",  # a built-in world: where rootlang is installed is not for the page
    "",
)
BODY = "when started\n    move 10 cm / 0\n"  # a run's error: in its ending and What happened
MISTAKE = "when started\n    move 10\n"  # E108


def server_paths(studio: RunningStudio) -> list[str]:
    """The server's own paths no page may see: the class folder's (as given and resolved),
    and rootlang's."""
    return [str(studio.folder), str(studio.folder.resolve()), str(Path(rootlang.__file__).parent)]


async def received_by_a_run(client: Client, text: str, world: str = "") -> list[str]:
    """Every message a run of ``text`` sends the page, to its end."""
    got: list[str] = []
    async with client.ws_connect("/ws") as socket:
        await socket.send_json({"type": "run", "name": "mine.root", "text": text, "speed": 0,
                                "world": world})  # fmt: skip
        async with _time_limit(60):
            async for message in socket:
                got.append(message.data)
                if json.loads(message.data)["type"] in ("ended", "error"):
                    return got
    raise AssertionError("the run never ended")


def test_no_page_receives_a_server_path(class_studio: RunningStudio) -> None:
    received: list[str] = []

    async def check() -> None:
        async with browser(class_studio) as anna, browser(class_studio) as miss:
            await pupil(anna, "Anna")
            await teacher(miss)
            worlds = class_studio.folder / "Anna" / "worlds"
            worlds.mkdir(exist_ok=True)
            for name, text in BAD_WORLDS.items():
                (worlds / name).write_text(text, encoding="utf-8")
            async with miss.ws_connect("/ws/teacher") as view:
                for line in WORLD_LINES:
                    for body in (BODY, MISTAKE):
                        text = f"{line}\n{body}"
                        received.extend(await received_by_a_run(anna, text))
                        for route in ("/api/blocks", "/api/stage"):
                            reply = await anna.post(route, json={"name": "mine.root",
                                                                 "text": text})  # fmt: skip
                            received.append(await reply.text())
                        check = {"name": "square.root", "text": text}
                        received.append(await (await anna.post("/api/check", json=check)).text())
                for world in ("bad", "broken", "wrong", "arena"):  # chosen on the page
                    received.extend(await received_by_a_run(anna, BODY, world))
                    reply = await anna.post(
                        "/api/stage", json={"name": "mine.root", "text": BODY, "world": world}
                    )
                    received.append(await reply.text())
                for route in ("/api/setup", "/api/teacher/setup"):
                    received.append(await (await miss.get(route)).text())
                received.append(await (await anna.get("/api/setup")).text())
                for kind in ("csv", "junit"):
                    export = await miss.get("/api/teacher/export", params={"format": kind})
                    received.append(await export.text())
                async with _time_limit(10):  # what the teacher's page was told meanwhile
                    while True:
                        try:
                            message = await view.receive(timeout=1.0)
                        except asyncio.TimeoutError:
                            break
                        if message.type != aiohttp.WSMsgType.TEXT:
                            break
                        received.append(message.data)

    asyncio.run(check())
    codes = {code for text in received for code in ("E302", "E303", "E304", "E607", "E616")
             if code in text}  # fmt: skip
    assert codes == {"E302", "E303", "E304", "E607", "E616"}, "every world mistake was met"
    assert any("worlds/bad.toml" in text for text in received), "a world named as the pupil has it"
    for path in server_paths(class_studio):
        leaking = [text[max(0, text.find(path) - 200) : text.find(path) + 200]
                   for text in received if path in text]  # fmt: skip
        assert not leaking, f"{len(leaking)} messages name {path}: {leaking[:3]}"


def test_a_world_line_cant_load_a_world_through_a_link_out_of_the_folder(
    class_studio: RunningStudio, tmp_path: Path
) -> None:
    """A pupil's ``worlds/`` (or one world file in it) linking out of the folder is refused
    as a program linking out is (E616), whichever way the line names it."""
    outside = tmp_path / "outside"
    outside.mkdir()
    (outside / "evil.toml").write_text('name = "outside"\ntime_limit = 5\n', encoding="utf-8")

    async def check() -> None:
        async with browser(class_studio) as anna:
            await pupil(anna, "Anna")
            folder = class_studio.folder / "Anna"
            (folder / "worlds").symlink_to(outside, target_is_directory=True)
            (folder / "evil.toml").symlink_to(outside / "evil.toml")
            for line in ("# world: worlds/evil.toml", "# world: evil", "# world: evil.toml"):
                text = f"{line}\nwhen started\n    move 1 cm\n"
                ended = json.loads((await received_by_a_run(anna, text))[-1])
                assert ended["end"] == "mistakes", line
                assert [e["code"] for e in ended["errors"]] == ["E616"], line
                reply = await anna.post("/api/stage", json={"name": "mine.root", "text": text})
                assert reply.status == 400, line
                assert [e["code"] for e in (await reply.json())["errors"]] == ["E616"], line

    asyncio.run(check())
