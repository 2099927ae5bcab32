"""The studio's server, over real HTTP and a real WebSocket: files, conversions, live runs in
worker processes, stimuli, limits, and refusing what it must refuse."""

from __future__ import annotations

import asyncio
import contextlib
import json
import re
from collections.abc import AsyncIterator, Awaitable, Callable
from dataclasses import replace
from pathlib import Path
from types import SimpleNamespace
from typing import Any, cast

import aiohttp
import pytest

import rootlang.blocks
import rootlang.blocks.pictures
from rootlang.app.session import simulate
from rootlang.checks import load_checked
from rootlang.cli import main
from rootlang.diagnostics import RootlangError
from rootlang.locale.keywords import LANGUAGE_NAMES
from rootlang.locale.translate import about, from_english
from rootlang.messages import MESSAGES
from rootlang.runtime.stops import StoppedBy, StopReason
from rootlang.sim.world import default_world
from rootlang.studio.folder import ClassFolder
from rootlang.studio.pages import setup_in_language
from rootlang.studio.runs import ClassLimits
from rootlang.studio.server import Session, make_app
from rootlang.studio.worker import child_trace
from rootlang.wording.catalogue import translations
from rootlang.wording.language import Languages

from .conftest import PROGRAMS, RunningStudio

Check = Callable[[aiohttp.ClientSession], Awaitable[None]]
Socket = aiohttp.ClientWebSocketResponse[bool]


@contextlib.asynccontextmanager
async def _time_limit(seconds: float) -> AsyncIterator[None]:
    """``asyncio.timeout`` for Python 3.10 too: the block is cancelled after ``seconds``."""
    task = asyncio.current_task()
    assert task is not None
    handle = asyncio.get_running_loop().call_later(seconds, task.cancel)
    try:
        yield
    except asyncio.CancelledError:
        raise TimeoutError(f"still waiting after {seconds} s") from None
    finally:
        handle.cancel()


def with_session(studio: RunningStudio, check: Check) -> None:
    async def main() -> None:
        async with aiohttp.ClientSession(studio.address) as session:
            await check(session)

    asyncio.run(main())


async def run_program(
    session: aiohttp.ClientSession,
    name: str,
    text: str,
    *,
    speed: float = 0,
    world: str = "",
    during: Callable[[Socket, dict[str, Any]], Awaitable[None]] | None = None,
    origin: str = "",
    language: str = "",
) -> tuple[dict[str, Any], list[dict[str, Any]]]:
    """Run over the WebSocket (from a page in ``language``, if given); the "ended" message and
    every frame before it."""
    base = str(session._base_url).rstrip("/")
    frames: list[dict[str, Any]] = []
    spoken = {"language": language} if language else {}
    async with session.ws_connect("/ws", origin=origin or base, params=spoken) as socket:
        await socket.send_json({"type": "run", "name": name, "text": text, "speed": speed,
                                "world": world})  # fmt: skip
        async with _time_limit(60):
            async for message in socket:
                data = json.loads(message.data)
                if data["type"] == "frame":
                    frames.append(data)
                    if during is not None:
                        await during(socket, data)
                elif data["type"] == "ended":
                    return data, frames
                elif data["type"] == "error":
                    raise AssertionError(data["message"])
    raise AssertionError("the run never ended")


def golden_world_pose(name: str) -> tuple[int, int, int]:
    golden = (PROGRAMS / name).with_suffix(".golden").read_text(encoding="utf-8")
    found = re.search(r"in the world: x (-?\d+) mm, y (-?\d+) mm, heading (\d+)°", golden)
    assert found, "the golden file has the final pose"
    x, y, heading = found.groups()
    return int(x), int(y), int(heading)


# --- files ------------------------------------------------------------------------------------


def test_setup_lists_the_folder_programs_and_worlds(studio: RunningStudio) -> None:
    async def check(session: aiohttp.ClientSession) -> None:
        setup = await (await session.get("/api/setup")).json()
        names = [p["name"] for p in setup["programs"]]
        assert names == sorted(names) and "square.root" in names
        assert {"arena", "nose_button"} <= set(setup["worlds"])
        assert setup["speeds"] == [1, 2, 5, 10, 0]
        assert list(setup["languages"].items()) == list(LANGUAGE_NAMES.items())

    with_session(studio, check)


