"""One simulated run in a worker process, streaming what the robot does.

The studio's server starts one worker process per run (:class:`RunJob`); a child's endless loop
or memory bomb then stalls nobody else. The worker runs the program exactly as ``rootlang sim``
does — the real runtime, scheduler, robot client and packet-level simulator, through
:class:`~rootlang.sim.transport.SimTransport` — on a clock paced to the chosen speed
(:class:`~rootlang.studio.clock.ScaledWallClock`), or in virtual time for "as fast as it goes",
which gives the very trace ``rootlang sim`` gives.

The worker and the server talk over a duplex pipe, in small tuples ``(kind, data)``:

- to the server: ``("started", stage)``, ``("frame", frame)`` about 25 times a second,
  ``("ended", outcome)`` once, at the end;
- to the worker: ``("stimulus", {"action": "touch", "sensors": [...]})`` or
  ``("stimulus", {"action": "nose"})`` — a person touching the robot, as a world file's scripted
  stimuli do. The studio's Stop is the nose button, so ``when stopped`` scripts run;
  ``("debug", {"action": "pause" | "resume" | "step" | "breakpoints", ...})``: the debugger's
  buttons, answered by ``("paused", pause)`` and ``("resumed", ...)``; ``("watch", ...)``: the
  values while a paced run goes on
  (:mod:`rootlang.studio.debugging`).

A sampling thread reads the robot's recording and the trace (it never touches the event loop,
so watching a run cannot change it) and sends frames; the server forwards them to the page.
"""

from __future__ import annotations

import asyncio
import contextlib
import multiprocessing
import os
import signal
import threading
import time
from dataclasses import dataclass
from multiprocessing.connection import Connection
from pathlib import Path

# Imported up front (not when a run starts): the worker processes fork from a server that
# preloads this module, so every run starts with the runtime, simulator and pictures loaded.
import rootlang
from rootlang import ast
from rootlang.app import link, session
from rootlang.app.bluetooth import bluetooth
from rootlang.app.link import RelayTransport
from rootlang.app.sandbox import (  # the limits of `rootlang test`
    KERNEL_MARGIN_SECONDS,
    cap_cpu,
    cap_memory,
    cpu_backstop,
)
from rootlang.diagnostics import RootlangError, diagnostic
from rootlang.locale.translate import about
from rootlang.runtime.budget import CpuBudget
from rootlang.runtime.clock import Clock, VirtualClock, WallClock
from rootlang.runtime.scheduler import RunResult
from rootlang.runtime.stops import Connected, RunEnded, StoppedBy, StopReason
from rootlang.runtime.trace import ChildView, TraceEntry, ViewLine
from rootlang.runtime.transport import Transport
from rootlang.sim.recording import Recording
from rootlang.sim.render import html_text
from rootlang.sim.render.compose import replay_of, scene_of
from rootlang.sim.render.html import page_data
from rootlang.sim.world import World
from rootlang.studio.clock import ScaledWallClock
from rootlang.studio.debugging import RobotDebugging, RunDebugging
from rootlang.studio.messages import StageData
from rootlang.studio.page_robot import PageRobot, PageTransport
from rootlang.studio.timeslider import GoingBack
from rootlang.wording.catalogue import message
from rootlang.wording.language import ENGLISH, Languages
from rootlang.wording.shown import unquoted

FRAME_PERIOD_S = 0.04  # 25 frames a second: smooth to the eye, light on the pipe
FASTEST = 0.0  # the speed that means "as fast as it goes" (virtual time)
SPEEDS = (1.0, 2.0, 5.0, 10.0, FASTEST)


@dataclass(frozen=True)
class RunJob:
    """What to run: the program's text, where it lives (for its ``# world:`` line), the world
    chosen (a .toml path, or "" for the program's own) and the speed (0: as fast as it goes)."""

    source: str
    program_path: str
    world_path: str = ""
    speed: float = 1.0
    memory_mb: int = 512
    cpu_seconds: float = 60.0  # at "as fast as it goes"; a paced run adds its paced length
    robot: str | None = None  # a robot's name or address: run on it over Bluetooth, not simulated
    page_robot: PageRobot | None = None  # the robot linked by the page (Web Bluetooth)
    transport: str | None = None  # bumble's HCI spec for Bluetooth (`virtual`: in this process)
    languages: Languages = ENGLISH  # the page's: its messages speak them
    breakpoints: tuple[int, ...] = ()  # source lines the run pauses at

    @property
    def on_robot(self) -> bool:
        """A run on a real (or virtual Bluetooth) robot, in real time; else simulated."""
        return self.robot is not None or self.page_robot is not None


