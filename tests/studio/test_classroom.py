"""A class on one studio, over real HTTP and WebSockets with real worker processes: each pupil's
own folder (and no way into another's), starters handed out, the teacher's code, the teacher's
live view, Stop for every run, messages and "hands off", and tasks that check themselves."""

from __future__ import annotations

import asyncio
import contextlib
import json
import shutil
from collections.abc import AsyncIterator, Callable, Coroutine
from contextlib import asynccontextmanager
from pathlib import Path
from typing import Any

import aiohttp
import pytest

from rootlang.adventures import BUILT_IN, SOLUTION
from rootlang.diagnostics import RootlangError
from rootlang.jstypes import problems
from rootlang.studio import messages as m
from rootlang.studio.classroom import Classroom, pupil_name
from rootlang.studio.folder import ClassFolder
from rootlang.studio.lessons import PROGRESS_FILE

from .conftest import CODE, PROGRAMS, RunningStudio, make_class
from .test_server import Socket, _time_limit

SQUARE = (PROGRAMS / "square.root").read_text(encoding="utf-8")
# drives for a minute of real time: still running when the teacher stops everyone
LONG_RUN = "when started\n    repeat 600\n        move 1 cm\n"


Client = aiohttp.ClientSession


@asynccontextmanager
async def browser(studio: RunningStudio, address: str = "127.0.0.1") -> AsyncIterator[Client]:
    """One browser: its own cookies (a cookie for 127.0.0.1 needs an "unsafe" jar), on a
    computer at ``address`` (any of 127.0.0.0/8 reaches the studio on Linux)."""
    jar = aiohttp.CookieJar(unsafe=True)
    headers = {"Origin": studio.address}
    connector = aiohttp.TCPConnector(local_addr=(address, 0))
    async with aiohttp.ClientSession(
        studio.address, cookie_jar=jar, headers=headers, connector=connector
    ) as client:
        yield client


async def pupil(client: Client, name: str) -> dict[str, Any]:
    reply = await client.post("/api/pupil", json={"name": name})
    data: dict[str, Any] = await reply.json()
    assert reply.status == 200, data
    return data


async def teacher(client: Client, code: str = CODE) -> None:
    reply = await client.post("/api/teacher/login", json={"code": code})
    assert reply.status == 200, await reply.text()


async def errors(reply: aiohttp.ClientResponse) -> list[str]:
    data = await reply.json()
    return [item["code"] for item in data["errors"]]


def in_class(studio: RunningStudio, check: Callable[[], Coroutine[Any, Any, None]]) -> None:
    asyncio.run(check())


# --- pupils -------------------------------------------------------------------------------------


def test_a_pupil_names_themself_and_works_in_their_own_folder(class_studio: RunningStudio) -> None:
    async def check() -> None:
        async with browser(class_studio) as anna, browser(class_studio) as ben:
            page = await (await anna.get("/")).text()
            assert 'id="join"' in page  # first the name
            assert (await anna.get("/api/setup")).status == 401
            assert await pupil(anna, "  Anna  ") == {"name": "Anna"}
            assert 'id="blocks"' in await (await anna.get("/")).text()  # now the studio
            await pupil(ben, "Ben")
            setup = await (await anna.get("/api/setup")).json()
            assert [p["name"] for p in setup["programs"]] == ["hello.root", "square.root"]
            put = await anna.put("/api/program", json={"name": "mine.root", "text": SQUARE})
            assert put.status == 200
            assert (class_studio.folder / "Anna" / "mine.root").is_file()
            # Ben sees none of it, and no name or path reaches it
            setup = await (await ben.get("/api/setup")).json()
            assert "mine.root" not in [p["name"] for p in setup["programs"]]
            for name in ("mine.root", "../Anna/mine.root", "Anna/mine.root"):
                reply = await ben.get("/api/program", params={"name": name})
                assert reply.status == 400 and (await errors(reply))[0] in ("E801", "E802")
            reply = await ben.put("/api/program", json={"name": "../Anna/mine.root", "text": "x"})
            assert await errors(reply) == ["E801"]
            await ben.put("/api/program", json={"name": "mine.root", "text": "# Ben's\n"})
            assert (class_studio.folder / "Anna" / "mine.root").read_text("utf-8") == SQUARE
            # a forged cookie is nobody
            async with browser(class_studio) as forger:
                forger.cookie_jar.update_cookies({"rootlang_pupil": "Anna"})
                assert (await forger.get("/api/setup")).status == 401
                assert (await forger.get("/ws")).status == 401

    in_class(class_studio, check)