def test_the_setup_in_a_language_is_made_once(
    studio: RunningStudio, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The page asks for the setup at every New and Rename: its blocks and toolbox in a
    language are translated the first time only."""
    made: list[str] = []
    translated = rootlang.blocks.block_definitions

    def counted(language: str = "en") -> list[dict[str, Any]]:
        made.append(language)
        return translated(language)

    monkeypatch.setattr(rootlang.blocks, "block_definitions", counted)
    setup_in_language.cache_clear()

    async def check(session: aiohttp.ClientSession) -> None:
        for language in ("nl", "nl", "fr", "nl", "fr"):
            setup = await (await session.get("/api/setup", params={"language": language})).json()
            assert setup["language"] == language
            pictures = rootlang.blocks.pictures.picture_definitions(language)  # (Level 1's)
            assert setup["blocks"]["definitions"] == [*translated(language), *pictures]

    try:
        with_session(studio, check)
    finally:
        setup_in_language.cache_clear()  # (made with the counting stand-in)
    assert made == ["nl", "fr"]


@pytest.mark.parametrize(("language", "if_word"), [("en", "if"), ("nl", "als"), ("de", "falls")])
def test_the_setup_names_blocklys_own_words_in_the_language(
    studio: RunningStudio, language: str, if_word: str
) -> None:
    async def check(session: aiohttp.ClientSession) -> None:
        setup = await (await session.get("/api/setup", params={"language": language})).json()
        served = await session.get(setup["blockly_messages"])
        assert served.status == 200
        assert f'Blockly.Msg["CONTROLS_IF_MSG_IF"] = "{if_word}";' in await served.text()

    with_session(studio, check)


def test_save_create_rename_and_the_layout_sidecar(studio: RunningStudio) -> None:
    async def check(session: aiohttp.ClientSession) -> None:
        made = await (await session.post("/api/program", json={"name": "dance.root"})).json()
        assert made["text"].startswith("# dance.root")
        text = "when started\n    move 10 cm\n"
        layout = {"top": {"0:when started": [40, 60]}}
        reply = await session.put("/api/program", json={"name": "dance.root", "text": text,
                                                        "layout": layout})  # fmt: skip
        assert reply.status == 200
        assert (studio.folder / "dance.root").read_text(encoding="utf-8") == text
        renamed = await session.post("/api/rename", json={"old": "dance.root", "new": "jig.root"})
        assert renamed.status == 200
        opened = await (await session.get("/api/program", params={"name": "jig.root"})).json()
        assert opened["text"] == text and opened["layout"] == layout
        assert not (studio.folder / "dance.root").exists()
        again = await session.post("/api/program", json={"name": "jig.root"})
        assert again.status == 400 and (await again.json())["errors"][0]["code"] == "E803"

    with_session(studio, check)


@pytest.mark.parametrize(
    "name", ["../escape.root", "/etc/passwd.root", "sub/x.root", "notes.txt", "..root", ""]
)
def test_names_outside_the_folder_are_refused(studio: RunningStudio, name: str) -> None:
    async def check(session: aiohttp.ClientSession) -> None:
        read = await session.get("/api/program", params={"name": name})
        assert read.status == 400 and (await read.json())["errors"][0]["code"] == "E801"
        written = await session.put("/api/program", json={"name": name, "text": "x"})
        assert written.status == 400

    with_session(studio, check)
    assert not (studio.folder.parent / "escape.root").exists()


def test_a_symlink_out_of_the_folder_is_not_followed(studio: RunningStudio) -> None:
    secret = studio.folder.parent / "secret.root"
    secret.write_text('when started\n    say "secret"\n', encoding="utf-8")
    (studio.folder / "link.root").symlink_to(secret)

    async def check(session: aiohttp.ClientSession) -> None:
        setup = await (await session.get("/api/setup")).json()
        assert "link.root" not in [p["name"] for p in setup["programs"]]
        read = await session.get("/api/program", params={"name": "link.root"})
        assert read.status == 400
        static = await session.get("/static/../../secret.root")
        assert static.status in (403, 404)

    with_session(studio, check)


def test_changes_from_another_origin_are_refused(studio: RunningStudio) -> None:
    async def check(session: aiohttp.ClientSession) -> None:
        reply = await session.put("/api/program", json={"name": "square.root", "text": "x"},
                                  headers={"Origin": "http://evil.example"})  # fmt: skip
        assert reply.status == 403 and (await reply.json())["errors"][0]["code"] == "E804"
        with pytest.raises(aiohttp.WSServerHandshakeError):
            await session.ws_connect("/ws", origin="http://evil.example")

    with_session(studio, check)
    assert (studio.folder / "square.root").read_text(encoding="utf-8").startswith("# square")


def test_text_that_does_not_parse_gets_its_errors_and_no_blocks(studio: RunningStudio) -> None:
    async def check(session: aiohttp.ClientSession) -> None:
        broken = {"text": 'when started\n    say "unfinished\n', "name": "a.root"}
        reply = await (await session.post("/api/blocks", json=broken)).json()
        assert reply["workspace"] is None
        assert [(d["code"], d["line"]) for d in reply["diagnostics"]] == [("E002", 2)]
        # a check mistake still has blocks: the mistake is shown on them
        mistaken = {"text": "when started\n    move 10\n", "name": "a.root"}
        reply = await (await session.post("/api/blocks", json=mistaken)).json()
        assert reply["workspace"]["blocks"]["blocks"][0]["id"] == "L1"
        assert [(d["code"], d["line"]) for d in reply["diagnostics"]] == [("E108", 2)]

    with_session(studio, check)


def test_blocks_become_canonical_text(studio: RunningStudio) -> None:
    text = (PROGRAMS / "square.root").read_text(encoding="utf-8")

    async def check(session: aiohttp.ClientSession) -> None:
        blocks = await (await session.post("/api/blocks", json={"text": text})).json()
        back = await (await session.post("/api/text", json=blocks)).json()
        assert back["text"] == text and back["diagnostics"] == []
        # the text's own blocks come with it: which block is which line, in one request
        assert back["workspace"] == blocks["workspace"]
        bad = await session.post("/api/text", json={"workspace": {"blocks": 3}})
        assert bad.status == 400 and (await bad.json())["errors"][0]["code"].startswith("E7")

    with_session(studio, check)


@pytest.mark.parametrize("language", ["en", "nl"])
def test_the_texts_own_blocks_come_without_parsing_it_again(language: str) -> None:
    """For every program (and in Dutch): the blocks → text reply's workspace is what text →
    blocks gives for its text, made from the parse that checked the text reads back."""
    from rootlang.studio.complete import complete_text

    for path in sorted(PROGRAMS.glob("*.root")):
        text = path.read_text(encoding="utf-8")
        if language != "en":
            text = f"# language: {language}\n" + from_english(text, language)
        try:
            workspace = rootlang.blocks.to_workspace(text)
        except RootlangError:
            continue  # (the programs with mistakes have no blocks)
        made, left_out = complete_text(workspace)
        assert left_out == []
        assert made.text_workspace() == rootlang.blocks.to_workspace(made.text), path.name


# --- the WebSocket --------------------------------------------------------------------------


@pytest.mark.parametrize(
    "message",
    ["not json", "[1, 2]", '{"type": "fly"}', '{"type": "run"}',
     '{"type": "run", "name": "../x.root", "text": ""}',
     '{"type": "run", "name": "a.root", "text": "", "speed": 3}',
     '{"type": "run", "name": "a.root", "text": "", "world": "nowhere"}',
     '{"type": "stimulus", "action": "explode"}',
     '{"type": "stimulus", "action": "touch", "sensors": "all"}'],
)  # fmt: skip
def test_bad_messages_get_an_error_reply_and_the_socket_stays_up(
    studio: RunningStudio, message: str
) -> None:
    async def check(session: aiohttp.ClientSession) -> None:
        async with session.ws_connect("/ws", origin=studio.address) as socket:
            await socket.send_str(message)
            reply = await socket.receive_json(timeout=10)
            assert reply["type"] == "error" and re.fullmatch(r"E\d{3}", reply["code"])
            await socket.send_str('{"type": "fly"}')  # still answering
            assert (await socket.receive_json(timeout=10))["code"] == "E806"

    with_session(studio, check)


def test_square_runs_live_and_ends_where_its_golden_file_says(studio: RunningStudio) -> None:
    text = (PROGRAMS / "square.root").read_text(encoding="utf-8")

    async def check(session: aiohttp.ClientSession) -> None:
        ended, frames = await run_program(session, "square.root", text, speed=10)
        assert ended["end"] == "finished" and ended["said"] == ["done"]
        pose = ended["world_pose"]
        x, y, heading = golden_world_pose("square.root")
        assert (pose["x_mm"], pose["y_mm"], round(pose["heading_deg"]) % 360) == (x, y, heading)
        assert len(frames) > 10  # streamed as it ran, not at the end
        assert any(f["running"] for f in frames)  # the running line came along
        lines = {line for f in frames for line in f["running"].values()}
        assert {5, 6} <= lines  # move 10 cm, turn right 90 degrees
        ink = [f for f in frames if f["ink"]]
        assert ink and ink[0]["ink"][0]["kind"] == "marker"
        replay = await session.get(ended["replay"])
        assert replay.status == 200 and "<canvas" in await replay.text()
        assert any("say" in line for line in ended["trace"])

    with_session(studio, check)


def test_the_nose_button_stops_the_run_and_when_stopped_runs(studio: RunningStudio) -> None:
    text = (PROGRAMS / "stop_button.root").read_text(encoding="utf-8")
    text = text.replace("# world: worlds/nose_button.toml\n", "")  # no scripted press

    async def press_once(socket: Socket, frame: dict[str, Any]) -> None:
        if frame["t"] >= 1.0 and not pressed:
            pressed.append(frame["t"])
            await socket.send_json({"type": "stimulus", "action": "nose"})

    pressed: list[float] = []

    async def check(session: aiohttp.ClientSession) -> None:
        ended, _ = await run_program(session, "stop_button.root", text, speed=5, during=press_once)
        assert ended["end"] == "stopped" and "stop button" in ended["stopped_by"]
        assert ended["sim_time_s"] < 10
        assert any(p.startswith("stopped at") for p in ended["printed"])  # `when stopped` ran

    with_session(studio, check)


def test_touching_the_robot_fires_its_touch_scripts(studio: RunningStudio) -> None:
    text = (
        "when started\n    wait 30 seconds\n\n"
        'when touch front left pressed\n    print "ouch"\n    stop all\n'
    )

    async def touch(socket: Socket, frame: dict[str, Any]) -> None:
        if frame["t"] >= 0.5 and not touched:
            touched.append(True)
            await socket.send_json({"type": "stimulus", "action": "touch",
                                    "sensors": ["front left"]})  # fmt: skip

    touched: list[bool] = []

    async def check(session: aiohttp.ClientSession) -> None:
        ended, _ = await run_program(session, "touch.root", text, speed=10, during=touch)
        assert ended["printed"] == ["ouch"] and ended["end"] == "stopped"

    with_session(studio, check)


def test_pressing_a_bumper_fires_its_bumper_scripts(studio: RunningStudio) -> None:
    text = (
        "when started\n    wait 30 seconds\n\n"
        'when bumper right pressed\n    print "right"\n\n'
        'when bumper right released\n    print "let go"\n    stop all\n'
    )

    async def bump(socket: Socket, frame: dict[str, Any]) -> None:
        if frame["t"] >= 0.5 and not pressed:
            pressed.append(True)
            await socket.send_json({"type": "stimulus", "action": "bump", "sensors": ["right"]})

    pressed: list[bool] = []

    async def check(session: aiohttp.ClientSession) -> None:
        ended, _ = await run_program(session, "bump.root", text, speed=10, during=bump)
        assert ended["printed"] == ["right", "let go"] and ended["end"] == "stopped"

    with_session(studio, check)


def test_the_frames_tell_what_the_robot_felt(studio: RunningStudio) -> None:
    """A wall the simulated robot drives into (the page says it to a screen reader)."""

    async def check(session: aiohttp.ClientSession) -> None:
        _, frames = await run_program(session, "wall.root", "when started\n    move 300 cm\n")
        felt = [happening for frame in frames for happening in frame["happened"]]
        assert "bumper both" in felt, felt

    with_session(studio, check)


def test_an_endless_busy_loop_is_stopped_and_stalls_nobody(studio: RunningStudio) -> None:
    endless = "when started\n    set n to 0\n    repeat forever\n        change n by 1\n"
    square = (PROGRAMS / "square.root").read_text(encoding="utf-8")

    async def check(session: aiohttp.ClientSession) -> None:
        async with session.ws_connect("/ws", origin=studio.address) as busy:
            await busy.send_json({"type": "run", "name": "busy.root", "text": endless,
                                  "speed": 10})  # fmt: skip
            # meanwhile, another child's run goes on as usual
            ended, _ = await run_program(session, "square.root", square, speed=10)
            assert ended["end"] == "finished"
            await busy.send_json({"type": "stop"})
            async with _time_limit(30):
                async for message in busy:
                    data = json.loads(message.data)
                    if data["type"] == "ended":
                        assert data["end"] in ("stopped", "limit")
                        break

    with_session(studio, check)


def test_a_run_that_computes_too_long_ends_at_the_cpu_time_limit(class_folder: Path) -> None:
    """At "as fast as it goes", a busy loop in a world with a very long time limit is ended by
    its CPU time (1 s here): the run stops itself (E220, at the line it was running, the robot
    stopped), with the message that says so; the server goes on serving."""
    (class_folder / "worlds").mkdir()
    (class_folder / "worlds" / "long.toml").write_text("time_limit = 100000\n", encoding="utf-8")
    endless = "when started\n    set n to 0\n    repeat forever\n        change n by 1\n"
    studio = RunningStudio(class_folder, limits=ClassLimits(cpu_seconds=1)).start()

    async def check(session: aiohttp.ClientSession) -> None:
        ended, _ = await run_program(session, "busy.root", endless, speed=0, world="long")
        assert ended["end"] == "error" and ended["error"]["code"] == "E220", ended
        assert ended["error"]["message"].startswith("This program kept the computer busy for 1 s")
        assert ended["error"]["line"] in (3, 4)  # the loop's line, or the line in it
        square = (PROGRAMS / "square.root").read_text(encoding="utf-8")
        ended, _ = await run_program(session, "square.root", square, speed=0)
        assert ended["end"] == "finished"

    try:
        with_session(studio, check)
    finally:
        studio.stop()


def test_a_memory_bomb_ends_with_the_memory_message(studio: RunningStudio) -> None:
    bomb = 'when started\n    set s to "x"\n    forever\n        set s to join(s, s)\n'

    async def check(session: aiohttp.ClientSession) -> None:
        ended, _ = await run_program(session, "bomb.root", bomb, speed=0)
        # the runtime names the line that kept growing; the cap kept the machine safe
        assert ended["end"] == "error" and ended["error"]["code"] == "E216"
        assert ended["error"]["line"] == 4

    with_session(studio, check)


def test_closing_the_page_stops_the_run(studio: RunningStudio) -> None:
    forever = "when started\n    forever\n        move 10 cm\n        turn right 90 degrees\n"

    async def check(session: aiohttp.ClientSession) -> None:
        earlier = alive_workers()  # (an earlier test's, still ending: not this run's)
        socket = await session.ws_connect("/ws", origin=studio.address)
        await socket.send_json({"type": "run", "name": "f.root", "text": forever, "speed": 1})
        assert (await socket.receive_json(timeout=20))["type"] == "started"
        workers = [worker for worker in alive_workers() if worker not in earlier]
        assert workers, "the run has a worker process"
        await socket.close()
        for worker in workers:  # (killed at once; the bound is for a busy machine)
            await asyncio.get_running_loop().run_in_executor(None, worker.join, 30)
        assert not any(worker.is_alive() for worker in workers), "the worker outlived the page"

    with_session(studio, check)


def alive_workers() -> list[Any]:
    import multiprocessing

    from rootlang.studio.pool import PROCESS_NAME

    return [
        p
        for p in multiprocessing.active_children()
        if p.is_alive() and p.name != PROCESS_NAME  # a run's, not a conversion worker
    ]


def test_program_mistakes_come_back_as_diagnostics(studio: RunningStudio) -> None:
    async def check(session: aiohttp.ClientSession) -> None:
        ended, frames = await run_program(session, "bad.root", "when started\n    move 10\n")
        assert ended["end"] == "mistakes" and not frames
        assert ended["errors"][0]["code"] == "E108" and ended["errors"][0]["line"] == 2

    with_session(studio, check)


def test_a_world_from_the_chooser_is_used(studio: RunningStudio, tmp_path: Path) -> None:
    text = "when started\n    drive 10 cm/s\n    wait until bumper any pressed\n    stop all\n"

    async def check(session: aiohttp.ClientSession) -> None:
        ended, _ = await run_program(session, "wall.root", text, world="arena", speed=0)
        assert ended["end"] == "stopped" and ended["stage"]["world"]["name"] == "arena"

    with_session(studio, check)


# --- the page's language: everything the server tells a page is in it ---------------------------

TRANSLATED = ("nl", "es", "fr", "de")
# a typo (with a suggestion), a unit it does not know, a time where an angle goes
MISTAKES = "when started\n    mvoe 10 cm\n    move 10 apples\n    turn left 10 seconds\n"
DIVIDES_BY_ZERO = "when started\n    move 10 cm / 0\n"


def written_in(language: str, english: str) -> str:
    return f"# language: {language}\n" + from_english(english, language)


async def mistakes_of(session: aiohttp.ClientSession, text: str, language: str) -> list[Any]:
    """The mistakes the page in ``language`` is shown for ``text``, as it types."""
    asked = {"text": text, "name": "a.root"}
    reply = await session.post("/api/blocks", params={"language": language}, json=asked)
    return list((await reply.json())["diagnostics"])


@pytest.mark.usefixtures("english_computer")
@pytest.mark.parametrize("language", TRANSLATED)
def test_a_pages_mistakes_are_told_in_its_language_as_the_command_line_tells_them(
    studio: RunningStudio,
    language: str,
    monkeypatch: pytest.MonkeyPatch,
    capsys: pytest.CaptureFixture[str],
) -> None:
    text = written_in(language, MISTAKES)
    shown: list[Any] = []

    async def check(session: aiohttp.ClientSession) -> None:
        shown.extend(await mistakes_of(session, text, language))

    with_session(studio, check)  # (first: the command line leaves its choices behind it)
    (studio.folder / "a.root").write_text(text, encoding="utf-8")
    monkeypatch.chdir(studio.folder)
    assert main(["check", "a.root"]) == 1
    told = capsys.readouterr().err.strip().split("\n\n")
    assert [d["code"] for d in shown] == ["E023", "E014", "E109"]
    assert [d["rendered"] for d in shown] == told


@pytest.mark.usefixtures("english_computer")
def test_an_english_program_on_a_dutch_page_gets_dutch_messages_about_its_english_code(
    studio: RunningStudio,
) -> None:
    async def check(session: aiohttp.ClientSession) -> None:
        shown = await mistakes_of(session, "when started\n    move 10\n", "nl")
        assert [d["message"] for d in shown] == [
            "move heeft een afstand nodig, zoals `move 10 cm`. Schrijf: `move 10 cm`"
        ]
        typo = await mistakes_of(
            session, "# language: nl\nwanneer gestart\n    beweg 10 cm\n", "nl"
        )
        assert [d["message"] for d in typo] == [
            'Ik ken de opdracht "beweg" niet. Bedoel je "beweeg"?'
        ]
        english = await mistakes_of(session, "when started\n    move 10\n", "en")
        assert [d["message"] for d in english] == [
            "move needs a distance, like `move 10 cm`. Write: `move 10 cm`"
        ]

    with_session(studio, check)


@pytest.mark.usefixtures("english_computer")
@pytest.mark.parametrize("language", TRANSLATED)
def test_a_runs_mistakes_and_errors_are_told_in_the_pages_language(
    studio: RunningStudio, language: str
) -> None:
    async def check(session: aiohttp.ClientSession) -> None:
        failed, _ = await run_program(
            session, "zero.root", written_in(language, DIVIDES_BY_ZERO), language=language
        )
        assert failed["end"] == "error" and failed["error"]["code"] == "E204"
        assert failed["error"]["message"] == translations(language)["E204"] != MESSAGES["E204"]
        # a program that does not check is told by the run's worker as by the text's checks
        text = written_in(language, MISTAKES)
        stopped, _ = await run_program(session, "a.root", text, language=language)
        assert stopped["end"] == "mistakes"
        checked = await mistakes_of(session, text, language)
        assert [d["message"] for d in stopped["errors"]] == [d["message"] for d in checked]
        english = await mistakes_of(session, text, "en")
        assert stopped["errors"][0]["message"] != english[0]["message"]

    with_session(studio, check)


@pytest.mark.usefixtures("english_computer")
def test_the_servers_own_refusals_are_told_in_the_pages_language(studio: RunningStudio) -> None:
    async def check(session: aiohttp.ClientSession) -> None:
        read = await session.get("/api/program", params={"name": "../x.root", "language": "fr"})
        told = (await read.json())["errors"][0]["message"]
        assert told == translations("fr")["E801"].format(name="../x.root")
        spoken = {"language": "es"}
        async with session.ws_connect("/ws", origin=studio.address, params=spoken) as socket:
            await socket.send_str('{"type": "fly"}')
            reply = await socket.receive_json(timeout=10)
            assert reply["message"].startswith("El estudio no pudo usar este mensaje: ")

    with_session(studio, check)


STOPS_ALL = 'when started\n    say "hi"\n    stop all\n'


@pytest.mark.usefixtures("english_computer")
def test_what_happened_in_a_run_is_told_in_the_pages_language(studio: RunningStudio) -> None:
    async def check(session: aiohttp.ClientSession) -> None:
        dutch, _ = await run_program(
            session, "stop.root", written_in("nl", STOPS_ALL), language="nl"
        )
        assert dutch["end"] == "stopped" and dutch["stopped_by"] == "stop alles"
        told = [line.split(" s  ", 1)[1] for line in dutch["trace"]]
        assert told[1] == "regel 2: `wanneer gestart` begint"
        assert told[2:4] == ['regel 3: zeg "hi"', "regel 2: `wanneer gestart` is afgebroken"]
        assert told[-1] == "afgelopen: gestopt (stop alles)"
        english, _ = await run_program(session, "stop.root", STOPS_ALL, language="en")
        assert english["stopped_by"] == "stop all"
        told = [line.split(" s  ", 1)[1] for line in english["trace"]]
        assert told[1] == "line 1: `when started` starts"
        assert told[2:4] == ['line 2: say "hi"', "line 1: `when started` cancelled"]
        assert told[-1] == "ended: stopped (stop all)"

    with_session(studio, check)


MOVES = "when started\n    move 10 cm\n    turn left 90 degrees\n"


@pytest.mark.usefixtures("english_computer")
def test_what_happened_shows_the_commands_as_the_program_wrote_them(
    studio: RunningStudio,
) -> None:
    """Commands in the program's own words (not the trace's English), which robot it ran on in
    the page's language, and none of the runtime's own commands (Stop and Reset, the position
    read at the end)."""

    async def check(session: aiohttp.ClientSession) -> None:
        dutch, _ = await run_program(session, "m.root", written_in("nl", MOVES), language="nl")
        told = [line.split(" s  ", 1)[1] for line in dutch["trace"]]
        assert told == [
            "verbonden met Root RT1 (protocol 1.3)",
            "regel 2: `wanneer gestart` begint",
            "regel 3: beweeg 10 cm",
            "regel 4: draai links 90 graden",
            "regel 2: `wanneer gestart` is klaar",
            "afgelopen: klaar (elk script is klaar)",
        ]
        english, _ = await run_program(session, "m.root", MOVES, language="en")
        told = [line.split(" s  ", 1)[1] for line in english["trace"]]
        assert told[0] == "connected to Root RT1 (protocol 1.3)"
        assert told[2:4] == ["line 2: move 10 cm", "line 3: turn left 90 degrees"]

    with_session(studio, check)


@pytest.mark.usefixtures("english_computer")
def test_what_happened_tells_a_command_cut_short_and_a_push_as_rootlang_sim_does(
    studio: RunningStudio,
) -> None:
    """The same lines as the command line's child's view (one view, its records): which line
    cut a move short and after how long, and how long the robot pushed against a wall."""
    cut = (Path(__file__).parents[2] / "programs" / "interrupted.root").read_text("utf-8")
    wall = "when started\n    drive 5 cm/s\n    wait 20 seconds\n    stop moving\n"

    async def check(session: aiohttp.ClientSession) -> None:
        ended, _ = await run_program(session, "cut.root", cut, language="en")
        told = [line.split(" s  ", 1)[1] for line in ended["trace"]]
        assert "line 4: move 50 cm — stopped after 0.7 s: line 13 started a new one" in told
        assert any(t.startswith("line 9: play note C4 for 5 seconds — stopped after 2.2 s")
                   for t in told), told  # fmt: skip
        ended, _ = await run_program(session, "wall.root", wall, world="arena", language="en")
        pushed = [line for line in ended["trace"] if "pushed against something" in line]
        assert [line.split()[0] for line in pushed] == ["15.36"], ended["trace"]
        assert pushed[0].endswith("the robot pushed against something for 4.6 s")

    with_session(studio, check)


def test_what_happened_counts_a_line_that_comes_again_and_again() -> None:
    """A loop with one command in it fills *What happened* with one line and a count (as
    `rootlang sim` shows it), in the page's language; then the run's end."""
    source = written_in("nl", 'when started\n    forever\n        say "hi"\n        wait 0.2 s\n')
    checked = load_checked(source, "loop.root")
    result, _ = simulate(checked.program, replace(default_world(), time_limit=10), source=source)
    languages = about(Languages(page="nl"), source)  # (as the worker does: its keywords)
    told = [
        line.split(" s  ", 1)[1]
        for line in child_trace(result.trace.entries, source, checked.program, languages)
    ]
    assert told[2] == 'regel 4: zeg "hi"'
    assert re.fullmatch(r"\.\.\. nog \d\d keer, tot 9\.\d s", told[3]), told[3]
    assert told[4:] == [
        "regel 2: `wanneer gestart` is afgebroken",
        "afgelopen: de tijd is op (de tijdslimiet van 10 s)",
    ]


@pytest.mark.parametrize("language", TRANSLATED)
def test_a_run_stopped_by_the_studio_is_told_in_the_pages_language(
    tmp_path: Path, language: str
) -> None:
    closed = cast(Any, SimpleNamespace(closed=True))  # (the page has gone: nothing is sent)
    session = Session(make_app(ClassFolder(tmp_path)), closed, Languages(page=language))
    ended = {"end": "stopped", **StoppedBy(StopReason.ROBOT_STOP_BUTTON).outcome()}
    session._forward("ended", ended)
    assert ended["stopped_by"] == translations(language)["V022"] != MESSAGES["V022"]
    assert "stop" not in ended  # the page is told in words


def test_a_runs_ending_told_later_is_told_in_the_pages_language(tmp_path: Path) -> None:
    """A deadline or the worker's end is called back outside the page's request: the session
    keeps the page's language for it."""
    closed = cast(Any, SimpleNamespace(closed=True))  # (the page has gone: nothing is sent)
    session = Session(make_app(ClassFolder(tmp_path)), closed, Languages(page="de"))
    ended: dict[str, Any] = {"end": "limit", "code": "E811", "limit": "65 s"}
    session._forward("ended", ended)
    assert ended["error"]["message"] == translations("de")["E811"].format(limit="65 s")


