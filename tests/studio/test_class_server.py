"""The class server holds (``rootlang studio --host 0.0.0.0``): what one page or one pupil can
do can't flood the server or stall the others. Against the real server, over real HTTP and
WebSockets; a page that doesn't read is a raw socket that never reads."""

from __future__ import annotations

import base64
import contextlib
import json
import os
import socket
import time
from collections.abc import Callable
from multiprocessing.process import BaseProcess
from pathlib import Path
from typing import Any

import aiohttp
import pytest

from rootlang.messages import MESSAGES
from rootlang.studio import runs
from rootlang.studio.server import merge_frames
from rootlang.studio.worker import LINE_CHARS, NOTES_PER_FRAME, TEXT_LINES

from .conftest import PROGRAMS, RunningStudio
from .test_server import _time_limit, run_program, with_session

SHORT_WORLD = "time_limit = 15\n"
# a `print` bomb: lines of 4,096 characters, as fast as the loop goes (100 a second), for 15 s
PRINT_BOMB = """\
# world: short.toml
when started
    set s to "x"
    repeat 12
        set s to join(s, s)
    forever
        print s
"""


@pytest.fixture
def bomb_folder(class_folder: Path) -> Path:
    (class_folder / "short.toml").write_text(SHORT_WORLD, encoding="utf-8")
    return class_folder


def test_a_print_bomb_is_capped_per_line_and_per_run(bomb_folder: Path) -> None:
    studio = RunningStudio(bomb_folder).start()

    async def check(session: aiohttp.ClientSession) -> None:
        ended, frames = await run_program(session, "bomb.root", PRINT_BOMB, speed=0)
        assert ended["end"] == "time_limit", ended["error"]["message"]
        live = [line for frame in frames for line in frame["printed"]]
        assert live == ended["printed"]  # every line sent live, in order, once
        cut = MESSAGES["V070"].format(count=LINE_CHARS)
        assert len(ended["printed"]) == TEXT_LINES + 1
        assert all(line == "x" * LINE_CHARS + cut for line in ended["printed"][:-1])
        assert ended["printed"][-1] == MESSAGES["V071"].format(count=TEXT_LINES)
        assert all(len(line) <= LINE_CHARS + len(cut) for line in ended["trace"])
        sent = sum(len(json.dumps(frame)) for frame in frames) + len(json.dumps(ended))
        assert (
            sent < 3_000_000
        )  # (without the caps: 3,000 lines of 4 kB, and of a MB each with `repeat 20`)

    try:
        with_session(studio, check)
    finally:
        studio.stop()


def raw_page(address: str, path: str = "/ws", origin: str = "") -> socket.socket:
    """A WebSocket opened by hand on a plain socket, with a small receive buffer: a page that
    reads only when the test says so."""
    host, port = address.removeprefix("http://").split(":")
    raw = socket.socket()
    raw.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
    raw.connect((host, int(port)))
    key = base64.b64encode(os.urandom(16)).decode()
    raw.sendall(
        f"GET {path} HTTP/1.1\r\nHost: {host}:{port}\r\nUpgrade: websocket\r\n"
        f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n"
        f"Origin: {origin or address}\r\n\r\n".encode()
    )
    answer = b""
    while b"\r\n\r\n" not in answer:
        answer += raw.recv(1)
    assert answer.startswith(b"HTTP/1.1 101"), answer
    return raw


def send_text(raw: socket.socket, text: str) -> None:
    """One masked text frame, as a browser sends it."""
    data = text.encode()
    mask = os.urandom(4)
    size = len(data)
    head = bytes([0x81]) + (
        bytes([0x80 | size]) if size < 126
        else bytes([0x80 | 126]) + size.to_bytes(2, "big") if size < 65536
        else bytes([0x80 | 127]) + size.to_bytes(8, "big")
    )  # fmt: skip
    raw.sendall(head + mask + bytes(b ^ mask[i % 4] for i, b in enumerate(data)))


