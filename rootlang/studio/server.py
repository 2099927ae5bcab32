"""The studio's web server: one page, the class folder's files, conversions, and live runs.

Routes (all on one port; the page requests nothing else):

- ``GET /`` — the page; ``/static/...`` its modules, styles and the vendored Blockly/CodeMirror;
  ``/blocks/root_blocks.js`` the block extensions that ship with :mod:`rootlang.blocks`, and
  ``/sim/render/viewer.js``, ``announce.js`` and ``moment.js`` the replay page's viewer, live
  region and moments (the stage draws, speaks and goes back in time with them): served at the
  addresses that match their places in the package, so the modules' relative imports work
  both in the browser and for ``tsc``;
- ``GET /api/setup`` — the block definitions and toolbox, the page's words and Blockly's own
  words file, the languages to choose from, the folder's programs and the worlds;
- ``GET|PUT|POST /api/program`` — read, save (formatted) or create (from the starter) a program,
  ``POST /api/rename`` renames one; block layouts travel with them (the sidecar). Each answer
  carries the program's ``version``; a Save sends back the version it opened and is refused
  (E819, HTTP 409) when the file has changed since; every Save keeps the file's last versions
  (:mod:`rootlang.studio.folder`);
- ``POST /api/blocks`` (text → blocks and diagnostics; ``text_only`` with E817 for a program
  too long for blocks), ``POST /api/text`` (blocks → text). These and a Save's formatting run
  in :mod:`rootlang.studio.pool`'s worker processes, never on the event loop (E818 past a
  request's time or memory limit);
- ``POST /api/stage`` — the world and the robot at its start pose, before any run (the stage
  shows them from the moment a program opens, and when another world is chosen);
- ``GET /replay/{token}`` — the last run's one-file HTML replay, to download;
- ``GET /ws`` — the WebSocket that runs programs (see :class:`Session`).

Every body and message is one of :mod:`rootlang.studio.messages`' types (the page's JavaScript is
checked against the same types).

Languages: the page asks in its language (``?language=xx`` on every request and on the
WebSocket), and every message it gets back is in it: mistakes, run-time errors, refusals. Each
request carries its own :class:`~rootlang.wording.language.Languages` (the studio's command's,
with the page's: :func:`languages_of`), handed to what answers it, to the conversion workers
with their jobs and to a WebSocket's runs in their :class:`RunJob`, so pages in different
languages served at once never get each other's.

Safety: only ``.root`` files and their sidecars directly inside the folder are read or written
(:mod:`rootlang.studio.folder`); requests that change something and WebSocket connections must
come from the studio's own page (the ``Origin`` header); the server binds to 127.0.0.1 unless
told otherwise. A bad request or WebSocket message gets an error reply with a catalogue code.
"""

from __future__ import annotations

import asyncio
import collections
import contextlib
import ipaddress
import json
import logging
import os
import secrets
import socket as socket_module
from collections import OrderedDict
from collections.abc import Awaitable, Callable
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import TYPE_CHECKING, Any

from aiohttp import WSMsgType, web

from rootlang import jsontree
from rootlang.app.files import starter
from rootlang.diagnostics import Diagnostic, RootlangError, diagnostic
from rootlang.locale.keywords import LANGUAGE_NAMES
from rootlang.runtime.stops import StoppedBy, StopReason
from rootlang.sim.world import STIMULI as ALL_STIMULI
from rootlang.studio import messages as m
from rootlang.studio.conversions import (
    blocks_module,
    diagnostic_json,
    error_json,
    request_object,
    text_field,
)
from rootlang.studio.debugging import breakpoint_lines, debug_request
from rootlang.studio.folder import ClassFolder, built_in_worlds, folder_worlds, version_of
from rootlang.studio.lessons import Home
from rootlang.studio.page_robot import (
    PAGE_LINK,
    WEB_BLUETOOTH,
    PageRobot,
    link_packets,
    packet_from_hex,
    page_stop,
)
from rootlang.studio.pages import (
    LANGUAGES,
    STATIC,
    VENDOR,
    cache_control,
    compress,
    json_body,
    languages_of,
    own_origin,
    page,
    setup_in_language,
    vendor_url,
)
from rootlang.studio.pool import ConversionPool
from rootlang.studio.runs import FORKSERVER, STARTS, ClassLimits, RunPlaces, SimRun, scan_robots
from rootlang.studio.tls import StudioCertificate, lan_names
from rootlang.studio.worker import NOTES_PER_FRAME, SPEEDS, RunJob
from rootlang.wording import catalogue
from rootlang.wording.language import Languages