@pytest.mark.usefixtures("english_computer")
def test_two_pages_in_two_languages_at_once_each_get_their_own(studio: RunningStudio) -> None:
    """Two tabs served by one server at the same time: their requests interleave (one still
    sending while the other is answered), their WebSockets are open together and their runs
    overlap; nothing of one's language reaches the other."""
    dutch, german = written_in("nl", DIVIDES_BY_ZERO), written_in("de", DIVIDES_BY_ZERO)

    async def sent_slowly(
        session: aiohttp.ClientSession, language: str, go_on: asyncio.Event
    ) -> list[Any]:
        """The mistakes of MISTAKES in ``language``, the request's body held back until
        ``go_on``: the server has begun it and waits for the rest."""
        body = json.dumps({"text": written_in(language, MISTAKES), "name": "a.root"}).encode()

        async def slowly() -> AsyncIterator[bytes]:
            yield body[:8]
            await go_on.wait()
            yield body[8:]

        reply = await session.post("/api/blocks", params={"language": language}, data=slowly(),
                                   headers={"Content-Type": "application/json"})  # fmt: skip
        return list((await reply.json())["diagnostics"])

    async def interleaved_requests(session: aiohttp.ClientSession) -> None:
        go_on = {language: asyncio.Event() for language in ("nl", "de")}
        asked = {language: asyncio.ensure_future(sent_slowly(session, language, go_on[language]))
                 for language in go_on}  # fmt: skip
        await asyncio.sleep(0.3)  # both have begun; the first to begin is answered first
        for language, begins in [("nl", "Ik ken de opdracht"), ("de", "Ich kenne den Befehl")]:
            go_on[language].set()
            told = await asyncio.wait_for(asked[language], 30)
            assert told == await mistakes_of(session, written_in(language, MISTAKES), language)
            assert told[0]["message"].startswith(begins)

    async def sockets_open_together(session: aiohttp.ClientSession) -> None:
        async with (
            session.ws_connect("/ws", origin=studio.address, params={"language": "nl"}) as nl,
            session.ws_connect("/ws", origin=studio.address, params={"language": "de"}) as de,
        ):
            for socket, said in [(nl, "De studio"), (de, "Das Studio"), (nl, "De studio")]:
                await socket.send_str('{"type": "fly"}')
                assert (await socket.receive_json(timeout=10))["message"].startswith(said)

    async def check(session: aiohttp.ClientSession) -> None:
        await interleaved_requests(session)
        await sockets_open_together(session)
        runs = await asyncio.gather(
            run_program(session, "nul.root", dutch, language="nl", speed=1),
            run_program(session, "null.root", german, language="de", speed=1),
            run_program(session, "zero.root", DIVIDES_BY_ZERO, speed=1),  # (no language asked)
        )
        assert [ended["error"]["message"] for ended, _ in runs] == [
            translations("nl")["E204"], translations("de")["E204"], MESSAGES["E204"]
        ]  # fmt: skip

    with_session(studio, check)


