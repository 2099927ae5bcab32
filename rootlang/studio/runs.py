"""The server's side of a simulated run: a worker process, its limits, and its messages.

Each run is a process of its own (:func:`rootlang.studio.worker.worker_main`), started from a
fork server that has the runtime and simulator loaded and warm (:mod:`rootlang.studio.preload`),
so a run starts in milliseconds and one
child's endless loop or memory bomb stalls nobody. The limits are those of ``rootlang test``:
the world's simulated time limit (kept by the run itself), a CPU-time limit and a memory cap
(kept by the process: a busy machine can't make a program fail), and a wall-clock backstop kept
here — far out, for a machine too busy to finish; it never blames the program.
"""

from __future__ import annotations

import asyncio
import collections
import json
import multiprocessing
import os
import sys
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from multiprocessing import spawn
from multiprocessing.process import BaseProcess
from typing import Any

from rootlang.app.pipe import Pipe
from rootlang.app.sandbox import Limits, ended_by_cpu_limit
from rootlang.diagnostics import RootlangError
from rootlang.runtime.stops import StoppedBy, StopReason
from rootlang.studio.worker import FASTEST, RunJob, scan_main, worker_main
from rootlang.wording.language import Languages

STOP_GRACE_S = 3.0  # after Stop, `when stopped` scripts get 2 s; then the worker is ended
WALL_MARGIN_S = 60.0  # beyond the simulated time limit at the chosen speed: the backstop
HOLDER_GRACE_S = 3.0  # a run on a robot, asked to end, stops the robot within this
PAUSED_AT_MOST_S = 30 * 60.0  # chosen: a lesson's pause; a run left paused longer is ended
DEATH_POLL_S, DEATH_POLLS = 0.02, 50  # a dead worker's exit code: looked for for a second
Listener = Callable[[str, Any], None]


FORKSERVER = "forkserver" in multiprocessing.get_all_start_methods()  # (not on Windows)


def _context() -> multiprocessing.context.DefaultContext:
    methods = multiprocessing.get_all_start_methods()
    # typeshed gives each start method's context its own class; they share this interface
    context: multiprocessing.context.DefaultContext = multiprocessing.get_context(
        "forkserver" if "forkserver" in methods else "spawn"
    )  # type: ignore[assignment]
    script = main_script()
    if script is not None:  # the fork server runs it once (see rootlang.studio.preload)
        os.environ[MAIN_SCRIPT] = json.dumps({"path": script, "argv": sys.argv})
    context.set_forkserver_preload(["rootlang.studio.preload"])  # (spawn: does nothing)
    return context


MAIN_SCRIPT = "ROOTLANG_MAIN_SCRIPT"  # the environment variable the fork server inherits


def main_script() -> str | None:
    """This process's main script as multiprocessing names it to each process it starts
    (``None`` when the main is a module, ``python -m …``, which is never run again, and in the
    fork server while it runs the script)."""
    if getattr(multiprocessing.current_process(), "_inheriting", False):
        return None
    path = spawn.get_preparation_data("rootlang").get("init_main_from_path")
    return path if isinstance(path, str) else None


CONTEXT = _context()


RUNS_PER_CORE = 16  # a run at real time uses a few % of a core: 30 on 2 cores keep up
WAITING_PER_PLACE = 4  # runs that may wait, per place: beyond, a new one is refused (E825)


def default_runs() -> int:
    """Runs at once on this computer, by default: :data:`RUNS_PER_CORE` per core."""
    return RUNS_PER_CORE * (os.cpu_count() or 1)


@dataclass(frozen=True)
class ClassLimits:
    """What a class's runs may ask of the machine (``rootlang studio``'s options)."""

    cpu_seconds: float = Limits.cpu_seconds  # a run "as fast as it goes" computes at most this
    runs: int = field(default_factory=default_runs)  # at once on this computer; others wait
    runs_each: int = 1  # at once for each pupil: a new one replaces their oldest
    conversion_seconds: float = 10.0  # a conversion's time limit (past it: E818; pool.py)


