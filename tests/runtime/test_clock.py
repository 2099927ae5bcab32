"""The clocks: virtual time jumps and keeps order; wall time really passes."""

from __future__ import annotations

import asyncio
import time

import pytest

from rootlang.runtime.clock import VirtualClock, WallClock


def test_virtual_clock_jumps_to_the_next_timer_without_waiting() -> None:
    clock = VirtualClock()

    async def main() -> float:
        await clock.sleep(600.0)
        return clock.now()

    started = time.perf_counter()
    assert clock.run(main()) == pytest.approx(600.0)
    assert time.perf_counter() - started < 1.0


def test_virtual_clock_wakes_sleepers_in_time_order_and_ties_in_start_order() -> None:
    clock = VirtualClock()
    woke: list[tuple[str, float]] = []

    async def sleeper(name: str, seconds: float) -> None:
        await clock.sleep(seconds)
        woke.append((name, round(clock.now(), 6)))

    async def main() -> None:
        await asyncio.gather(
            sleeper("c", 2.0), sleeper("a", 1.0), sleeper("b", 1.0), sleeper("d", 0.5)
        )

    clock.run(main())
    assert woke == [("d", 0.5), ("a", 1.0), ("b", 1.0), ("c", 2.0)]


def test_asyncio_timeouts_follow_virtual_time() -> None:
    clock = VirtualClock()

    async def main() -> float:
        with pytest.raises(asyncio.TimeoutError):
            await asyncio.wait_for(asyncio.Event().wait(), timeout=30.0)
        return clock.now()

    assert clock.run(main()) == pytest.approx(30.0)


def test_wall_clock_really_sleeps() -> None:
    clock = WallClock()

    async def main() -> float:
        await clock.sleep(0.05)
        return clock.now()

    started = time.perf_counter()
    assert clock.run(main()) >= 0.05
    assert time.perf_counter() - started >= 0.05


def test_leftover_tasks_are_cancelled_when_run_ends() -> None:
    clock = VirtualClock()
    cancelled = []

    async def forever() -> None:
        try:
            await clock.sleep(1e9)
        except asyncio.CancelledError:
            cancelled.append(True)
            raise

    async def main() -> None:
        asyncio.get_running_loop().create_task(forever())
        await clock.sleep(1.0)

    clock.run(main())
    assert cancelled == [True]
