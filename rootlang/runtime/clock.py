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
import itertools
import math
import selectors
from collections.abc import Callable, Coroutine
from contextvars import Context
from typing import Any, TypeVar

from rootlang.runtime import loop_fence

T = TypeVar("T")


class Clock(abc.ABC):
    """Seconds since :meth:`run` started, and sleeping in those seconds."""

    def __init__(self) -> None:
        self._loop: asyncio.AbstractEventLoop | None = None
        self._start = 0.0

    @abc.abstractmethod
    def _new_loop(self) -> asyncio.AbstractEventLoop: ...

    def now(self) -> float:
        """Seconds since the clock started running (0.0 before)."""
        return 0.0 if self._loop is None else self._loop.time() - self._start

    def nothing_else_now(self) -> bool:
        """Whether nothing else is ready or due at this moment, so a callback run right away
        runs in the very order one given to ``loop.call_soon`` would (the virtual clock can
        tell; a wall clock says no)."""
        return False

    def quiet_until(self) -> float | None:
        """A time (as :meth:`now` gives it) before which nothing else on the loop will run:
        its first timer's (``math.inf`` if none); None when something is ready to run now, or
        the clock cannot tell (a wall clock, where the outside world may wake the loop)."""
        return None

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
    """Simulated time that jumps ahead whenever everything is waiting."""

    def _new_loop(self) -> asyncio.AbstractEventLoop:
        return _VirtualTimeLoop()

    def nothing_else_now(self) -> bool:
        return isinstance(self._loop, _VirtualTimeLoop) and self._loop.nothing_else_now()

    def quiet_until(self) -> float | None:
        loop = self._loop
        if not isinstance(loop, _VirtualTimeLoop) or loop_fence.anything_ready(loop):
            return None
        first = loop_fence.first_timer(loop)
        return math.inf if first is None else first.when() - self._start


class _VirtualTimeSelector(selectors.DefaultSelector):
    """Polls real file descriptors without blocking; a wait for a timer moves time instead."""

    def __init__(self, loop: _VirtualTimeLoop) -> None:
        super().__init__()
        self._virtual_loop = loop

    def select(self, timeout: float | None = None) -> list[tuple[selectors.SelectorKey, int]]:
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


class _VirtualTimeLoop(asyncio.SelectorEventLoop):
    def __init__(self) -> None:
        self._virtual_now = 0.0
        self._timer_sequence = itertools.count()
        super().__init__(_VirtualTimeSelector(self))
        loop_fence.check(self)

    def call_at(
        self,
        when: float,
        callback: Callable[..., object],
        *args: object,
        context: Context | None = None,
    ) -> asyncio.TimerHandle:
        # asyncio's heap compares timers by deadline only; ties would fire in heap order.
        loop_fence.check_open(self)
        timer = _OrderedTimerHandle(
            next(self._timer_sequence), when, callback, args, self, context=context
        )
        loop_fence.push_timer(self, timer)
        return timer

    def time(self) -> float:
        return self._virtual_now

    def nothing_else_now(self) -> bool:
        """No callback is ready and no timer is due now (a cancelled one first: we say no)."""
        if loop_fence.anything_ready(self):
            return False
        first = loop_fence.first_timer(self)
        if first is None:
            return True
        resolution = loop_fence.clock_resolution(self)
        return not first.cancelled() and first.when() > self._virtual_now + resolution

    def advance(self, seconds: float) -> None:
        self._virtual_now += max(seconds, 0.0)


def _cancel_leftover_tasks(loop: asyncio.AbstractEventLoop) -> None:
    tasks = [task for task in asyncio.all_tasks(loop) if not task.done()]
    for task in tasks:
        task.cancel()
    if tasks:
        loop.run_until_complete(asyncio.gather(*tasks, return_exceptions=True))