LOG = logging.getLogger(__name__)
MAX_MESSAGE_BYTES = 1024 * 1024  # a program or a workspace is a few kB; a MB is plenty
KEPT_REPLAYS = 200  # the last runs' replays, to download (a class's worth, a few times over)
STIMULI = frozenset(action for action, kind in ALL_STIMULI.items() if kind.on_the_page)
Handler = Callable[[web.Request], Awaitable[web.StreamResponse]]

if TYPE_CHECKING:
    from rootlang.studio.classroom import Classroom, Pupil


@dataclass
class Studio:
    """What the server keeps: the class folder, the last runs' replays, the open pages."""

    folder: ClassFolder
    transport: str | None = None  # bumble's HCI spec for Bluetooth, else this computer's
    loopback_only: bool = True  # served on 127.0.0.1: only loopback host names are answered
    # the names a page may ask for the studio by (the Host header): on 127.0.0.1 the loopback
    # names, on the network also this computer's names and addresses; and each --allow-host
    host_names: frozenset[str] = frozenset(("127.0.0.1", "localhost", "::1"))
    limits: ClassLimits = field(default_factory=ClassLimits)
    places: RunPlaces = field(init=False)  # the computer's places for runs (limits.runs)
    replays: OrderedDict[str, tuple[str, str]] = field(default_factory=OrderedDict)
    sessions: set[Session] = field(default_factory=set)
    classroom: Classroom | None = None  # a class: each pupil their own folder, a teacher's page
    pool: ConversionPool = field(init=False)  # conversions off the event loop (limits too)
    # the command's (`rootlang studio --language`, the computer's locale): a page's adds its own
    languages: Languages = field(kw_only=True)

    def __post_init__(self) -> None:
        self.places = RunPlaces(self.limits)
        self.pool = ConversionPool(seconds=self.limits.conversion_seconds)


STUDIO = web.AppKey("studio", Studio)


def make_app(
    folder: ClassFolder,
    transport: str | None = None,
    *,
    loopback_only: bool = True,
    classroom: Classroom | None = None,
    limits: ClassLimits | None = None,
    languages: Languages | None = None,
) -> web.Application:
    """The studio's application; ``languages``: the command's (by default the computer's)."""
    app = web.Application(client_max_size=MAX_MESSAGE_BYTES, middlewares=[_guard])
    app[STUDIO] = Studio(
        folder, transport, loopback_only, classroom=classroom, limits=limits or ClassLimits(),
        languages=languages or Languages.of_command(),
    )  # fmt: skip
    app.router.add_get("/", _page)
    app.router.add_get("/api/setup", _setup)
    app.router.add_get("/api/program", _read_program)
    app.router.add_put("/api/program", _save_program)
    app.router.add_post("/api/program", _create_program)
    app.router.add_post("/api/rename", _rename_program)
    app.router.add_post("/api/blocks", _text_to_blocks)
    app.router.add_post("/api/text", _blocks_to_text)
    app.router.add_post("/api/stage", _stage)
    app.router.add_get("/replay/{token}", _replay)
    app.router.add_get("/api/robots", _robots)
    app.router.add_get("/blocks/root_blocks.js", _root_blocks_js)
    app.router.add_get("/sim/render/{module:viewer|announce|moment}.js", _render_module)
    app.router.add_get("/ws", _websocket)
    app.router.add_get("/sw.js", _service_worker)
    app.router.add_static("/static", STATIC, follow_symlinks=False)
    app.router.add_static(vendor_url(), VENDOR, follow_symlinks=False)
    app.on_shutdown.append(_stop_every_run)
    app.on_shutdown.append(_close_pool)  # a conversion under way ends now (E818), not later
    if classroom is not None:
        app.on_startup.append(warm_up_runs)
        classroom.add_routes(app)
    else:  # one child, at home: the adventures, their progress kept in the folder
        Home(folder).add_routes(app)
    return app


def folder_of(request: web.Request) -> ClassFolder:
    """The folder this request works in: the class folder, or in a class the pupil's own."""
    studio = request.app[STUDIO]
    return studio.folder if studio.classroom is None else studio.classroom.folder_of(request)


async def _close_pool(app: web.Application) -> None:
    app[STUDIO].pool.close()


async def warm_up_runs(app: web.Application) -> None:
    """Start the runs' fork server and the conversion workers now, in threads: started by
    the first Run and the first edit instead, those waited for them (measured: the first
    frame of a class's first runs 1.5-2 s after Run, instead of 0.3 s; the first edits of a
    class 1.9 s, up to 2.7 s, on a busy 2-core computer)."""
    from multiprocessing import forkserver

    if FORKSERVER:
        await asyncio.get_running_loop().run_in_executor(STARTS, forkserver.ensure_running)
    app[STUDIO].pool.warm_up()


