"""A class on one studio: each pupil their own folder, the teacher's page, tasks that check.

With ``rootlang studio --class`` (and whenever it serves a network) the page first asks the
pupil's name. The name picks the pupil's own folder, ``FOLDER/<name>/`` (made on first use, with
a copy of each starter in ``FOLDER/_start/`` and of each task's starter in ``FOLDER/_tasks/``),
and the server hands back a random token in a cookie. Every file request and run is then served
from the folder the *token* belongs to — never from a name or path in the request — so no
address can reach another pupil's files.

The teacher's page (``/teacher``) is opened with the code the studio prints at start-up (a
cookie then keeps the teacher in): it gets every pupil live over its own WebSocket — the program
they have open (its text, as the page syncs it at every change, and its mistakes), whether it
runs and on what, the last run's ending and replay, their checks — at most every
:data:`PUSH_PERIOD_S`; it stops every run (a simulated one at once, a robot — over Bluetooth
or linked by the pupil's page — with Stop, its worker ended :data:`ROBOT_STOP_S` later), sends
the class a message, locks editing ("hands off": the pages cover themselves, and the server
refuses changes and runs) and mutes the robots' sounds in every pupil's page.

Tasks (:mod:`rootlang.testing.tasks`) are checked in child processes under ``rootlang test``'s
limits, in a thread so the server serves on; at most one check per core at once. Adventures
(:mod:`rootlang.adventures`: the built-in ones and the class folder's ``_adventures/``) are
tasks a pupil starts from a list, checked the same way and then given a hint; which ones each
pupil has passed is kept in their folder, for the teacher's page (the routes for both are
:mod:`rootlang.studio.lessons`', the one-person studio's too).
"""

from __future__ import annotations

import asyncio
import contextlib
import json
import re
import secrets
import shutil
import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Protocol

from aiohttp import WSCloseCode, WSMsgType, web

from rootlang.diagnostics import Diagnostic, RootlangError, diagnostic
from rootlang.locale.blocks import studio_strings
from rootlang.locale.translate import about
from rootlang.runtime.stops import StoppedBy, StopReason
from rootlang.studio import messages as m
from rootlang.studio.conversions import diagnostic_json, text_field
from rootlang.studio.folder import PROGRAM_SUFFIX, SIDECAR_SUFFIX, ClassFolder
from rootlang.studio.lessons import (
    WORLDS,
    Learner,
    Lessons,
    checked_json,
    task_json,
)
from rootlang.studio.pages import json_body, languages_of, own_origin, page, setup_in_language
from rootlang.studio.runs import SimRun
from rootlang.studio.worker import RunJob
from rootlang.testing.reports import junit_xml, report_text
from rootlang.testing.tasks import Checked, CheckJob, Task
from rootlang.wording.language import Languages

PUPIL_COOKIE = "rootlang_pupil"
TEACHER_COOKIE = "rootlang_teacher"
STARTERS = "_start"
PUSH_PERIOD_S = 0.1  # the teacher's page gets changes batched, at most 10 times a second
ROBOT_STOP_S = 0.5  # after the teacher's Stop, a robot's run gets this long to stop itself
CODE_TRIES = 5  # wrong teacher's codes in a row from one page before a pause of a minute
PUPILS_CODE_TRIES = 50  # ... from all the pupils at one address (a pupil may make new names)
CODE_PAUSE_S = 60.0
_PUPILS = "\0pupils"  # (the key of all the pupils at one address: no pupil is called that)
# A name a child types: letters (any script), digits, spaces, - and _; not starting with _ or
# . (FOLDER/_start, FOLDER/_tasks and hidden folders are the teacher's)
_PUPIL_NAME = re.compile(r"[^\W_][\w \-]{0,31}", re.UNICODE)
_RESERVED = {WORLDS}


def pupil_name(typed: str) -> str:
    """The name as the pupil's folder is called: spaces tidied; E843 for one that can't be."""
    name = " ".join(typed.split()) if isinstance(typed, str) else ""
    if not _PUPIL_NAME.fullmatch(name) or name.casefold() in _RESERVED:
        raise RootlangError.of("E843", name=str(typed)[:40] or '""')
    return name