def test_names_are_tidied_and_confined() -> None:
    assert pupil_name("  Zoë   van  Dijk ") == "Zoë van Dijk"
    for bad in (
        "",
        "   ",
        "../x",
        "a/b",
        "_start",
        "_tasks",
        ".hidden",
        "worlds",
        "x" * 40,
        "a\\b",
    ):
        with pytest.raises(RootlangError) as raised:
            pupil_name(bad)
        assert raised.value.diagnostics[0].code == "E843"


def test_the_same_name_is_the_same_folder_but_not_two_pages_at_once(
    class_studio: RunningStudio,
) -> None:
    async def check() -> None:
        async with browser(class_studio) as first, browser(class_studio) as second:
            await pupil(first, "anna")
            async with first.ws_connect("/ws/class"):
                await asyncio.sleep(0.1)
                reply = await second.post("/api/pupil", json={"name": "ANNA"})
                assert await errors(reply) == ["E844"]
            await asyncio.sleep(0.1)
            assert await pupil(second, "ANNA") == {"name": "anna"}  # her folder, her case
            assert (await first.get("/api/setup")).status == 401  # one computer at a time

    in_class(class_studio, check)


# --- the teacher --------------------------------------------------------------------------------


async def until(socket: Socket, wanted: Callable[[dict[str, Any]], bool]) -> dict[str, Any]:
    """The teacher's view of the pupils once ``wanted`` holds for it (every message as the
    contract says)."""
    view: dict[str, dict[str, Any]] = {}
    async with _time_limit(60):  # (a hang's bound, never a speed)
        async for message in socket:
            data = json.loads(message.data)
            assert problems(data, m.ToTeacher) == []
            for one in data.get("pupils", []):
                view[one["name"]] = one
            with contextlib.suppress(KeyError):  # (a pupil the page has not shown yet)
                if wanted(view):
                    return view
    raise AssertionError("the teacher's page never saw it")


def test_stopping_the_studio_tells_the_class_pages_it_goes_away(
    class_studio: RunningStudio,
) -> None:
    """Ctrl-C with the class's pages open: each is told at once (1001), the studio does not
    wait for them to leave."""

    async def check() -> None:
        async with browser(class_studio) as anna, browser(class_studio) as miss:
            await pupil(anna, "Anna")
            await teacher(miss)
            pages = [await anna.ws_connect("/ws/class"), await miss.ws_connect("/ws/teacher")]
            await pages[1].receive()  # (the class, as the teacher's page first sees it)
            stopping = asyncio.get_running_loop().run_in_executor(None, class_studio.stop)
            for page in pages:
                async with _time_limit(10):
                    while not page.closed:
                        await page.receive()
                assert page.close_code == aiohttp.WSCloseCode.GOING_AWAY
            await stopping

    in_class(class_studio, check)


def test_the_teachers_page_needs_the_code(class_studio: RunningStudio) -> None:
    async def check() -> None:
        async with browser(class_studio) as someone:
            await pupil(someone, "Ben")
            assert await errors(await someone.post("/api/teacher/stop")) == ["E847"]
            assert (await someone.get("/ws/teacher")).status == 401
            assert 'id="login"' in await (await someone.get("/teacher")).text()
            for _ in range(5):
                reply = await someone.post("/api/teacher/login", json={"code": "000000"})
                assert await errors(reply) == ["E846"]
            reply = await someone.post("/api/teacher/login", json={"code": CODE})
            assert await errors(reply) == ["E849"]  # guessing is paused, even the right one

    in_class(class_studio, check)


async def guess_five_times(client: Client) -> None:
    for _ in range(5):
        reply = await client.post("/api/teacher/login", json={"code": "000000"})
        assert await errors(reply) == ["E846"]
    reply = await client.post("/api/teacher/login", json={"code": CODE})
    assert await errors(reply) == ["E849"]  # their own tries are paused, even the right one