# --- errors and the origin check ----------------------------------------------------------------


# A refusal's HTTP status: the program changed on disk (a conflict), else a bad request
STATUS = {"E819": 409}


def error_reply(
    found: RootlangError | Diagnostic, languages: Languages, status: int = 400
) -> web.Response:
    first = found.diagnostics[0].code if isinstance(found, RootlangError) else found.code
    reply: m.ErrorsReply = error_json(found, languages)
    return web.json_response(reply, status=STATUS.get(first, status))


def origin_allowed(request: web.Request) -> bool:
    """A change or a WebSocket must come from the studio's own page (browsers always send
    ``Origin`` on those). Plain tools that send none may change files, as curl could anyway."""
    origin = request.headers.get("Origin")
    if request.path == "/ws":
        return origin == own_origin(request)
    if request.headers.get("Sec-Fetch-Site") in ("cross-site", "same-site"):
        return False  # (a browser says so even where it sends no Origin: an <img>, a link)
    return origin is None or origin == own_origin(request)


SIDE_EFFECT_GETS = ("/ws", "/api/robots")  # a scan starts a Bluetooth process: not for others


LOOPBACK_NAMES = ("127.0.0.1", "localhost", "::1")


def host_allowed(request: web.Request) -> bool:
    """The page must be asked for by one of this computer's own names or addresses (on
    127.0.0.1: a loopback one), or one ``--allow-host`` names: a web site whose name was made
    to point at this computer (DNS rebinding) is refused, whatever address the studio is on."""
    studio = request.app[STUDIO]
    host = (request.url.host or "").lower().rstrip(".").strip("[]")
    if host in studio.host_names:
        return True
    if studio.loopback_only or request.transport is None:
        return False
    sockname = request.transport.get_extra_info("sockname")  # the address it was reached at
    return bool(sockname) and host == str(sockname[0]).split("%")[0].lower()


@web.middleware
async def _guard(request: web.Request, handler: Handler) -> web.StreamResponse:
    # this request's alone: the page's language, else the studio's
    request[LANGUAGES] = request.app[STUDIO].languages.for_page(request.query.get("language"))
    return await _guarded(request, handler)


async def _guarded(request: web.Request, handler: Handler) -> web.StreamResponse:
    languages = languages_of(request)
    if not host_allowed(request):
        refused = diagnostic("E804", origin=request.host or "none")
        return error_reply(refused, languages, status=403)
    if (request.method != "GET" or request.path in SIDE_EFFECT_GETS) and not origin_allowed(
        request
    ):
        refused = diagnostic("E804", origin=request.headers.get("Origin", "none"))
        return error_reply(refused, languages, status=403)
    try:
        response = await handler(request)
    except RootlangError as error:
        return error_reply(error, languages)
    response.headers.setdefault("Cache-Control", cache_control(request.path))
    compress(request, response)
    if request.path in ("/", "/teacher"):  # the pages may talk to their own address only
        response.headers["Content-Security-Policy"] = (
            "default-src 'self'; img-src 'self' data:; style-src 'self' 'unsafe-inline'; "
            "connect-src 'self'; media-src 'self'"
        )
    return response


# --- the page and the setup -----------------------------------------------------------------------


async def _page(request: web.Request) -> web.StreamResponse:
    classroom = request.app[STUDIO].classroom
    if classroom is not None and classroom.pupil_of(request) is None:
        return page("pupil.html")  # first the pupil's name
    return page("index.html")


async def _service_worker(request: web.Request) -> web.StreamResponse:
    """The page's service worker (static/sw.js), from the top of the site: only from there
    may it look after the whole page (docs/studio.md, "Offline")."""
    return web.FileResponse(STATIC / "sw.js", headers={"Content-Type": "application/javascript"})


async def _render_module(request: web.Request) -> web.StreamResponse:
    """How the replay page draws a run (viewer.js), speaks (announce.js) and finds a moment of
    it (moment.js): the stage does the same with them."""
    module = request.match_info["module"] + ".js"
    path = Path(str(resources.files("rootlang.sim.render").joinpath(module)))
    return web.FileResponse(path, headers={"Content-Type": "application/javascript"})


# Without rootlang.blocks the page still imports the module; the setup says there are no blocks.
NO_BLOCKS_JS = (
    "// rootlang.blocks is not in this build\n"
    "export function install() {}\nexport function attach() {}\n"
)


async def _root_blocks_js(request: web.Request) -> web.StreamResponse:
    blocks = blocks_module()
    if blocks is None:
        return web.Response(text=NO_BLOCKS_JS, content_type="application/javascript")
    path = Path(str(resources.files("rootlang.blocks").joinpath("root_blocks.js")))
    return web.FileResponse(path, headers={"Content-Type": "application/javascript"})


