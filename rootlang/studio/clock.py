"""A wall clock scaled for speed: a run at 2×, 5× or 10× real time.

The loop's time runs ``speed`` times as fast as the wall, and every wait the loop makes is
shortened by the same factor, so timers (``clock.sleep``, ``call_later``, the simulator's steps)
fire at the scaled moments. At speed 1 it is the wall clock of ``rootlang sim --realtime``.
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

    def _new_loop(self) -> asyncio.AbstractEventLoop:
        return _ScaledLoop(self.speed)


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
        super().__init__(_ScaledSelector(speed))

    def time(self) -> float:
        return self._origin + (time.monotonic() - self._origin) * self._speed