def test_a_pupil_guessing_the_code_never_locks_the_teacher_out(
    class_studio: RunningStudio,
) -> None:
    """Wrong codes are counted per address, and per pupil at an address: Ben's five lock Ben's
    page (also under a new name from the same computer, after fifty) and a guesser at another
    computer locks that computer, never the teacher's page."""

    async def check() -> None:
        async with browser(class_studio) as ben, browser(class_studio, "127.0.0.2") as guesser:
            await pupil(ben, "Ben")
            await guess_five_times(ben)
            await guess_five_times(guesser)
            async with browser(class_studio) as miss:  # the same address as Ben, no pupil
                await teacher(miss)
            async with browser(class_studio, "127.0.0.3") as miss:
                await teacher(miss)
            reply = await ben.post("/api/teacher/login", json={"code": CODE})
            assert await errors(reply) == ["E849"]  # the teacher's login did not free Ben's
            for name in range(9):  # new names from Ben's computer: 45 more tries, then none
                async with browser(class_studio) as again:
                    await pupil(again, f"Ben{name}")
                    await guess_five_times(again)
            async with browser(class_studio) as again:
                await pupil(again, "Ben again")
                reply = await again.post("/api/teacher/login", json={"code": "000000"})
                assert await errors(reply) == ["E849"]
                async with browser(class_studio) as miss:  # still not the teacher
                    await teacher(miss)

    in_class(class_studio, check)


def test_the_teacher_sees_each_pupil_live_and_stops_every_run(class_studio: RunningStudio) -> None:
    async def check() -> None:
        async with (
            browser(class_studio) as anna,
            browser(class_studio) as ben,
            browser(class_studio) as miss,
        ):
            await teacher(miss)
            async with miss.ws_connect("/ws/teacher") as view:
                first = json.loads((await view.receive()).data)
                assert problems(first, m.ClassMessage) == []
                assert first["type"] == "class" and first["pupils"] == []
                assert [t["name"] for t in first["tasks"]] == ["square"]
                await pupil(anna, "Anna")
                await pupil(ben, "Ben")
                await anna.post("/api/blocks", json={"text": SQUARE, "name": "square.root"})
                seen = await until(view, lambda v: v.get("Anna", {}).get("text") == SQUARE)
                assert seen["Anna"]["program"] == "square.root"
                await ben.post("/api/blocks", params={"language": "nl"},
                               json={"text": "when started\n    mvoe 1 cm\n",
                                     "name": "oops.root"})  # fmt: skip
                seen = await until(view, lambda v: bool(v.get("Ben", {}).get("problems")))
                assert seen["Ben"]["problems"][0]["severity"] == "error"
                # Ben's page speaks Dutch, the teacher's English: the teacher reads English
                assert 'Did you mean "move"?' in seen["Ben"]["problems"][0]["message"]
                sockets = [await c.ws_connect("/ws") for c in (anna, ben)]
                await sockets[0].send_json({"type": "run", "name": "square.root",
                                            "text": SQUARE, "speed": 0})  # fmt: skip
                seen = await until(view, lambda v: bool(v["Anna"]["last"]))
                assert seen["Anna"]["last"]["end"] == "finished"
                assert seen["Anna"]["last"]["replay"].startswith("/replay/")
                assert any("move" in line for line in seen["Anna"]["last"]["trace"])
                while json.loads((await sockets[0].receive()).data)["type"] != "ended":
                    pass
                for socket in sockets:  # (Anna's says goodbye when stopped)
                    text = LONG_RUN + (
                        'when stopped\n    print "bye"\n' if socket is sockets[0] else ""
                    )
                    await socket.send_json({"type": "run", "name": "long.root",
                                            "text": text, "speed": 1})  # fmt: skip
                seen = await until(view, lambda v: all(v[n]["run"] for n in ("Anna", "Ben")))
                assert seen["Anna"]["run"]["robot"] is None  # on the simulator
                # (how soon they end, and the seconds the reply says: benchmarks/studio_class.py;
                # a busy machine's runs may end after the reply, which counts those ended by then)
                stop = await (await miss.post("/api/teacher/stop")).json()
                assert problems(stop, m.StopAllReply) == []
                assert stop["stopped"] == 2
                for socket in sockets:
                    async with _time_limit(30):
                        async for message in socket:
                            data = json.loads(message.data)
                            if data["type"] == "ended":  # as by Stop: with a replay
                                assert data["end"] == "stopped"
                                assert data["stopped_by"] == "the teacher"
                                assert data["replay"].startswith("/replay/")
                                assert data["printed"] == (["bye"] if socket is sockets[0] else [])
                                break
                    await socket.close()
                seen = await until(view, lambda v: all(v[n]["last"] for n in ("Anna", "Ben")))
                assert seen["Ben"]["last"]["end"] == "stopped" and not seen["Ben"]["run"]

    in_class(class_studio, check)