async def _setup(request: web.Request) -> web.StreamResponse:
    """What the page needs first, in the page's language (``?language=xx``; by default the
    one `rootlang studio --language` or the computer's settings choose)."""
    folder = folder_of(request)
    language = languages_of(request).messages
    reply: m.SetupReply = {
        "folder": folder.root.name,
        "programs": [p.to_json() for p in folder.programs()],
        "worlds": world_names(folder),
        "speeds": list(SPEEDS),
        "bluetooth": WEB_BLUETOOTH,  # for the page's own robot link (Web Bluetooth)
        "languages": LANGUAGE_NAMES,  # the Language menu: each language named in itself
        "language": language,
        **setup_in_language(language),
    }  # fmt: skip
    return web.json_response(reply)


def world_names(folder: ClassFolder) -> list[str]:
    return sorted({**built_in_worlds(), **folder_worlds(folder)})


def world_path(folder: ClassFolder, name: str) -> str:
    """The world file for a name from the page ("" for the program's own world)."""
    if not name:
        return ""
    found = {**built_in_worlds(), **folder_worlds(folder)}.get(name)
    if found is None:
        known = ", ".join(world_names(folder)) or "none"
        raise RootlangError.of("E306", name=name, known=known, suggestion="")
    return str(found)


# --- files --------------------------------------------------------------------------------------


async def _read_program(request: web.Request) -> web.StreamResponse:
    folder = folder_of(request)
    name = request.query.get("name", "")
    text = folder.read(name)
    reply: m.ProgramReply = {"name": name, "text": text, "version": version_of(text),
                             "layout": folder.read_layout(name)}  # fmt: skip
    return web.json_response(reply)


async def _save_program(request: web.Request) -> web.StreamResponse:
    """Save what the page shows, in canonical form (formatted in a worker; past its time
    limit, or ``as_written``, as it was written), over the version the page opened
    (``version``: E819 if the file changed since; left out, as by a tool without a page:
    saved whatever the file is)."""
    folder = folder_of(request)
    body = await request.read()
    data = request_object(body)
    name, text = text_field(data, "name"), text_field(data, "text")
    version = data.get("version")
    if version is not None and not isinstance(version, str):
        raise RootlangError.of("E805", reason="`version` must be the text the page was given")
    folder.path_of(name)  # a bad name is refused before any work is done
    formatted = text  # (as_written, or too long to format in time: as the child wrote it)
    if data.get("as_written") is not True:
        with contextlib.suppress(RootlangError):
            formatted = await request.app[STUDIO].pool.run(
                "format_text", languages_of(request), text, name, size=len(body)
            )
    # from here on nothing awaits: no other Save of this file can come in between
    saved = folder.save(name, formatted, version)
    layout = data.get("layout")
    if isinstance(layout, dict):
        folder.write_layout(name, layout)
    reply: m.SavedReply = {"name": name, "text": formatted, "version": saved}
    return web.json_response(reply)


async def _create_program(request: web.Request) -> web.StreamResponse:
    folder = folder_of(request)
    name = text_field(await json_body(request), "name")
    folder.path_of(name)  # the name is checked before it is written into the starter
    stem = name.removesuffix(".root")
    # in the page's language
    folder.create(name, starter(stem, name, languages_of(request).messages))
    text = folder.read(name)
    reply: m.SavedReply = {"name": name, "text": text, "version": version_of(text)}
    return web.json_response(reply)


async def _rename_program(request: web.Request) -> web.StreamResponse:
    data = await json_body(request)
    old, new = text_field(data, "old"), text_field(data, "new")
    folder_of(request).rename(old, new)
    reply: m.RenamedReply = {"name": new}
    return web.json_response(reply)


# --- blocks <-> text ------------------------------------------------------------------------------


async def _converted(request: web.Request, job: str) -> web.StreamResponse:
    """A conversion done by a worker process: the body goes as it came, the JSON it answers
    comes back as it is (see :mod:`rootlang.studio.conversions`)."""
    body = await request.read()
    languages = languages_of(request)
    status, text, seen = await request.app[STUDIO].pool.run(job, languages, body, size=len(body))
    classroom = request.app[STUDIO].classroom
    if classroom is not None and seen is not None:  # a pupil's program as it is now
        classroom.saw_text(request, *seen)
    return web.Response(text=text, status=status, content_type="application/json")


async def _text_to_blocks(request: web.Request) -> web.StreamResponse:
    return await _converted(request, "text_to_blocks")


async def _blocks_to_text(request: web.Request) -> web.StreamResponse:
    return await _converted(request, "blocks_to_text")