class Session(Protocol):
    """A pupil's page as the class sees it (:class:`rootlang.studio.server.Session`): whose
    it is, and its run."""

    @property
    def pupil(self) -> Pupil | None: ...

    @property
    def run(self) -> SimRun | None: ...

    @property
    def name(self) -> str: ...


@dataclass
class Pupil(Learner):
    """A pupil, and what the teacher's page shows of them."""

    program: str = ""  # the program open in their page
    text: str = ""
    problems: list[Diagnostic] = field(default_factory=list)  # the text's, as checked
    run: m.PupilRunJson | None = None  # the run going on: its program, where
    # the last run's ending, mistakes, replay (told by the run's page, in the pupil's words)
    last: m.LastRunJson | None = None
    checks: dict[str, Checked] = field(default_factory=dict)  # by task
    pages: int = 0  # pages open (their class WebSockets)
    sessions: set[Session] = field(default_factory=set)
    level: int | None = None  # the level the teacher chose for them (None: the class's)

    def to_json(self, languages: Languages, class_level: int) -> m.PupilJson:
        """The pupil as a teacher's page sees them: mistakes and checks in its ``languages``
        (code in them as the pupil's program writes it), the level their pages show."""
        shown = about(languages, self.text)
        problems: list[m.ProblemJson] = [
            {"severity": item.severity, "line": item.span.line, "message": item.shown(shown)}
            for item in self.problems
        ]
        return {
            "name": self.name, "program": self.program, "text": self.text,
            "problems": problems, "run": self.run, "last": self.last,
            "checks": {task: checked_json(checked, languages)
                       for task, checked in self.checks.items()},
            "online": self.pages > 0,
            "level": self.level or class_level, "own_level": self.level is not None,
            "adventures": dict(self.adventures),
        }  # fmt: skip


@dataclass
class _CodeTries:
    """Wrong teacher's codes from one page (or one address's pupils), and its pause."""

    wrong: int = 0
    paused_until: float = 0.0  # (time.monotonic)


