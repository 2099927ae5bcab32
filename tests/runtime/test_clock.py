"""The clocks: virtual time jumps and keeps order; wall time really passes."""

from __future__ import annotations

import asyncio
import time
from types import SimpleNamespace
from typing import cast

import pytest

from rootlang.runtime import loop_fence
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


def test_asyncios_private_loop_members_are_as_the_virtual_clock_expects() -> None:
    # the virtual clock relies on four private members of asyncio's loop (loop_fence.py): this
    # fails loudly on a Python that changes them, before any program runs out of order
    loop = asyncio.new_event_loop()
    try:
        loop_fence.check(loop)
        assert not loop_fence.anything_ready(loop) and loop_fence.first_timer(loop) is None
        loop.call_soon(lambda: None)
        assert loop_fence.anything_ready(loop)
        later = loop.call_later(5, lambda: None)
        sooner = asyncio.TimerHandle(loop.time() + 1, lambda: None, (), loop)
        loop_fence.push_timer(loop, sooner)
        assert loop_fence.first_timer(loop) is sooner
        sooner.cancel()  # a pushed timer is known to the loop as scheduled: cancel tells it
        assert sooner.cancelled() and later.when() > sooner.when()
        assert 0 < loop_fence.clock_resolution(loop) < 0.1
    finally:
        loop.close()
    with pytest.raises(RuntimeError, match="closed"):
        loop_fence.check_open(loop)


def test_a_loop_without_those_members_is_refused_with_a_clear_error() -> None:
    changed = SimpleNamespace(
        _scheduled=[], _ready=None, _check_closed=print, _clock_resolution=1e-9
    )
    with pytest.raises(loop_fence.LoopInternalsChanged, match=r"loop_fence\.py"):
        loop_fence.check(cast(asyncio.AbstractEventLoop, changed))  # _ready is not a deque