class SimRun:
    """One run: start it, forward the page's stimuli, stop it; ``listener`` gets every message
    the worker sends, and finally ``("ended", outcome)`` — also when the worker had to be
    ended at a limit, crashed, or was stopped.

    Nothing here blocks the server's event loop, which streams every other run: the worker
    process is started in a thread (:func:`start_process`), and its messages are read and
    written in threads of their own (:class:`~rootlang.app.pipe.Pipe`)."""

    def __init__(
        self,
        job: RunJob,
        listener: Listener,
        limits: Limits | None = None,
        owner: str | None = None,
    ) -> None:
        self.job = job
        self.owner = owner  # whose run it is (a pupil), for :class:`RunPlaces`
        self.on_end: Callable[[SimRun], None] | None = None
        self.limits = limits or Limits(cpu_seconds=job.cpu_seconds, memory_mb=job.memory_mb)
        self._listener = listener
        self._pipe: Pipe | None = None
        self._process: BaseProcess | None = None
        self._deadline: asyncio.TimerHandle | None = None
        self._loop: asyncio.AbstractEventLoop | None = None
        self._stopped_by = StopReason.STOP_BUTTON  # who pressed a Stop, if anyone did
        self._wall_left: float | None = None  # of its deadline, when it paused
        self.done = asyncio.Event()

    def start(self) -> None:
        self._loop = asyncio.get_running_loop()
        ours, theirs = CONTEXT.Pipe(duplex=True)
        # what is sent before the worker is up waits in the pipe for it
        self._pipe = Pipe(ours, self._loop, self._received, "rootlang-run")
        # until the world's limit is known (the "started" message), the backstop of `rootlang test`
        self._set_deadline(self.limits.wall_seconds)
        starting = self._loop.run_in_executor(
            STARTS, start_process, worker_main, (theirs, self.job)
        )
        starting.add_done_callback(self._started)

    @property
    def started(self) -> bool:
        """Its worker was asked to start (else it waits for a place)."""
        return self._loop is not None

    def waiting(self, place: int) -> None:
        """It waits for a place to run, ``place``-th in the queue: its page is told."""
        self._listener("waiting", {"place": place})

    def _started(self, starting: asyncio.Future[BaseProcess]) -> None:
        error = starting.exception()
        if error is not None:  # no process (the machine is out of them, or of memory)
            self.kill({"end": "crashed", "reason": f"the run's process did not start ({error})"})
            return
        self._process = starting.result()
        if self.done.is_set():  # stopped while it started
            self._process.kill()

    def stimulate(self, data: dict[str, Any]) -> None:
        self._send(("stimulus", data))

    def debug(self, request: dict[str, Any]) -> None:
        """A debugger's button for a simulated run (checked: :func:`debug_request`)."""
        self._send(("debug", request))

    def relay(self, kind: str, data: object) -> None:
        """What the page reports of its own robot (a run on the page's link), to the run."""
        self._send((kind, data))

    def stop(self, by: StopReason = StopReason.STOP_BUTTON) -> None:
        """A Stop button (the page's, or ``by`` the teacher's for every run): the nose button
        (on a robot: Ctrl-C to its run), so `when stopped` runs and the run ends as it does,
        with its replay; the worker is ended if it lingers. A run still waiting for a place
        just ends."""
        self._stopped_by = by
        if not self.started:
            self.kill({"end": "stopped", **StoppedBy(by).outcome()})
        elif not self.job.on_robot:
            self.stimulate({"action": "nose"})
        else:
            self._send(("stop", None))
        if self._loop is not None and not self.done.is_set():
            self._set_deadline(STOP_GRACE_S)

    def kill(self, outcome: dict[str, object] | None = None) -> None:
        """End the worker now (the page went away, the server stops, or a limit). A run on a
        robot over Bluetooth is asked to end (SIGTERM: its program's process is ended, and
        the run's process, which holds the link, stops the robot), and is ended if it
        lingers."""
        process = self._process
        if process is not None and process.is_alive() and self.job.robot is not None:
            process.terminate()
            assert self._loop is not None
            self._loop.call_later(HOLDER_GRACE_S, _kill_if_alive, process)
        elif process is not None and process.is_alive():
            process.kill()
        self._finish(outcome or {"end": "stopped", **StoppedBy(StopReason.STUDIO).outcome()})

    def _send(self, message: tuple[str, object]) -> None:
        if self._pipe is not None and not self.done.is_set():
            self._pipe.send(message)

    def _set_deadline(self, seconds: float) -> None:
        assert self._loop is not None
        if self._deadline is not None:
            self._deadline.cancel()
        self._deadline = self._loop.call_later(seconds, self._too_long, seconds)

    def _too_long(self, seconds: float) -> None:
        self.kill({"end": "limit", "code": "E820", "limit": f"{seconds:g} s"})  # not its fault

    def _received(self, message: tuple[str, Any] | None) -> None:
        if self.done.is_set():
            return
        if message is None:  # the worker died without a word (CPU, memory, a signal)
            self._died(DEATH_POLLS)
            return
        kind, data = message
        if kind == "started" and not self.job.on_robot:
            speed = self.job.speed
            wall = self.limits.wall_seconds if speed == FASTEST else data["time_limit"] / speed
            self._set_deadline(wall + WALL_MARGIN_S)
        elif kind == "started" and self._deadline is not None:
            self._deadline.cancel()  # on a robot, as `rootlang run`: it runs until stopped
            self._deadline = None
        elif kind == "paused":  # its time stands still: so does its deadline, up to a limit
            assert self._loop is not None
            deadline = self._deadline
            self._wall_left = None if deadline is None else deadline.when() - self._loop.time()
            self._set_deadline(PAUSED_AT_MOST_S)
        elif kind == "resumed" and self._wall_left is not None:
            self._set_deadline(self._wall_left)
        elif kind == "resumed" and self._deadline is not None:  # on a robot: none again
            self._deadline.cancel()
            self._deadline = None
        if kind == "ended":
            self._finish(data)
            return
        self._listener(kind, data)

    def _died(self, polls_left: int) -> None:
        """The worker's pipe closed without an "ended": why it died is its exit code, which
        comes a moment later (looked at without waiting: the server serves others meanwhile)."""
        assert self._loop is not None
        code = None if self._process is None else self._process.exitcode
        if code is None and polls_left > 0:
            self._loop.call_later(DEATH_POLL_S, self._died, polls_left - 1)
        elif ended_by_cpu_limit(code):
            self.kill({"end": "limit", "code": "E811", "limit": f"{self.limits.cpu_seconds:g} s"})
        else:
            self.kill({"end": "crashed", "reason": f"the run's process ended (exit code {code})"})

    def _finish(self, outcome: dict[str, object]) -> None:
        if self.done.is_set():
            return
        self.done.set()
        if outcome.get("end") == "stopped" and self._stopped_by is not StopReason.STOP_BUTTON:
            outcome.update(StoppedBy(self._stopped_by).outcome())  # (the nose said it was it)
        if self._deadline is not None:
            self._deadline.cancel()
        if self._pipe is not None:
            self._pipe.close()  # (its reader ends as the worker does)
        if self._loop is not None:
            # reaped a moment later (never waited for here: the server serves others meanwhile)
            self._loop.call_later(1.0, multiprocessing.active_children)
        self._listener("ended", outcome)
        if self.on_end is not None:
            self.on_end(self)


