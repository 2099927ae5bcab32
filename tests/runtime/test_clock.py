"""The clocks: virtual time jumps and keeps order; wall time really passes."""

from __future__ import annotations

import asyncio
import math
import time
from types import SimpleNamespace
from typing import Any, cast

import pytest

from rootlang.runtime import loop_fence
from rootlang.runtime.clock import TURNS_SAVED_AT_MOST, VirtualClock, WallClock


def test_virtual_clock_jumps_to_the_next_timer_without_waiting() -> None:
    clock = VirtualClock()

    async def main() -> float:
        await clock.sleep(600.0)
        return clock.now()

    started = time.perf_counter()
    assert clock.run(main()) == pytest.approx(600.0)
    # a clock that waited would take the 600 s; the bound is far from that and from how long a
    # busy machine takes for a loop's few turns
    assert time.perf_counter() - started < 60.0


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
    # the virtual clock relies on five private members of asyncio's loop (loop_fence.py): this
    # fails loudly on a Python that changes them, before any program runs out of order
    loop = asyncio.new_event_loop()
    try:
        loop_fence.check(loop)
        later = loop.call_later(5, lambda: None)
        sooner = asyncio.TimerHandle(loop.time() + 1, lambda: None, (), loop)
        loop_fence.push_timer(loop, sooner)
        assert loop_fence.idle_until(loop) == sooner.when()  # first on the loop's heap
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


def test_running_ahead_moves_the_time_only_when_nothing_else_would_run_first() -> None:
    clock = VirtualClock()
    seen: list[tuple[bool, float]] = []

    async def main() -> None:
        loop = asyncio.get_running_loop()
        seen.append((clock.run_ahead(0.5), clock.now()))  # nothing else: the time moves
        loop.call_soon(lambda: None)
        seen.append((clock.run_ahead(0.5), clock.now()))  # a callback is ready
        await asyncio.sleep(0)
        other = loop.call_later(1.0, lambda: None)
        seen.append((clock.run_ahead(1.0), clock.now()))  # a timer due then runs in that turn
        seen.append((clock.run_ahead(0.25), clock.now()))  # one due later does not count
        other.cancel()

    clock.run(main())
    assert seen == [(True, 0.5), (False, 0.5), (False, 0.5), (True, 0.75)]
    assert WallClock().run_ahead(1.0) is False


def test_running_ahead_lands_where_a_timer_would_have() -> None:
    # the same float sums as call_later and the loop's turn: the times are exactly equal
    delays = [0.04, 0.01, 1 / 3, 0.07, 0.1, 1e-3, 0.0, 0.3]

    def by(run_ahead: bool) -> list[float]:
        clock = VirtualClock()
        times: list[float] = []

        async def main() -> None:
            for delay in delays:
                if not (run_ahead and clock.run_ahead(delay)):
                    await asyncio.sleep(delay)
                times.append(clock.now())

        clock.run(main())
        return times

    assert by(run_ahead=True) == by(run_ahead=False)


def test_sleepers_for_one_time_one_right_after_another_share_one_timer_in_turn() -> None:
    """Every script of a busy program ends its loop's round so: one timer wakes them all, in
    the order they slept, as a timer each would; one cancelled is not woken, and a timer set
    between two sleepers keeps its turn between them."""
    clock = VirtualClock()
    woke: list[str] = []

    async def sleeper(name: str) -> None:
        await clock.sleep(1.0)
        woke.append(name)

    async def timed() -> None:
        await asyncio.sleep(1.0)  # asyncio's own timer
        woke.append("timer")

    def place() -> int:
        taken = clock.take_place()
        assert taken is not None  # (a virtual clock orders ties)
        return taken

    async def main() -> tuple[int, int]:
        first = place()
        sleepers = [asyncio.ensure_future(sleeper(f"s{n}")) for n in range(50)]
        await asyncio.sleep(0)  # all asleep now
        sleepers[10].cancel()
        timers = place() - first - 1
        between = asyncio.ensure_future(timed())  # its timer: between the sleepers around it
        later = [asyncio.ensure_future(sleeper(f"t{n}")) for n in range(2)]
        await asyncio.gather(*sleepers, between, *later, return_exceptions=True)
        return timers, place() - first - 2  # (less the place taken between)

    timers, all_timers = clock.run(main())
    assert timers == 1 and all_timers == 3  # (a timer each for the 50, 1 and 2 would be 53)
    assert woke == [f"s{n}" for n in range(50) if n != 10] + ["timer", "t0", "t1"]


def test_a_sleeper_after_one_cancelled_for_the_same_time_is_woken() -> None:
    clock = VirtualClock()
    woke: list[float] = []

    async def sleeper() -> None:
        await clock.sleep(1.0)
        woke.append(clock.now())

    async def main() -> None:
        cancelled = asyncio.ensure_future(sleeper())
        await asyncio.sleep(0)  # asleep
        cancelled.cancel()
        await asyncio.gather(cancelled, sleeper(), return_exceptions=True)

    clock.run(asyncio.wait_for(main(), 5.0))  # (a sleeper never woken: TimeoutError at 5 s)
    assert woke == [1.0]


