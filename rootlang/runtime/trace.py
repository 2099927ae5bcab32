"""The trace of a run: what happened, when, and which script and line it came from.

Every script start and end, every command sent with its outcome, every event received and every
``print`` is one :class:`TraceEntry`. Times are whole milliseconds of the run's clock, and values
are quantised (whole mm, whole degrees) so a trace is byte-identical on any machine; the golden
tests diff :meth:`Trace.text`. :meth:`Trace.to_json` gives the same entries as data. An entry's
``text`` is for people (English); what it is — its record, packet, actuator group — is data, and
the child's view (:class:`ChildView`) reads that, in the languages it is handed.
"""

from __future__ import annotations

import json
from collections.abc import Callable, Iterable
from dataclasses import asdict, dataclass
from enum import Enum
from typing import Literal, NamedTuple

from rootlang import ast
from rootlang.runtime.stops import Failed, Record, RunEnded
from rootlang.wording.catalogue import message
from rootlang.wording.language import Languages

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
    part: bool = False  # a later command of the statement on its line (a `go to` as turn, move)
    record: Record | None = None  # a run's own entry as data (``text`` is its English)
    # what a command or event is, as data (``text`` is for people): the packet, the actuator
    # group of a command (commands of one group interrupt each other), and a reading a line
    # asked for (a Get)
    packet: str = ""
    group: str = ""
    reading: bool = False

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
        data["record"] = None if self.record is None else self.record.to_json()
        return data


class Trace:
    """An append-only list of entries, stamped with the clock's time; ``on_add`` (if given) sees
    each new entry as it is added (a live view of the run)."""

    def __init__(
        self, now: Callable[[], float], on_add: Callable[[TraceEntry], None] | None = None
    ) -> None:
        self._now = now
        self._on_add = on_add
        self._zero = 0.0
        self.entries: list[TraceEntry] = []

    def starts_at(self, seconds: float) -> None:
        """Count the run's time from ``seconds`` of the clock on: the program's start, once the
        robot is connected (a real robot's scan and connection are not the program's time)."""
        self._zero = seconds

    def now_ms(self) -> int:
        return round((self._now() - self._zero) * 1000)

    def add(
        self,
        kind: EntryKind,
        text: str,
        *,
        script: str = "",
        line: int = 0,
        outcome: Outcome | None = None,
        detail: str = "",
        part: bool = False,
        record: Record | None = None,
        packet: str = "",
        group: str = "",
        reading: bool = False,
    ) -> TraceEntry:
        entry = TraceEntry(
            self.now_ms(), kind, script, line, text, outcome, detail=detail, part=part,
            record=record, packet=packet, group=group, reading=reading,
        )  # fmt: skip
        self.entries.append(entry)
        if self._on_add is not None:
            self._on_add(entry)
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
    x, y, heading = quantised_pose(x_mm, y_mm, heading_degrees)
    return f"x {x} mm, y {y} mm, heading {heading}°"


def quantised_pose(x_mm: float, y_mm: float, heading_degrees: float) -> tuple[int, int, int]:
    """Whole millimetres, and whole degrees in [0, 360)."""
    return round(x_mm), round(y_mm), round(heading_degrees) % 360


# --- the child's view -------------------------------------------------------------------------

ViewKind = Literal["start", "command", "print", "error", "end", "repeat"]


class ViewLine(NamedTuple):
    """One line of the child's view: when, the program line behind it (0: none), what."""

    time_ms: int
    line: int
    text: str
    kind: ViewKind

    def render(self, languages: Languages) -> str:
        """The line as ``languages`` show it (the view's own words: "line 4")."""
        seconds = f"{self.time_ms / 1000:>6.1f} s"
        where = message("V007", {"line": f"{self.line:<3}" if self.line else "   "}, languages)
        if not self.line:
            where = " " * len(where)  # as wide as a line number: the texts stay in a column
        indent = "" if self.kind in ("start", "end", "repeat") else "    "
        return f"{seconds}  {where}  {indent}{self.text}".rstrip()


def in_program_words(text: str, language: str) -> str:
    """A command the trace records in English (``say "hi"``) with ``language``'s keywords."""
    if language == "en":
        return text
    from rootlang.locale.translate import from_english  # only for a program in another language

    return from_english(text, language)