def test_a_message_and_hands_off_reach_every_pupil(class_studio: RunningStudio) -> None:
    async def check() -> None:
        async with browser(class_studio) as anna, browser(class_studio) as miss:
            await teacher(miss)
            await pupil(anna, "Anna")
            async with anna.ws_connect("/ws/class") as page:
                assert json.loads((await page.receive()).data) == {
                    "type": "locked",
                    "locked": False,
                }
                assert json.loads((await page.receive()).data) == {
                    "type": "muted",
                    "muted": False,
                }
                assert json.loads((await page.receive()).data) == {"type": "level", "level": 2}
                # the teacher's level: for the class, then for Anna (docs/levels.md)
                chose = await miss.post("/api/teacher/level", json={"level": 1, "pupil": ""})
                assert await chose.json() == {"level": 1, "pupil": ""}
                assert json.loads((await page.receive()).data) == {"type": "level", "level": 1}
                await miss.post("/api/teacher/level", json={"level": 3, "pupil": "anna"})
                assert json.loads((await page.receive()).data) == {"type": "level", "level": 3}
                assert (await (await anna.get("/api/pupil")).json())["level"] == 3
                wrong = await miss.post("/api/teacher/level", json={"level": 4, "pupil": ""})
                assert wrong.status == 400 and "1, 2 or 3" in (await wrong.text())
                await miss.post("/api/teacher/notice", json={"text": "Tidy up, please"})
                told = json.loads((await page.receive()).data)
                assert problems(told, m.ToClassPage) == []
                assert told["type"] == "notice" and told["text"] == "Tidy up, please"
                await miss.post("/api/teacher/lock", json={"locked": True})
                assert json.loads((await page.receive()).data)["locked"] is True
                reply = await anna.put("/api/program", json={"name": "a.root", "text": "x"})
                assert await errors(reply) == ["E845"]
                assert (await anna.get("/api/setup")).status == 200  # looking is fine
                async with anna.ws_connect("/ws") as socket:
                    await socket.send_json({"type": "run", "name": "a.root", "text": SQUARE})
                    refused = json.loads((await socket.receive()).data)
                    assert refused["type"] == "error" and refused["code"] == "E845"
                await miss.post("/api/teacher/lock", json={"locked": False})
                assert json.loads((await page.receive()).data)["locked"] is False
                reply = await anna.put("/api/program", json={"name": "a.root", "text": SQUARE})
                assert reply.status == 200
                # the class muted: every pupil's page is told; only the teacher may
                assert (await anna.post("/api/teacher/mute", json={"muted": True})).status != 200
                await miss.post("/api/teacher/mute", json={"muted": True})
                muted = json.loads((await page.receive()).data)
                assert problems(muted, m.ToClassPage) == [] and muted["muted"] is True
                assert (await anna.get("/api/pupil")).status == 200
                assert (await (await anna.get("/api/pupil")).json())["muted"] is True
                reply = await miss.post("/api/teacher/mute", json={"muted": "yes"})
                assert await errors(reply) == ["E805"]

    in_class(class_studio, check)