async def _stage(request: web.Request) -> web.StreamResponse:
    """The world and the robot where a run of the program would start (before any run)."""
    folder = folder_of(request)
    body = await request.read()
    data = request_object(body)
    name, text = text_field(data, "name"), text_field(data, "text")
    world = data.get("world", "")
    program = str(folder.path_of(name))
    chosen = world_path(folder, world if isinstance(world, str) else "")
    status, reply, _ = await request.app[STUDIO].pool.run(
        "stage", languages_of(request), program, text, chosen, size=len(body)
    )
    return web.Response(text=reply, status=status, content_type="application/json")


# --- robots ---------------------------------------------------------------------------------------

SCAN_SECONDS = 4.0


async def _robots(request: web.Request) -> web.StreamResponse:
    """The robots in range (name, model, signal), strongest first."""
    languages = languages_of(request)
    kind, found = await scan_robots(request.app[STUDIO].transport, SCAN_SECONDS, languages)
    if kind == "robots":
        return web.json_response({"robots": found})
    errors = found if isinstance(found, list) and found else [
        diagnostic_json(diagnostic("E815"), "", languages)
    ]  # fmt: skip
    return web.json_response({"errors": errors}, status=503)


# --- replays --------------------------------------------------------------------------------------


def keep_replay(app: web.Application, html: str, name: str) -> str:
    replays = app[STUDIO].replays
    token = secrets.token_urlsafe(12)
    replays[token] = (name, html)
    while len(replays) > KEPT_REPLAYS:
        replays.popitem(last=False)
    return token


async def _replay(request: web.Request) -> web.StreamResponse:
    kept = request.app[STUDIO].replays.get(request.match_info["token"])
    if kept is None:
        raise web.HTTPNotFound()
    name, html = kept
    download = name.removesuffix(".root") + "-replay.html"
    return web.Response(
        text=html, content_type="text/html",
        headers={"Content-Disposition": f'attachment; filename="{download}"'},
    )  # fmt: skip


# --- the WebSocket: runs --------------------------------------------------------------------------


async def _websocket(request: web.Request) -> web.StreamResponse:
    classroom = request.app[STUDIO].classroom
    pupil = None if classroom is None else classroom.pupil_of(request)
    if classroom is not None and pupil is None:
        return error_reply(diagnostic("E842"), languages_of(request), status=401)
    # a message up to 4 MB is read and refused if over 1 MB (the session goes on); past 4 MB
    # aiohttp closes the socket (code 1009, message too big): nothing is read into memory
    socket = web.WebSocketResponse(heartbeat=20, max_msg_size=4 * MAX_MESSAGE_BYTES)
    await socket.prepare(request)
    _bounded_send_buffer(request)
    session = Session(request.app, socket, languages_of(request), pupil)
    request.app[STUDIO].sessions.add(session)
    try:
        async for message in socket:
            if message.type == WSMsgType.TEXT:
                await session.handle(message.data)
            elif message.type == WSMsgType.BINARY:
                await session.reply_error(diagnostic("E806", reason="it is not text"))
    finally:  # the tab closed or reloaded, or the link dropped: the robot is stopped
        session.close()
        request.app[STUDIO].sessions.discard(session)
    return socket


SEND_BUFFER_BYTES = 32 * 1024  # a page's kernel send buffer (doubled by Linux): frames enough


def _bounded_send_buffer(request: web.Request) -> None:
    """A fixed send buffer for a page's socket (the kernel would grow it to megabytes), so a
    page that stops reading holds up its sends soon, and its frames are merged instead."""
    raw = request.transport.get_extra_info("socket") if request.transport else None
    if raw is not None:
        with contextlib.suppress(OSError):
            raw.setsockopt(socket_module.SOL_SOCKET, socket_module.SO_SNDBUF, SEND_BUFFER_BYTES)


def shown(value: object) -> str:
    """A value from a message, as an error reply quotes it: short, whatever it is."""
    if isinstance(value, str):
        text = repr(value)
    elif isinstance(value, list):
        text = "a list"
    elif isinstance(value, dict):
        text = "an object"
    else:  # a number, true, false or null
        try:
            text = json.dumps(value)
        except ValueError:  # more digits than Python turns into text
            text = "a number too long to show"
    return text if len(text) <= 40 else text[:37] + "..."


