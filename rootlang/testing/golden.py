"""The golden file format: what a program did, as plain text that diffs well.

A program ``spiral.root`` keeps its expected output next to it in ``spiral.golden``. For a program
that passes ``rootlang check`` the file has these sections, each a few readable lines::

    end: finished at 8.431 s
    warnings: ...                       (only when the checks warn)

    trace:
           0 ms  when started @2     start   ...
    ...

    robot at the end: x 1000 mm, y 1200 mm, heading 90°

    drawing: 1 stroke
      marker #000000 2 mm from 120 ms:
        (1000,1000) (1000,1100) (1100,1100)

For a program that does not pass its checks (the ``programs/mistakes/`` set) the golden file is
exactly what ``rootlang check`` prints for it.

Everything is quantised (whole milliseconds, millimetres and degrees), so a golden file is the same
on every machine. Strokes are simplified to the corners a person would see (points that lie
within :data:`STROKE_TOLERANCE_MM` of the line through their neighbours are dropped).

Each line of golden text remembers the program line that produced it (0 for none), so a mismatch
can point at the program line behind the first difference.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence, Set
from dataclasses import dataclass, field

from rootlang.runtime.trace import TraceEntry, pose_text, quantised_pose
from rootlang.sim.recording import IntPoint, Recording, Stroke

STROKE_TOLERANCE_MM = 2.0
POINTS_PER_LINE = 8


@dataclass
class GoldenText:
    """Golden text being built: its lines, and for each the program line behind it (or 0)."""

    lines: list[str] = field(default_factory=list)
    source_lines: list[int] = field(default_factory=list)

    def add(self, text: str, source_line: int = 0) -> None:
        """Add one or more lines (split at newlines; a trailing newline adds a blank line)."""
        for line in text.split("\n"):
            self.lines.append(line.rstrip())
            self.source_lines.append(source_line)

    def blank(self) -> None:
        self.add("")

    @property
    def text(self) -> str:
        return "\n".join(self.lines) + "\n"


def end_line(end: str, sim_time_s: float, error: str | None) -> str:
    """``end: finished at 8.431 s`` (and the error's text on the lines after, when there is one)."""
    words = {"finished": "finished", "stopped": "stopped", "time_limit": "reached the time limit",
             "error": "stopped by an error"}  # fmt: skip
    line = f"end: {words.get(end, end)} at {sim_time_s:.3f} s"
    return line + ("\n" + error if error else "")


def add_trace(golden: GoldenText, entries: Iterable[TraceEntry], listened: Set[str]) -> None:
    """The run's trace, with only the events of the packets in ``listened``.

    A tight loop (a line follower setting its wheels thousands of times) would fill thousands of
    lines, so a block of up to :data:`LONGEST_REPEAT` entries that comes again and again, the same
    but for its times, is written once and then counted."""
    golden.add("trace:")
    kept = [
        entry for entry in entries
        if entry.kind != "event" or entry.packet in listened
    ]  # fmt: skip
    keys = [_repeat_key(entry) for entry in kept]
    index = 0
    while index < len(kept):
        length, times = _repeats(keys, index)
        for entry in kept[index : index + length]:
            golden.add(entry.render(), entry.line)
        if times > 1:
            last = kept[index + length * times - 1]
            what = "this line" if length == 1 else f"these {length} lines"
            golden.add(
                f"{'':10}... {what} {times - 1} more times, until {last.time_ms} ms",
                kept[index].line,
            )
        index += length * times


LONGEST_REPEAT = 8
FEWEST_REPEATS = 3


def _repeat_key(entry: TraceEntry) -> tuple[object, ...]:
    duration = None if entry.end_ms is None else entry.end_ms - entry.time_ms
    return (entry.kind, entry.script, entry.line, entry.text, entry.outcome, entry.detail, duration)


def _repeats(keys: Sequence[tuple[object, ...]], start: int) -> tuple[int, int]:
    """The shortest block at ``start`` that comes at least FEWEST_REPEATS times in a row, and
    how many times it comes; (1, 1) when none does."""
    for length in range(1, LONGEST_REPEAT + 1):
        block = keys[start : start + length]
        if len(block) < length:
            break
        times = 1
        while keys[start + times * length : start + (times + 1) * length] == block:
            times += 1
        if times >= FEWEST_REPEATS:
            return length, times
    return 1, 1


Pose = tuple[int, int, int]  # x mm, y mm, heading degrees


@dataclass(frozen=True)
class Ending:
    """Where a run left the robot and what its marker drew, quantised as its golden text says
    it: what a task compares (:mod:`rootlang.testing.tasks`)."""

    pose: Pose | None
    strokes: tuple[tuple[IntPoint, ...], ...]  # the marker's, simplified

    @classmethod
    def of(cls, recording: Recording) -> Ending:
        frame = recording.final_frame
        pose = None if frame is None else quantised_pose(frame.x_mm, frame.y_mm, frame.heading_deg)
        marked = tuple(
            tuple(points) for stroke, points in _drawn(recording) if stroke.kind == "marker"
        )
        return cls(pose, marked)

    @classmethod
    def read(cls, golden_text: str) -> Ending:
        """The ending a golden file tells: a task's target is the golden file of the teacher's
        own solution, and that file is all a task keeps of it (a test reads back the text
        :func:`add_recording` writes and gets :meth:`of` the recording)."""
        pose = None
        strokes: list[tuple[IntPoint, ...]] = []
        marker = False
        for line in golden_text.splitlines():
            found = _POSE.fullmatch(line)
            if found:
                x, y, heading = (int(part) for part in found.groups())
                pose = (x, y, heading)
            elif _STROKE.match(line):
                marker = line.startswith("  marker")
                if marker:
                    strokes.append(())
            elif line.startswith("    (") and marker and strokes:
                strokes[-1] += tuple((int(x), int(y)) for x, y in _POINT.findall(line))
        return cls(pose, tuple(strokes))


_POSE_LINE = "robot at the end, in the world: "
_POSE = re.compile(_POSE_LINE + r"x (-?\d+) mm, y (-?\d+) mm, heading (\d+)°")
_POINT = re.compile(r"\((-?\d+),(-?\d+)\)")
_STROKE = re.compile(r"  (marker|eraser) ")


def _drawn(recording: Recording) -> list[tuple[Stroke, list[IntPoint]]]:
    """Each stroke of more than one point, with its points simplified."""
    return [(stroke, simplify(stroke.points, STROKE_TOLERANCE_MM))
            for stroke in recording.strokes if len(stroke.points) > 1]  # fmt: skip


def add_recording(golden: GoldenText, recording: Recording) -> None:
    """The robot's final pose and its drawing (marker and eraser strokes, simplified)."""
    frame = recording.final_frame
    if frame is not None:
        pose = pose_text(frame.x_mm, frame.y_mm, frame.heading_deg)
        golden.add(_POSE_LINE + pose)
    strokes = _drawn(recording)
    if not strokes:
        golden.add("drawing: nothing")
        return
    golden.add(f"drawing: {len(strokes)} stroke{'s' if len(strokes) != 1 else ''}")
    for stroke, points in strokes:
        golden.add(stroke_heading(stroke))
        for start in range(0, len(points), POINTS_PER_LINE):
            chunk = points[start : start + POINTS_PER_LINE]
            golden.add("    " + " ".join(f"({x},{y})" for x, y in chunk))


def stroke_heading(stroke: Stroke) -> str:
    return f"  {stroke.kind} {stroke.color} {stroke.width_mm} mm from {stroke.t_ms} ms:"


def simplify(points: Sequence[IntPoint], tolerance: float) -> list[IntPoint]:
    """Ramer-Douglas-Peucker on whole-millimetre points: the corners, without the points
    that lie on (within ``tolerance`` of) the straight line between them. Exact integer input
    and a fixed order of work make the result the same everywhere."""
    unique = [p for i, p in enumerate(points) if i == 0 or p != points[i - 1]]
    if len(unique) < 3:
        return unique
    keep = [False] * len(unique)
    keep[0] = keep[-1] = True
    pending = [(0, len(unique) - 1)]
    while pending:
        first, last = pending.pop()
        farthest, distance = _farthest(unique, first, last)
        if farthest and distance > tolerance:
            keep[farthest] = True
            pending.extend([(first, farthest), (farthest, last)])
    return [point for point, kept in zip(unique, keep, strict=True) if kept]


def _farthest(points: Sequence[IntPoint], first: int, last: int) -> tuple[int, float]:
    (ax, ay), (bx, by) = points[first], points[last]
    dx, dy = bx - ax, by - ay
    length = (dx * dx + dy * dy) ** 0.5
    best, best_distance = 0, -1.0
    for index in range(first + 1, last):
        px, py = points[index]
        if length == 0:
            distance = ((px - ax) ** 2 + (py - ay) ** 2) ** 0.5
        else:
            distance = abs(dy * (px - ax) - dx * (py - ay)) / length
        if distance > best_distance:
            best, best_distance = index, distance
    return best, best_distance