LINE_CHARS = 1000  # of a printed or said line, or one of the trace's, sent to the page
NOTES_PER_FRAME = 8  # notes a frame carries to the page (more in 40 ms can't be heard apart)
TEXT_LINES = 1000  # printed lines (and said ones) a run sends; then one line says so
TRACE_LINES = 5000  # lines of the child's view of a run sent at its end


class TextCap:
    """Text a run sends the page, capped so a `print` bomb can't flood the server or the page:
    each line at most :data:`LINE_CHARS` characters, at most ``lines`` lines, then one line
    that says more was left out (in the page's language: made where the run speaks it)."""

    def __init__(
        self, languages: Languages, lines: int = TEXT_LINES, more_code: str = "V071"
    ) -> None:
        self.lines: list[str] = []
        self._most = lines
        self._cut = message("V070", {"count": LINE_CHARS}, languages)
        self._more = message(more_code, {"count": lines}, languages)
        self.full = False

    def add(self, text: str) -> None:
        if len(self.lines) < self._most:
            self.lines.append(
                text if len(text) <= LINE_CHARS else f"{text[:LINE_CHARS]}{self._cut}"
            )
        elif not self.full:
            self.full = True
            self.lines.append(self._more)


class _Shared:
    """What the run's thread and the sampling thread share (lists only grow), their notes
    in ``languages``."""

    def __init__(self, languages: Languages) -> None:
        self.printed = TextCap(languages)
        self.said = TextCap(languages, more_code="V072")
        self.lock = threading.Lock()

    def print(self, text: str) -> None:
        """``run_program``'s ``on_print`` (in the run's thread)."""
        with self.lock:
            self.printed.add(text)


def capped_trace(lines: list[str], languages: Languages) -> list[str]:
    """The child's view of a run as the page is sent it (see :class:`TextCap`)."""
    cap = TextCap(languages, TRACE_LINES, "V073")
    for line in lines:
        cap.add(line)
        if cap.full:
            break
    return cap.lines


def worker_main(connection: Connection, job: RunJob) -> None:
    """The worker process's entry point (module-level: it is pickled for the process)."""
    cap_memory(job.memory_mb)
    if job.robot is None:  # (on a robot, as `rootlang run`: it runs until stopped)
        cap_cpu(job.cpu_seconds + KERNEL_MARGIN_SECONDS)  # a simulated run stops itself first
    languages = about(job.languages, job.source)  # the page's, and code in the program's
    try:
        outcome: dict[str, object] | None = _run(connection, job, languages)
    except MemoryError:
        outcome = {"end": "limit", "code": "E812", "limit": f"{job.memory_mb} MB"}
    except RootlangError as error:  # the world file, or the program does not check
        outcome = session.mistakes_json(error, "", languages)
    except BaseException as error:  # a bug of ours: say so; the server shows it plainly
        reason = f"{type(error).__name__}: {error}"
        outcome = {"end": "crashed", "reason": without_paths(reason, job)}
    if outcome is not None:  # (None: the program's own process has told the server)
        with contextlib.suppress(OSError, ValueError):  # the server has gone: nobody to tell
            connection.send(("ended", outcome))
    connection.close()


def without_paths(text: str, job: RunJob) -> str:
    """``text`` (a bug's own words, which may name any file) with the server's paths named as
    the page knows them: the folder's files relative to it, rootlang's own by its name."""
    folder = Path(job.program_path).parent
    for path, shown in ((folder, "."), (folder.resolve(), "."),
                        (Path(rootlang.__file__).parent, "rootlang")):  # fmt: skip
        text = text.replace(f"{path}{os.sep}", "" if shown == "." else shown + "/")
        text = text.replace(str(path), shown)
    return text