class Session:
    """One browser tab: at most one run at a time.

    From the page: ``{"type": "run", "name", "text", "world", "speed"}``,
    ``{"type": "stimulus", "action": "touch", "sensors": [...]}`` or ``{"action": "nose"}``,
    ``{"type": "stop"}``, ``{"type": "debug", "action": "pause" | "resume" | "step" |
    "breakpoints", "breakpoints": [...]}`` (a run's, simulated or on a robot; its own
    breakpoints come with it). To the page: ``started``, ``frame``, ``paused`` and
    ``resumed``, ``ended`` (with the trace, the replay's address and the final stage) and
    ``error`` (a bad message: nothing else happens).
    """

    def __init__(
        self,
        app: web.Application,
        socket: web.WebSocketResponse,
        languages: Languages,
        pupil: Pupil | None = None,
    ) -> None:
        self.app = app
        self.socket = socket
        self.pupil = pupil  # in a class: whose runs these are, in whose folder
        self.folder: ClassFolder = app[STUDIO].folder if pupil is None else pupil.folder
        self.run: SimRun | None = None
        self.name = ""
        self.page_robot: PageRobot | None = None  # the robot this page has linked, if any
        # the page's (from its /ws address): kept for the runs' messages, which come back later
        self.languages = languages
        self._outbox: collections.deque[dict[str, Any]] = collections.deque()
        self._sender: asyncio.Future[None] | None = None

    async def handle(self, raw: str) -> None:
        """One message from the page. Whatever it holds, it gets an error reply if it can't be
        used, and the session goes on (the page, or a script posing as one, is not trusted)."""
        try:
            await self._handle(raw)
        except RootlangError as error:
            for item in error.diagnostics:
                await self.reply_error(item)
        except Exception:  # a message no check foresaw: refused, and logged for us to fix
            LOG.exception("a WebSocket message could not be used")
            await self.reply_error(diagnostic("E806", reason="it holds something unexpected"))

    async def _handle(self, raw: str) -> None:
        if len(raw) > MAX_MESSAGE_BYTES:
            raise RootlangError.of("E806", reason=f"it is longer than {MAX_MESSAGE_BYTES} bytes")
        try:
            message = jsontree.loads(raw)  # at any depth, without recursion (json's C code
        except ValueError:  # can crash a 1 MB stack before its RecursionError on Python 3.13)
            raise RootlangError.of("E806", reason="it is not JSON") from None
        kind = message.get("type") if isinstance(message, dict) else None
        if kind == "run":
            self.start(message)
        elif kind == "stimulus":
            self.stimulate(message)
        elif kind == "stop":
            if self.run is not None:
                self.run.stop()
        elif kind == "debug":
            request = debug_request(message)
            if self.run is not None and not self.run.done.is_set():
                self.run.debug(request)
        elif isinstance(kind, str) and kind.startswith("robot_"):
            await self.page_link(kind, message)
        else:
            raise RootlangError.of("E806", reason=f"there is no message type {shown(kind)}")

    def start(self, message: dict[str, Any]) -> None:
        if self.run is not None and not self.run.done.is_set():
            raise RootlangError.of("E810")
        classroom = self.app[STUDIO].classroom
        if classroom is not None and classroom.locked:
            raise RootlangError.of("E845")
        folder = self.folder
        name, text = text_field(message, "name"), text_field(message, "text")
        speed = message.get("speed", 1)
        if isinstance(speed, bool) or not isinstance(speed, (int, float)) or speed not in SPEEDS:
            raise RootlangError.of(
                "E806", reason=f"the speed {shown(speed)} is not one of {SPEEDS}"
            )
        world = message.get("world", "")
        robot = message.get("robot")
        if robot is not None and not isinstance(robot, str):
            raise RootlangError.of("E806", reason="`robot` must be a robot's name or address")
        on_page = message.get("link") == PAGE_LINK
        if on_page and self.page_robot is None:
            raise RootlangError.of("E816")
        job = RunJob(
            source=text,
            program_path=str(folder.path_of(name)),
            world_path=world_path(folder, world if isinstance(world, str) else ""),
            speed=float(speed),
            robot=None if on_page else robot,
            page_robot=self.page_robot if on_page else None,
            transport=self.app[STUDIO].transport,
            languages=self.languages,
            cpu_seconds=self.app[STUDIO].limits.cpu_seconds,
            breakpoints=breakpoint_lines(message.get("breakpoints")),
        )
        # in a class, each pupil's runs are theirs (a pupil's name, whichever tab runs it)
        owner = None if self.pupil is None else self.pupil.name.casefold()
        run = SimRun(job, self._forward, owner=owner)
        self.name = name
        places = self.app[STUDIO].places
        places.admit(run)  # started now, or when a place is free (E825: full)
        self.run = run
        if classroom is not None:
            classroom.run_started(self, places.place_of(run))

    async def page_link(self, kind: str, message: dict[str, Any]) -> None:
        """The page's own robot (Web Bluetooth): linked or unlinked, and, during a run on it,
        each packet written, each notification, and the link dropping (which ends the run)."""
        if kind == "robot_linked":
            self.page_robot = PageRobot.from_message(message)
            await self._send_now(dict(link_packets(self.page_robot)))
            return
        if kind == "robot_unlinked":
            self.page_robot = None
            return
        run = self.run
        if kind == "robot_stopped":
            self.page_stopped(message.get("why"))
            return
        if kind not in ("robot_written", "robot_notify", "robot_lost"):
            raise RootlangError.of("E806", reason=f"there is no message type {shown(kind)}")
        number, error = message.get("n"), message.get("error")
        if kind == "robot_written" and not (
            isinstance(number, int)
            and 0 <= number < 2**53
            and (error is None or isinstance(error, str))
        ):
            raise RootlangError.of("E806", reason="`n` must be a packet's number, `error` text")
        packet = packet_from_hex(message.get("data")) if kind == "robot_notify" else None
        if run is None or run.done.is_set() or run.job.page_robot is None:
            return  # late news of a run that has ended: nothing to do
        if kind == "robot_written":
            run.relay(kind, {"n": number, "error": error})
        elif kind == "robot_notify":
            run.relay(kind, packet)
        else:  # the robot's link dropped: the run ends (and is ended if it lingers)
            run.relay(kind, StoppedBy(StopReason.PAGE_LINK_DROPPED).to_json())
            run.stop()

    def page_stopped(self, why: object) -> None:
        """The page stopped its robot itself (``why``: its rule that did): the run on it ends
        now, saying so, rather than when its next packet finds the link gone."""
        stop = page_stop(why)
        run = self.run
        if run is None or run.done.is_set() or run.job.page_robot is None:
            return  # (told when the socket came back: that run has ended already)
        run.relay("robot_stopped", stop.to_json())
        run.stop()  # (and it is ended if it lingers)

    def stimulate(self, message: dict[str, Any]) -> None:
        action = message.get("action")
        if not isinstance(action, str) or action not in STIMULI:
            raise RootlangError.of("E806", reason=f"there is no stimulus {shown(action)}")
        sensors = message.get("sensors", [])
        if not isinstance(sensors, list) or not all(isinstance(s, str) for s in sensors):
            raise RootlangError.of("E806", reason="`sensors` must be a list of names")
        if self.run is not None and not self.run.done.is_set():
            self.run.stimulate({"action": action, "sensors": sensors})

    def _forward(self, kind: str, data: Any) -> None:
        if kind == "waiting":  # (told again as the queue moves on)
            data["message"] = catalogue.message("V074", {"place": data["place"]}, self.languages)
        if kind == "ended":
            html = data.pop("replay_html", None)
            if isinstance(html, str):
                data["replay"] = "/replay/" + keep_replay(self.app, html, self.name)
            self._describe_ending(data)
        classroom = self.app[STUDIO].classroom
        if classroom is not None and kind in ("waiting", "started", "ended"):
            classroom.run_told(self, kind, data)
        self._send({"type": kind, **data})

    def _describe_ending(self, outcome: dict[str, Any]) -> None:
        """What stopped a run, and the catalogue's message for a run ended at a limit or by a
        crash, in the page's language (an ending is called back: by the worker, a deadline,
        the server)."""
        languages = self.languages
        stop = StoppedBy.from_json(outcome.pop("stop", None))  # (the page wants words)
        if stop is not None:
            outcome["stopped_by"] = stop.shown(languages)
        if outcome.get("end") == "limit":
            limit = diagnostic(outcome["code"], limit=outcome["limit"])
            outcome["error"] = diagnostic_json(limit, "", languages)
        elif outcome.get("end") == "crashed":
            crashed = diagnostic("E813", reason=outcome["reason"])
            outcome["error"] = diagnostic_json(crashed, "", languages)

    def _send(self, payload: dict[str, Any]) -> None:
        """Queue a message for the page, in order (the worker's messages come as callbacks).
        A page that doesn't keep up has its waiting frames merged into one, so the server
        holds at most one frame per page, not a stream of them."""
        if self.socket.closed:
            return
        waiting = self._outbox[-1] if self._outbox else None
        if payload["type"] == "frame" and waiting is not None and waiting["type"] == "frame":
            merge_frames(waiting, payload)
        else:
            self._outbox.append(payload)
        if self._sender is None or self._sender.done():
            self._sender = asyncio.ensure_future(self._drain())

    async def _drain(self) -> None:
        while self._outbox:
            await self._send_now(self._outbox.popleft())

    async def _send_now(self, payload: dict[str, Any]) -> None:
        with contextlib.suppress(ConnectionError, RuntimeError):  # the page went away meanwhile
            await self.socket.send_json(payload)

    async def reply_error(self, item: Diagnostic) -> None:
        await self._send_now({"type": "error", **diagnostic_json(item, "", self.languages)})

    def close(self) -> None:
        """The page went away: a simulated run ends now; a robot first gets Stop (and Stop and
        Reset from the runtime), and its worker is ended if it lingers."""
        if self.run is None or self.run.done.is_set():
            return
        if not self.run.job.on_robot or not self.run.started:
            self.run.kill({"end": "stopped", **StoppedBy(StopReason.PAGE_CLOSED).outcome()})
            return
        if self.run.job.page_robot is not None:  # the page's link to its robot went with it
            self.run.relay("robot_lost", StoppedBy(StopReason.PAGE_LOST_STUDIO).to_json())
        self.run.stop()


