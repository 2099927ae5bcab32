"""Seeing inside a run: pause, resume and step it, stop at a line, and watch its values.

A :class:`Debugger` handed to :func:`~rootlang.runtime.scheduler.run_program` is told as each
statement of any script begins (the interpreter's ``on_statement``). It pauses the run there when
a step, a breakpoint (a source line) or a pause asked for says so, or at a time of the run
(``pause_at``, a timer on the run's own clock). Pausing is a call: ``on_pause`` is handed a
:class:`Pause` (where every script is, and a :class:`Watch` of the values) and answers how to
go on (:class:`Go`). Nothing runs while it is being answered, not even the clock's timers, so
a paused run goes on exactly as if it never paused: the same trace, drawing and end
(tests/runtime/test_debugger.py holds every gallery program to that). A step runs on until the
next statement of any script begins, in the scheduler's own order, so two scripts take turns;
a motion in progress meanwhile carries on as it physically would, on the run's clock.

On a robot the run's loop must go on while paused (the robot's link), so a pause is answered
later instead (``on_hold``): each script waits at the next statement it begins until then.

The debugger only reads the run: it sends no packet and evaluates nothing (docs/runtime.md,
"Pausing and stepping").
"""

from __future__ import annotations

import asyncio
import enum
from collections.abc import Awaitable, Callable, Collection, Iterator, Sequence
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Literal, Protocol, TypedDict

from rootlang import ast, forms
from rootlang.locale.translate import lines_in_english
from rootlang.protocol import PACKETS
from rootlang.protocol.behaviour import NOTE
from rootlang.protocol.enums import BumperState, TouchSensors
from rootlang.runtime.budget import UNLIMITED
from rootlang.runtime.client import Pose, SensorState
from rootlang.runtime.interpreter import Frame
from rootlang.runtime.scheduler import Scheduler, SentMessage, color_letters
from rootlang.runtime.stops import StoppedBy, StopReason
from rootlang.runtime.trace import Outcome, ViewLine
from rootlang.units import Value, show
from rootlang.wording.catalogue import message
from rootlang.wording.language import Languages
from rootlang.wording.shown import unquoted

if TYPE_CHECKING:
    from rootlang.runtime.interpreter import _Running

SOUND_PACKETS = frozenset(packet.name for packet in PACKETS if packet.behaviour == NOTE)
# each bumper and touch sensor by the bit the robot sends for it, as programs name it
BUMPER_WORDS = {
    BumperState[forms.BUMPER_SIDE.meaning(side)[0][0]]: side for side in forms.BUMPER_SIDE_NAMES
}
TOUCH_WORDS = {
    TouchSensors[forms.TOUCH_SENSOR.meaning(sensor)[0]]: sensor
    for sensor in forms.TOUCH_SENSOR_NAMES
}


class Go(enum.Enum):
    """How a paused run goes on."""

    RESUME = "resume"  # until a breakpoint, or a pause asked for
    STEP = "step"  # until the next statement of any script begins
    STOP = "stop"  # the run ends here


PauseReason = Literal["step", "breakpoint", "pause", "time"]
PlaceState = Literal["next", "starting", "running", "waiting", "finished"]


@dataclass(frozen=True)
class Place:
    """Where one script is: about to run a statement (``next``), started and soon to run its
    first (``starting``), inside one (``running``: waiting for it to end), not running
    (``waiting`` for its event) or ``finished``."""

    script: str  # its label, "2:when bumped"
    state: PlaceState
    statement: ast.Statement | None = None
    command: str = ""  # the statement's line, its keywords in English

    @property
    def name(self) -> str:
        """The script's header, in English: ``when bumped``."""
        return _name(self.script)

    @property
    def line(self) -> int:
        return 0 if self.statement is None else self.statement.span.line

    def words(self, languages: Languages) -> str:
        """Where the script is, said in ``languages``: "when bumped: waiting for `turn right
        90 degrees` to end (line 6)"."""
        values = {
            "script": unquoted(self.name),
            "command": unquoted(self.command),
            "line": self.line,
        }
        code = {"next": "V200", "starting": "V220", "running": "V201", "waiting": "V202",
                "finished": "V203"}  # fmt: skip
        return message(code[self.state], values, languages)

    def to_json(self) -> dict[str, object]:
        span = None if self.statement is None else self.statement.span
        return {
            "script": self.script,
            "state": self.state,
            "line": self.line,
            "span": None
            if span is None
            else [span.line, span.column, span.end_line, span.end_column],
        }