def scan_main(
    connection: Connection, transport: str | None, seconds: float, languages: Languages
) -> None:
    """A worker process that lists the robots in range: ``("robots", [...])`` or
    ``("errors", [...])`` (Bluetooth off or missing), in the page's ``languages``."""
    from rootlang.ble.scan import scan  # (bleak loads only when robots are looked for)

    clock = WallClock()

    async def listen() -> list[dict[str, object]]:
        async with bluetooth(transport, clock) as backend:
            return [robot.to_json() for robot in await scan(seconds, backend)]

    try:
        message: tuple[str, object] = ("robots", clock.run(listen()))
    except RootlangError as error:
        found = [session.diagnostic_json(d, "", languages) for d in error.diagnostics]
        message = ("errors", found)
    with contextlib.suppress(OSError, ValueError):
        connection.send(message)
    connection.close()


def load_job(job: RunJob) -> session.Program:
    """The job's program, checked, in its world (on a robot: for any robot, no world)."""
    return session.load(
        job.program_path, source=job.source, world=job.world_path or None,
        names_from=Path(job.program_path).parent, on_robot=job.on_robot,
        language=job.languages.chosen,  # (the studio's --language, if it was given one)
    )  # fmt: skip


def _run(connection: Connection, job: RunJob, languages: Languages) -> dict[str, object] | None:
    program = load_job(job)
    if job.robot is not None:
        return _hold_the_link(connection, job, program, languages)
    if job.on_robot:
        return _run_on_robot(connection, job, program, languages)
    world = program.world
    assert world is not None
    paced = 0.0 if job.speed == FASTEST else world.time_limit / job.speed  # it may compute
    clock: Clock = VirtualClock() if job.speed == FASTEST else ScaledWallClock(job.speed)
    simulation = session.Simulation(world, clock=clock)
    robot = simulation.robot
    trace: list[TraceEntry] = []  # the run's trace as it grows (run_program's on_trace)
    shared = _Shared(languages)
    sender = _Sender(connection)
    sender.send(
        "started",
        {
            "stage": stage_of(robot.recording, world),
            "time_limit": world.time_limit,
            "speed": job.speed,
        },
    )
    sampler = _Sampler(sender, robot.recording, trace, shared, clock)
    sampler.start()
    debugging = RunDebugging(
        connection, sender.send, simulation.sim_transport, clock, languages, job.breakpoints
    )
    going_back = GoingBack(simulation, trace, languages)
    debugging.debugger.recorder = going_back.timeline
    session.keep_moments(robot, going_back.timeline)

    def moments() -> None:  # asked for by a paused run's page: with the stage so far
        story = child_story(list(trace), job.source, program.checked.program, languages)
        texts = story_text(story, languages)
        data = going_back.to_json(story)
        data["trace"] = capped_trace(texts, languages)
        data["stage"] = stage_of(robot.recording, world)
        sender.send("timeline", data)

    debugging.on_timeline = moments

    def traced(entry: TraceEntry) -> None:
        trace.append(entry)
        going_back.timeline.seen(entry)

    async def main(budget: CpuBudget) -> RunResult:
        loop = asyncio.get_running_loop()
        loop.add_reader(connection.fileno(), debugging.read)
        debugging.watch_live()
        try:
            return await simulation.run(
                program.checked, source=job.source, on_print=shared.print,
                on_trace=traced, debugger=debugging.debugger, cpu_budget=budget,
            )  # fmt: skip
        finally:
            loop.remove_reader(connection.fileno())

    try:
        # (for as long as it is paced to run: E220)
        with cpu_backstop(job.cpu_seconds + paced) as budget:
            result = clock.run(main(budget))
    finally:
        sampler.stop()
    recording = robot.finish()
    sampler.sample()  # the last frame, exactly where the robot ended
    outcome = session.outcome_json(program, result, languages, recording, robot)
    story = child_story(trace, job.source, program.checked.program, languages)
    view = story_text(story, languages)
    outcome.update(
        printed=list(shared.printed.lines),  # capped, as the frames sent them
        said=list(shared.said.lines),
        trace=capped_trace(view, languages),
        replay_html=html_text(recording, story=story, languages=languages),
        stage=stage_of(recording, world),
        timeline=going_back.to_json(story),
    )
    return outcome