class Classroom(Lessons):
    """The class's pupils, the teacher's code and pages, and what the teacher has said."""

    def __init__(self, folder: ClassFolder, code: str | None = None, level: int = 2) -> None:
        super().__init__(folder.root, with_tasks=True)
        self.level = level  # the level the pupils' pages show (docs/levels.md)
        self.code = code or f"{secrets.randbelow(10**6):06d}"
        self.pupils: dict[str, Pupil] = {}  # by the name's casefold
        self._tokens: dict[str, str] = {}  # a pupil's cookie -> their name's casefold
        self._teachers: set[str] = set()  # the teachers' cookies
        self._code_tries: dict[tuple[str, str], _CodeTries] = {}
        self.locked = False
        self.muted = False  # no robot sounds in the pupils' pages
        self.notice = ""
        self._watchers: dict[web.WebSocketResponse, Languages] = {}  # teachers' pages
        self._pages: dict[web.WebSocketResponse, Pupil] = {}  # pupils' class sockets
        self._changed: set[str] = set()
        self._push: asyncio.TimerHandle | None = None

    # --- who is asking --------------------------------------------------------------------

    def pupil_of(self, request: web.Request) -> Pupil | None:
        key = self._tokens.get(request.cookies.get(PUPIL_COOKIE, ""))
        return None if key is None else self.pupils.get(key)

    def folder_of(self, request: web.Request) -> ClassFolder:
        """The requesting pupil's folder; E842 (401) without a name, E845 for a change while
        the class is locked."""
        pupil = self.pupil_of(request)
        if pupil is None:
            raise web.HTTPUnauthorized(**_error_body(request, "E842"))
        if self.locked and request.method != "GET":
            raise RootlangError.of("E845")
        return pupil.folder

    def is_teacher(self, request: web.Request) -> bool:
        return request.cookies.get(TEACHER_COOKIE, "") in self._teachers

    def code_tried(self, request: web.Request, code: str) -> bool:
        """Whether ``code`` is the teacher's, from this page; E849 while its tries are paused.

        Wrong codes are counted per client address and, for a pupil's page, per pupil at it:
        :data:`CODE_TRIES` wrong in a row pause that page's tries for :data:`CODE_PAUSE_S`
        (guessing a million codes then takes for ever), and :data:`PUPILS_CODE_TRIES` from the
        pupils at one address pause them all (a name costs nothing). A page without a pupil's
        cookie at another address (the teacher's) is never paused by them."""
        now = time.monotonic()
        for key, tries in list(self._code_tries.items()):  # (forget the ones long done)
            if tries.wrong == 0 and tries.paused_until <= now:
                del self._code_tries[key]
        remote = request.remote or ""
        pupil = self._tokens.get(request.cookies.get(PUPIL_COOKIE, ""))
        keys = {(remote, ""): CODE_TRIES} if pupil is None else {
            (remote, pupil): CODE_TRIES, (remote, _PUPILS): PUPILS_CODE_TRIES}  # fmt: skip
        counted = [(self._code_tries.setdefault(key, _CodeTries()), most)
                   for key, most in keys.items()]  # fmt: skip
        if any(now < tries.paused_until for tries, _ in counted):
            raise RootlangError.of("E849")
        right = secrets.compare_digest(code.encode(), self.code.encode())
        for tries, most in counted:
            tries.wrong = 0 if right else tries.wrong + 1
            if tries.wrong >= most:
                tries.wrong, tries.paused_until = 0, now + CODE_PAUSE_S
        return right

    # --- pupils ---------------------------------------------------------------------------

    def join(self, typed: str, token: str | None) -> tuple[Pupil, str]:
        """The pupil of this name (their folder made, starters handed out) and their new
        token; E844 while someone else's page is open under the name."""
        name = pupil_name(typed)
        key = name.casefold()
        pupil = self.pupils.get(key)
        if pupil is not None and pupil.pages > 0 and self._tokens.get(token or "") != key:
            raise RootlangError.of("E844", name=pupil.name)
        if pupil is None:
            pupil = Pupil(self._existing(name), ClassFolder(self._make_folder(name)))
            pupil.name = pupil.folder.root.name
            pupil.load_progress()
            self.pupils[key] = pupil
        self._hand_out(pupil.folder.root)
        for old in [t for t, k in self._tokens.items() if k == key]:
            del self._tokens[old]  # one computer at a time per name
        token = secrets.token_urlsafe(18)
        self._tokens[token] = key
        self.changed(pupil)
        return pupil, token

    def _existing(self, name: str) -> str:
        """A folder already there for this name in other letters' case (anna, Anna) is it."""
        for below in self.root.iterdir():
            if below.is_dir() and below.name.casefold() == name.casefold():
                return below.name
        return name

    def _make_folder(self, name: str) -> Path:
        folder = self.root / name
        if folder.is_symlink() or (folder.exists() and not folder.is_dir()):
            raise RootlangError.of("E843", name=name)
        folder.mkdir(exist_ok=True)
        if folder.resolve().parent != self.root:
            raise RootlangError.of("E843", name=name)
        return folder

    def _hand_out(self, folder: Path) -> None:
        """Copies of the starters and the tasks' starters the pupil has not got yet (never
        over their own work), and the class's worlds (so `# world:` lines find them)."""
        starters = sorted((self.root / STARTERS).glob("*" + PROGRAM_SUFFIX))
        starters += [task.starter for task in self.tasks()]
        for starter in starters:
            target = folder / starter.name
            if starter.is_file() and not target.exists():
                shutil.copyfile(starter, target)
                layout = starter.with_name("." + starter.name + SIDECAR_SUFFIX)
                if layout.is_file():
                    shutil.copyfile(layout, folder / layout.name)
        worlds = self.root / WORLDS
        if worlds.is_dir():
            (folder / WORLDS).mkdir(exist_ok=True)
            for world in worlds.glob("*.toml"):
                if world.is_file():
                    shutil.copyfile(world, folder / WORLDS / world.name)

    def learner_of(self, request: web.Request) -> Pupil:
        """The pupil asking: 401 without a name, E845 for a change while the class is locked."""
        self.folder_of(request)
        pupil = self.pupil_of(request)
        assert pupil is not None
        return pupil

    def checked(self, learner: Learner, job: CheckJob, result: Checked) -> None:
        """A pupil's check, kept for the teacher's page."""
        if isinstance(learner, Pupil):
            learner.checks[job.task.name] = result
            self.changed(learner)

    # --- what pupils do (hooks from the server) -------------------------------------------

    def saw_text(
        self, request: web.Request, name: str, text: str, found: Sequence[Diagnostic]
    ) -> None:
        pupil = self.pupil_of(request)
        if pupil is None:
            return
        pupil.program, pupil.text, pupil.problems = name, text, list(found)
        self.changed(pupil)

    def run_started(self, session: Session, waiting: int) -> None:
        """A pupil's run has begun: it runs, or waits for a free place (``waiting``-th)."""
        pupil, run = session.pupil, session.run
        if pupil is None or run is None:
            return
        pupil.sessions.add(session)
        pupil.run = {
            "program": session.name,
            "robot": robot_of(run.job),
            "since": time.time(),
            "waiting": waiting,
        }
        self.changed(pupil)

    def run_told(self, session: Session, kind: str, outcome: dict[str, Any]) -> None:
        """A run waits for a free place (its place in the queue), its worker has started it (on
        a robot: which one it found), or it has ended."""
        pupil = session.pupil
        if pupil is None:
            return
        if kind in ("waiting", "started"):
            if pupil.run is not None:
                pupil.run["waiting"] = int(outcome.get("place", 0)) if kind == "waiting" else 0
                if isinstance(outcome.get("robot"), str):
                    pupil.run["robot"] = outcome["robot"]
                self.changed(pupil)
            return
        pupil.sessions.discard(session)
        pupil.run = None
        error = outcome.get("error") or next(iter(outcome.get("errors") or []), None)
        pupil.last = {
            "program": session.name,
            "robot": None if session.run is None else robot_of(session.run.job),
            "end": str(outcome.get("end")),
            "stopped_by": outcome.get("stopped_by"),
            "error": None if not isinstance(error, dict) else
            {"line": error.get("line", 0), "message": error.get("message", "")},
            "replay": outcome.get("replay"),
            "trace": list(outcome.get("trace") or [])[-40:],
        }  # fmt: skip
        self.changed(pupil)

    # --- the teacher ------------------------------------------------------------------------

    def stop_all(self) -> list[Session]:
        """Stop every run as its own Stop button would (the robot stops at once, `when
        stopped` runs, the pupil keeps the run's replay), said to be by the teacher; a run on
        a robot is ended a moment later whatever it does. The runs stopped."""
        loop = asyncio.get_running_loop()
        stopped = []
        ended = {"end": "stopped", **StoppedBy(StopReason.TEACHER).outcome()}
        for pupil in self.pupils.values():
            for session in list(pupil.sessions):
                run = session.run
                if run is None or run.done.is_set():
                    pupil.sessions.discard(session)
                    continue
                stopped.append(session)
                run.stop(StopReason.TEACHER)
                if run.job.on_robot:
                    loop.call_later(ROBOT_STOP_S, run.kill, dict(ended))
        return stopped

    def tell(self, text: str) -> None:
        self.notice = text[:500]
        self._to_pages(m.NoticeMessage(type="notice", text=self.notice, at=time.time()))

    def lock(self, locked: bool) -> None:
        self.locked = locked
        self._to_pages(m.LockedMessage(type="locked", locked=locked))
        self._push_soon()

    def choose_level(self, level: int, pupil: Pupil | None) -> None:
        """The level for one pupil's pages, or (None) for the class's: each page told."""
        if pupil is not None:
            pupil.level = level
        else:
            self.level = level
        for socket, owner in list(self._pages.items()):
            if pupil is None or owner is pupil:
                shown = owner.level or self.level
                _send_soon(socket, m.LevelMessage(type="level", level=shown))
        for each in [pupil] if pupil is not None else self.pupils.values():
            self.changed(each)

    def mute(self, muted: bool) -> None:
        self.muted = muted
        self._to_pages(m.MutedMessage(type="muted", muted=muted))

    def _to_pages(self, message: m.ToClassPage) -> None:
        for socket in list(self._pages):
            _send_soon(socket, message)

    # --- keeping the teacher's pages up to date -----------------------------------------------

    def changed(self, pupil: Pupil) -> None:
        self._changed.add(pupil.name.casefold())
        self._push_soon()

    def _push_soon(self) -> None:
        if self._push is None and self._watchers:
            self._push = asyncio.get_running_loop().call_later(PUSH_PERIOD_S, self._push_now)

    def _push_now(self) -> None:
        self._push = None
        changed = [self.pupils[key] for key in sorted(self._changed) if key in self.pupils]
        self._changed.clear()
        told: dict[Languages, m.PupilsMessage] = {}  # (each language's said once)
        for socket, languages in list(self._watchers.items()):
            if languages not in told:
                told[languages] = {
                    "type": "pupils", "pupils": [p.to_json(languages, self.level) for p in changed],
                    "locked": self.locked, "sent_at": time.time(),
                }  # fmt: skip
            _send_soon(socket, told[languages])

    def snapshot(self, languages: Languages) -> m.ClassMessage:
        """The whole class, as a teacher's page in ``languages`` sees it."""
        return {
            "type": "class",
            "pupils": [p.to_json(languages, self.level) for _, p in sorted(self.pupils.items())],
            "tasks": [task_json(task) for task in self.tasks()],
            "adventures": [
                {"name": a.name, "level": a.level, "title": a.title(languages.messages)}
                for a in self.adventures()
            ],
            "locked": self.locked,
            "muted": self.muted,
            "level": self.level,
            "notice": self.notice,
            "sent_at": time.time(),
        }

    def add_routes(self, app: web.Application) -> None:
        super().add_routes(app)
        app[CLASSROOM] = self
        app.router.add_get("/teacher", _teacher_page)
        app.router.add_post("/api/pupil", _join)
        app.router.add_get("/api/pupil", _who)
        app.router.add_get("/ws/class", _class_socket)
        app.router.add_post("/api/teacher/login", _login)
        app.router.add_get("/api/teacher/setup", _teacher_setup)
        app.router.add_post("/api/teacher/stop", _stop_all)
        app.router.add_post("/api/teacher/notice", _notice)
        app.router.add_post("/api/teacher/lock", _lock)
        app.router.add_post("/api/teacher/mute", _mute)
        app.router.add_post("/api/teacher/level", _level)
        app.router.add_post("/api/teacher/check", _check_class)
        app.router.add_get("/api/teacher/export", _export)
        app.router.add_get("/ws/teacher", _teacher_socket)
        app.on_shutdown.append(self._say_goodbye)

    async def _say_goodbye(self, app: web.Application) -> None:
        """The studio stopping: each pupil's and teacher's page is told it goes away, so the
        studio need not wait for them to leave (they come back by themselves when it starts
        again)."""
        for socket in [*self._pages, *self._watchers]:
            await socket.close(code=WSCloseCode.GOING_AWAY)