@dataclass(frozen=True)
class Named:
    """A variable (``script`` "" for a shared one) or a parameter, and its value (put in
    words only when shown: a run's recording keeps many)."""

    name: str
    value: Value
    script: str = ""

    @property
    def shown(self) -> str:
        return watched(self.value)

    def to_json(self) -> dict[str, str]:
        return {"name": self.name, "value": self.shown, "script": self.script}


@dataclass(frozen=True)
class Call:
    """A procedure call under way in a script, and its parameters' values now."""

    script: str
    procedure: str
    parameters: tuple[Named, ...]


@dataclass(frozen=True)
class LoopRound:
    """A loop running in a script: which round (of how many, for ``repeat``; else 0)."""

    script: str
    line: int
    round: int
    count: int = 0


@dataclass(frozen=True)
class Watch:
    """The values of a run at one moment: variables, parameters, loops, sensors, messages."""

    time_s: float
    variables: tuple[Named, ...]
    calls: tuple[Call, ...]
    loops: tuple[LoopRound, ...]
    bumpers: tuple[str, ...]
    touched: tuple[str, ...]
    colors: str  # one letter a sensor, left to right (as the trace writes them)
    light_percent: tuple[float, float]
    pose: Pose
    messages: tuple[SentMessage, ...]  # as they were at that moment
    note: str  # the note playing now ("" for none), as the trace writes it

    def lines(self, languages: Languages) -> list[str]:
        """The values in ``languages``' words, one a line (``rootlang sim --until``): the
        program's values, the robot's readings, the messages, the note."""
        return [
            *self.value_lines(languages),
            *self.reading_lines(languages),
            pose_words(self.pose, languages),
            *self.message_lines(languages),
            *self.note_lines(languages),
        ]

    def value_lines(self, languages: Languages) -> list[str]:
        """The variables, the calls' parameters and the loops' rounds."""
        said: list[str] = []
        for named in self.variables:
            script = unquoted(_name(named.script))
            values = {"name": named.name, "value": named.shown, "script": script}
            said.append(message("V207" if named.script else "V219", values, languages))
        for call in self.calls:
            parameters = ", ".join(f"{p.name} = {p.shown}" for p in call.parameters)
            values = {"procedure": call.procedure, "parameters": parameters}
            said.append(message("V208", values, languages))
        for loop in self.loops:
            counted = {"line": loop.line, "round": loop.round, "count": loop.count}
            said.append(message("V209" if loop.count else "V210", counted, languages))
        return said

    def reading_lines(self, languages: Languages) -> list[str]:
        """The bumpers, the touch sensors, the colours under the sensors and the light."""
        said: list[str] = []
        none = message("V218", {}, languages)
        for code, pressed in (("V211", self.bumpers), ("V212", self.touched)):
            said.append(message(code, {"keyword": unquoted(", ".join(pressed)) or none}, languages))
        said.append(message("V213", {"colors": self.colors}, languages))
        left, right = (f"{percent:g}" for percent in self.light_percent)
        said.append(message("V214", {"left": left, "right": right}, languages))
        return said

    def message_lines(self, languages: Languages) -> list[str]:
        """The messages sent, and whether their senders wait for them still."""
        return [
            message("V216" if sent.waiting else "V215",
                    {"message": sent.message, "script": unquoted(_name(sent.by))}, languages)
            for sent in self.messages
        ]  # fmt: skip

    def note_lines(self, languages: Languages) -> list[str]:
        """The note playing, if one is."""
        return [note_words(self.note, languages)] if self.note else []

    def to_json(self) -> dict[str, object]:
        return {
            "time_s": round(self.time_s, 3),
            "variables": [named.to_json() for named in self.variables],
            "calls": [
                {
                    "script": c.script,
                    "procedure": c.procedure,
                    "parameters": [p.to_json() for p in c.parameters],
                }
                for c in self.calls
            ],
            "loops": [vars(loop) for loop in self.loops],
            "bumpers": list(self.bumpers),
            "touched": list(self.touched),
            "colors": self.colors,
            "light_percent": list(self.light_percent),
            "pose": {
                "x_mm": round(self.pose.x_mm, 1),
                "y_mm": round(self.pose.y_mm, 1),
                "heading_degrees": round(self.pose.heading_degrees, 1),
            },
            "messages": [vars(sent) for sent in self.messages],
            "note": self.note,
        }


