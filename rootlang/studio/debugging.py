"""Pause, Resume, Step and breakpoints for a run in the studio's worker: simulated
(:class:`RunDebugging`), or on a robot (:class:`RobotDebugging`, at the end).

The page's buttons reach the worker as ``("debug", {"action": ...})`` on its pipe (the server
checks them first, :func:`debug_request`). The run's loop reads its pipe between callbacks
(:meth:`RunDebugging.read`), so Pause is :meth:`Debugger.pause_now` there, at once, even while
every script waits. Paused, the loop's thread is inside :meth:`RunDebugging.on_pause`: it tells
the server (``("paused", pause)``: where each script is, in the page's words, and the values)
and reads the pipe itself until Resume, Step or Stop; the paced clock is held meanwhile, so the
run goes on from the very moment it paused at (:class:`~rootlang.studio.clock.ScaledWallClock`).
A touch or a bumper pressed while paused happens as the run goes on. See docs/studio.md,
"Pause and step".
"""

from __future__ import annotations

import asyncio
import contextlib
import threading
from collections.abc import Callable
from multiprocessing.connection import Connection
from typing import Any

from rootlang.diagnostics import RootlangError
from rootlang.runtime.clock import Clock
from rootlang.runtime.debugger import Debugger, Go, Pause
from rootlang.sim.transport import SimTransport
from rootlang.sim.world import STIMULI, Stimulus
from rootlang.studio.clock import ScaledWallClock
from rootlang.wording.language import Languages

DEBUG_ACTIONS = ("pause", "resume", "step", "breakpoints", "timeline")
MOST_BREAKPOINTS = 1000  # chosen: more lines than a child's program has
MOST_LINE = 1_000_000
LIVE_WATCH_S = 0.2  # chosen: a value's change is seen at once, the pipe barely used


def breakpoint_lines(value: object) -> tuple[int, ...]:
    """A page's breakpoints, checked: source lines (E806 for anything else)."""
    if value is None:
        return ()
    if (
        not isinstance(value, list)
        or len(value) > MOST_BREAKPOINTS
        or not all(type(line) is int and 0 < line <= MOST_LINE for line in value)
    ):
        raise RootlangError.of("E806", reason="`breakpoints` must be a list of line numbers")
    return tuple(sorted(set(value)))


def debug_request(message: dict[str, Any]) -> dict[str, Any]:
    """The page's ``{"type": "debug", "action": ..., "breakpoints": [...]}``, checked."""
    action = message.get("action")
    if not isinstance(action, str) or action not in DEBUG_ACTIONS:
        raise RootlangError.of(
            "E806", reason="`action` must be pause, resume, step, breakpoints or timeline"
        )
    request: dict[str, Any] = {"action": action}
    if action == "breakpoints":
        request["breakpoints"] = list(breakpoint_lines(message.get("breakpoints")))
    return request


