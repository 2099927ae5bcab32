"""Hints: what a run did differently from an adventure's goal, in a child's terms.

Both the goal (the golden file of the adventure's model solution) and the pupil's run are
golden texts, so both are read the same way into a :class:`Summary` of what a child can see
the robot do: the scripts its events started, the path it drove and the turns it made, the
sides of its drawing, the colours it lit, the notes it played and what it said. :func:`hint`
compares two summaries aspect by aspect, in the order a child would fix them, and tells the
first difference ("Your robot stopped 10 cm short.", "Your drawing has 3 sides, but the
goal's has 4."): what differs, never the program that would make it right. Only what the goal
does is asked of the run (a run may light up more colours than the goal does, not fewer).

:func:`missing_parts` is the other half: what an adventure asks a program to be made of
(``uses = ["procedure"]`` in its ``adventure.toml``), looked for in the pupil's syntax tree.
"""

from __future__ import annotations

import itertools
import math
import re
from collections.abc import Sequence
from dataclasses import dataclass

from rootlang import ast
from rootlang.diagnostics import Diagnostic, RootlangError, diagnostic
from rootlang.testing.golden import Ending
from rootlang.wording.shown import Code

DISTANCE_TOLERANCE_MM = 30.0  # as a task's own tolerance: a robot length is 150 mm
TURN_TOLERANCE_DEG = 15.0

# a trace line (TraceEntry.render): time, where (a script and its line, or `run`), kind, text
# (the first " @line" ends a script's name; a kind is padded to 7 letters, then a space)
_ENTRY = re.compile(
    r"\s*\d+ ms  (?:(?P<where>.*? @\d+|run) +| +)"
    r"(?P<kind>start  |end    |command|event  |print  |error  |run    ) (?P<text>.*)"
)
_REPEATED = re.compile(r"\s*\.\.\. (?:this line|these (\d+) lines) (\d+) more times")
_POSE = re.compile(r"\[x (-?\d+) mm, y (-?\d+) mm, heading (\d+)°\]")
_TURN = re.compile(r"turn (left|right) (\d+(?:\.\d+)?)°")
_LIGHT = re.compile(r"light (?:on|blink|spin) (\w+)")
_WHEN = re.compile(r"\d+:(when .*)")
_SAID = re.compile(r'say "(.*)"')


@dataclass(frozen=True)
class Step:
    """Where a move (or a turn) left the robot, and whether its marker drew on the way."""

    x: int
    y: int
    heading: int
    drawing: bool


@dataclass(frozen=True)
class Summary:
    """What a run did, as a child watching it would tell it."""

    events: tuple[str, ...]  # the `when` lines of the scripts that started (not `when started`)
    track: tuple[Step, ...]  # where it drove, from (0, 0) facing up: each move's end
    turns: tuple[float, ...]  # each turn, in degrees: left positive, right negative
    sides: int  # the straight lines of its drawing
    drew: bool
    lights: tuple[str, ...]  # the colours it lit, each once, in order
    notes: int
    said: tuple[str, ...]  # what it said and printed, in order

    @classmethod
    def of(cls, golden_text: str) -> Summary:
        entries = _entries(golden_text)
        events: list[str] = []
        track: list[Step] = []
        turns: list[float] = []
        lights: list[str] = []
        said: list[str] = []
        notes, pen = 0, False
        for where_from, kind, text in entries:
            if kind == "start":
                found = _WHEN.fullmatch(text)
                if found and found.group(1) != "when started" and found.group(1) not in events:
                    events.append(found.group(1))
            if kind == "print":
                said.append(text.strip().strip('"'))
            if kind != "command" or where_from == "run":
                continue
            pose, turn, light = _POSE.search(text), _TURN.match(text), _LIGHT.match(text)
            if pose:
                track.append(Step(int(pose.group(1)), int(pose.group(2)), int(pose.group(3)), pen))
            if text.startswith("marker "):
                pen = text.startswith("marker down")
            if turn:
                turns.append(float(turn.group(2)) * (1 if turn.group(1) == "left" else -1))
            if light and light.group(1) not in lights:
                lights.append(light.group(1))
            if text.startswith("play ") and " Hz for " in text:
                notes += 1
            spoken = _SAID.match(text.split(" -> ")[0])
            if spoken:
                said.append(spoken.group(1))
        ending = Ending.read(golden_text)
        sides = _distinct([side for stroke in ending.strokes for side in _straight(stroke)])
        return cls(tuple(events), tuple(track), tuple(turns), len(sides), bool(ending.strokes),
                   tuple(lights), notes, tuple(said))  # fmt: skip

    @property
    def path_mm(self) -> float:
        """How far the robot drove, all its moves together."""
        points = [(0, 0)] + [(step.x, step.y) for step in self.track]
        return sum(math.dist(a, b) for a, b in itertools.pairwise(points))


def _entries(golden_text: str) -> list[tuple[str, str, str]]:
    """The trace's entries as (where, kind, text), its repeats written out again."""
    entries: list[tuple[str, str, str]] = []
    in_trace = False
    for line in golden_text.splitlines():
        if line == "trace:":
            in_trace = True
            continue
        if not in_trace:
            continue
        if not line.strip():
            break
        repeated = _REPEATED.match(line)
        if repeated:
            length, times = int(repeated.group(1) or 1), int(repeated.group(2))
            entries += entries[-length:] * times
            continue
        found = _ENTRY.fullmatch(line)
        if found:
            where = (found["where"] or "").rsplit(" @", 1)[0]
            entries.append((where, found["kind"].rstrip(), found["text"]))
    return entries


Point = tuple[int, int]