def _hold_the_link(
    connection: Connection, job: RunJob, program: session.Program, languages: Languages
) -> dict[str, object] | None:
    """A run on a robot over this computer's Bluetooth (or bumble's virtual robot), as
    ``rootlang run`` does it: this process holds the robot's link and the program runs in a
    process of its own (:mod:`rootlang.app.link`), which talks to the server itself. If that
    process dies (a crash, out of memory, killed), this one stops the robot and says so (E218,
    or E219 if the robot never confirmed the stop). None: the program's process has told the
    server how the run ended."""
    from rootlang.ble.select import choose_robot  # bleak loads only for a robot
    from rootlang.ble.transport import BleakTransport

    # the server ends this process when it must (it is its daemon); this one has a child
    multiprocessing.current_process().daemon = False  # (a daemon process may have none)
    apart = link.start_program(  # before Bluetooth
        _program_on_robot, connection, job, program, languages
    )
    clock = WallClock()

    async def hold() -> link.Held:
        # the server ends a run on a robot with SIGTERM: the program's process is ended, and
        # this one stops the robot as for any program that dies
        asyncio.get_running_loop().add_signal_handler(signal.SIGTERM, apart.process.kill)
        async with bluetooth(job.transport, clock) as backend:
            chosen = await choose_robot(job.robot or None, backend=backend)
            transport = BleakTransport(chosen.device, chosen.robot, backend=backend, clock=clock)
            return await apart.serve(transport, clock, chosen.robot.describe())

    try:
        held = clock.run(hold())
    except BaseException:  # no robot found, or Bluetooth failed: the program never ran
        apart.kill()
        raise
    if not held.died:
        return None
    error = session.diagnostic_json(diagnostic(held.code, how=held.how), "", languages)
    return {"end": "error", "error": error, "printed": [], "trace": []}


def _program_on_robot(
    transport: RelayTransport,
    connection: Connection,
    job: RunJob,
    program: session.Program,
    languages: Languages,
) -> int:
    """The program's process of a run on a robot over Bluetooth: it runs and streams as
    :func:`_run_on_robot` does, on the link holder's relay, and tells the server its end."""
    try:
        outcome = _run_on_robot(connection, job, program, languages, transport)
    except RootlangError as error:  # the link could not be made
        outcome = session.mistakes_json(error, "", languages)
    with contextlib.suppress(OSError, ValueError):
        connection.send(("ended", outcome))
    return 0


def _run_on_robot(
    connection: Connection,
    job: RunJob,
    program: session.Program,
    languages: Languages,
    relay: RelayTransport | None = None,
) -> dict[str, object]:
    """The same run on a robot in real time: over this computer's Bluetooth (or bumble's
    virtual robot) through the link holder's ``relay``, or over the page's own link to its
    robot (Web Bluetooth). The studio's Stop is Ctrl-C to the runtime (the robot gets Stop and
    Reset, `when stopped` runs), and the robot stops when the link goes (the link holder
    stops it if this process dies, and the page if its link drops). The debugger's buttons
    pause it (:class:`~rootlang.studio.debugging.RobotDebugging`), on a wall clock that can be
    held (at 1×: real time)."""
    clock = ScaledWallClock(1.0)
    trace: list[TraceEntry] = []  # the run's trace as it grows (run_program's on_trace)
    shared = _Shared(languages)
    sender = _Sender(connection)
    sampler = _Sampler(sender, None, trace, shared, clock)
    debugging = RobotDebugging(sender.send, clock, languages, job.breakpoints)

    def started(robot: str) -> None:
        sender.send("started", {"stage": None, "robot": robot})
        sampler.start()

    def traced(entry: TraceEntry) -> None:
        trace.append(entry)
        if relay is not None and isinstance(entry.record, Connected):  # the holder's robot
            started(relay.description)

    page: PageTransport | None = None

    async def main() -> RunResult:
        nonlocal page
        loop = asyncio.get_running_loop()
        transport: Transport
        if job.page_robot is not None:
            page = transport = PageTransport(job.page_robot, sender.send)
            loop.add_reader(connection.fileno(), _read_from_page, connection, page, debugging)
            started(job.page_robot.describe())
        else:
            assert relay is not None
            transport = relay
            loop.add_reader(connection.fileno(), _read_stop, connection, debugging)
        debugging.watch_live()
        return await session.run_on_robot(
            program, transport, clock, on_print=shared.print, on_trace=traced,
            debugger=debugging.debugger,
        )  # fmt: skip

    try:
        result = clock.run(main())
    finally:
        debugging.finish()
        sampler.stop()
    sampler.sample()
    outcome = session.outcome_json(program, result, languages)
    story = child_story(trace, job.source, program.checked.program, languages)
    view = story_text(story, languages)
    outcome.update(printed=list(shared.printed.lines), trace=capped_trace(view, languages))
    if result.interrupted:
        outcome.update(StoppedBy(StopReason.STOP_BUTTON).outcome())
    if page is not None:
        outcome["link"] = page.link_figures()
        if page.stopped_by_page is not None:  # stopped, by the page, for its reason
            outcome.update(end="stopped", error=None, **page.stopped_by_page.outcome())
    return outcome


