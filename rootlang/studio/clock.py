"""A wall clock scaled for speed: a run at 2×, 5× or 10× real time.

The loop's time runs ``speed`` times as fast as the wall, and every wait the loop makes is
shortened by the same factor, so timers (``clock.sleep``, ``call_later``, the simulator's steps)
fire at the scaled moments. At speed 1 it is the wall clock of ``rootlang sim --realtime``.
While :meth:`ScaledWallClock.hold` holds it (a paused run), its time stands still: the run goes
on afterwards from the very moment it paused at, no timer late.
"""

from __future__ import annotations

import asyncio
import selectors
import time

from rootlang.runtime.clock import Clock


class ScaledWallClock(Clock):
    def __init__(self, speed: float = 1.0) -> None:
        super().__init__()
        if speed <= 0:
            raise ValueError("a scaled clock needs a positive speed")
        self.speed = speed
        self._scaled: _ScaledLoop | None = None

    def _new_loop(self) -> asyncio.AbstractEventLoop:
        self._scaled = _ScaledLoop(self.speed)
        return self._scaled

    def hold(self) -> None:
        """Stop the time (until :meth:`release`)."""
        if self._scaled is not None and self._scaled.held_since is None:
            self._scaled.held_since = time.monotonic()

    def release(self) -> None:
        """Let the time go on from where it stood."""
        loop = self._scaled
        if loop is not None and loop.held_since is not None:
            loop.held_for += time.monotonic() - loop.held_since
            loop.held_since = None


class _ScaledSelector(selectors.DefaultSelector):
    def __init__(self, speed: float) -> None:
        super().__init__()
        self._speed = speed

    def select(self, timeout: float | None = None) -> list[tuple[selectors.SelectorKey, int]]:
        ready: list[tuple[selectors.SelectorKey, int]] = super().select(
            None if timeout is None else max(timeout, 0.0) / self._speed
        )
        return ready


class _ScaledLoop(asyncio.SelectorEventLoop):
    def __init__(self, speed: float) -> None:
        self._speed = speed
        self._origin = time.monotonic()
        self.held_since: float | None = None  # the wall's time when it was held
        self.held_for = 0.0  # wall seconds it was held before
        super().__init__(_ScaledSelector(speed))

    def time(self) -> float:
        wall = time.monotonic() if self.held_since is None else self.held_since
        return self._origin + (wall - self.held_for - self._origin) * self._speed
