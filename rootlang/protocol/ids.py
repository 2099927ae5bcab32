"""Packet ids: the host's counter for commands, and a watch on the robot's event ids.

The spec: the host numbers its packets 0, 1, ... 255, 0, ... (id 0 is always accepted and
resets the robot's count); a response repeats its request's id; the robot numbers its events
with its own counter, so a jump in that counter means events were lost.
"""

from __future__ import annotations

import enum
import logging
from dataclasses import dataclass

ID_COUNT = 256
_BEHIND_WINDOW = ID_COUNT // 2
"""An id at most this far behind the last one is an old or repeated event, not a gap."""

log = logging.getLogger("rootlang.protocol")
# Lost or repeated robot events are counted in a run's stats; as log records they stay quiet
# unless the host application configures logging (`rootlang --debug` does). Set up here, beside
# rootlang's only logger, so that `import rootlang` does without the logging module.
logging.getLogger("rootlang").addHandler(logging.NullHandler())


class HostPacketIds:
    """The incrementing id for the host's packets: starts at 0, wraps 255 -> 0."""

    def __init__(self, first: int = 0) -> None:
        self._next = first % ID_COUNT

    def next_id(self) -> int:
        packet_id = self._next
        self._next = (packet_id + 1) % ID_COUNT
        return packet_id

    def peek(self) -> int:
        """The id the next packet will get."""
        return self._next

    def reset(self) -> None:
        """Start again at 0 (a new connection: id 0 resets the robot's count too)."""
        self._next = 0


class EventOrder(enum.Enum):
    FIRST = "first"
    """The first event seen since the tracker started or was reset."""
    IN_ORDER = "in order"
    GAP = "gap"
    """Events were lost between the previous one and this one (``missed`` says how many)."""
    REPEAT = "repeat"
    """The same id again, or an id from just behind: a duplicate or late event."""


@dataclass(frozen=True)
class EventCheck:
    """What the watch made of an event's id: its order, and how many events were missed."""

    order: EventOrder
    missed: int = 0

    @property
    def is_new(self) -> bool:
        """Whether the event should be handled (a repeat should be skipped)."""
        return self.order is not EventOrder.REPEAT


_IN_ORDER = EventCheck(EventOrder.IN_ORDER)  # the usual answer, shared (checks are frozen)


class EventIdTracker:
    """Follows the robot's event ids; notices (and logs) gaps and repeats.

    >>> tracker = EventIdTracker()
    >>> tracker.observe(7).order, tracker.observe(8).order, tracker.observe(11).missed
    (<EventOrder.FIRST: 'first'>, <EventOrder.IN_ORDER: 'in order'>, 2)
    """

    def __init__(self) -> None:
        self._last: int | None = None
        self.lost = 0
        """Events missed in all, by counting the gaps."""
        self.repeats = 0

    def reset(self) -> None:
        self._last = None

    def observe(self, event_id: int) -> EventCheck:
        last = self._last
        if last is None:
            self._last = event_id
            return EventCheck(EventOrder.FIRST)
        step = (event_id - last) % ID_COUNT
        if step == 1:
            self._last = event_id
            return _IN_ORDER
        if step == 0 or step > ID_COUNT - _BEHIND_WINDOW:
            self.repeats += 1
            log.warning("robot event id %d repeats or arrives late (last was %d)", event_id, last)
            return EventCheck(EventOrder.REPEAT)
        missed = step - 1
        self.lost += missed
        self._last = event_id
        log.warning("lost %d robot event(s): id went from %d to %d", missed, last, event_id)
        return EventCheck(EventOrder.GAP, missed)