class ChildView:
    """The run as a child reads it, built entry by entry (so it can be shown live).

    Shown: each script as it starts (its ``when`` line as written), the program's commands as
    written on their lines, what ``say`` and ``print`` said, errors and how the run ended, in
    seconds. Left out: events that started no script (sensor readings), the runtime's own
    commands (reading the final position, Stop and Reset) and readings a line asked for. The
    same line coming again and again at once (a loop with nothing else in it) is shown once and
    then counted. With the ``program``'s syntax tree, a line is shown in its canonical spelling
    (``play note A4 for 0.2 seconds`` for ``Play Note a4 For .2 Seconds  #beep``), else as the
    source has it. Its words are in the language ``languages`` show messages in, its lines with
    their program's keywords."""

    def __init__(self, source: str, program: ast.Program | None, languages: Languages) -> None:
        self._languages = languages
        self._source_lines = source.splitlines()
        canonical = {} if program is None else canonical_lines(program)
        keywords = languages.keywords
        self._canonical = {line: in_program_words(text, keywords)
                           for line, text in canonical.items()}  # fmt: skip
        self._last: ViewLine | None = None
        self._again = 0
        self._last_time_ms = 0
        self._running: list[TraceEntry] = []  # commands shown, still going when last seen
        self._commands: list[TraceEntry] = []  # the commands of the last moment, for "by"
        self._stalled_ms: int | None = None  # when the robot began pushing against something

    def add(self, entry: TraceEntry) -> list[ViewLine]:
        """The lines ready to show once ``entry`` has happened."""
        told = [*self._cut_short(entry.time_ms), *self._pushing(entry)]
        line = self.line_of(entry)
        shown = [line for item in told for line in self.show(item)]
        if line is not None and entry.kind == "command":
            self._running.append(entry)
        if entry.kind == "command" and not entry.part:
            self._commands = [*self._commands[-RECENT:], entry]
        return shown if line is None else [*shown, *self.show(line)]

    def _cut_short(self, now_ms: int | None) -> list[ViewLine]:
        """A command shown earlier that a newer one interrupted, once the view is past that
        moment: how long it ran, and which line cut it short ("line 4: move 50 cm — stopped
        after 0.6 s: line 13 started a new one")."""
        told = []
        for entry in self._running:
            if entry.end_ms is not None and now_ms is not None and entry.end_ms >= now_ms:
                continue  # not there yet (the trace of a finished run knows it from the start)
            if entry.outcome is Outcome.INTERRUPTED and entry.end_ms is not None:
                by = next((c.line for c in self._commands if c.time_ms == entry.end_ms
                           and c is not entry and c.group == entry.group), 0)  # fmt: skip
                seconds = _seconds(entry.end_ms - entry.time_ms)
                values = {"line": entry.line, "command": self._written(entry),
                          "seconds": seconds, "by": by}  # fmt: skip
                code = ("V092" if by else "V093") if seconds else ("V096" if by else "V097")
                text = message(code, values, self._languages)
                told.append(ViewLine(entry.end_ms, 0, text, "command"))
        self._running = [e for e in self._running if e.outcome in (None, Outcome.PENDING)
                         or (now_ms is not None and (e.end_ms or 0) >= now_ms)]  # fmt: skip
        return told

    def _pushing(self, entry: TraceEntry | None) -> list[ViewLine]:
        """The wheels stalled (the robot pushed against something) until it was told to move
        another way or the run ended: once, with how long."""
        if entry is not None and entry.kind == "event" and entry.packet == STALL:
            if self._stalled_ms is None:
                self._stalled_ms = entry.time_ms
            return []
        moving = (
            entry is None
            or entry.kind == "run"
            or (entry.kind == "command" and entry.group == "motion")
        )
        if self._stalled_ms is None or not moving:
            return []
        start, self._stalled_ms = self._stalled_ms, None
        end = self._last_time_ms if entry is None else entry.time_ms
        seconds = _seconds(end - start)
        told = message("V094" if seconds else "V095", {"seconds": seconds}, self._languages)
        return [ViewLine(start, 0, told, "command")]

    def show(self, line: ViewLine) -> list[ViewLine]:
        """The lines ready to show once ``line`` is to be shown: none while it repeats the last
        one (counted instead); the count of the repeats, if any, before a new one."""
        last = self._last
        if last is not None and (last.line, last.text, last.kind) == (
            line.line,
            line.text,
            line.kind,
        ):
            self._again += 1
            self._last_time_ms = line.time_ms
            return []
        ready = self._repeats()
        self._last, self._last_time_ms = line, line.time_ms
        return [*ready, line]

    def finish(self, end_ms: int | None = None) -> list[ViewLine]:
        """The lines still held back (a count of repeats, a push not told yet) once the run
        is over."""
        if end_ms is not None:
            self._last_time_ms = max(self._last_time_ms, end_ms)
        told = [line for item in [*self._cut_short(None), *self._pushing(None)]
                for line in self.show(item)]  # fmt: skip
        return [*told, *self._repeats()]

    def _repeats(self) -> list[ViewLine]:
        if not self._again:
            return []
        times, self._again = self._again, 0
        seconds = f"{self._last_time_ms / 1000:.1f}"
        values = {"times": times, "seconds": seconds}
        counted = message("V005" if times == 1 else "V006", values, self._languages)
        text = f"    {counted}"
        return [ViewLine(self._last_time_ms, 0, text, "repeat")]

    def line_of(self, entry: TraceEntry) -> ViewLine | None:
        """The view's line for one entry (before repeats are counted); None: not shown."""
        kind, time_ms, line = entry.kind, entry.time_ms, entry.line
        if kind == "start":
            return ViewLine(time_ms, line, self._written(entry), "start")
        if kind == "command":
            told = self._command_text(entry)
            return None if told is None else ViewLine(time_ms, line, told, "command")
        if kind == "print":
            printed = in_program_words(f"print {entry.text}", self._languages.keywords)
            return ViewLine(time_ms, line, printed, "print")
        if kind == "error":  # without the code: stderr shows it in full
            record = entry.record
            told = record.shown(self._languages) if isinstance(record, Failed) else entry.text
            return ViewLine(
                time_ms, line, f"{message('V008', {}, self._languages)} {told}", "error"
            )
        if isinstance(entry.record, RunEnded):
            return ViewLine(time_ms, 0, entry.record.shown(self._languages), "end")
        return None

    def _command_text(self, entry: TraceEntry) -> str | None:
        """What was said in the program's words, other commands as written on their line; None
        for the runtime's own commands, readings a line asked for and a statement's later
        commands (its line is shown once)."""
        if entry.script == "run" or entry.part or entry.reading:
            return None
        if entry.packet == SAY:
            return in_program_words(entry.text, self._languages.keywords)
        return self._written(entry)

    def _written(self, entry: TraceEntry) -> str:
        """The program's line as written (the trace's own text when there is no such line)."""
        if entry.line in self._canonical:
            return self._canonical[entry.line]
        if 0 < entry.line <= len(self._source_lines):
            written = self._source_lines[entry.line - 1].strip()
            if written:
                return written
        return entry.text


def _seconds(ms: int) -> str:
    """A time the view tells, in tenths of a second; "" when it is under a tenth (the view then
    says "at once", never "for 0.0 s": a stall handled at once is a bump, not a push)."""
    return f"{ms / 1000:.1f}" if ms >= 50 else ""


STALL = "motor_stall_event"  # the wheels stalled
SAY = "say_phrase"  # its text shows what was said, not the expression that made it
RECENT = 50  # commands remembered to find which line cut a command short


def canonical_lines(program: ast.Program) -> dict[int, str]:
    """Each line that starts a statement, script or procedure, in its canonical spelling."""
    from rootlang.formatting import line_text  # the printer of `rootlang format`

    lines: dict[int, str] = {}
    for item in program.items:
        for node in ast.walk(item):
            if isinstance(node, ast.Statement | ast.Script | ast.Procedure):
                lines.setdefault(node.span.line, line_text(node))
    return lines


def child_view(
    entries: Iterable[TraceEntry], source: str, program: ast.Program | None, languages: Languages
) -> list[ViewLine]:
    """The whole run's child view (see :class:`ChildView`), as ``languages`` show it."""
    view = ChildView(source, program, languages)
    lines = [line for entry in entries for line in view.add(entry)]
    return lines + view.finish()