# --- a robot over Bluetooth: bumble's virtual robot (rootlang[virtual]) ------------------------


def test_robots_in_range_are_listed_and_a_program_runs_on_one(robot_studio: RunningStudio) -> None:
    text = 'when started\n    print "on the robot"\n    move 5 cm\n    say "done"\n'

    async def check(session: aiohttp.ClientSession) -> None:
        listed = await (await session.get("/api/robots")).json()
        robots = listed["robots"]
        assert [(r["name"], r["model"]) for r in robots] == [("Virtual Root", "RT1")]
        async with session.ws_connect("/ws", origin=robot_studio.address) as socket:
            await socket.send_json({"type": "run", "name": "robot.root", "text": text,
                                    "robot": robots[0]["address"]})  # fmt: skip
            messages = []
            async with _time_limit(60):
                async for message in socket:
                    messages.append(json.loads(message.data))
                    if messages[-1]["type"] in ("ended", "error"):
                        break
        started = next(m for m in messages if m["type"] == "started")
        assert "Virtual Root" in started["robot"]
        ended = messages[-1]
        assert ended["type"] == "ended" and ended["end"] == "finished", ended
        assert ended["printed"] == ["on the robot"]
        assert any("move" in line for line in ended["trace"])

    with_session(robot_studio, check)