CLASSROOM = web.AppKey("classroom", Classroom)


def robot_of(job: RunJob) -> str | None:
    """The robot a run is on, as the teacher's page names it; None: the simulator."""
    if job.page_robot is not None:  # the pupil's own, linked by their page (Web Bluetooth)
        return job.page_robot.describe()
    return job.robot


def _error_body(request: web.Request, code: str, origin: str = "") -> dict[str, Any]:
    """The body of a refusal that is not a 400 (401, 403), as :func:`error_reply` writes it."""

    found = diagnostic(code, origin=origin) if origin else diagnostic(code)
    body = {"errors": [diagnostic_json(found, "", languages_of(request))]}
    return {"text": json.dumps(body), "content_type": "application/json"}


_SENDING: set[asyncio.Task[None]] = set()  # (kept until done: a task only weakly held may vanish)
_IN_ORDER: dict[web.WebSocketResponse, asyncio.Lock] = {}


def _send_soon(
    socket: web.WebSocketResponse, message: m.ToClassPage | m.ToTeacher | m.LockedMessage
) -> None:
    """Send without waiting here, each socket's messages in the order given (a lock is FIFO,
    and the tasks reach it in the order they were made)."""

    async def send() -> None:
        async with _IN_ORDER.setdefault(socket, asyncio.Lock()):
            with contextlib.suppress(ConnectionError, RuntimeError):
                await socket.send_json(message)
        if socket.closed:
            _IN_ORDER.pop(socket, None)

    if not socket.closed:
        task = asyncio.ensure_future(send())
        _SENDING.add(task)
        task.add_done_callback(_SENDING.discard)