def test_a_sleeper_for_the_time_of_sleepers_woken_a_little_early_is_woken_too() -> None:
    """A timer runs when its time is within the clock's resolution: a sleeper for the very
    time of sleepers just woken so gets a timer of its own."""
    clock = VirtualClock()
    woke: list[str] = []

    async def sleeper(name: str, seconds: float) -> None:
        await clock.sleep(seconds)
        woke.append(name)

    async def main() -> None:
        loop = asyncio.get_running_loop()
        early = loop.create_future()
        loop.call_at(1.0 - 5e-10, early.set_result, None)  # the sleepers' timer runs with it
        first = asyncio.ensure_future(sleeper("first", 1.0))
        await early
        assert clock.now() < 1.0
        await asyncio.gather(first, sleeper("after", 1.0 - clock.now()))

    clock.run(asyncio.wait_for(main(), 5.0))  # (a sleeper never woken: TimeoutError at 5 s)
    assert woke == ["first", "after"]


def test_a_timer_keeps_the_place_taken_before_timers_set_in_between() -> None:
    clock = VirtualClock()
    fired: list[str] = []

    async def main() -> None:
        loop = asyncio.get_running_loop()
        place = clock.take_place()
        loop.call_later(1.0, fired.append, "set in between")
        clock.call_later(1.0, lambda: fired.append("set later, in the place taken first"),
                         place=place)  # fmt: skip
        clock.call_later(1.0, lambda: fired.append("set last, no place"))
        await clock.sleep(2.0)

    clock.run(main())
    assert fired == ["set later, in the place taken first", "set in between", "set last, no place"]


def test_the_fence_tells_until_when_the_loop_is_idle() -> None:
    loop = asyncio.new_event_loop()
    try:
        assert loop_fence.idle_until(loop) == math.inf  # no timer at all
        later = loop.call_later(5, lambda: None)
        assert loop_fence.idle_until(loop) == later.when()
        later.cancel()
        assert loop_fence.idle_until(loop) == later.when()  # (a cancelled one still counts)
        ready = loop.call_soon(lambda: None)
        assert loop_fence.idle_until(loop) is None  # a callback is ready
        ready.cancel()
        loop.run_until_complete(asyncio.sleep(0))
        loop.stop()  # the loop would end after this turn
        assert loop_fence.idle_until(loop) is None
    finally:
        loop.close()


def _turns_and_times(clock: VirtualClock, sleeps: list[float], other: float | None) -> list[object]:
    """Where a sleeper that sleeps ``sleeps`` one after another wakes, interleaved with another
    that wakes at ``other``, on ``clock`` (asyncio's own sleep when it is None)."""
    seen: list[object] = []

    async def sleeper() -> None:
        for seconds in sleeps:
            await clock.sleep(seconds)
            seen.append(clock.now())

    async def another() -> None:
        if other is not None:
            await asyncio.sleep(other)
            seen.append(("other", clock.now()))

    async def main() -> None:
        await asyncio.gather(sleeper(), another())

    clock.run(main())
    return seen


class _AsyncioSleeps(VirtualClock):
    """The virtual clock as it was: every sleep a timer on the loop."""

    async def sleep(self, seconds: float) -> None:
        await asyncio.sleep(max(seconds, 0.0))


@pytest.mark.parametrize("other", [None, 0.0105, 0.003, 0.0])
def test_a_sleep_nothing_else_runs_before_wakes_where_a_timer_would_have(
    other: float | None,
) -> None:
    sleeps = [0.001] * 15 + [0.0, 1 / 3, 0.0, 0.0007] * 3
    saving = _turns_and_times(VirtualClock(), sleeps, other)
    assert saving == _turns_and_times(_AsyncioSleeps(), sleeps, other)


def test_a_busy_loops_sleeps_save_the_loops_turns_but_not_all() -> None:
    clock = VirtualClock()
    turns = 0

    async def main() -> None:
        nonlocal turns
        loop = asyncio.get_running_loop()
        selector = cast(Any, loop)._selector
        select = selector.select

        def counted(timeout: float | None = None) -> object:
            nonlocal turns
            turns += 1
            return select(timeout)

        selector.select = counted
        for _ in range(2000):  # two simulated seconds of a busy loop's rounds
            await clock.sleep(0.001)
        selector.select = select

    clock.run(main())
    assert clock.now() == pytest.approx(2.0)
    # asyncio's sleep would turn the loop twice a round (the timer, then the sleeper): 4,000
    assert 2000 // (TURNS_SAVED_AT_MOST + 1) <= turns <= 2 * 2000 // TURNS_SAVED_AT_MOST + 2