def test_class_sockets_refuse_other_origins(class_studio: RunningStudio) -> None:
    async def check() -> None:
        async with browser(class_studio) as anna:
            await pupil(anna, "Anna")
            reply = await anna.get("/ws/class", headers={"Origin": "http://evil.example"})
            assert await errors(reply) == ["E804"]

    in_class(class_studio, check)


# --- tasks --------------------------------------------------------------------------------------


def test_check_says_pass_and_the_first_difference_and_the_teacher_exports_it(
    class_studio: RunningStudio,
) -> None:
    async def check() -> None:
        async with (
            browser(class_studio) as anna,
            browser(class_studio) as ben,
            browser(class_studio) as miss,
        ):
            await pupil(anna, "Anna")
            await pupil(ben, "Ben")
            assert (class_studio.folder / "Ben" / "square.root").is_file()  # the starter
            asked = {"name": "square.root", "text": SQUARE}
            right = await (await anna.post("/api/check", json=asked)).json()
            assert right["passed"] is True and right["said"] == "Well done: your robot did it!"
            assert problems(right, m.CheckReply) == []
            assert problems(await (await anna.get("/api/pupil")).json(), m.WhoReply) == []
            short = SQUARE.replace("repeat 4", "repeat 3")
            asked = {"name": "square.root", "text": short}
            dutch = {"language": "nl"}
            wrong = await (await ben.post("/api/check", params=dutch, json=asked)).json()
            assert wrong["passed"] is False
            assert wrong["said"] == "Je robot eindigde 10 cm rechts van het doel."
            reply = await anna.post("/api/check", json={"name": "hello.root", "text": SQUARE})
            assert await errors(reply) == ["E848"]
            await teacher(miss)
            async with miss.ws_connect("/ws/teacher", params={"language": "de"}) as view:
                first = json.loads((await view.receive()).data)
                said = {p["name"]: p["checks"]["square"]["said"] for p in first["pupils"]}
                # each check as the teacher's page speaks (Ben's was asked in Dutch)
                assert said == {
                    "Anna": "Gut gemacht: Dein Roboter hat es geschafft!",
                    "Ben": "Dein Roboter hat 10 cm rechts neben dem Ziel angehalten.",
                }
            csv = await (await miss.get("/api/teacher/export", params={"task": "square"})).text()
            assert csv.splitlines()[1:] == [
                line for line in csv.splitlines()[1:] if line.split(",")[0] in
                ("Anna/square.root", "Ben/square.root")
            ] and len(csv.splitlines()) == 3  # fmt: skip
            assert "Anna/square.root,passed,True" in csv and "Ben/square.root,failed,False" in csv
            assert "right of the target" in csv  # (asked without a language: English)
            # what a check said is kept as data: the export says it in the teacher's language
            as_junit = {"task": "square", "format": "junit", "language": "nl"}
            junit = await (await miss.get("/api/teacher/export", params=as_junit)).text()
            assert 'tests="2" failures="1"' in junit and "rechts van het doel" in junit
            # the teacher checks everyone's saved program
            await anna.put("/api/program", json={"name": "square.root", "text": SQUARE})
            everyone = await (await miss.post("/api/teacher/check", json={"task": "square"})).json()
            assert problems(everyone, m.ClassCheckReply) == []
            assert everyone["results"]["Anna"]["passed"] is True
            assert everyone["results"]["Ben"]["passed"] is False  # the starter draws nothing

    in_class(class_studio, check)


