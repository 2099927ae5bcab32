"""Packet ids: the host's wrapping counter and the watch on the robot's event ids."""

from __future__ import annotations

import logging
import subprocess
import sys

import pytest

from rootlang.protocol import EventIdTracker, EventOrder, HostPacketIds


def test_host_ids_count_from_zero_and_wrap() -> None:
    ids = HostPacketIds()
    taken = [ids.next_id() for _ in range(258)]
    assert taken[:3] == [0, 1, 2]
    assert taken[255:] == [255, 0, 1]
    assert ids.peek() == 2
    ids.reset()
    assert ids.next_id() == 0


def test_events_in_order_across_the_wrap() -> None:
    tracker = EventIdTracker()
    orders = [tracker.observe(i).order for i in (254, 255, 0, 1)]
    assert orders == [
        EventOrder.FIRST,
        EventOrder.IN_ORDER,
        EventOrder.IN_ORDER,
        EventOrder.IN_ORDER,
    ]
    assert tracker.lost == 0


def test_a_gap_is_noticed_counted_and_logged(caplog: pytest.LogCaptureFixture) -> None:
    tracker = EventIdTracker()
    tracker.observe(250)
    with caplog.at_level(logging.WARNING, logger="rootlang.protocol"):
        check = tracker.observe(3)  # 251..255, 0, 1, 2 lost
    assert check.order is EventOrder.GAP and check.missed == 8 and check.is_new
    assert tracker.lost == 8
    assert "lost 8 robot event(s)" in caplog.text
    assert tracker.observe(4).order is EventOrder.IN_ORDER


def test_a_gap_stays_quiet_when_the_application_has_not_configured_logging() -> None:
    # (else Python's last-resort handler would print the warning on stderr)
    script = (
        "from rootlang.protocol import EventIdTracker\n"
        "tracker = EventIdTracker()\n"
        "tracker.observe(1)\n"
        "tracker.observe(9)\n"  # 2 to 8 lost: a warning
    )
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
    assert done.returncode == 0 and done.stderr == ""


def test_repeats_and_late_events_are_flagged_not_counted_as_gaps() -> None:
    tracker = EventIdTracker()
    tracker.observe(10)
    tracker.observe(11)
    repeat = tracker.observe(11)
    assert repeat.order is EventOrder.REPEAT and not repeat.is_new
    assert tracker.observe(9).order is EventOrder.REPEAT
    assert tracker.observe(12).order is EventOrder.IN_ORDER
    assert (tracker.lost, tracker.repeats) == (0, 2)


def test_reset_starts_over() -> None:
    tracker = EventIdTracker()
    tracker.observe(5)
    tracker.reset()
    assert tracker.observe(200).order is EventOrder.FIRST