class RunDebugging:
    """A simulated run's debugger, driven by the worker's pipe (see the module's docstring)."""

    def __init__(
        self,
        connection: Connection,
        send: Callable[[str, object], None],
        transport: SimTransport,
        clock: Clock,
        languages: Languages,
        breakpoints: tuple[int, ...] = (),
    ) -> None:
        self._connection = connection
        self._send = send  # the worker's, shared with its sampling thread
        self._transport = transport
        self._clock = clock
        self._languages = languages
        self._later: list[Stimulus] = []  # what the page did while the run was paused
        self._stopping = False
        self.debugger = Debugger(self.on_pause, breakpoints=breakpoints)
        self.on_timeline: Callable[[], None] = lambda: None  # sends the run's moments so far

    def watch_live(self) -> None:
        """While a paced run goes on, its values go to the page about five times a second
        (``("watch", ...)``, read on the run's loop between its callbacks: exact only when
        paused, never torn). Not at "as fast as it goes", whose run is `rootlang sim`'s to the
        timer (a timer of ours would be one more on its clock)."""
        if not isinstance(self._clock, ScaledWallClock):
            return
        loop = asyncio.get_running_loop()
        period = LIVE_WATCH_S * self._clock.speed  # (the loop's time is the run's, scaled)

        def tell() -> None:
            if self.debugger.ending:
                return
            data = self.debugger.live(self._languages)
            if data is not None:  # (None: not started yet)
                self._send("watch", data)
            loop.call_later(period, tell)

        loop.call_later(period, tell)

    def read(self) -> None:
        """One message from the server (the loop's reader): a stimulus, or a debugger's
        button; the server gone is the nose button (the run stops, `when stopped` runs)."""
        try:
            kind, data = self._connection.recv()
        except (EOFError, OSError):
            asyncio.get_running_loop().remove_reader(self._connection.fileno())
            self._transport.stimulate(Stimulus(0.0, "nose"))
            return
        if kind == "stimulus":
            self._transport.stimulate(stimulus_from(data))
        elif kind == "debug":
            self._button(data)

    def _button(self, data: dict[str, Any]) -> None:
        action = data["action"]
        if action == "breakpoints":
            self.debugger.breakpoints = frozenset(data["breakpoints"])
        elif action == "pause":
            self.debugger.pause_now()
        elif action == "step":
            self.debugger.pause_soon()

    def on_pause(self, pause: Pause) -> Go:
        """Paused (the loop's thread, nothing else of the run going on): tell the page, then
        wait for its word."""
        if self._stopping:
            return Go.RESUME
        if isinstance(self._clock, ScaledWallClock):
            self._clock.hold()
        go = Go.RESUME
        try:
            self._send("paused", pause.to_json(self._languages))
            go = self._wait()
        finally:
            if isinstance(self._clock, ScaledWallClock):
                self._clock.release()
        self._send("resumed", {"step": go is Go.STEP})
        loop = asyncio.get_running_loop()
        for stimulus in self._later:  # (the world caught up to now first, as always)
            loop.call_soon(self._transport.stimulate, stimulus)
        self._later.clear()
        return go

    def _wait(self) -> Go:
        while True:
            try:
                kind, data = self._connection.recv()
            except (EOFError, OSError):  # the server went away: the run stops
                self._stop()
                return Go.RESUME
            if kind == "debug" and data["action"] in ("resume", "step"):
                return Go.STEP if data["action"] == "step" else Go.RESUME
            if kind == "debug" and data["action"] == "breakpoints":
                self.debugger.breakpoints = frozenset(data["breakpoints"])
            elif kind == "debug" and data["action"] == "timeline":  # the time slider's
                self.on_timeline()
            elif kind == "stimulus":
                stimulus = stimulus_from(data)
                self._later.append(stimulus)
                if stimulus.action == "nose":  # Stop: the run goes on to stop as it does
                    self._stopping = True
                    return Go.RESUME

    def _stop(self) -> None:
        self._stopping = True
        self._later.append(Stimulus(0.0, "nose"))


def stimulus_from(data: dict[str, Any]) -> Stimulus:
    """A stimulus from the page (already checked by the server)."""
    kind = STIMULI.get(str(data.get("action")), STIMULI["nose"])
    if kind.parts:
        sensors = tuple(s for s in data.get("sensors", ()) if s in kind.parts)
        return Stimulus(0.0, kind.action, sensors, duration=0.3)
    return Stimulus(0.0, "nose")