def test_the_teachers_stop_reaches_a_robot_and_the_simulator(tmp_path: Path) -> None:
    """One pupil on bumble's virtual robot over the real Bluetooth stack, one on the simulator:
    the teacher sees which robot, and one Stop ends both."""
    pytest.importorskip("bumble", reason="the virtual robot needs rootlang[virtual]")
    folder = make_class(tmp_path / "class")
    studio = RunningStudio(folder, "virtual", Classroom(ClassFolder(folder), CODE)).start()
    forever = "when started\n    forever\n        move 5 cm\n"

    async def check() -> None:
        async with browser(studio) as anna, browser(studio) as ben, browser(studio) as miss:
            await teacher(miss)
            await pupil(anna, "Anna")
            await pupil(ben, "Ben")
            async with (
                miss.ws_connect("/ws/teacher") as view,
                anna.ws_connect("/ws") as on_robot,
                ben.ws_connect("/ws") as on_sim,
            ):
                await on_robot.send_json({"type": "run", "name": "a.root", "text": forever,
                                          "robot": ""})  # fmt: skip
                await on_sim.send_json({"type": "run", "name": "b.root", "text": forever,
                                        "speed": 1})  # fmt: skip
                async with _time_limit(60):  # until the robot's run has started moving
                    async for message in on_robot:
                        data = json.loads(message.data)
                        if data["type"] == "frame" and data["t"] > 0.5:
                            break
                seen = await until(
                    view, lambda v: "Virtual Root" in ((v["Anna"]["run"] or {}).get("robot") or "")
                )
                assert seen["Ben"]["run"]["robot"] is None
                stop = await (await miss.post("/api/teacher/stop")).json()
                assert stop["stopped"] == 2  # (how soon they end: benchmarks/studio_class.py)
                for socket in (on_robot, on_sim):
                    async with _time_limit(30):
                        async for message in socket:
                            data = json.loads(message.data)
                            if data["type"] == "ended":
                                assert data["end"] == "stopped", data
                                break

    try:
        in_class(studio, check)
    finally:
        studio.stop()


def test_adventures_are_handed_out_checked_and_kept(class_studio: RunningStudio) -> None:
    """A pupil's adventures over HTTP: the list in their language, an adventure's starter and
    its own world in their folder (never over their work), a check's hint, the progress kept
    in their folder and on the teacher's page; the teacher's own adventure in the list."""
    mine = class_studio.folder / "_adventures" / "05-traffic-light"
    shutil.copytree(BUILT_IN / "05-traffic-light", mine)
    (mine / "adventure.toml").write_text('level = 2\n[title]\nen = "Mine"\n[goal]\nen = "Go"\n')

    async def check() -> None:
        async with browser(class_studio) as anna, browser(class_studio) as miss:
            await pupil(anna, "Anna")
            listed = (await (await anna.get("/api/adventures?language=nl")).json())["adventures"]
            assert len(listed) >= 12 and [a["level"] for a in listed] == sorted(
                a["level"] for a in listed
            )
            first = listed[0]
            assert (first["title"], first["passed"]) == ("Vooruit", False)
            assert first["picture"].startswith("data:image/svg+xml")
            assert next(a for a in listed if a["name"] == "05-traffic-light")["title"] == "Mine"
            reply = await anna.post("/api/adventure", json={"name": "nothing"})
            assert await errors(reply) == ["E851"]
            bump = await (
                await anna.post("/api/adventure", json={"name": "06-bump-and-ring"})
            ).json()
            folder = class_studio.folder / "Anna"
            assert (folder / bump["program"]).is_file() and (
                folder / "worlds" / "bumped.toml"
            ).is_file()
            assert "bumped" in (await (await anna.get("/api/setup")).json())["worlds"]
            (folder / bump["program"]).write_text("# mine\n", encoding="utf-8")
            await anna.post("/api/adventure", json={"name": "06-bump-and-ring"})
            assert (folder / bump["program"]).read_text("utf-8") == "# mine\n"  # never over it
            starter = (BUILT_IN / "06-bump-and-ring" / "06-bump-and-ring.root").read_text("utf-8")
            program = bump["program"]
            said = await (
                await anna.post("/api/check", json={"name": program, "text": starter})
            ).json()
            assert not said["passed"] and "`when bumped`" in said["said"]
            solution = (BUILT_IN / "06-bump-and-ring" / SOLUTION).read_text("utf-8")
            said = await (
                await anna.post("/api/check", json={"name": program, "text": solution})
            ).json()
            assert said["passed"]
            assert json.loads((folder / PROGRESS_FILE).read_text("utf-8")) == {
                "06-bump-and-ring": True
            }
            await teacher(miss)
            async with miss.ws_connect("/ws/teacher") as socket:
                snapshot = await socket.receive_json()
            assert len(snapshot["adventures"]) == len(listed)
            assert snapshot["pupils"][0]["adventures"] == {"06-bump-and-ring": True}

    in_class(class_studio, check)
