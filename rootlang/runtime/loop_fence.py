"""The one place that touches asyncio's private event-loop members (the virtual clock needs them).

asyncio has no public way to order timers with equal deadlines, or to ask whether anything is
ready or due now, so :class:`rootlang.runtime.clock.VirtualClock`'s loop reads five private
members of :class:`asyncio.BaseEventLoop` here and nowhere else:

- ``_scheduled``: the heap of timer handles (a list kept by :mod:`heapq`);
- ``_ready``: the deque of callbacks to run on the next turn;
- ``_stopping``: whether ``stop()`` was called (the loop ends after this turn);
- ``_check_closed()``: raises RuntimeError once the loop is closed;
- ``_clock_resolution``: how near a timer must be to count as due.

:func:`check` finds out whether this Python still has them as expected; the clock calls it for
every new loop, and ``tests/runtime/test_clock.py`` runs it, so a Python that changes them fails
loudly instead of running programs out of order.
"""

from __future__ import annotations

import asyncio
import collections
import heapq
import math
from typing import Any

MEMBERS = ("_scheduled", "_ready", "_stopping", "_check_closed", "_clock_resolution")


class LoopInternalsChanged(RuntimeError):
    """This Python's asyncio no longer has the private members the virtual clock relies on."""


def check(loop: asyncio.AbstractEventLoop) -> None:
    """Raise :class:`LoopInternalsChanged` unless ``loop`` has the members, of the kinds used."""
    members: dict[str, Any] = {name: getattr(loop, name, None) for name in MEMBERS}
    kinds_ok = (
        isinstance(members["_scheduled"], list)
        and isinstance(members["_ready"], collections.deque)
        and isinstance(members["_stopping"], bool)
        and callable(members["_check_closed"])
        and isinstance(members["_clock_resolution"], float)
    )
    if not kinds_ok:
        raise LoopInternalsChanged(
            "asyncio's event loop no longer has " + ", ".join(MEMBERS) + " as the virtual clock "
            "expects (see rootlang/runtime/loop_fence.py)"
        )


# Each function below takes the loop as ``Any``: the members it reads are not in asyncio's public
# types (an annotated name, not a cast: these run for every timer, so no extra call).


def check_open(loop: asyncio.AbstractEventLoop) -> None:
    """Raise RuntimeError as asyncio does when the loop is closed."""
    private: Any = loop
    private._check_closed()


def push_timer(loop: asyncio.AbstractEventLoop, timer: asyncio.TimerHandle) -> None:
    """Put a timer on the loop's heap, as ``loop.call_at`` does with the handle it makes."""
    private: Any = loop
    heapq.heappush(private._scheduled, timer)
    marked: Any = timer
    marked._scheduled = True  # what call_at marks: cancel() then tells the loop


def idle_until(loop: asyncio.AbstractEventLoop) -> float | None:
    """The loop's time of its first timer (perhaps a cancelled one; ``math.inf`` if none) when
    nothing else is to run before it: None when a callback is ready or the loop is stopping."""
    private: Any = loop
    if private._ready or private._stopping:
        return None
    timers: list[asyncio.TimerHandle] = private._scheduled
    return timers[0].when() if timers else math.inf


def clock_resolution(loop: asyncio.AbstractEventLoop) -> float:
    private: Any = loop
    resolution: float = private._clock_resolution
    return resolution