def _own_page(request: web.Request) -> None:
    """A WebSocket must come from the studio's own pages (browsers always send Origin)."""

    origin = request.headers.get("Origin", "none")
    if origin != own_origin(request):
        raise web.HTTPForbidden(**_error_body(request, "E804", origin=origin))


# --- pupils' routes -----------------------------------------------------------------------------


async def _join(request: web.Request) -> web.StreamResponse:

    classroom = request.app[CLASSROOM]
    typed = text_field(await json_body(request), "name")
    pupil, token = classroom.join(typed, request.cookies.get(PUPIL_COOKIE))
    reply: m.PupilReply = {"name": pupil.name}
    response = web.json_response(reply)
    response.set_cookie(PUPIL_COOKIE, token, httponly=True, samesite="Strict", path="/")
    return response


async def _who(request: web.Request) -> web.StreamResponse:
    classroom = request.app[CLASSROOM]
    pupil = classroom.pupil_of(request)
    tasks = [task_json(task) for task in classroom.tasks()]
    language = languages_of(request).messages
    reply: m.WhoReply = {
        "class": True, "name": None if pupil is None else pupil.name, "tasks": tasks,
        "locked": classroom.locked, "muted": classroom.muted, "notice": classroom.notice,
        "level": (pupil.level if pupil is not None else None) or classroom.level,
        "language": language,
        "strings": studio_strings(language),
    }  # fmt: skip
    return web.json_response(reply)


