"""Clocks: where rootlang's time comes from.

Everything that waits (scripts, the robot client's timeouts, the simulator's physics steps) asks
the clock, never ``time`` or ``asyncio.sleep`` directly. Two clocks:

- :class:`WallClock` — real time, for a real robot (and ``rootlang sim --realtime``).
- :class:`VirtualClock` — simulated time. Its event loop never waits: when nothing is ready to run,
  time jumps to the next timer. A 10-minute program runs in well under a second, and the same
  inputs give the same order of events every time. Real file descriptors (the loop's wake-up pipe,
  signals such as Ctrl-C) are still polled, so Ctrl-C works in virtual time too.

Each clock runs a coroutine on an event loop of its own with :meth:`Clock.run`; inside it, use
:meth:`Clock.now` and :meth:`Clock.sleep`. asyncio's own timers (``asyncio.wait_for``,
``loop.call_later``) follow the same clock, because the loop's ``time()`` is the clock.
"""

from __future__ import annotations

import abc
import asyncio
import selectors
from collections.abc import Callable, Coroutine
from contextvars import Context
from typing import Any, TypeVar

from rootlang.runtime import loop_fence

T = TypeVar("T")

TURNS_SAVED_AT_MOST = 200
"""Chosen: a virtual clock's loop saves at most this many turns in a row (:meth:`Clock.run_ahead`)
before it turns again and so hears Ctrl-C: some milliseconds of a busy loop. A count, not a
time, so a run saves the same turns on every machine."""


class Clock(abc.ABC):
    """Seconds since :meth:`run` started, and sleeping in those seconds."""

    def __init__(self) -> None:
        self._loop: asyncio.AbstractEventLoop | None = None
        self._start = 0.0
        self._passing: asyncio.TimerHandle | None = None  # (:meth:`when_time_passes`)

    @abc.abstractmethod
    def _new_loop(self) -> asyncio.AbstractEventLoop: ...

    def now(self) -> float:
        """Seconds since the clock started running (0.0 before)."""
        return 0.0 if self._loop is None else self._loop.time() - self._start

    def nothing_else_now(self) -> bool:
        """Whether nothing else is ready or due at this moment and the loop goes on after it,
        so a callback run right away runs in the very order one given to ``loop.call_soon``
        would (the virtual clock can tell; a wall clock says no)."""
        return False

    def call_later(
        self, delay: float, callback: Callable[[], object], *, place: int | None = None
    ) -> asyncio.TimerHandle:
        """``loop.call_later`` on the running loop. ``place`` (from :meth:`take_place`) puts the
        timer among timers with the same deadline where one set when the place was taken
        would be."""
        return asyncio.get_running_loop().call_later(delay, callback)

    def take_place(self) -> int | None:
        """A place in the order of timers with equal deadlines, for a timer set a little later
        (see :meth:`call_later`); None on a clock that orders no ties (a wall clock)."""
        return None

    def when_time_passes(self, when: float, callback: Callable[[], None]) -> None:
        """Call ``callback`` once the time has passed ``when`` (one at a time: a new one
        replaces the last), before anything due then runs. A timer here; a virtual clock looks
        as its time moves, without a turn of its own (a timer would cost a busy loop the turns
        it saves: :meth:`run_ahead`)."""
        if self._passing is not None:
            self._passing.cancel()
        self._passing = self.call_later(when - self.now(), callback)

    def run_ahead(self, delay: float) -> bool:
        """Move the time on by ``delay`` now, as the loop's next turn would if a timer were set
        for then: only when that turn would run that timer alone (nothing ready, no other timer
        due by then, the loop not stopping). The caller then does at once what the timer would
        have done, saving the turn. False (time stays) otherwise, and on a clock that cannot
        tell (a wall clock, where the outside world may wake the loop)."""
        return False

    async def sleep(self, seconds: float) -> None:
        await asyncio.sleep(max(seconds, 0.0))

    async def sleep_until(self, when: float) -> None:
        await self.sleep(when - self.now())

    def run(self, main: Coroutine[Any, Any, T]) -> T:
        """Run ``main`` to completion on a new event loop driven by this clock."""
        loop = self._new_loop()
        self._loop = loop
        self._start = loop.time()
        try:
            asyncio.set_event_loop(loop)
            return loop.run_until_complete(main)
        finally:
            try:
                _cancel_leftover_tasks(loop)
                loop.run_until_complete(loop.shutdown_asyncgens())
            finally:
                asyncio.set_event_loop(None)
                loop.close()


class WallClock(Clock):
    """Real time."""

    def _new_loop(self) -> asyncio.AbstractEventLoop:
        return asyncio.new_event_loop()