def _read_stop(connection: Connection, debugging: RobotDebugging) -> None:
    """On a robot, a debugger's button, or else any word from the server (or its going away)
    is Stop: Ctrl-C to the run (a paused one ends where it stands)."""
    with contextlib.suppress(EOFError, OSError):
        kind, data = connection.recv()
        if kind == "debug":
            debugging.button(data)
            return
    asyncio.get_running_loop().remove_reader(connection.fileno())
    debugging.stop()
    os.kill(os.getpid(), signal.SIGINT)


def _read_from_page(connection: Connection, page: PageTransport, debugging: RobotDebugging) -> None:
    """What the page reports of its robot (relayed by the server), a debugger's button, or
    Stop."""
    try:
        kind, data = connection.recv()
    except (EOFError, OSError):  # the server went away, and the page's link with it
        asyncio.get_running_loop().remove_reader(connection.fileno())
        page.lost(StoppedBy(StopReason.STUDIO))
        return
    if kind == "debug":
        debugging.button(data)
    elif kind == "robot_written":
        page.written(int(data["n"]), data.get("error"))
    elif kind == "robot_notify":
        page.notified(bytes(data))
    elif kind == "robot_lost":  # (the server's own reason, as data)
        page.lost(StoppedBy.from_json(data) or StoppedBy.link(str(data)))
    elif kind == "robot_stopped":  # the page stopped the robot itself: the run ends, so told
        page.stopped_by_page = StoppedBy.from_json(data) or StoppedBy(StopReason.PAGE_CLOSED)
        page.lost(page.stopped_by_page)
    elif kind == "stop":
        debugging.stop()
        os.kill(os.getpid(), signal.SIGINT)


def child_story(
    entries: list[TraceEntry], source: str, program: ast.Program, languages: Languages
) -> list[ViewLine]:
    """The run in a child's words, line by line (the page's trace shows them: :func:`story_text`;
    the replay page lists them)."""
    view = StudioView(source, program, languages)
    return [line for entry in entries for line in view.add(entry)] + view.finish()


def child_trace(
    entries: list[TraceEntry], source: str, program: ast.Program, languages: Languages
) -> list[str]:
    """The run in a child's words, in ``languages`` (the page's): when, which line, what happened
    (no sensor readings, nor the runtime's own commands); the program's commands as written,
    the same line again and again at once shown once and counted, a command cut short and
    wheels that stalled told as `rootlang sim` tells them (the same view, its records)."""
    return story_text(child_story(entries, source, program, languages), languages)


def story_text(story: list[ViewLine], languages: Languages) -> list[str]:
    """:func:`child_story`'s lines as the page's trace shows them."""
    lines = []
    for line in story:
        where = f"{message('V007', {'line': line.line}, languages)}: " if line.line else ""
        text = line.text.strip() if line.kind == "repeat" else line.text  # (not indented here)
        lines.append(f"{line.time_ms / 1000:7.2f} s  {where}{text}")
    return lines