def note_words(note: str, languages: Languages) -> str:
    """The note playing, as the trace writes it, in words: "the robot plays ..."."""
    return message("V217", {"note": note}, languages)


def pose_words(pose: Pose, languages: Languages) -> str:
    """Where the robot is, in cm and whole degrees: "the robot is at x 12.5 cm, y 30 cm ..."."""
    values = {
        "x": f"{round(pose.x_mm / 10, 1):g}",
        "y": f"{round(pose.y_mm / 10, 1):g}",
        "heading": f"{round(pose.heading_degrees) % 360}",
    }
    return message("V205", values, languages)


@dataclass(frozen=True)
class Pause:
    """A paused run: why, where every script is (in the scheduler's order), and its values."""

    reason: PauseReason
    places: tuple[Place, ...]
    watch: Watch

    def lines(self, languages: Languages) -> list[str]:
        """When, every script's place, then the values, in ``languages``' words."""
        when = message("V204", {"seconds": f"{self.watch.time_s:.1f}"}, languages)
        places = [place.words(languages) for place in self.places]
        return [when, *places, *self.watch.lines(languages)]

    def to_json(self, languages: Languages) -> dict[str, object]:
        """The pause as data, each place and the values also in words (for a page)."""
        places = [{**place.to_json(), "words": place.words(languages)} for place in self.places]
        return {
            "reason": self.reason,
            "places": places,
            "watch": self.watch.to_json(),
            "lines": self.watch.lines(languages),
        }


@dataclass
class _Rounds:
    """A loop's rounds as seen so far (the interpreter counts only ``repeat``'s, downwards)."""

    running: _Running
    started: float
    seen: int = 1
    count: int = 0


@dataclass
class _Level:
    """A script's statement at one depth of value calls (each has its own block stack), and
    the rounds of the loops on that stack (by the id of their running block)."""

    statement: ast.Statement
    frame: Frame
    stack: Sequence[_Running]
    rounds: dict[int, _Rounds] = field(default_factory=dict)


OnPause = Callable[[Pause], Go]
OnHold = Callable[[Pause], "asyncio.Future[Go]"]


class Recorder(Protocol):
    """Keeps a run's moments to go back to (:class:`rootlang.runtime.timeline.Timeline`)."""

    def attach(self, debugger: Debugger, scheduler: Scheduler) -> None: ...

    def begins(self) -> None: ...