def read_messages(raw: socket.socket, until: str, seconds: float = 60) -> list[dict[str, Any]]:
    """The server's text frames (unmasked) up to a message of type ``until``."""
    raw.settimeout(seconds)
    buffer, messages = b"", []

    def need(count: int) -> bytes:
        nonlocal buffer
        while len(buffer) < count:
            chunk = raw.recv(65536)
            assert chunk, "the server closed the connection"
            buffer += chunk
        taken, buffer = buffer[:count], buffer[count:]
        return taken

    while True:
        first, second = need(2)
        size = second & 0x7F
        if size == 126:
            size = int.from_bytes(need(2), "big")
        elif size == 127:
            size = int.from_bytes(need(8), "big")
        payload = need(size)
        if first & 0x0F == 0x1:
            messages.append(json.loads(payload))
            if messages[-1]["type"] == until:
                return messages


def test_a_page_that_does_not_read_gets_its_frames_merged_and_stalls_nobody(
    bomb_folder: Path,
) -> None:
    studio = RunningStudio(bomb_folder).start()
    drawing = (  # it drives and prints a MB of text (1,000 lines of a kB) as fast as it goes
        '# world: short.toml\nwhen started\n    drive 10 cm/s\n    set s to "x"\n    repeat 10\n'
        "        set s to join(s, s)\n    forever\n        print s\n"
    )
    try:
        page = raw_page(studio.address)
        send_text(page, json.dumps({"type": "run", "name": "d.root", "text": drawing, "speed": 0}))

        async def meanwhile(session: aiohttp.ClientSession) -> None:
            # the page doesn't read; another page is served as usual (a stalled server never
            # ends this run: run_program's bound)
            square = (bomb_folder / "square.root").read_text(encoding="utf-8")
            ended, _ = await run_program(session, "square.root", square, speed=0)
            assert ended["end"] == "finished"

        with_session(studio, meanwhile)
        time.sleep(1.0)  # the slow page's run has ended meanwhile (or goes on: it's the same)
        got = read_messages(page, until="ended")
        page.close()
    finally:
        studio.stop()
    frames = [message for message in got if message["type"] == "frame"]
    # the page that didn't read got at most the frames that were made (merged ones leave gaps
    # in the numbers; on a fast machine a run may make so few that none needed merging), in
    # order, and none of the text was lost (merging itself: the test below)
    numbers = [frame["n"] for frame in frames]
    assert numbers == sorted(numbers) and numbers[-1] >= len(frames), numbers
    assert frames[-1]["t"] >= 2.9
    ended = got[-1]
    assert ended["type"] == "ended"
    assert [line for frame in frames for line in frame["printed"]] == ended["printed"]
    assert len(ended["printed"]) == TEXT_LINES + 1  # (a MB: more than the socket's buffers)


def test_merging_frames_keeps_the_newest_pose_and_all_text_and_happenings() -> None:
    """What the robot felt is kept too: a bump in a frame that waited was once replaced by the
    stall of the frame after it, and a page that fell behind (a busy machine) never said it."""
    older = {
        "type": "frame",
        "t": 1.0,
        "pose": {"x": 1},
        "printed": ["a"],
        "said": ["s"],
        "ink": [],
        "notes": [{"t_ms": t} for t in range(6)],
        "happened": ["bumper both"],
    }
    newer = {"type": "frame", "t": 2.0, "pose": {"x": 2}, "printed": ["b"], "said": [], "ink": [],
             "notes": [{"t_ms": t} for t in range(6, 10)],
             "happened": ["left motor stalled"]}  # fmt: skip
    merge_frames(older, newer)
    # (the notes: the newest few, as many as a frame carries; late ones are not worth hearing)
    assert older == {"type": "frame", "t": 2.0, "pose": {"x": 2}, "printed": ["a", "b"],
                     "said": ["s"], "ink": [],
                     "notes": [{"t_ms": t} for t in range(10 - NOTES_PER_FRAME, 10)],
                     "happened": ["bumper both", "left motor stalled"]}  # fmt: skip