class RunPlaces:
    """The computer's places for runs (:class:`ClassLimits`): ``runs`` at once, the others
    wait their turn in order (their pages are told their place) and start as places free; each
    pupil has at most ``runs_each`` runs, going or waiting: a new one replaces their oldest, so
    a pupil who presses Run again, in another tab or a script, never stacks runs. Past
    :data:`WAITING_PER_PLACE` waiting runs per place, a new run is refused (E825): a flood of
    runs can't fill the server's memory with waiting programs either."""

    def __init__(self, limits: ClassLimits) -> None:
        self.limits = limits
        self.live: set[SimRun] = set()
        self.waiting: collections.deque[SimRun] = collections.deque()
        self._owners: dict[str, list[SimRun]] = {}  # each pupil's runs, oldest first
        self._closed = False

    def admit(self, run: SimRun) -> None:
        """Start ``run`` now if a place is free, else queue it (RootlangError E825 if the
        queue is full and it replaces none of its pupil's)."""
        theirs = self._owners.get(run.owner, []) if run.owner is not None else []
        replaces = len(theirs) >= max(1, self.limits.runs_each)
        if self._full() and not replaces:
            raise RootlangError.of("E825")
        replaced = {"end": "stopped", **StoppedBy(StopReason.REPLACED).outcome()}
        while len(theirs) >= max(1, self.limits.runs_each):
            theirs.pop(0).kill(dict(replaced))  # (its place goes to the next in line)
        run.on_end = self._ended
        if run.owner is not None:
            self._owners.setdefault(run.owner, []).append(run)
        if len(self.live) < self.limits.runs and not self.waiting and not self._closed:
            self._start(run)
        else:
            self.waiting.append(run)
            run.waiting(len(self.waiting))

    def close(self) -> None:
        """The studio stops: no run starts any more (each is ended by its session)."""
        self._closed = True

    def _full(self) -> bool:
        return (
            len(self.live) >= self.limits.runs
            and len(self.waiting) >= WAITING_PER_PLACE * self.limits.runs
        )

    def _start(self, run: SimRun) -> None:
        self.live.add(run)
        run.start()

    def place_of(self, run: SimRun) -> int:
        """Its place in the queue for a free place (1: next), 0 when it runs or has ended."""
        return self.waiting.index(run) + 1 if run in self.waiting else 0

    def _ended(self, run: SimRun) -> None:
        self.live.discard(run)
        moved = run in self.waiting
        if moved:
            self.waiting.remove(run)
        theirs = self._owners.get(run.owner or "")
        if theirs is not None and run in theirs:
            theirs.remove(run)
            if not theirs:
                del self._owners[run.owner or ""]
        while self.waiting and len(self.live) < self.limits.runs and not self._closed:
            self._start(self.waiting.popleft())
            moved = True
        if moved:  # the ones still waiting are told their new places
            for place, waiting in enumerate(self.waiting, 1):
                waiting.waiting(place)


