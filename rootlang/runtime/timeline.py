"""Going back in time: a run's recording of what a pause would have shown, at any moment.

A :class:`Timeline` handed to the :class:`~rootlang.runtime.debugger.Debugger` (its
``recorder``, and told each trace entry: ``on_trace=timeline.seen``) keeps step functions of
the run's time, each only where it changes:

- the program's state (where each script is, the variables, the calls' parameters, the loops'
  rounds, the messages), as each statement begins and as a script starts or ends (the
  interpreter changes nothing else); where the program is busy (its states last less than
  :data:`LASTED_S`) every :data:`BUSY_S`, and always each that lasted :data:`LASTED_S`;
- the robot's readings (bumpers, touch, colours, light), as each new sensor state arrives
  (the client's ``on_state``);
- the notes, from the trace's sound commands (when each began, when it ended);
- where the robot reckons it is, as a simulator tells it (:meth:`Timeline.reckoned`, from
  ``session.keep_moments``: each time its world moves on).

So the state at time ``t`` (:meth:`Timeline.at`) is the last of each kept before ``t`` (a
pause at ``t`` comes before anything else due then): what a run paused at ``t`` shows
(``rootlang sim --until t``; tests/runtime/test_timeline.py holds it to that, but in busy
stretches). Keeping them costs a few tuples a change: ``benchmarks/timeline.py`` measures what
it costs the simulator (docs/studio.md, "Going back in time").
"""

from __future__ import annotations

import math
from bisect import bisect_left
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any, Generic, NamedTuple, TypeVar

from rootlang.protocol.enums import BumperState, SensorColor, TouchSensors
from rootlang.runtime.client import Pose, SensorState
from rootlang.runtime.debugger import (
    SOUND_PACKETS,
    Call,
    LoopRound,
    Named,
    Pause,
    Place,
    Readings,
    Watch,
    note_words,
    readings,
)
from rootlang.runtime.scheduler import SentMessage
from rootlang.runtime.trace import TraceEntry
from rootlang.wording.language import Languages

if TYPE_CHECKING:
    from rootlang.runtime.debugger import Debugger
    from rootlang.runtime.scheduler import Scheduler

T = TypeVar("T")
SCRIPTS_CHANGE = frozenset(("start", "end", "run", "error"))  # trace entries that change places
BUSY_S = 0.5
"""Chosen: where the program changes faster, its state is kept this often (a busy loop kept every
250 ms cost it 11 %)..."""
LASTED_S = 0.25
"""... but a state that lasted this long is always kept (a loop that waits a quarter of a second
each round, blinking a light, is kept at every change, its last state before each wait too)."""
MOMENTS_KEPT = 4_000
"""Chosen: each step function keeps at most this many changes; past it, every other one is let
go (so a long busy run's moments stay a few MB at most: ten minutes of a busy loop kept every
50 ms are 12,000, and each world step's pose 60,000). Going back there shows the nearest kept."""


@dataclass(frozen=True)
class ProgramState:
    """The program's part of a moment: where its scripts are and its values."""

    places: tuple[Place, ...]
    variables: tuple[Named, ...]
    calls: tuple[Call, ...]
    loops: tuple[LoopRound, ...]
    messages: tuple[SentMessage, ...]

    def same(self, other: ProgramState) -> bool:
        """Whether ``other`` shows the same (a place's statement by its identity: quick)."""
        return (
            self.variables == other.variables
            and self.calls == other.calls
            and self.loops == other.loops
            and self.messages == other.messages
            and len(self.places) == len(other.places)
            and all(
                a.script == b.script and a.state == b.state and a.statement is b.statement
                for a, b in zip(self.places, other.places, strict=True)
            )
        )


class Sensed(NamedTuple):
    """The robot's readings a :class:`Watch` shows, but where it is (told apart: it changes
    at every reading while the robot moves). Kept as read, put in words only when shown."""

    bumpers: BumperState
    touch: TouchSensors
    colors: tuple[SensorColor, ...]
    light_percent: tuple[float, float]

    @staticmethod
    def of(state: SensorState) -> Sensed:
        return Sensed(state.bumpers, state.touch, state.colors, state.light_percent)

    def watched(self, pose: Pose) -> Readings:
        """As a :class:`Watch` shows them, the robot at ``pose``."""
        state = SensorState(self.bumpers, self.touch, self.colors, light_percent=self.light_percent)
        return readings(state, pose)