async def _class_socket(request: web.Request) -> web.StreamResponse:
    """A pupil's page, online: the teacher's messages and locks come this way."""
    classroom = request.app[CLASSROOM]
    pupil = classroom.pupil_of(request)
    if pupil is None:
        raise web.HTTPUnauthorized(**_error_body(request, "E842"))
    _own_page(request)
    socket = web.WebSocketResponse(heartbeat=20)
    await socket.prepare(request)
    classroom._pages[socket] = pupil
    pupil.pages += 1
    classroom.changed(pupil)
    await socket.send_json(m.LockedMessage(type="locked", locked=classroom.locked))
    await socket.send_json(m.MutedMessage(type="muted", muted=classroom.muted))
    await socket.send_json(m.LevelMessage(type="level", level=pupil.level or classroom.level))
    try:
        async for message in socket:
            if message.type == WSMsgType.ERROR:
                break
    finally:
        classroom._pages.pop(socket, None)
        pupil.pages -= 1
        classroom.changed(pupil)
    return socket


# --- the teacher's routes -----------------------------------------------------------------------


def _teacher(request: web.Request) -> Classroom:
    classroom = request.app[CLASSROOM]
    if not classroom.is_teacher(request):
        raise web.HTTPUnauthorized(**_error_body(request, "E847"))
    return classroom


async def _teacher_page(request: web.Request) -> web.StreamResponse:

    return page("teacher.html")


async def _login(request: web.Request) -> web.StreamResponse:

    classroom = request.app[CLASSROOM]
    code = text_field(await json_body(request), "code").strip()
    if not classroom.code_tried(request, code):
        raise web.HTTPForbidden(**_error_body(request, "E846"))
    token = secrets.token_urlsafe(18)
    classroom._teachers.add(token)
    reply: m.LoginReply = {"teacher": True}
    response = web.json_response(reply)
    response.set_cookie(TEACHER_COOKIE, token, httponly=True, samesite="Strict", path="/")
    return response


async def _teacher_setup(request: web.Request) -> web.StreamResponse:
    """What the teacher's page needs first: its words, the blocks (to show pupils' programs
    read-only), the languages."""
    from rootlang.locale.keywords import LANGUAGE_NAMES

    _teacher(request)
    language = languages_of(request).messages
    reply: m.TeacherSetupReply = {"language": language, "languages": LANGUAGE_NAMES,
                                   **setup_in_language(language)}  # fmt: skip
    return web.json_response(reply)


async def _stop_all(request: web.Request) -> web.StreamResponse:
    """Stop every run; answer when all have ended (or after a second and a half)."""
    classroom = _teacher(request)
    started = time.monotonic()
    stopped = classroom.stop_all()
    waits = [asyncio.ensure_future(s.run.done.wait()) for s in stopped if s.run is not None]
    if waits:
        await asyncio.wait(waits, timeout=ROBOT_STOP_S + 1.0)
    for wait in waits:
        wait.cancel()
    ended = sum(1 for s in stopped if s.run is not None and s.run.done.is_set())
    reply: m.StopAllReply = {"stopped": len(stopped), "ended": ended,
                             "seconds": round(time.monotonic() - started, 3)}  # fmt: skip
    return web.json_response(reply)