@dataclass
class Debugger:
    """Pauses a run where asked and says where its scripts are and what its values are.

    ``on_pause`` answers each pause (None: go on at once); ``breakpoints`` are source lines;
    ``step`` pauses at the first statement; ``pause_at`` pauses once at that time of the run
    (seconds, as ``timer`` counts them); ``pose`` tells where the robot is (default: where it
    last said it was).

    ``on_hold`` instead answers each pause later, while the run's loop goes on (a run on a
    robot, whose link must: :mod:`rootlang.studio.debugging`): it is handed the pause and gives
    a future of the answer; meanwhile each script waits at the next statement it begins."""

    on_pause: OnPause | None = None
    on_hold: OnHold | None = None
    hold_time: Callable[[], None] | None = None  # stops the run's time as a held pause begins
    breakpoints: Collection[int] = ()
    step: bool = False
    pause_at: float | None = None
    pose: Callable[[], Pose] | None = None
    pauses: int = 0
    _scheduler: Scheduler | None = None
    watching: NameWatch | None = None
    recorder: Recorder | None = None  # told as each statement begins, before any pause
    _levels: dict[str, list[_Level]] = field(default_factory=dict)
    last: ast.Statement | None = None  # the statement begun last, in any script
    _pause_asked: bool = False
    _english: dict[int, str] | None = None
    _held: asyncio.Future[Go] | None = None  # a pause answered later (``on_hold``)
    _held_next: str = ""  # the script that held pause stopped at (it goes on first)
    _at_hold: set[str] = field(default_factory=set)  # scripts waiting at their next statement

    def attach(self, scheduler: Scheduler) -> None:
        """Watch ``scheduler``'s run (``run_program`` calls this, on the run's loop)."""
        self._scheduler = scheduler
        scheduler.interpreter.on_statement = self._begins
        if self.recorder is not None:
            self.recorder.attach(self, scheduler)
        if self.pause_at is not None:
            self._pause_later(self.pause_at)

    def pause_soon(self) -> None:
        """Pause as the next statement of any script begins."""
        self._pause_asked = True

    def pause_now(self, reason: PauseReason = "pause") -> None:
        """Pause here (on the run's loop, between its callbacks: a page's Pause); before the
        run has started, at its first statement."""
        scheduler = self._scheduler
        if scheduler is None or not scheduler.started:
            self.pause_soon()
        elif not scheduler.ending and self._held is None:
            self._stop_here(reason, "")

    @property
    def scheduler(self) -> Scheduler | None:
        """The run looked into (once attached)."""
        return self._scheduler

    @property
    def ending(self) -> bool:
        """Whether the run is being stopped (or has been)."""
        return self._scheduler is not None and self._scheduler.ending

    def live(self, languages: Languages) -> dict[str, object] | None:
        """Where the scripts are and the values now, as a page shows them while the run goes
        on (None before it has started, or once it is ending)."""
        scheduler = self._scheduler
        if scheduler is None or not scheduler.started or scheduler.ending:
            return None
        data = self.paused().to_json(languages)
        del data["reason"]
        return data

    # ---- being told -------------------------------------------------------------------------

    def _begins(
        self, statement: ast.Statement, frame: Frame, stack: Sequence[_Running]
    ) -> Awaitable[None] | None:
        if self.watching is not None:
            self.watching.look(self)
        levels = self._levels.setdefault(frame.script, [])
        depth = self._depth_of(stack, levels)
        before = levels[depth].rounds if depth < len(levels) else {}
        del levels[depth:]
        levels.append(_Level(statement, frame, stack, _count_rounds(stack, before)))
        self.last = statement
        if self.recorder is not None:
            self.recorder.begins()
        return self._at_statement(statement.span.line, frame.script)

    def _at_statement(self, line: int, script: str) -> Awaitable[None] | None:
        """Pause here if a step, a breakpoint or a pause asked for says so: answered at once
        (None: go on), or later (``on_hold``: what to await before the statement runs)."""
        if self._held is not None:
            return self._wait_held(line, script)
        reason: PauseReason | None = None
        if line in self.breakpoints:
            reason = "breakpoint"
        elif self.step:
            reason = "step"
        elif self._pause_asked:
            reason = "pause"
        if reason is None:
            return None
        if self._stop_here(reason, script) is Go.STOP:
            raise asyncio.CancelledError  # (the scheduler has cancelled this script too)
        return None if self._held is None else self._wait_held(line, script)

    async def _wait_held(self, line: int, script: str) -> None:
        """A script at the beginning of a statement while a held pause lasts: it waits for the
        answer. The script paused at then goes on; any other one is at its next statement
        only now, so a step or a breakpoint there pauses it (two scripts take turns)."""
        held = self._held
        assert held is not None
        self._at_hold.add(script)
        try:
            go = await asyncio.shield(held)
        finally:
            self._at_hold.discard(script)
        if go is Go.STOP:
            raise asyncio.CancelledError
        if script != self._held_next or self._held is not None:
            again = self._at_statement(line, script)
            if again is not None:
                await again

    @staticmethod
    def _depth_of(stack: Sequence[_Running], levels: list[_Level]) -> int:
        """The level ``stack`` is: one seen is the same; a new one (a procedure called for
        its value) goes under the levels whose calls are shallower than its own."""
        for depth, level in enumerate(levels):
            if level.stack is stack:
                return depth
        call_depth = stack[0].frame.depth
        depth = 0
        while depth < len(levels) and _calls_shallower(levels[depth].stack, call_depth):
            depth += 1
        return depth

    def _pause_later(self, seconds: float) -> None:
        """A timer on the run's clock for ``seconds`` of the run (counted from its start, which
        comes after connecting: the timer looks again when it fires early)."""
        scheduler = self._scheduler
        assert scheduler is not None
        left = seconds - (scheduler.elapsed() if scheduler.started else 0.0)

        def due() -> None:
            if scheduler.ending:
                return
            if not scheduler.started or scheduler.elapsed() < seconds - 1e-9:
                self._pause_later(seconds)
                return
            self._stop_here("time", "")

        scheduler.clock.call_later(max(left, 0.0), due)

    def _stop_here(self, reason: PauseReason, next_script: str) -> Go | None:
        """Pause: answered now (:meth:`_pause`), or held until answered (None)."""
        if self.on_hold is None:
            return self._pause(reason, next_script)
        self._pause_asked = False
        self.pauses += 1
        self._held_next = next_script
        if self.hold_time is not None:  # (first: the pause is said at the time it holds)
            self.hold_time()
        held = self._held = self.on_hold(self.paused(reason, next_script))
        held.add_done_callback(self._answered)  # (first: before any script wakes)
        return None

    def _answered(self, held: asyncio.Future[Go]) -> None:
        """A held pause's answer: how the run goes on."""
        if self._held is held:
            self._held = None
        go = Go.RESUME if held.cancelled() else held.result()
        self.step = go is Go.STEP
        scheduler = self._scheduler
        if go is Go.STOP and scheduler is not None:
            scheduler.request_stop("stopped", StoppedBy(StopReason.STOP_BUTTON))

    def _pause(self, reason: PauseReason, next_script: str) -> Go:
        self._pause_asked = False
        self.pauses += 1
        go = Go.RESUME
        if self.on_pause is not None:
            pause = self.paused(reason, next_script)
            budget = UNLIMITED if self._scheduler is None else self._scheduler.budget
            with budget.set_aside():  # (the child looking is not the program computing)
                go = self.on_pause(pause)
        self.step = go is Go.STEP
        if go is Go.STOP:
            scheduler = self._scheduler
            assert scheduler is not None
            if reason == "time":
                by = StoppedBy(StopReason.TIME_LIMIT, seconds=scheduler.elapsed())
                scheduler.request_stop("time_limit", by)
            else:
                scheduler.request_stop("stopped", StoppedBy(StopReason.STOP_BUTTON))
        return go

    # ---- telling ----------------------------------------------------------------------------

    def paused(self, reason: PauseReason = "pause", next_script: str = "") -> Pause:
        """Where the run is now (``next_script`` is about to begin its statement)."""
        return Pause(reason, tuple(self.places(next_script)), self.watch())

    def places(self, next_script: str = "") -> Iterator[Place]:
        scheduler = self._scheduler
        assert scheduler is not None
        for run in scheduler.runs:
            levels = self._levels.get(run.label)
            if not run.active:
                event = run.script.event
                ran = levels is not None
                done = ran and isinstance(event, ast.Started | ast.Stopped)
                yield Place(run.label, "finished" if done else "waiting")
            elif not levels:  # started, its first statement not yet begun
                first = run.script.body[0]
                yield Place(run.label, "starting", first, self._english_line(first))
            else:
                statement = levels[-1].statement
                about_to = run.label == next_script or run.label in self._at_hold
                state: PlaceState = "next" if about_to else "running"
                yield Place(run.label, state, statement, self._english_line(statement))

    def watch(self) -> Watch:
        scheduler = self._scheduler
        assert scheduler is not None
        state = scheduler.client.state
        variables, calls, loops = self.values()
        return Watch(
            time_s=scheduler.elapsed(),
            variables=variables,
            calls=calls,
            loops=loops,
            **readings(state, self.pose() if self.pose is not None else state.pose),
            messages=self.messages(),
            note=self._note(),
        )

    def values(self) -> tuple[tuple[Named, ...], tuple[Call, ...], tuple[LoopRound, ...]]:
        """The variables (shared ones first), the calls under way and the loops' rounds."""
        scheduler = self._scheduler
        assert scheduler is not None
        variables = [Named(name, value) for name, value in scheduler.shared.items()]
        calls: list[Call] = []
        loops: list[LoopRound] = []
        for run in scheduler.runs:
            if not run.active:
                continue
            for frame in self._frames(run.label):
                named = tuple(Named(n, v, run.label) for n, v in frame.local.items())
                if frame.depth == 0:
                    variables.extend(named)
                else:
                    calls.append(Call(run.label, frame.procedure, named))
            loops.extend(self._loops(run.label))
        return tuple(variables), tuple(calls), tuple(loops)

    def messages(self) -> tuple[SentMessage, ...]:
        """The messages sent, each as it is now (copied: a sender stops waiting later)."""
        scheduler = self._scheduler
        assert scheduler is not None
        return tuple(replace(sent) for sent in scheduler.sent_messages)

    def values_of(self, name: str) -> dict[str, Value]:
        """``name``'s value in each script that has it (key: its label), or shared (key "");
        a script's innermost call first (its parameter or variable hides the script's)."""
        scheduler = self._scheduler
        assert scheduler is not None
        found: dict[str, Value] = {}
        if name in scheduler.shared:
            found[""] = scheduler.shared[name]
        for script in self._levels:
            for frame in reversed(list(self._frames(script))):
                if name in frame.local:
                    found[script] = frame.local[name]
                    break
        return found

    def elapsed(self) -> float:
        """Seconds of the run so far."""
        scheduler = self._scheduler
        return 0.0 if scheduler is None or not scheduler.started else scheduler.elapsed()

    def trace_length(self) -> int:
        """How many entries the run's trace has so far."""
        return 0 if self._scheduler is None else len(self._scheduler.trace.entries)

    def scripts(self) -> list[str]:
        """The labels of the scripts running now, in the scheduler's order."""
        scheduler = self._scheduler
        return [] if scheduler is None else [run.label for run in scheduler.runs if run.active]

    def last_statement(self, script: str) -> ast.Statement | None:
        levels = self._levels.get(script)
        return levels[-1].statement if levels else None

    def _frames(self, script: str) -> Iterator[Frame]:
        seen: set[int] = set()
        for level in self._levels.get(script, ()):
            for running in level.stack:
                if id(running.frame) not in seen:
                    seen.add(id(running.frame))
                    yield running.frame

    def _loops(self, script: str) -> Iterator[LoopRound]:
        for level in self._levels.get(script, ()):
            for running in level.stack:
                rounds = level.rounds.get(id(running))
                if running.loop is None or rounds is None or rounds.running is not running:
                    continue
                if rounds.count:  # repeat: the interpreter counts the rounds still to run
                    number = rounds.count - running.rounds + 1
                    yield LoopRound(script, running.loop.span.line, number, rounds.count)
                else:
                    yield LoopRound(script, running.loop.span.line, rounds.seen)

    def _note(self) -> str:
        scheduler = self._scheduler
        assert scheduler is not None
        for entry in reversed(scheduler.trace.entries):
            if entry.packet in SOUND_PACKETS:
                return entry.text if entry.outcome is Outcome.PENDING else ""
        return ""

    def _english_line(self, statement: ast.Statement) -> str:
        """The statement's line with its keywords in English (a message shows it with the
        program's): the line as written, without its comment or indentation."""
        scheduler = self._scheduler
        assert scheduler is not None
        if self._english is None:
            lines = {
                node.span.line for node in ast.walk(scheduler.program)
                if isinstance(node, ast.Statement)
            }  # fmt: skip
            english = lines_in_english(scheduler.source, lines, scheduler.program.language)
            self._english = {
                line: text.split("#", 1)[0].strip() if '"' not in text else text.strip()
                for line, text in english.items()
            }  # (asked at every moment a run's recording keeps: made once)
        return self._english.get(statement.span.line, "")