MALFORMED = {
    "a list as action": json.dumps({"type": "stimulus", "action": ["nose"]}),
    "an object as type": json.dumps({"type": {"run": 1}}),
    "a 400-digit speed": '{"type": "run", "name": "a.root", "text": "", "speed": 1'
    + "0" * 400
    + "}",
    "a 5,000-digit speed": '{"type": "run", "name": "a.root", "text": "", "speed": 1'
    + "0" * 5000
    + "}",
    "NaN as speed": '{"type": "run", "name": "a.root", "text": "", "speed": NaN}',
    "true as speed": json.dumps({"type": "run", "name": "a.root", "text": "", "speed": True}),
    "a list as name": json.dumps({"type": "run", "name": ["a.root"], "text": ""}),
    "sensors nested": json.dumps({"type": "stimulus", "action": "touch", "sensors": [["x"]]}),
    "JSON nested 1,000 deep": "[" * 1000 + "]" * 1000,
    "JSON nested 100,000 deep": '{"type": ' + "[" * 100_000 + "]" * 100_000 + "}",
    "a 2 MB message": json.dumps({"type": "run", "name": "a.root", "text": "x" * 2_000_000}),
    "a robot message with nonsense": json.dumps({"type": "robot_linked", "name": [1, {}]}),
    "a written packet numbered 10**400": '{"type": "robot_written", "n": 1' + "0" * 400 + "}",
    "a notify with a number for data": json.dumps({"type": "robot_notify", "data": 7}),
    "not an object": "[1, 2, 3]",
    "a bare number": "1" + "0" * 400,
}


@pytest.mark.parametrize("message", MALFORMED.values(), ids=MALFORMED.keys())
def test_every_malformed_message_gets_an_error_reply_and_the_session_goes_on(
    studio: RunningStudio, message: str
) -> None:
    async def check(session: aiohttp.ClientSession) -> None:
        async with session.ws_connect("/ws", origin=studio.address) as socket:
            await socket.send_str(message)
            reply = await socket.receive_json(timeout=10)
            assert reply["type"] == "error" and reply["code"] in ("E805", "E806", "E816")
            assert len(reply["message"]) < 300
            square = (PROGRAMS / "square.root").read_text(encoding="utf-8")
            await socket.send_json({"type": "run", "name": "square.root", "text": square,
                                    "speed": 0})  # fmt: skip
            async with _time_limit(30):  # the session still runs programs
                async for answer in socket:
                    data = json.loads(answer.data)
                    assert data["type"] != "error", data
                    if data["type"] == "ended":
                        assert data["end"] == "finished"
                        break

    with_session(studio, check)


def test_a_message_too_big_to_read_closes_the_socket_with_its_code(studio: RunningStudio) -> None:
    async def check(session: aiohttp.ClientSession) -> None:
        async with session.ws_connect("/ws", origin=studio.address) as socket:
            with contextlib.suppress(ConnectionError):  # (closed while it was still sending)
                await socket.send_str("x" * 5_000_000)
                closing = await socket.receive(timeout=10)
                assert closing.type in (aiohttp.WSMsgType.CLOSE, aiohttp.WSMsgType.CLOSED)
                assert socket.close_code == 1009
        # and the server serves the next page as ever
        setup = await session.get("/api/setup")
        assert setup.status == 200

    with_session(studio, check)