class VirtualClock(Clock):
    """Simulated time that jumps ahead whenever everything is waiting. Its loop's time starts
    at 0, so the loop's time is the clock's: :meth:`now` reads it directly (it is asked for
    every packet and every line of the trace)."""

    def __init__(self) -> None:
        super().__init__()
        self._virtual: _VirtualTimeLoop | None = None

    def _new_loop(self) -> asyncio.AbstractEventLoop:
        self._virtual = _VirtualTimeLoop()
        return self._virtual

    def now(self) -> float:
        loop = self._virtual
        return 0.0 if loop is None else loop.virtual_time

    def nothing_else_now(self) -> bool:
        return self._virtual is not None and self._virtual.nothing_else_now()

    def call_later(
        self, delay: float, callback: Callable[[], object], *, place: int | None = None
    ) -> asyncio.TimerHandle:
        loop = self._virtual
        if loop is None:
            return super().call_later(delay, callback)  # (asyncio's error: no running loop)
        return loop.call_at(loop.virtual_time + delay, callback, place=place)  # as call_later

    def take_place(self) -> int | None:
        return None if self._virtual is None else self._virtual.take_place()

    async def sleep(self, seconds: float) -> None:
        """As ``asyncio.sleep`` does it (the same timer at the same place among its equals).
        But when nothing else would run before the sleep ends, the loop's turns would only
        move the time and hand the sleeper back: then the time moves as they would move it
        and the sleeper goes on at once (:meth:`run_ahead`; every round of a busy loop
        sleeps, docs/simulator.md)."""
        loop = self._virtual
        if loop is None:
            await super().sleep(seconds)
            return
        if seconds <= 0:
            if not (loop.nothing_else_now() and loop.save_turn()):
                await asyncio.sleep(0)
            return
        if loop.run_ahead(seconds):
            return
        woken = loop.create_future()
        wakeups = loop.wake_at(loop.virtual_time + seconds, woken)
        try:
            await woken
        finally:
            if woken.cancelled():
                wakeups.cancelled_one()

    def run_ahead(self, delay: float) -> bool:
        return self._virtual is not None and self._virtual.run_ahead(delay)

    def when_time_passes(self, when: float, callback: Callable[[], None]) -> None:
        if self._virtual is not None:
            self._virtual.passing = (when, callback)


class _VirtualTimeSelector(selectors.DefaultSelector):
    """Polls real file descriptors without blocking; a wait for a timer moves time instead."""

    def __init__(self, loop: _VirtualTimeLoop) -> None:
        super().__init__()
        self._virtual_loop = loop

    def select(self, timeout: float | None = None) -> list[tuple[selectors.SelectorKey, int]]:
        self._virtual_loop.turned()
        ready: list[tuple[selectors.SelectorKey, int]] = super().select(0)
        if ready:
            return ready
        if timeout is None:  # no timer at all: only the real world (a signal) can wake us
            blocked: list[tuple[selectors.SelectorKey, int]] = super().select(None)
            return blocked
        self._virtual_loop.advance(timeout)
        return []


class _OrderedTimerHandle(asyncio.TimerHandle):
    """A timer that breaks ties by creation order, so equal deadlines fire first-come first."""

    def __init__(self, sequence: int, when: float, *args: Any, **kwargs: Any) -> None:
        super().__init__(when, *args, **kwargs)
        self._key = (when, sequence)  # made once: the timer heap compares it a lot

    def __lt__(self, other: object) -> bool:
        if isinstance(other, _OrderedTimerHandle):
            return self._key < other._key
        return NotImplemented

    def __le__(self, other: object) -> bool:
        if isinstance(other, _OrderedTimerHandle):
            return self._key <= other._key
        return NotImplemented

    def __hash__(self) -> int:
        return hash(self._key)


_NO_SEQUENCE = -1  # (no timer has it)


class _Wakeups:
    """Sleepers that a timer of each, set one right after the other for the same time, would
    wake in turn (every script of a busy program ends its loop's round so): one timer wakes
    them all, in that order, with no other timer between them to run."""

    __slots__ = ("sequence", "sleepers", "timer", "when")

    def __init__(self, when: float, sequence: int) -> None:
        self.when = when
        self.sequence = sequence
        self.sleepers: list[asyncio.Future[None]] = []
        self.timer: asyncio.TimerHandle | None = None

    def wake(self) -> None:
        """Their time has come (perhaps a little before it, within the clock's resolution, as
        for any timer): wake them, and none joins them after."""
        self.sequence = _NO_SEQUENCE
        for sleeper in self.sleepers:
            _wake(sleeper)

    def cancelled_one(self) -> None:
        """A sleeper was cancelled: with none left to wake, the timer is cancelled, as each
        sleeper's own would be, and no sleeper joins them any more."""
        if self.timer is not None and all(sleeper.done() for sleeper in self.sleepers):
            self.timer.cancel()
            self.sequence = _NO_SEQUENCE