class RobotDebugging:
    """A run on a robot's debugger: Pause, Step, Resume and breakpoints as for a simulated run,
    but the run's loop goes on while paused (the robot's link must: its packets, its answers,
    its sensors' events), so a pause is answered later (``Debugger.on_hold``):

    - paused, the robot stops at once (:meth:`RobotClient.hold`: both wheels to 0) and the
      run's time stands still (its clock is held: a `wait`, `timer` and the robot's answer
      times go on afterwards from where they stood), and each script waits at the next
      statement it begins;
    - Resume or Step: the movement a pause cut short is finished from where the robot stands,
      and the run goes on (a step to the next statement of any script);
    - the Watch follows the robot's own readings five times a second, paused or not (its
      bumpers, touch sensors, colours, light and pose, as the robot told them).

    See docs/studio.md, "Pause and step on a robot"."""

    def __init__(
        self,
        send: Callable[[str, object], None],
        clock: ScaledWallClock,
        languages: Languages,
        breakpoints: tuple[int, ...] = (),
    ) -> None:
        self._send = send
        self._clock = clock
        self._languages = languages
        self._answer: asyncio.Future[Go] | None = None  # the held pause's, until answered
        self._halted: asyncio.Task[None] | None = None  # the robot being stopped
        self._told: dict[str, object] | None = None  # the values the page was sent last
        self._ticking = threading.Event()
        self.debugger = Debugger(
            on_hold=self._on_hold, hold_time=clock.hold, breakpoints=breakpoints
        )

    def watch_live(self) -> None:
        """The values to the page about five times a second, paused or not (a thread asks the
        loop: the loop's own timers stand still while paused)."""
        loop = asyncio.get_running_loop()

        def tick() -> None:
            while not self._ticking.wait(LIVE_WATCH_S):
                with contextlib.suppress(RuntimeError):  # (the loop has closed)
                    loop.call_soon_threadsafe(self._tell)

        threading.Thread(target=tick, name="robot-watch", daemon=True).start()

    def finish(self) -> None:
        """The run is over: no more values."""
        self._ticking.set()

    def _tell(self) -> None:
        data = self.debugger.live(self._languages)
        if data is not None and data != self._told:
            self._told = data
            self._send("watch", data)

    def button(self, data: dict[str, Any]) -> None:
        """A debugger's button from the page (on the run's loop)."""
        action = data["action"]
        if action == "breakpoints":
            self.debugger.breakpoints = frozenset(data["breakpoints"])
        elif action == "pause":
            self.debugger.pause_now()
        elif action in ("resume", "step") and self._answer is not None:
            go = Go.STEP if action == "step" else Go.RESUME
            asyncio.get_running_loop().create_task(self._go_on(self._answer, go))
            self._answer = None
        elif action == "step":
            self.debugger.pause_soon()

    def stop(self) -> None:
        """Stop pressed (or the studio gone): a paused run ends where it stands."""
        answer, self._answer = self._answer, None
        if answer is not None and not answer.done():
            self._clock.release()
            answer.set_result(Go.STOP)

    def _on_hold(self, pause: Pause) -> asyncio.Future[Go]:
        loop = asyncio.get_running_loop()
        scheduler = self.debugger.scheduler
        assert scheduler is not None
        answer = self._answer = loop.create_future()  # (the clock is held: ``hold_time``)
        self._halted = loop.create_task(scheduler.client.hold())  # the robot stops at once
        self._send("paused", pause.to_json(self._languages))
        self._told = None
        ending = loop.create_task(scheduler.stopping())  # a lost link ends a paused run too

        def ended(task: asyncio.Task[None]) -> None:
            if not task.cancelled() and self._answer is answer:  # (not a later pause's)
                self.stop()

        ending.add_done_callback(ended)
        answer.add_done_callback(lambda _: ending.cancel())
        return answer

    async def _go_on(self, answer: asyncio.Future[Go], go: Go) -> None:
        """The robot goes on: the movement cut short is finished, then the scripts go on."""
        scheduler = self.debugger.scheduler
        assert scheduler is not None
        if self._halted is not None:
            with contextlib.suppress(Exception):  # (a lost link: the run ends as it does)
                await self._halted
        self._clock.release()
        with contextlib.suppress(Exception):
            await scheduler.client.release()
        if not answer.done():
            self._send("resumed", {"step": go is Go.STEP})
            answer.set_result(go)