def test_stop_stops_a_program_on_a_robot(robot_studio: RunningStudio) -> None:
    text = 'when started\n    forever\n        move 5 cm\n\nwhen stopped\n    print "bye"\n'

    async def check(session: aiohttp.ClientSession) -> None:
        async with session.ws_connect("/ws", origin=robot_studio.address) as socket:
            await socket.send_json({"type": "run", "name": "robot.root", "text": text,
                                    "robot": ""})  # fmt: skip
            async with _time_limit(60):
                async for message in socket:
                    data = json.loads(message.data)
                    if data["type"] == "frame" and data["t"] > 1:
                        await socket.send_json({"type": "stop"})
                    if data["type"] == "ended":
                        assert data["end"] == "stopped" and data["stopped_by"] == "the Stop button"
                        assert data["printed"] == ["bye"]
                        return
        raise AssertionError("no end")

    with_session(robot_studio, check)


def test_frames_keep_a_steady_beat_whatever_making_one_takes() -> None:
    """The frames come 25 a second while the run's own thread computes and holds the
    interpreter's lock for long spells: the next frame is due a period after the last one was
    due, not after it was made (the wait for the lock added to every period: 17 a second), and
    a beat missed is let go, not made up in a burst. (The rate on a busy class is measured by
    benchmarks/studio_clients.py.)"""
    from rootlang.studio.worker import FRAME_PERIOD_S, next_beat

    due = 10.0
    made = due + 0.03  # the frame took 30 ms to make, lock included
    assert next_beat(due, made) == pytest.approx(due + FRAME_PERIOD_S)
    beats, now = [due], due
    for _ in range(25):  # each frame made 30 ms late: still 25 frames in the second
        now = beats[-1] + 0.03
        beats.append(next_beat(beats[-1], now))
    assert beats[-1] - beats[0] == pytest.approx(25 * FRAME_PERIOD_S)
    late = due + 3 * FRAME_PERIOD_S  # stalled for three periods: the next frame comes at once
    assert next_beat(due, late) == late
    assert next_beat(late, late + 0.001) == pytest.approx(late + FRAME_PERIOD_S)  # then a beat