_WAKING = Context()
"""The context waking sleepers runs in (it reads no context variable: none is copied)."""


class _VirtualTimeLoop(asyncio.SelectorEventLoop):
    def __init__(self) -> None:
        self.virtual_time = 0.0
        self._next_sequence = 0  # of the timers, to break ties between equal deadlines
        self._wakeups: _Wakeups | None = None  # the last timer set, if it wakes sleepers
        self._saved = 0  # turns saved since the loop last turned
        self.passing: tuple[float, Callable[[], None]] | None = None  # Clock.when_time_passes
        super().__init__(_VirtualTimeSelector(self))
        loop_fence.check(self)

    def call_at(
        self,
        when: float,
        callback: Callable[..., object],
        *args: object,
        context: Context | None = None,
        place: int | None = None,
    ) -> asyncio.TimerHandle:
        # asyncio's heap compares timers by deadline only; ties would fire in heap order.
        loop_fence.check_open(self)
        if place is None:
            place = self._next_sequence
            self._next_sequence += 1
        timer = _OrderedTimerHandle(place, when, callback, args, self, context=context)
        loop_fence.push_timer(self, timer)
        return timer

    def take_place(self) -> int:
        self._next_sequence += 1
        return self._next_sequence - 1

    def wake_at(self, when: float, sleeper: asyncio.Future[None]) -> _Wakeups:
        """Wake ``sleeper`` at ``when`` just as a timer of its own set now would: with the
        sleepers of the last timer set, if that one is for the same time and is still the
        last timer (no timer nor place taken since, so none can fall between them)."""
        wakeups = self._wakeups
        if (
            wakeups is None
            or wakeups.when != when
            or wakeups.sequence != self._next_sequence - 1  # (-1 once it woke them)
        ):
            wakeups = self._wakeups = _Wakeups(when, self._next_sequence)
            wakeups.timer = self.call_at(when, wakeups.wake, context=_WAKING)
        wakeups.sleepers.append(sleeper)
        return wakeups

    def run_ahead(self, delay: float) -> bool:
        """See :meth:`Clock.run_ahead`. The time moves by the very float sums of ``call_later``
        and ``_run_once``; the turn's poll of real file descriptors is skipped, as if none were
        ready (callers bound how far they run ahead)."""
        idle = loop_fence.idle_until(self)  # the first timer's deadline, if nothing is ready
        if idle is None:
            return False  # a callback is ready, or the loop is stopping
        now = self.virtual_time
        then = now + max(now + delay - now, 0.0)
        if idle < then + loop_fence.clock_resolution(self):
            return False  # something else is due by then: that turn runs it (too)
        if not self.save_turn():
            return False  # time to turn: Ctrl-C may be waiting
        self._move_to(then)
        return True

    def turned(self) -> None:
        """A turn of the loop begins: it polls the real file descriptors (Ctrl-C)."""
        self._saved = 0

    def save_turn(self) -> bool:
        """Whether one more turn may be saved (see :data:`TURNS_SAVED_AT_MOST`); counted if so."""
        if self._saved >= TURNS_SAVED_AT_MOST:
            return False
        self._saved += 1
        return True

    def time(self) -> float:
        return self.virtual_time

    def nothing_else_now(self) -> bool:
        """No callback is ready, the loop is not stopping and no timer is due now. The first
        timer has the earliest deadline: if it is later, so are all; if it is due but cancelled,
        we say no (one behind it may be due too)."""
        idle = loop_fence.idle_until(self)
        return idle is not None and idle > self.virtual_time + loop_fence.clock_resolution(self)

    def advance(self, seconds: float) -> None:
        self._move_to(self.virtual_time + max(seconds, 0.0))

    def _move_to(self, then: float) -> None:
        self.virtual_time = then
        passing = self.passing
        if passing is not None and then >= passing[0]:
            self.passing = None
            passing[1]()


def _wake(sleeper: asyncio.Future[None]) -> None:
    if not sleeper.done():  # (cancelled meanwhile)
        sleeper.set_result(None)


def _cancel_leftover_tasks(loop: asyncio.AbstractEventLoop) -> None:
    tasks = [task for task in asyncio.all_tasks(loop) if not task.done()]
    for task in tasks:
        task.cancel()
    if tasks:
        loop.run_until_complete(asyncio.gather(*tasks, return_exceptions=True))