def merge_frames(older: dict[str, Any], newer: dict[str, Any]) -> None:
    """``older`` (not sent yet) becomes the one frame that says what both say: the newer one's
    time, pose and running lines; the ink, printed and said text and what the robot felt of
    both, in order (the worker caps a run's text, so a merged frame stays as small as the
    run); the newest notes (heard late, a page hears the last few only)."""
    for key in ("ink", "printed", "said", "happened"):
        newer[key] = older.get(key, []) + newer.get(key, [])
    newer["notes"] = (older.get("notes", []) + newer.get("notes", []))[-NOTES_PER_FRAME:]
    older.clear()
    older.update(newer)


async def _stop_every_run(app: web.Application) -> None:
    app[STUDIO].places.close()  # (a run waiting for a place doesn't start as others end)
    for session in list(app[STUDIO].sessions):
        session.close()
        await session.socket.close()


# --- running the server ---------------------------------------------------------------------------


def pupils_address(names: tuple[str, ...]) -> str:
    """Of this computer's names and addresses, the one to tell pupils: its IPv4 address on
    the network (digits type alike on every keyboard, and need no name service); the one its
    default route leaves from, which :func:`lan_names` lists last."""
    for name in reversed(names):
        with contextlib.suppress(ValueError):
            address = ipaddress.ip_address(name)
            if address.version == 4 and not address.is_loopback:
                return name
    return next((name for name in names if name not in LOOPBACK_NAMES), "")