def _kill_if_alive(process: BaseProcess) -> None:
    if process.is_alive():
        process.kill()


# Starting a process waits for the fork server (or, where processes are spawned, for a new
# Python): done in these threads, never on the event loop. A few at once: the fork server
# forks one at a time anyway.
STARTS = ThreadPoolExecutor(4, thread_name_prefix="rootlang-run-starts")


def start_process(target: Callable[..., None], args: tuple[Any, ...]) -> BaseProcess:
    """A worker process running ``target(*args)``, started (in a thread of :data:`STARTS`);
    ``args[0]`` is its end of the pipe, closed here once the process has it."""
    process = CONTEXT.Process(target=target, args=args, daemon=True)
    try:
        process.start()
    finally:
        args[0].close()
    return process


SCAN_MARGIN_S = 10.0  # starting Bluetooth (or bumble's virtual robot) takes a few seconds


async def scan_robots(
    transport: str | None, seconds: float, languages: Languages
) -> tuple[str, object]:
    """The robots in range, listened for in a worker process (Bluetooth stacks hold state that
    a long-running server is better without): ``("robots", [...])`` or ``("errors", [...])``,
    in ``languages`` (the request's)."""
    loop = asyncio.get_running_loop()
    ours, theirs = CONTEXT.Pipe(duplex=False)
    asked = (theirs, transport, seconds, languages)
    try:
        process = await loop.run_in_executor(STARTS, start_process, scan_main, asked)
    except BaseException:
        ours.close()
        raise
    answer: asyncio.Future[tuple[str, object]] = loop.create_future()

    def readable() -> None:  # (a short message: the list of robots)
        loop.remove_reader(ours.fileno())
        try:
            answer.set_result(ours.recv())
        except (EOFError, OSError):
            answer.set_result(("errors", []))

    loop.add_reader(ours.fileno(), readable)
    try:
        return await asyncio.wait_for(answer, seconds + SCAN_MARGIN_S)
    except asyncio.TimeoutError:
        loop.remove_reader(ours.fileno())
        return ("errors", [])
    finally:
        ours.close()
        if process.is_alive():
            process.kill()
        loop.call_later(1.0, multiprocessing.active_children)