async def _notice(request: web.Request) -> web.StreamResponse:

    classroom = _teacher(request)
    classroom.tell(text_field(await json_body(request), "text"))
    reply: m.NoticeReply = {"notice": classroom.notice}
    return web.json_response(reply)


async def _switched(request: web.Request, key: str) -> tuple[Classroom, bool]:
    """The teacher's switch ``key`` (``locked``, ``muted``): true or false, else E805."""

    classroom = _teacher(request)
    value = (await json_body(request)).get(key)
    if not isinstance(value, bool):
        raise RootlangError.of("E805", reason=f"`{key}` must be true or false")
    return classroom, value


async def _lock(request: web.Request) -> web.StreamResponse:
    classroom, locked = await _switched(request, "locked")
    classroom.lock(locked)
    reply: m.LockRequest = {"locked": locked}
    return web.json_response(reply)


async def _mute(request: web.Request) -> web.StreamResponse:
    classroom, muted = await _switched(request, "muted")
    classroom.mute(muted)
    reply: m.MuteRequest = {"muted": muted}
    return web.json_response(reply)


async def _level(request: web.Request) -> web.StreamResponse:
    """The teacher chose a level (1, 2 or 3) for the class, or for one pupil."""
    classroom = _teacher(request)
    data = await json_body(request)
    level, name = data.get("level"), data.get("pupil", "")
    if level not in (1, 2, 3) or isinstance(level, bool):
        raise RootlangError.of("E805", reason="`level` must be 1, 2 or 3")
    pupil = classroom.pupils.get(str(name).casefold()) if name else None
    if name and pupil is None:
        raise RootlangError.of("E805", reason=f"no pupil is called {str(name)[:40]}")
    classroom.choose_level(level, pupil)
    reply: m.LevelRequest = {"level": level, "pupil": "" if pupil is None else pupil.name}
    return web.json_response(reply)


def _task_named(classroom: Classroom, name: object) -> Task:
    task = next((t for t in classroom.tasks() if t.name == name), None)
    if task is None:
        raise RootlangError.of("E848", name=str(name)[:80])
    return task


async def _check_class(request: web.Request) -> web.StreamResponse:
    """Check every pupil's program for a task (each as the pupil last saved it)."""

    classroom = _teacher(request)
    task = _task_named(classroom, (await json_body(request)).get("task"))
    jobs, pupils = [], []
    for pupil in classroom.pupils.values():
        with contextlib.suppress(RootlangError):
            text = pupil.folder.read(task.program)
            jobs.append(CheckJob(task, f"{pupil.name}/{task.program}", text))
            pupils.append(pupil)
    languages = languages_of(request)
    results = await classroom.check(jobs, pupils) if jobs else []
    reply: m.ClassCheckReply = {
        "task": task.name,
        "results": {p.name: checked_json(r, languages)
                    for p, r in zip(pupils, results, strict=True)},
    }  # fmt: skip
    return web.json_response(reply)


async def _export(request: web.Request) -> web.StreamResponse:
    """The class's progress on a task: CSV (``format=csv``) or JUnit XML (``format=junit``),
    the reports ``rootlang test --report/--junit`` writes, what each check said in the
    teacher's language."""
    classroom = _teacher(request)
    task = _task_named(classroom, request.query.get("task"))
    languages = languages_of(request)
    rows = [
        pupil.checks[task.name].report(languages)
        for _, pupil in sorted(classroom.pupils.items())
        if task.name in pupil.checks
    ]
    kind = request.query.get("format", "csv")
    if kind == "junit":
        body, suffix, content = junit_xml(rows, name=task.name), "xml", "application/xml"
    else:
        body, suffix, content = report_text(rows, ".csv"), "csv", "text/csv"
    return web.Response(
        text=body, content_type=content,
        headers={"Content-Disposition": f'attachment; filename="{task.name}.{suffix}"'},
    )  # fmt: skip


async def _teacher_socket(request: web.Request) -> web.StreamResponse:
    classroom = _teacher(request)
    _own_page(request)
    socket = web.WebSocketResponse(heartbeat=20)
    await socket.prepare(request)
    languages = languages_of(request)
    classroom._watchers[socket] = languages
    await socket.send_json(classroom.snapshot(languages))
    try:
        async for message in socket:
            if message.type == WSMsgType.ERROR:
                break
    finally:
        classroom._watchers.pop(socket, None)
    return socket