def _count_rounds(stack: Sequence[_Running], before: dict[int, _Rounds]) -> dict[int, _Rounds]:
    """The rounds of the loops on ``stack``: those seen ``before`` (a new round if the loop's
    round started since), and the new ones (in their first round)."""
    counted: dict[int, _Rounds] = {}
    for running in stack:
        if running.loop is None:
            continue
        rounds = before.get(id(running))
        if rounds is None or rounds.running is not running:
            count = running.rounds if isinstance(running.loop, ast.Repeat) else 0
            rounds = _Rounds(running, running.started, count=count)
        elif rounds.started != running.started:
            rounds.started = running.started
            rounds.seen += 1
        counted[id(running)] = rounds
    return counted


def _calls_shallower(stack: Sequence[_Running], depth: int) -> bool:
    """Whether a block stack is still running (a finished one is empty), its innermost
    procedure call less deep than ``depth``."""
    return bool(stack) and stack[-1].frame.depth < depth


WATCHED_CHARS = 200
"""Chosen: a value in the Watch shows at most this many characters (a text doubled in a loop
would otherwise be copied whole at every look, and into every moment kept to go back to)."""


def watched(value: Value) -> str:
    """``value`` as the Watch shows it: as the trace writes it, cut short if long."""
    shown = show(value)
    return shown if len(shown) <= WATCHED_CHARS else shown[:WATCHED_CHARS] + "…"