@dataclass
class Steps(Generic[T]):
    """A value over the run's time: each change, when it came (seconds, in order)."""

    times: list[float] = field(default_factory=list)
    values: list[T] = field(default_factory=list)

    def add(self, time_s: float, value: T) -> None:
        if self.times and self.times[-1] == time_s:  # (the last at one moment is what it shows)
            self.values[-1] = value
            return
        self.times.append(time_s)
        self.values.append(value)
        if len(self.times) > MOMENTS_KEPT:  # a long run: every other change is let go
            last_time, last_value = self.times[-1], self.values[-1]
            del self.times[1::2], self.values[1::2]
            if self.times[-1] != last_time:  # (the latest always stays)
                self.times.append(last_time)
                self.values.append(last_value)

    def index_at(self, time_s: float) -> int:
        """The change in force at ``time_s`` (-1: none yet): the last before it (a run paused
        at a time pauses before anything else due then happens)."""
        return bisect_left(self.times, time_s) - 1


@dataclass
class Timeline:
    """A run's moments (see the module's docstring); attached by the debugger."""

    program: Steps[ProgramState] = field(default_factory=Steps)
    robot: Steps[Sensed] = field(default_factory=Steps)
    sounds: list[TraceEntry] = field(default_factory=list)  # the trace's, in time order
    poses: Steps[Any] = field(default_factory=Steps)  # where the robot reckons it is, if told
    pose_of: Callable[[Any], Pose] = field(default=lambda pose: pose)  # as told -> a Pose
    busy: list[tuple[float, float]] = field(default_factory=list)
    """Stretches where the program changed faster than every :data:`BUSY_S` (from, to): its
    state is kept that often there."""
    _debugger: Debugger | None = None
    _scheduler: Scheduler | None = None
    _elapsed: Callable[[], float] = field(default=lambda: 0.0)  # the attached run's time
    _pending: float | None = None  # when the program last changed, if not yet kept
    _taken: float = -math.inf  # when the program state last kept was made
    _busy_from: float | None = None  # a busy stretch began then (its changes not all kept)
    _looking: bool = False  # to look again once a change has lasted

    def attach(self, debugger: Debugger, scheduler: Scheduler) -> None:
        self._debugger = debugger
        self._scheduler = scheduler
        self._elapsed = scheduler.elapsed
        scheduler.client.on_state = self._new_state
        self._new_state(scheduler.client.state)

    def begins(self) -> None:
        """A statement begins (the debugger has taken it in; or a script starts or ends): the
        program's state changes now. Kept at once, unless the last kept is less than
        :data:`BUSY_S` old: then once it has lasted :data:`LASTED_S` (the run's clock says
        when its time passes that: a busy loop's states never last so long), or that old.
        Told at every statement: one call, kept quick."""
        now = self._elapsed()
        pending = self._pending
        if pending is not None and now > pending and self._busy_from is None:
            self._busy_from = pending  # (a change not kept: a busy stretch, from here)
        self._pending = now
        if now - self._taken >= BUSY_S:
            self._take_pending()
        elif not self._looking:
            self._look_later(now)

    def seen(self, entry: TraceEntry) -> None:
        """A trace entry was added (``run_program``'s ``on_trace``)."""
        if entry.packet in SOUND_PACKETS:
            self.sounds.append(entry)
        if entry.kind in SCRIPTS_CHANGE:
            if self._scheduler is not None and self._scheduler.started:
                self.begins()
        else:
            self.moved_on()

    def reckoned(self, pose: Any) -> None:
        """Where the robot reckons it is now (a simulator tells it as its world moves on; as
        ``pose_of`` makes it a :class:`Pose`, when it is shown)."""
        now = self.now()
        if self._pending is not None:
            self.moved_on(now)
        self.poses.add(now, pose)

    @property
    def end_s(self) -> float:
        """The time of the last moment taken (the run's end, once it has ended)."""
        return max([0.0, *self.program.times[-1:], *self.robot.times[-1:]])

    def now(self) -> float:
        """The run's time now (0 until it has started)."""
        scheduler = self._scheduler
        return scheduler.elapsed() if scheduler is not None and scheduler.started else 0.0

    def _new_state(self, state: SensorState) -> None:
        now = self.now()
        self.moved_on(now)
        sensed = Sensed.of(state)
        if not self.robot.values or self.robot.values[-1] != sensed:
            self.robot.add(now, sensed)

    def moved_on(self, now: float | None = None) -> None:
        """Something happened now that changes none of the program's values: a change not
        kept yet is kept, once the time has moved on from it (nothing changed since: the
        interpreter changes nothing but as a statement begins, and a script starts or
        ends), at most every :data:`BUSY_S`."""
        pending = self._pending
        if pending is None:
            return
        now = self.now() if now is None else now
        if pending < now and now - self._taken >= BUSY_S:
            self._take_pending()

    def _look_later(self, changed: float) -> None:
        """Look again once the change at ``changed`` has lasted :data:`LASTED_S`."""
        scheduler = self._scheduler
        assert scheduler is not None
        self._looking = True
        clock = scheduler.clock
        clock.when_time_passes(clock.now() + changed + LASTED_S - scheduler.elapsed(), self._look)

    def _look(self) -> None:
        """The change a :meth:`_look_later` waited for has lasted: kept if it is the last
        (nothing changed since); else look again for the last."""
        self._looking = False
        pending = self._pending
        if pending is None or (scheduler := self._scheduler) is None or scheduler.ending:
            return
        if scheduler.elapsed() - pending >= LASTED_S - 1e-9:
            self._take_pending()
        else:
            self._look_later(pending)

    def _take_pending(self) -> None:
        pending = self._pending
        debugger = self._debugger
        if pending is None or debugger is None:
            return
        self._pending = None
        self._taken = pending
        if self._busy_from is not None:
            self.busy.append((self._busy_from, pending))
            self._busy_from = None
        variables, calls, loops = debugger.values()
        state = ProgramState(tuple(debugger.places()), variables, calls, loops, debugger.messages())
        values = self.program.values
        if not values or not values[-1].same(state):
            self.program.add(pending, state)

    # ---- telling ----------------------------------------------------------------------------

    def at(self, time_s: float, pose: Pose | None = None) -> Pause:
        """What a run paused at ``time_s`` shows (``reason`` "time"), the robot where it
        reckoned it was then (or at ``pose``, if given)."""
        self._take_pending()
        program = self.program.values[max(self.program.index_at(time_s), 0)]
        sensed = self.robot.values[max(self.robot.index_at(time_s), 0)]
        if pose is None:
            pose = self.pose_of(self.poses.values[max(self.poses.index_at(time_s), 0)])
        watch = _watch_of(program, sensed, pose)
        return Pause(
            "time", program.places, replace(watch, time_s=time_s, note=note_at(self.sounds, time_s))
        )

    def to_json(self, languages: Languages) -> dict[str, object]:
        """The moments for a page: each step function's changes (times in ms) and, once for
        each different value, what the Watch panel shows of it in ``languages``' words. A
        moment's lines are a program's ``values``, a robot's ``lines``, the program's
        ``messages`` and the note's line, in that order (as :meth:`Watch.lines` has them)."""
        self._take_pending()  # (the run as it stands: paused, or ended)
        programs: list[dict[str, object]] = []
        program_index: list[int] = []
        for number, state in enumerate(self.program.values):
            if number and state is self.program.values[number - 1]:
                program_index.append(program_index[-1])
                continue
            watch = _watch_of(state, NOTHING_SENSED, Pose())
            shown = watch.to_json()
            programs.append(
                {
                    "places": [
                        {**place.to_json(), "words": place.words(languages)}
                        for place in state.places
                    ],
                    **{part: shown[part] for part in ("variables", "calls")},
                    "values": watch.value_lines(languages),
                    "messages": watch.message_lines(languages),
                }
            )
            program_index.append(len(programs) - 1)
        robots: list[list[str]] = []
        seen: dict[Sensed, int] = {}
        robot_index: list[int] = []
        for sensed in self.robot.values:
            if sensed not in seen:
                seen[sensed] = len(robots)
                robots.append(_watch_of(None, sensed, Pose()).reading_lines(languages))
            robot_index.append(seen[sensed])
        notes = [
            [sound.time_ms, sound.end_ms, note_words(sound.text, languages)]
            for sound in self.sounds
        ]
        poses = [self.pose_of(pose) for pose in self.poses.values]
        return {
            "end_ms": _ms(self.end_s),
            # x mm, y mm, heading (degrees) as the robot reckons them, each with its time
            "poses": [
                _ms_list(self.poses.times),
                [round(pose.x_mm, 1) for pose in poses],
                [round(pose.y_mm, 1) for pose in poses],
                [round(pose.heading_degrees, 1) for pose in poses],
            ],
            "program": [_ms_list(self.program.times), program_index],
            "programs": programs,
            "robot": [_ms_list(self.robot.times), robot_index],
            "robots": robots,
            "notes": notes,
        }


def note_at(sounds: Sequence[TraceEntry], time_s: float) -> str:
    """The note playing at ``time_s``, as the trace writes it ("" for none): the last sound
    begun before then, if it had not ended (as :meth:`Debugger.watch` tells it)."""
    time_ms = _ms(time_s)
    begun = [sound for sound in sounds if sound.time_ms < time_ms]
    if not begun:
        return ""
    last = begun[-1]
    return last.text if last.end_ms is None or last.end_ms >= time_ms else ""


NOTHING_SENSED = Sensed.of(SensorState())


def _watch_of(program: ProgramState | None, sensed: Sensed, pose: Pose) -> Watch:
    return Watch(
        time_s=0.0,
        variables=() if program is None else program.variables,
        calls=() if program is None else program.calls,
        loops=() if program is None else program.loops,
        **sensed.watched(pose),
        messages=() if program is None else program.messages,
        note="",
    )


def _ms(seconds: float) -> int:
    return round(seconds * 1000)


def _ms_list(times: Sequence[float]) -> list[int]:
    return [_ms(time) for time in times]
