"""The trace of a run: what happened, when, and which script and line it came from.

Every script start and end, every command sent with its outcome, every event received and every
``print`` is one :class:`TraceEntry`. Times are whole milliseconds of the run's clock, and values
are quantised (whole mm, whole degrees) so a trace is byte-identical on any machine; the golden
tests diff :meth:`Trace.text`. :meth:`Trace.to_json` gives the same entries as data.
"""

from __future__ import annotations

import json
from collections.abc import Callable
from dataclasses import asdict, dataclass
from enum import Enum
from typing import Literal

EntryKind = Literal["start", "end", "command", "event", "print", "error", "run"]


class Outcome(str, Enum):
    """How a command's wait ended."""

    PENDING = "pending"
    DONE = "done"
    INTERRUPTED = "interrupted"
    CANCELLED = "cancelled"
    FAILED = "failed"


@dataclass(slots=True)  # a long run has an entry for every event: slots make them small
class TraceEntry:
    time_ms: int
    kind: EntryKind
    script: str
    line: int
    text: str
    outcome: Outcome | None = None
    end_ms: int | None = None
    detail: str = ""

    def render(self) -> str:
        where = f"{self.script} @{self.line}" if self.line else self.script
        parts = [f"{self.time_ms:>8} ms  {where:<28} {self.kind:<7} {self.text}"]
        if self.outcome is not None:
            parts.append(f"-> {self.outcome.value}")
            if self.end_ms is not None:
                parts.append(f"at {self.end_ms} ms")
        if self.detail:
            parts.append(f"[{self.detail}]")
        return " ".join(parts)

    def to_json(self) -> dict[str, object]:
        data = asdict(self)
        data["outcome"] = None if self.outcome is None else self.outcome.value
        return data


class Trace:
    """An append-only list of entries, stamped with the clock's time."""

    def __init__(self, now: Callable[[], float]) -> None:
        self._now = now
        self.entries: list[TraceEntry] = []

    def now_ms(self) -> int:
        return round(self._now() * 1000)

    def add(
        self,
        kind: EntryKind,
        text: str,
        *,
        script: str = "",
        line: int = 0,
        outcome: Outcome | None = None,
        detail: str = "",
    ) -> TraceEntry:
        entry = TraceEntry(self.now_ms(), kind, script, line, text, outcome, detail=detail)
        self.entries.append(entry)
        return entry

    def finish(self, entry: TraceEntry, outcome: Outcome, detail: str = "") -> None:
        """Record how a command ended (only its first ending counts)."""
        if entry.outcome not in (None, Outcome.PENDING):
            return
        entry.outcome = outcome
        entry.end_ms = self.now_ms()
        if detail:
            entry.detail = detail

    def of_kind(self, kind: EntryKind) -> list[TraceEntry]:
        return [entry for entry in self.entries if entry.kind == kind]

    def text(self) -> str:
        return "".join(entry.render() + "\n" for entry in self.entries)

    def to_json(self) -> str:
        return json.dumps([entry.to_json() for entry in self.entries], indent=1)


def pose_text(x_mm: float, y_mm: float, heading_degrees: float) -> str:
    """A pose quantised for the trace: whole millimetres and whole degrees."""
    return f"x {round(x_mm)} mm, y {round(y_mm)} mm, heading {round(heading_degrees) % 360}°"