def _name(script: str) -> str:
    """A script's header from its label (``3:when bumped``)."""
    return script.split(":", 1)[-1]


class Readings(TypedDict):
    """The robot's readings as a :class:`Watch` shows them."""

    bumpers: tuple[str, ...]
    touched: tuple[str, ...]
    colors: str
    light_percent: tuple[float, float]
    pose: Pose


def readings(state: SensorState, pose: Pose) -> Readings:
    """What the robot's sensors read in ``state`` (and where it is: ``pose``), as words."""
    return Readings(
        bumpers=tuple(word for bit, word in BUMPER_WORDS.items() if state.bumpers & bit),
        touched=tuple(word for bit, word in TOUCH_WORDS.items() if state.touch & bit),
        colors=color_letters(state.colors),
        light_percent=state.light_percent,
        pose=pose,
    )


# ---- watching a few names (`rootlang sim --watch`) --------------------------------------------


@dataclass
class NameWatch:
    """Each change of some variables' values, as lines of the child's view: as each statement
    begins (and at the run's end: :meth:`look`) their values are compared with the last seen;
    a change is told on the line of the ``set`` or ``change`` that made it (else of the
    statement begun last)."""

    names: tuple[str, ...]
    languages: Languages
    on_line: Callable[[ViewLine], None] | None = None  # each change as it is found
    lines: list[ViewLine] = field(default_factory=list)
    after: list[int] = field(default_factory=list)
    """For each line, how many entries the run's trace had when it was found (to put it among
    the child's view's lines in its place)."""
    _seen: dict[tuple[str, str], Value] = field(default_factory=dict)

    def look(self, debugger: Debugger) -> None:
        """Tell the watched values that changed since the last look."""
        for name in self.names:
            for script, value in debugger.values_of(name).items():
                key = (script, name)
                if key in self._seen and self._seen[key] == value:
                    continue
                self._seen[key] = value
                text = message("V206", {"name": name, "value": show(value)}, self.languages)
                line = _line_that_set(debugger, name)
                told = ViewLine(round(debugger.elapsed() * 1000), line, text, "command")
                self.lines.append(told)
                self.after.append(debugger.trace_length())
                if self.on_line is not None:
                    self.on_line(told)


def _line_that_set(debugger: Debugger, name: str) -> int:
    for script in debugger.scripts():
        statement = debugger.last_statement(script)
        if isinstance(statement, ast.SetVariable | ast.ChangeVariable) and statement.name == name:
            return statement.span.line
    return 0 if debugger.last is None else debugger.last.span.line