def test_on_the_network_only_this_computers_names_and_allowed_ones_are_answered(
    class_folder: Path,
) -> None:
    """DNS rebinding: a web site whose name was made to point at this computer is refused on
    0.0.0.0 as on 127.0.0.1; the address printed for pupils, this computer's names and
    addresses, and each --allow-host are answered."""
    studio = RunningStudio(class_folder, host="0.0.0.0", allow_hosts=("Studio.School.LAN",))
    studio.start()
    printed = studio.address.removeprefix("http://")
    shown, port = printed.rsplit(":", 1)
    assert shown not in ("0.0.0.0", "127.0.0.1", "localhost")  # what pupils should type

    async def check(session: aiohttp.ClientSession) -> None:
        async def status(host: str) -> int:
            reply = await session.get(f"http://127.0.0.1:{port}/api/setup",
                                      headers={"Host": f"{host}:{port}"})  # fmt: skip
            if reply.status == 403:
                assert (await reply.json())["errors"][0]["code"] == "E804"
            return reply.status

        assert await status("evil.example") == 403
        assert await status("rebind.attacker.test") == 403
        assert await status(socket.gethostname()) == 200
        assert await status(shown) == 200
        assert await status("localhost") == 200
        assert await status("studio.school.lan") == 200  # --allow-host, any case
        assert await status("127.0.0.1") == 200  # the address it was reached at

    try:
        with_session(studio, check)
    finally:
        studio.stop()


def test_on_this_computer_only_an_allowed_name_is_answered_too(class_folder: Path) -> None:
    studio = RunningStudio(class_folder, allow_hosts=("proxy.school.lan",)).start()
    port = studio.address.rsplit(":", 1)[1]

    async def check(session: aiohttp.ClientSession) -> None:
        for host, expected in (("proxy.school.lan", 200), (socket.gethostname(), 403),
                               ("evil.example", 403)):  # fmt: skip
            reply = await session.get("/api/setup", headers={"Host": f"{host}:{port}"})
            assert reply.status == expected, host

    try:
        with_session(studio, check)
    finally:
        studio.stop()


def test_a_layout_sidecar_or_worlds_folder_pointing_out_is_not_followed(
    class_folder: Path, tmp_path: Path
) -> None:
    outside = tmp_path / "outside"
    outside.mkdir()
    secret = outside / "secret.json"
    secret.write_text('{"secret": "not for the page"}', encoding="utf-8")
    (class_folder / ".square.root.layout.json").symlink_to(secret)
    (outside / "evil.toml").write_text("time_limit = 5\n", encoding="utf-8")
    (class_folder / "worlds").symlink_to(outside, target_is_directory=True)
    studio = RunningStudio(class_folder).start()

    async def check(session: aiohttp.ClientSession) -> None:
        read = await (await session.get("/api/program", params={"name": "square.root"})).json()
        assert read["layout"] == {}
        text = read["text"]
        saved = await session.put("/api/program", json={"name": "square.root", "text": text,
                                                         "layout": {"mine": 1}})  # fmt: skip
        assert saved.status == 400 and (await saved.json())["errors"][0]["code"] == "E808"
        setup = await (await session.get("/api/setup")).json()
        assert "evil" not in setup["worlds"]
        async with session.ws_connect("/ws", origin=studio.address) as socket:
            await socket.send_json({"type": "run", "name": "square.root", "text": text,
                                    "speed": 0, "world": "evil"})  # fmt: skip
            reply = await socket.receive_json(timeout=10)
            assert reply["type"] == "error" and reply["code"] == "E306"

    try:
        with_session(studio, check)
    finally:
        studio.stop()
    assert secret.read_text(encoding="utf-8") == '{"secret": "not for the page"}'


@pytest.mark.parametrize(
    "headers",
    [{"Origin": "http://evil.example"}, {"Sec-Fetch-Site": "cross-site"}],
    ids=["another origin", "a cross-site request without Origin (an <img>)"],
)
def test_a_cross_site_request_cant_start_a_robot_scan(
    studio: RunningStudio, headers: dict[str, str], monkeypatch: pytest.MonkeyPatch
) -> None:
    started: list[BaseProcess] = []  # the processes the studio started (a scan is one)
    start = runs.start_process

    def recorded(target: Callable[..., None], args: tuple[Any, ...]) -> BaseProcess:
        started.append(start(target, args))
        return started[-1]

    monkeypatch.setattr(runs, "start_process", recorded)

    async def check(session: aiohttp.ClientSession) -> None:
        reply = await session.get("/api/robots", headers=headers)
        assert reply.status == 403 and (await reply.json())["errors"][0]["code"] == "E804"
        assert started == []  # refused before any scan

    with_session(studio, check)