_SCRIPT_ENDS = {"finished": "V011", "stopped": "V012", "cancelled": "V013", "error": "V014"}
_RUN_ENDS = {
    "finished": "V015", "stopped": "V016", "time_limit": "V017", "error": "V018",
    "disconnected": "V019",
}  # fmt: skip


class StudioView(ChildView):
    """The child's view with the studio's own words for scripts starting and ending, how the
    run ended and which robot it ran on; commands, prints, errors, commands cut short and
    stalls as the child's view has them."""

    def line_of(self, entry: TraceEntry) -> ViewLine | None:
        kind = entry.kind
        if kind in ("command", "print", "error"):
            return super().line_of(entry)
        script = unquoted(entry.script.split(":", 1)[-1])  # "2:when bumped" -> "when bumped"
        languages = self._languages
        if kind == "start":
            text = message("V010", {"script": script}, languages)
        elif kind == "end":
            code = _SCRIPT_ENDS.get(entry.text)
            text = (
                f"`{script}` {entry.text}"
                if code is None
                else message(code, {"script": script}, languages)
            )
        elif kind == "run":
            record = entry.record
            if isinstance(record, RunEnded):
                by = record.by.shown(languages)
                text = message(_RUN_ENDS[record.end], {"by": by}, languages)
            else:
                text = entry.text if record is None else record.shown(languages)
        else:
            return None
        # (a run's own lines are "end" lines: the kind only tells a repeat from a new line)
        return ViewLine(entry.time_ms, entry.line, text, "start" if kind == "start" else "end")


def warm_up() -> None:
    """Load, check and stage a program once (in the fork server: every run starts warm)."""
    source = "when started\n    move 10 cm\n"
    program = session.load("warm.root", source=source, world=None, on_robot=False)
    assert program.world is not None
    stage_of(session.Simulation(program.world, clock=VirtualClock()).robot.recording, program.world)


def stage_of(recording: Recording, world: World) -> StageData:
    """The stage as the replay page draws it: the scene's shapes, the robot's outline and the
    frames so far (:func:`rootlang.sim.render.html.page_data`'s format)."""
    data = page_data(scene_of(recording), replay_of(recording))
    return StageData(**data, world={"name": world.name, "model": recording.model.value})


class _Sender:
    """Sends from either thread, one message at a time."""

    def __init__(self, connection: Connection) -> None:
        self._connection = connection
        self._lock = threading.Lock()
        self.gone = False

    def send(self, kind: str, data: object) -> None:
        if self.gone:
            return
        with self._lock:
            try:
                self._connection.send((kind, data))
            except (OSError, ValueError):
                self.gone = True


def next_beat(beat: float, now: float) -> float:
    """When the frame after the one due at ``beat`` is due, it having been made by ``now``:
    a period after ``beat`` (the making and the wait for the interpreter's lock don't add to
    it), or at once when that is past (a beat missed is let go, not made up in a burst)."""
    return max(beat + FRAME_PERIOD_S, now)