def _straight(stroke: Sequence[Point]) -> list[tuple[Point, Point]]:
    """A stroke's straight sides: its segments, those going on in the same direction joined."""
    sides: list[tuple[Point, Point]] = []
    for a, b in itertools.pairwise(stroke):
        if a == b:
            continue
        if sides:
            start, end = sides[-1]
            if end == a and _same_direction(start, a, b):
                sides[-1] = (start, b)
                continue
        sides.append((a, b))
    return sides


def _distinct(sides: list[tuple[Point, Point]]) -> list[tuple[Point, Point]]:
    """The sides, one drawn again over another (a square drawn round twice) counted once."""
    kept: list[tuple[Point, Point]] = []
    for side in sides:
        if not any(_same_side(side, other) for other in kept):
            kept.append(side)
    return kept


def _same_side(one: tuple[Point, Point], other: tuple[Point, Point]) -> bool:
    """Whether two sides join the same two points (within the tolerance), either way round."""
    (a, b), (c, d) = one, other
    near = DISTANCE_TOLERANCE_MM
    forth = math.dist(a, c) <= near and math.dist(b, d) <= near
    return forth or (math.dist(a, d) <= near and math.dist(b, c) <= near)


def _same_direction(a: Point, b: Point, c: Point) -> bool:
    first = math.atan2(b[1] - a[1], b[0] - a[0])
    second = math.atan2(c[1] - b[1], c[0] - b[0])
    return abs((math.degrees(second - first) + 180) % 360 - 180) < TURN_TOLERANCE_DEG


def hint(goal: Summary, run: Summary) -> Diagnostic | None:
    """The first way ``run`` differs from ``goal`` a child can see, as a message; None when
    it does all the goal does."""
    for compare in (_events, _drawing, _turns, _path, _lights, _notes, _said):
        told = compare(goal, run)
        if told is not None:
            return told
    return None


def _events(goal: Summary, run: Summary) -> Diagnostic | None:
    for event in goal.events:
        if event not in run.events:
            message = re.fullmatch(r'when message "(.*)" received', event)
            if message:
                return diagnostic("V302", name=message.group(1))
            return diagnostic("V300", event=Code(event))
    return None


def _drawing(goal: Summary, run: Summary) -> Diagnostic | None:
    if goal.drew and not run.drew:
        return diagnostic("V051")
    if goal.drew and run.sides != goal.sides:
        return diagnostic("V303", count=run.sides, goal=goal.sides)
    return None


def _turns(goal: Summary, run: Summary) -> Diagnostic | None:
    if goal.turns and not run.turns:
        return diagnostic("V301")
    if len(run.turns) != len(goal.turns):
        return diagnostic("V304", count=len(run.turns), goal=len(goal.turns))
    for number, (want, got) in enumerate(zip(goal.turns, run.turns, strict=True), start=1):
        if (want > 0) != (got > 0):
            return diagnostic("V305" if got > 0 else "V306", number=number)
        if abs(got) < abs(want) - TURN_TOLERANCE_DEG:
            return diagnostic("V307", number=number)
        if abs(got) > abs(want) + TURN_TOLERANCE_DEG:
            return diagnostic("V308", number=number)
    return None


def _path(goal: Summary, run: Summary) -> Diagnostic | None:
    short = goal.path_mm - run.path_mm
    if short > DISTANCE_TOLERANCE_MM:
        return diagnostic("V309", distance=_length(short))
    if -short > DISTANCE_TOLERANCE_MM:
        return diagnostic("V310", distance=_length(-short))
    return None


def _lights(goal: Summary, run: Summary) -> Diagnostic | None:
    for colour in goal.lights:
        if colour not in run.lights:
            other = next((c for c in run.lights if c not in goal.lights), None)
            if other is not None:
                return diagnostic("V312", colour=_colour(other), goal=_colour(colour))
            return diagnostic("V311", colour=_colour(colour))
    return None


def _notes(goal: Summary, run: Summary) -> Diagnostic | None:
    if run.notes != goal.notes:
        return diagnostic("V313", count=run.notes, goal=goal.notes)
    return None


def _said(goal: Summary, run: Summary) -> Diagnostic | None:
    if len(run.said) != len(goal.said):
        return diagnostic("V314", count=len(run.said), goal=len(goal.said))
    for number, (want, got) in enumerate(zip(goal.said, run.said, strict=True), start=1):
        if want != got:
            return diagnostic("V315", number=number, said=got)
    return None


def _colour(name: str) -> Code:
    return Code(name, quoted=False)


def _length(mm: float) -> str:
    return f"{round(mm / 10)} cm"


# --- what a program is made of ----------------------------------------------------------------

PARTS = {
    "procedure": "V316",  # a block of its own: `to ...`, and used
    "variable": "V317",  # `set ... to ...`
    "repeat": "V318",  # a loop
    "message": "V319",  # `send ...`
}


def missing_parts(text: str, uses: Sequence[str]) -> Diagnostic | None:
    """The first part of ``uses`` (keys of :data:`PARTS`) the program has none of, as a
    message; None when it has them all (or does not read: its mistakes are said first)."""
    from rootlang.checks import parse

    try:
        program = parse(text)
    except RootlangError:
        return None
    kinds = {type(node) for item in program.items for node in ast.walk(item)}
    has = {
        "procedure": bool(program.procedures) and ast.CallProcedure in kinds,
        "variable": ast.SetVariable in kinds or ast.ChangeVariable in kinds,
        "repeat": bool(kinds & {ast.Repeat, ast.Forever, ast.RepeatUntil, ast.While}),
        "message": ast.Send in kinds,
    }
    for part in uses:
        if not has.get(part, True):
            return diagnostic(PARTS[part])
    return None