async def serve(
    folder: ClassFolder,
    host: str,
    port: int,
    on_ready: Callable[[str], None],
    transport: str | None = None,
    classroom: Classroom | None = None,
    tls: StudioCertificate | None = None,
    limits: ClassLimits | None = None,
    allow_hosts: tuple[str, ...] = (),
    warm: bool = False,
    languages: Languages | None = None,
) -> None:
    """Serve until cancelled (Ctrl-C); every run is stopped on the way out. With ``tls``
    (``--https``), over TLS: a pupil's browser then has Web Bluetooth on the LAN. Pages may
    ask for it by this computer's names and addresses, and by each of ``allow_hosts``. With
    ``warm`` (``rootlang studio`` itself), the first Run and edit find the processes that do
    them started (a class always does). ``languages``: the command's (``--language``)."""
    loopback = host in LOOPBACK_NAMES
    app = make_app(folder, transport, loopback_only=loopback, classroom=classroom, limits=limits,
                   languages=languages)  # fmt: skip
    if warm and classroom is None:
        app.on_startup.append(warm_up_runs)
    names = set(LOOPBACK_NAMES) | {name.lower().rstrip(".") for name in allow_hosts}
    lan = () if loopback else lan_names(host)
    app[STUDIO].host_names = frozenset(names | {name.lower() for name in lan})
    runner = web.AppRunner(app, handle_signals=False)
    await runner.setup()
    site = web.TCPSite(runner, host, port, ssl_context=tls.ssl_context() if tls else None)
    try:
        await site.start()
    except OSError as error:
        await runner.cleanup()
        reason = os.strerror(error.errno) if error.errno else str(error)
        raise RootlangError.of("E814", host=host, port=port, reason=reason.lower()) from None
    bound = runner.addresses[0]
    shown_host = "127.0.0.1" if host in ("127.0.0.1", "localhost") else host
    if tls is not None and host in ("0.0.0.0", "::"):  # a name in the certificate, not 0.0.0.0
        shown_host = next((n for n in tls.names[3:] if n), shown_host)
    elif host in ("0.0.0.0", "::"):  # the address pupils type: this computer's on the LAN
        shown_host = pupils_address(lan) or shown_host
    on_ready(f"{'https' if tls else 'http'}://{shown_host}:{bound[1]}/")
    try:
        await asyncio.Event().wait()
    finally:
        await runner.cleanup()