class _Sampler:
    """Every :data:`FRAME_PERIOD_S` of wall time: the robot's latest pose and light, the ink
    drawn since the last frame, the lines running now, and what was printed and said."""

    def __init__(
        self,
        sender: _Sender,
        recording: Recording | None,  # None on a robot: no pose or ink, the lines and prints
        trace: list[TraceEntry],
        shared: _Shared,
        clock: Clock,
    ) -> None:
        self._sender = sender
        self._clock = clock
        self._recording = recording
        self._trace = trace
        self._shared = shared
        self._ink_sent: list[int] = []  # points sent of each stroke
        self._entries_seen = 0
        self._printed_sent = 0
        self._frames = 0  # made so far
        self._said_sent = 0  # of the recording's
        self._said_shown = 0  # of the capped lines
        self._notes_sent = 0  # of the recording's
        self._happened_sent = 0  # of the recording's events
        self._running: dict[str, int] = {}  # script -> its line now
        self._stopping = threading.Event()
        self._thread = threading.Thread(target=self._loop, name="studio-sampler", daemon=True)

    def start(self) -> None:
        self._thread.start()

    def stop(self) -> None:
        self._stopping.set()
        if self._thread.is_alive():
            self._thread.join()

    def _loop(self) -> None:
        # Frames on a steady beat, not a period after each one was made: the making and the
        # wait for the interpreter's lock (the run computes meanwhile) would otherwise add to
        # every period (measured: 23-24 frames a second instead of 25, fewer on a busy
        # computer). A beat missed by more than a period is let go, never made up in a burst.
        beat = time.monotonic() + FRAME_PERIOD_S
        while not self._stopping.wait(max(0.0, beat - time.monotonic())):
            self.sample()
            beat = next_beat(beat, time.monotonic())

    def sample(self) -> None:
        frame: dict[str, object] = {
            "t": round(self._clock.now(), 3),  # the run's time (the robot's frames: on change)
            "ink": self._new_ink(),
            "running": self._running_lines(),
            "printed": self._new_printed(),
            "said": self._new_said(),
            "notes": self._new_notes(),
            "happened": self._new_happenings(),
            "sent_at": time.time(),
            "n": self._number(),
        }
        frames = self._recording.frames if self._recording is not None else []
        if frames:
            last = frames[-1]
            frame["pose"] = {
                "x": last.x_mm,
                "y": last.y_mm,
                "h": last.heading_deg,
                "led": None
                if last.led_mode == "off"
                else "#{:02x}{:02x}{:02x}".format(*last.led_rgb),
                "led_mode": last.led_mode,
            }
        self._sender.send("frame", frame)

    def _new_ink(self) -> list[dict[str, object]]:
        changed: list[dict[str, object]] = []
        strokes = self._recording.strokes if self._recording is not None else []
        for index in range(len(strokes)):
            stroke = strokes[index]
            points = list(stroke.points)
            if index == len(self._ink_sent):
                self._ink_sent.append(0)
            sent = self._ink_sent[index]
            if len(points) == sent and sent > 0 and index < len(strokes) - 1:
                continue  # a finished stroke, all sent
            start = max(0, sent - 1)  # the last point sent may have moved on (a straight line)
            changed.append({
                "i": index, "kind": stroke.kind, "color": stroke.color, "w": stroke.width_mm,
                "from": start, "p": [v for point in points[start:] for v in point],
            })  # fmt: skip
            self._ink_sent[index] = len(points)
        return changed

    def _running_lines(self) -> dict[str, int]:
        entries = self._trace
        count = len(entries)
        for entry in entries[self._entries_seen : count]:
            if entry.kind == "end":
                self._running.pop(entry.script, None)
            elif entry.line and entry.kind in ("start", "command", "print"):
                self._running[entry.script] = entry.line
        self._entries_seen = count
        return dict(self._running)

    def _number(self) -> int:
        self._frames += 1
        return self._frames

    def _new_printed(self) -> list[str]:
        with self._shared.lock:
            new = self._shared.printed.lines[self._printed_sent :]
        self._printed_sent += len(new)
        return new

    def _new_notes(self) -> list[dict[str, object]]:
        """The notes begun since the last frame (the page plays them), at most
        :data:`NOTES_PER_FRAME`: a run that plays faster than a page can sound loses notes,
        never frames."""
        if self._recording is None:
            return []
        notes = self._recording.notes
        seen = len(notes)
        new = notes[max(self._notes_sent, seen - NOTES_PER_FRAME) : seen]
        self._notes_sent = seen
        return [{"t_ms": n.t_ms, "frequency_hz": n.frequency_hz, "duration_ms": n.duration_ms,
                 "end_hz": n.end_hz} for n in new]  # fmt: skip

    def _new_happenings(self) -> list[str]:
        """What the robot felt since the last frame (a bump, a touch, the nose button)."""
        if self._recording is None:
            return []
        events = self._recording.events
        seen = len(events)
        new = [event.text for event in events[self._happened_sent : seen]]
        self._happened_sent = seen
        return new

    def _new_said(self) -> list[str]:
        if self._recording is None:
            return []
        said, cap = self._recording.said, self._shared.said
        seen = len(said)
        for spoken in said[self._said_sent : seen]:
            cap.add(spoken.text)
        self._said_sent = seen
        new = cap.lines[self._said_shown :]
        self._said_shown += len(new)
        return new
