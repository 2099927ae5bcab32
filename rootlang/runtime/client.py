"""The robot client: commands out, responses matched, events routed, sensor state kept.

It sits between the scheduler (which thinks in commands like "drive 100 mm") and a
:class:`~rootlang.runtime.transport.Transport` (which moves 20-byte packets). It

- numbers every command with the host's packet-id counter and registers the awaited response
  *before* sending, matching responses by (packet name = device + command, packet id);
- gives every awaited command a timeout derived from what it asks (distance / speed + margin,
  say-duration, ...) and raises a run-time error naming the command and its source line;
- ends the wait of an older motion (marker, sound) command when a newer one is sent: the
  robot interrupts it too, and its late "finished" response is then quietly absorbed;
- keeps the latest sensor state from events and responses, and asks with Get packets for
  sensors that send no events, sharing one request among concurrent readers;
- gates every command on the robot model and protocol version;
- ignores and counts corrupt packets, duplicates, late responses, unknown packets and event-id
  gaps (:class:`ClientStats`): none of them stops a program.
"""

from __future__ import annotations

import asyncio
import contextlib
import enum
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any, TypeVar

from rootlang.diagnostics import NO_SPAN, RootlangError, Span, seconds_text
from rootlang.protocol import (
    PACKETS,
    EventIdTracker,
    EventOrder,
    HostPacketIds,
    Packet,
    PacketError,
    UnknownPacket,
    decode,
    encode,
    spec,
)
from rootlang.protocol.behaviour import Actuator, Behaviour, Place, Role, Tells, WhenSilent
from rootlang.protocol.behaviour import same_place as same_places
from rootlang.protocol.codec import unchecked
from rootlang.protocol.enums import (
    BumperState,
    Kind,
    LightState,
    SensorColor,
    StallCause,
    TouchSensors,
)
from rootlang.protocol.fields import COLOR_SENSORS
from rootlang.protocol.table import FILLER_FIELDS, HALT_FIELDS, WITNESS_FIELDS, by_role
from rootlang.robots import RobotModel
from rootlang.runtime.clock import Clock
from rootlang.runtime.trace import Outcome, Trace, TraceEntry, pose_text
from rootlang.runtime.transport import (
    USUAL_PROTOCOL,
    DisconnectHandler,
    LinkLost,
    PacketHandler,
    RobotInfo,
    Transport,
)
from rootlang.wording.shown import Code

POSE_FIELDS = frozenset(("x", "y", "heading"))  # a packet with these fields tells the pose

# Conservative speeds for timeouts: slower than any robot really goes, so only a robot that
# has stopped answering times out.
TIMEOUT_SPEED_MM_S = 40.0
TIMEOUT_WHEELBASE_MM = 235.0  # the wider of Root (102 mm) and Create 3 (235 mm)
TIMEOUT_MARGIN_S = 3.0

# A lossy link (docs/runtime.md, "A lossy link"): what is safe to send again is sent again; how
# each command behaves when the robot is silent is its row's in the packet table.
READ_ANSWER_SECONDS = 0.5  # a robot answers a Get at once; after this it is asked again
READ_ATTEMPTS = 5
MOTION_ATTEMPTS = 3  # a movement that never arrived is sent again (the pose tells)
EARLY_CHECK_SPEED_MM_S = 50.0  # see early_check_seconds
EARLY_CHECK_TURN_DEGREES_S = 45.0
EARLY_CHECK_MARGIN_S = 1.5
WHEEL_SPEED_COPIES = 3  # unacknowledged links: no answer, nothing reports them, sent 3 times
RESET_ATTEMPTS = 5
WITNESS_ANSWER_SECONDS = 1.0  # a stop's witness, cut short, is answered at once (else in 60 s)
WHERE = by_role(Role.WHERE).name  # asked to judge a movement's lost answer
STOP = by_role(Role.STOP).name
WITNESS = by_role(Role.WITNESS).name  # a Stop and Reset's witness (RobotClient._send_witness)
FILLER = by_role(Role.FILLER).name  # takes id 0 (RobotClient._fill_id_zero)
WHEELS = by_role(Role.WHEELS).name  # a pause stops the wheels, and sets them going again


@dataclass
class ClientStats:
    """What the client ignored: none of it stops a program, all of it is worth knowing."""

    commands_sent: int = 0
    responses: int = 0
    events: int = 0
    corrupt_packets: int = 0
    duplicates: int = 0
    late_responses: int = 0
    unknown_packets: int = 0
    event_id_gaps: int = 0
    interrupted: int = 0
    resent: int = 0
    recovered: int = 0

    def to_json(self) -> dict[str, int]:
        return dict(self.__dict__)

    def ignored(self) -> str:
        """What was ignored, in words ("2 corrupt packets, 1 duplicate"), or ""."""
        counts = (
            (self.corrupt_packets, "corrupt packet", "corrupt packets"),
            (self.unknown_packets, "unknown packet", "unknown packets"),
            (self.duplicates, "duplicate", "duplicates"),
            (self.late_responses, "late answer", "late answers"),
            (self.event_id_gaps, "gap in event numbers", "gaps in event numbers"),
            (self.resent, "resent command", "resent commands"),
            (self.recovered, "recovered lost answer", "recovered lost answers"),
        )
        return ", ".join(
            f"{count} {one if count == 1 else many}" for count, one, many in counts if count
        )


@dataclass(frozen=True)
class Pose:
    """Where the robot says it is: mm and degrees (90° = facing +y at the start)."""

    x_mm: float = 0.0
    y_mm: float = 0.0
    heading_degrees: float = 90.0

    def text(self) -> str:
        return pose_text(self.x_mm, self.y_mm, self.heading_degrees)

    @property
    def place(self) -> Place:
        return (self.x_mm, self.y_mm, self.heading_degrees)


@dataclass(frozen=True)
class SensorState:
    """The robot's latest readings; replaced (not mutated) on every change, so the scheduler
    can compare the state before and after an event."""

    bumpers: BumperState = BumperState.NONE
    touch: TouchSensors = TouchSensors.NONE
    colors: tuple[SensorColor, ...] = (SensorColor.WHITE,) * COLOR_SENSORS
    light_state: LightState | None = None
    light_percent: tuple[float, float] = (0.0, 0.0)
    cliff: bool = False
    battery_percent: float | None = None
    pose: Pose = field(default_factory=Pose)
    ir_triggered: int = 0
    ir_values: tuple[int, ...] = (0,) * 7
    docked: bool = False
    acceleration_g: tuple[float, float, float] = (0.0, 0.0, 1.0)


@dataclass(frozen=True)
class Origin:
    """Which script and source line a command comes from (for the trace and for errors), and
    whether it is a later command of the statement there (``TraceEntry.part``)."""

    script: str
    span: Span
    part: bool = False


EventHandler = Callable[[Packet, SensorState, SensorState], None]


_KEEP_WAITING = object()  # _await_early: no verdict yet


class _Verdict(enum.Enum):
    """What to do about a command whose answer did not come."""

    DONE = "done"  # as if it was answered: go on
    AGAIN = "again"  # it never arrived: send it again
    GIVE_UP = "give up"  # E203


class _NoAnswer(Exception):
    """A command's answer did not come in time; ``error`` (E203) says so if nothing helps."""

    def __init__(self, error: RootlangError) -> None:
        super().__init__(str(error))
        self.error = error


@dataclass
class _Waiter:
    name: str
    future: asyncio.Future[Packet | None]
    entry: TraceEntry | None
    group: Actuator | None
    stalled: bool = False  # a motor stalled while this movement was the robot's (its event)
    cut: bool = False  # a pause stopped the robot in the middle of it (RobotClient.hold)


class _CutShort(Exception):
    """A movement's answer came because a pause stopped the robot (:meth:`RobotClient.hold`)."""

    def __init__(self, answer: Packet | None) -> None:
        super().__init__("cut short by a pause")
        self.answer = answer


class RobotClient:
    """Talks to one robot over one transport, on one clock."""

    def __init__(self, transport: Transport, clock: Clock, trace: Trace) -> None:
        self.transport = transport
        self.clock = clock
        self.trace = trace
        self.stats = ClientStats()
        self.state = SensorState()
        self.info: RobotInfo | None = None
        self.connected = False
        self.on_event: EventHandler = lambda packet, before, after: None
        self.on_disconnect: DisconnectHandler = lambda reason: None
        self.on_state: Callable[[SensorState], None] | None = None  # each new sensor state
        self._ids = HostPacketIds()
        self._event_ids = EventIdTracker()
        self._waiting: dict[tuple[str, int], _Waiter] = {}
        self._absorb: set[tuple[str, int]] = set()  # interrupted: their answer is expected
        self._answered: set[tuple[str, int]] = set()  # recently answered: repeats are duplicates
        self._reads: dict[str, asyncio.Future[Packet | None]] = {}
        self._active: dict[Actuator, _Waiter] = {}  # actuator -> its command in progress
        self._supported: dict[str, bool] = {}
        self._pose_known = True  # the last pose answer is where the robot stands now
        self._wheels_turning = False  # a wheel speed other than 0 was the last word
        self._wheel_speeds = (0, 0)
        self._held: asyncio.Event | None = None  # set when a pause ends (RobotClient.hold)
        self._wheels_held = False  # the pause stopped wheels set going: they go again after

    # ---- the link --------------------------------------------------------------------------

    async def connect(self) -> RobotInfo:
        self.info = await self.transport.connect(self._received, self._lost)
        self._supported.clear()
        self.connected = True
        return self.info

    async def disconnect(self) -> None:
        self.connected = False
        await self.transport.disconnect()

    def adopt(self, info: RobotInfo) -> tuple[PacketHandler, DisconnectHandler]:
        """Take over a link another client opened on this transport (the program's process
        died: its link holder stops the robot, :mod:`rootlang.app.link`). The transport's
        packets and its loss go to the two handlers returned. Its first packet has id 0,
        which a robot always takes, whatever ids it saw before."""
        self.info = info
        self.connected = True
        return self._received, self._lost

    async def stop_robot(self) -> bool:
        """Stop and Reset, confirmed (:meth:`reset`): what every way a run ends does (a run
        stopped while paused: the movement cut short is not finished)."""
        self._wheels_held = False
        self._let_go()
        return await self.reset(STOP, Origin("run", NO_SPAN), "stop and reset")

    # ---- a pause (the debugger's, on a robot) ------------------------------------------------

    async def hold(self) -> None:
        """A pause: the robot stops at once — both wheels set to 0 (the table's Role.WHEELS
        packet), which cuts the movement under way short (the robot answers it from where it
        stopped) — and no command goes out until :meth:`release`. The movement cut short is then
        finished from where the robot stands (its row's ``rest``: the distance or angle still
        to go), and wheels set going turn again. Not a Stop and Reset: that would zero the
        position the program may read (docs/runtime.md, "Pausing a robot")."""
        if self._held is not None:
            return
        self._held = asyncio.Event()
        moving = self._active.get(Actuator.MOTION)
        if moving is not None and not moving.future.done():
            moving.cut = True  # (its trace entry ends with its answer; the rest is a part)
        self._wheels_held = self._wheels_turning
        if moving is None and not self._wheels_turning:
            return  # standing still already
        await self._set_wheels(HALT_FIELDS, "pause: the wheels stop")

    async def release(self) -> None:
        """The pause ends: wheels it stopped turn again, then the commands waiting go on (a
        movement cut short is finished from where the robot stands)."""
        if self._held is None:
            return
        if self._wheels_held:
            self._wheels_held = False
            left, right = self._wheel_speeds
            await self._set_wheels({"left": left, "right": right}, "resume: the wheels go again")
        self._let_go()

    def _let_go(self) -> None:
        held, self._held = self._held, None
        if held is not None:
            held.set()

    async def _set_wheels(self, fields: Mapping[str, int], trace_text: str) -> None:
        """Both wheels' speeds, for a pause: no script's command (nothing interrupted in the
        client's wait, the wheels the program set are kept to set again)."""
        origin = Origin("run", NO_SPAN)
        if self._ids.peek() == 0:
            await self._fill_id_zero(origin)
        entry = self.trace.add("command", trace_text, script="run", outcome=Outcome.PENDING,
                               packet=WHEELS, group=Actuator.MOTION.value)  # fmt: skip
        self.stats.commands_sent += 1
        await self._send(encode(WHEELS, dict(fields), self._ids.next_id(), robot=self.model),
                         entry, origin)  # fmt: skip
        if not self.transport.acknowledges_writes:
            await self._send_copies(WHEELS, fields, entry, origin)
        self.trace.finish(entry, Outcome.DONE)

    @property
    def model(self) -> RobotModel:
        return self.info.model if self.info else RobotModel.RT1

    @property
    def protocol_version(self) -> tuple[int, int]:
        return self.info.protocol_version if self.info else USUAL_PROTOCOL

    def supports(self, name: str) -> bool:
        """Whether this robot (model and protocol version) knows the packet ``name``."""
        known = self._supported.get(name)
        if known is None:
            known = self._supported[name] = spec(name).supported_by(
                self.model, self.protocol_version
            )
        return known

    def _lost(self, reason: LinkLost) -> None:
        if not self.connected:
            return
        self.connected = False
        self._fail_all(reason)
        self.on_disconnect(reason)

    # ---- commands --------------------------------------------------------------------------

    async def command(
        self,
        name: str,
        fields: Mapping[str, Any],
        origin: Origin,
        *,
        trace_text: str | None = None,
        answer_seconds: float | None = None,
    ) -> Packet | None:
        """Send one command; if it gets a response, wait for it.

        Returns the response, or None when a newer command on the same actuator interrupted
        it (or it has no response, or its lost answer was made good). Raises RootlangError when
        the robot can't do it, or when the answer never comes and can't be made good (see
        :meth:`_without_answer`). ``answer_seconds`` overrides the usual timeout.
        """
        if not self.supports(name):
            raise RootlangError.of(
                "E201",
                origin.span,
                robot=self.model.display_name,
                command=Code(trace_text or name, quoted=False),
            )
        if self._held is not None:  # a pause: a statement's next command waits for its end
            await self._held.wait()
        start_pose = self.state.pose if self._pose_known else None
        self._note_wheels(name, fields)
        attempt = 1
        while True:
            try:
                return await self._command_once(
                    name, fields, origin, trace_text, answer_seconds, start_pose
                )
            except _CutShort as cut:
                if self._held is not None:
                    await self._held.wait()
                if self.supports(WHERE):  # where it came to rest (it slows down to a stop)
                    await self.read(WHERE, origin, "get position")
                    self._pose_known = True
                rest = self._rest(name, fields, start_pose)
                if rest is None:
                    return cut.answer
                fields, start_pose, attempt = rest, self.state.pose, 1
                trace_text = _describe(name, fields)
                origin = Origin(origin.script, origin.span, part=True)
            except _NoAnswer as missing:
                verdict = await self._without_answer(name, fields, origin, start_pose, attempt)
                if verdict is _Verdict.GIVE_UP:
                    raise missing.error from None
                if verdict is _Verdict.DONE:
                    return None
                attempt += 1
                self.stats.resent += 1

    def _rest(
        self, name: str, fields: Mapping[str, Any], start: Pose | None
    ) -> Mapping[str, Any] | None:
        """What finishes a movement a pause cut short, from where the robot stands (None:
        nothing left, or it can't be told: where it started was not known)."""
        rest = behaviour(name).rest
        if rest is None or start is None or not self._pose_known:
            return None
        return rest(fields, start.place, self.state.pose.place)

    def _note_wheels(self, name: str, fields: Mapping[str, Any]) -> None:
        """Keep track of whether the last pose answer still tells where the robot is: not
        once the wheels were set going (they move it on between answers), or it was reset."""
        behaviour = spec(name).behaviour
        if behaviour.sets_wheels:
            left, right = self._wheel_speeds
            self._wheel_speeds = (fields.get("left", left), fields.get("right", right))
            self._wheels_turning = self._wheel_speeds != (0, 0)
            self._pose_known = False
            return
        if behaviour.moves or behaviour.stops:
            self._wheel_speeds = (0, 0)  # a movement stops the wheels first
            self._wheels_turning = False
        if behaviour.resets:
            self._pose_known = False

    async def _without_answer(
        self,
        name: str,
        fields: Mapping[str, Any],
        origin: Origin,
        start_pose: Pose | None,
        attempt: int,
    ) -> _Verdict:
        """After a command's answer did not come: what now? What is safe:

        - a sound has ended by now, heard or not: go on;
        - a marker position is the same however often it is asked for: send it again;
        - a movement is judged by the pose: where it should end, it was done (the answer was
          lost); where it started, it never arrived (send it again); anywhere else, or when
          the start is unknown (the wheels were driving), it is an error.
        """
        silent = spec(name).behaviour.when_silent
        if silent is WhenSilent.DONE:
            self.stats.recovered += 1
            return _Verdict.DONE
        if attempt >= MOTION_ATTEMPTS or not self.connected:
            return _Verdict.GIVE_UP
        if silent is WhenSilent.RESEND:
            return _Verdict.AGAIN
        if silent is not WhenSilent.BY_POSE or start_pose is None or not self.supports(WHERE):
            return _Verdict.GIVE_UP
        try:
            await self.read(WHERE, origin, "get position")
        except RootlangError:
            return _Verdict.GIVE_UP
        now = self.state.pose
        if same_place(now, expected_pose(start_pose, name, fields)):
            self.stats.recovered += 1
            self._pose_known = True
            return _Verdict.DONE
        return _Verdict.AGAIN if same_place(now, start_pose) else _Verdict.GIVE_UP

    async def _command_once(
        self,
        name: str,
        fields: Mapping[str, Any],
        origin: Origin,
        trace_text: str | None,
        answer_seconds: float | None,
        start_pose: Pose | None = None,
        *,
        reading: bool = False,
    ) -> Packet | None:
        if not self.connected:
            raise RootlangError.of("E208", origin.span, reason="the link is closed")
        packet_spec = spec(name)
        behaviour = packet_spec.behaviour
        if self._ids.peek() == 0:
            await self._fill_id_zero(origin)
        packet_id = self._ids.next_id()
        data = encode(name, dict(fields), packet_id, robot=self.model)
        group = behaviour.actuator
        entry = self.trace.add(
            "command",
            trace_text or _describe(name, fields),
            script=origin.script,
            line=origin.span.line,
            outcome=Outcome.PENDING,
            part=origin.part,
            packet=name,
            group=group.value if group else "",
            reading=reading,
        )
        if group is not None:
            self._interrupt(group)
        response = packet_spec.response
        waiter: _Waiter | None = None
        if response is not None:
            key = (response.name, packet_id)
            loop = asyncio.get_running_loop()
            waiter = _Waiter(name, loop.create_future(), entry, group)
            self._waiting[key] = waiter  # registered before sending: no answer can slip by
            self._answered.discard(key)
            self._absorb.discard(key)
            if group is not None:
                self._active[group] = waiter
        self.stats.commands_sent += 1
        try:
            await self._send(data, entry, origin)
            repeated = behaviour.when_silent is WhenSilent.REPEAT
            if repeated and not self.transport.acknowledges_writes:
                await self._send_copies(name, fields, entry, origin)
            if waiter is None or response is None:
                self.trace.finish(entry, Outcome.DONE)
                await asyncio.sleep(0)  # every command is a yield point
                return None
            seconds = timeout_for(name, fields) if answer_seconds is None else answer_seconds
            key = (response.name, packet_id)
            early = early_check_seconds(name, fields)
            judged = behaviour.when_silent is WhenSilent.BY_POSE
            if start_pose is not None and judged and early < seconds:
                answer = await self._await_early(waiter, key, early, start_pose, fields, origin)
                if answer is not _KEEP_WAITING:
                    return self._unless_cut(waiter, answer if isinstance(answer, Packet) else None)
                seconds -= early
            return self._unless_cut(waiter, await self._await(waiter, key, seconds, origin))
        except asyncio.CancelledError:
            self.trace.finish(entry, Outcome.CANCELLED)
            if waiter is not None and response is not None:
                self._forget(waiter, (response.name, packet_id))
            raise
        finally:
            if waiter is not None and waiter.group and self._active.get(waiter.group) is waiter:
                del self._active[waiter.group]

    @staticmethod
    def _unless_cut(waiter: _Waiter, answer: Packet | None) -> Packet | None:
        if waiter.cut:
            if waiter.entry is not None:
                waiter.entry.detail = f"{waiter.entry.detail} (a pause stopped it here)".strip()
            raise _CutShort(answer)
        return answer

    async def _send_copies(
        self, name: str, fields: Mapping[str, Any], entry: TraceEntry, origin: Origin
    ) -> None:
        """Wheel speeds have no answer and nothing reports them, so on a link that doesn't
        acknowledge writes a lost one would go unnoticed: they go out more than once (each a
        packet of its own, with its own id; the robot sets the same speeds again)."""
        for _ in range(WHEEL_SPEED_COPIES - 1):
            self.stats.commands_sent += 1
            await self._send(encode(name, dict(fields), self._ids.next_id(), robot=self.model),
                             entry, origin)  # fmt: skip

    async def _fill_id_zero(self, origin: Origin) -> None:
        """A robot always accepts id 0 (it starts the count again), so a repeated packet with id
        0 would be obeyed twice: a move made twice. Id 0 goes to a packet that does nothing
        (enable the events of no device), never to a command."""
        self.stats.commands_sent += 1
        filler = encode(FILLER, dict(FILLER_FIELDS), self._ids.next_id(), robot=self.model)
        try:
            await self.transport.send(filler)
        except Exception as error:  # a lost link, as in _send
            self._lost(f"sending failed: {error}")
            raise RootlangError.of("E208", origin.span, reason=str(error)) from error

    async def reset(self, name: str, origin: Origin, trace_text: str) -> bool:
        """Send ``name`` (Stop and Reset, or Reset Position) until the robot confirms it. Neither
        has an answer. A Stop and Reset is confirmed by its witness (:meth:`_send_witness`):
        a robot that got the stop answers it at once. Where the robot can't play a sweep, and
        for Reset Position, a Get Position answer at the start pose says it arrived (both put
        the position there) — which a robot that never left the start would give too. False
        when it never came (or nothing can tell)."""
        behaviour = spec(name).behaviour
        assert behaviour.resets
        witnessed = behaviour.stops and self.supports(WITNESS)
        for _ in range(RESET_ATTEMPTS):
            witness = await self._send_witness(origin) if witnessed else None
            await self.command(name, {}, origin, trace_text=trace_text)
            if witness is not None:
                if not await self._witnessed(*witness):
                    self.stats.resent += 1
                    continue
                with contextlib.suppress(RootlangError):  # the pose it reset, for the trace
                    await self.read(WHERE, origin, "get position")
                return True
            if not self.supports(WHERE):
                return False
            try:
                await self.read(WHERE, origin, "get position")
            except RootlangError:
                continue
            if same_place(self.state.pose, expected_pose(self.state.pose, name, {})):
                return True
            self.stats.resent += 1
        return False

    async def _send_witness(self, origin: Origin) -> tuple[_Waiter, tuple[str, int]]:
        """A silent sweep (volume 0) that would play for a minute, sent just before a Stop and
        Reset: the stop cancels it, and a sound cut short is answered at once (its finished
        response), so only a robot that got the stop answers it in time — wherever the robot
        stands. A lost sweep, a lost stop or a lost answer all look the same: no answer, and
        both are sent again. Not traced (the Stop and Reset is); counted as a command sent."""
        if self._ids.peek() == 0:
            await self._fill_id_zero(origin)
        packet_id = self._ids.next_id()
        response = spec(WITNESS).response
        assert response is not None
        key = (response.name, packet_id)
        waiter = _Waiter(WITNESS, asyncio.get_running_loop().create_future(), None, None)
        self._waiting[key] = waiter  # registered before sending: no answer can slip by
        self._answered.discard(key)
        self._absorb.discard(key)
        self.stats.commands_sent += 1
        data = encode(WITNESS, dict(WITNESS_FIELDS), packet_id, robot=self.model)
        try:
            await self.transport.send(data)
        except Exception as error:  # a lost link, as in _send
            self._lost(f"sending failed: {error}")
            raise RootlangError.of("E208", origin.span, reason=str(error)) from error
        return waiter, key

    async def _witnessed(self, waiter: _Waiter, key: tuple[str, int]) -> bool:
        """Whether the witness was answered in time (the stop arrived); if not, its answer is
        absorbed should it still come."""
        try:
            await _within(waiter.future, WITNESS_ANSWER_SECONDS)
        except asyncio.TimeoutError:
            self._forget(waiter, key)
            return False
        return True

    async def _send(self, data: bytes, entry: TraceEntry, origin: Origin) -> None:
        """Hand a packet to the transport. However a transport fails (bleak, an OS error, a
        closed link), it is a lost link (E208), not a crash; only the send is guarded, so a bug
        elsewhere still surfaces as one."""
        try:
            await self.transport.send(data)
        except RootlangError:
            raise
        except Exception as error:
            self.trace.finish(entry, Outcome.FAILED, str(error))
            self._lost(f"sending failed: {error}")
            raise RootlangError.of("E208", origin.span, reason=str(error)) from error

    async def _await(
        self, waiter: _Waiter, key: tuple[str, int], seconds: float, origin: Origin
    ) -> Packet | None:
        try:
            return await _within(waiter.future, seconds)
        except asyncio.TimeoutError:
            if waiter.stalled:
                self._ended_stalled(waiter, key)
                return None
            self._waiting.pop(key, None)  # an answer after this counts as late
            if waiter.entry is not None:
                self.trace.finish(waiter.entry, Outcome.FAILED, "no answer")
            error = RootlangError.of(
                "E203",
                origin.span,
                command=Code(waiter.entry.text if waiter.entry else waiter.name, quoted=False),
                seconds=seconds_text(seconds),
            )
            raise _NoAnswer(error) from None

    async def _await_early(
        self,
        waiter: _Waiter,
        key: tuple[str, int],
        early: float,
        start: Pose,
        fields: Mapping[str, Any],
        origin: Origin,
    ) -> Packet | object | None:
        """Wait for a movement's answer as long as a robot moving at a usual speed needs; if it
        has not come by then, the pose tells at once what the full timeout would tell later:
        at the movement's end, the answer was lost (done; a late one is absorbed); still at
        the start, the command never arrived (_NoAnswer: it is sent again). Anything else:
        _KEEP_WAITING (it may be slow, or held up)."""
        try:
            return await _within(waiter.future, early)
        except asyncio.TimeoutError:
            pass
        if not self.supports(WHERE):
            return _KEEP_WAITING
        try:
            await self.read(WHERE, origin, "get position")
        except RootlangError:
            return _KEEP_WAITING
        if waiter.future.done():
            return waiter.future.result()
        now = self.state.pose
        if same_place(now, expected_pose(start, waiter.name, fields)):
            self._forget(waiter, key)
            if waiter.entry is not None:
                self.trace.finish(waiter.entry, Outcome.DONE, f"{now.text()} (answer lost)")
            self.stats.recovered += 1
            self._pose_known = not self._wheels_turning
            return None
        if same_place(now, start) and waiter.stalled:
            self._ended_stalled(waiter, key)
            return None
        if same_place(now, start):
            self._waiting.pop(key, None)
            if waiter.entry is not None:
                self.trace.finish(waiter.entry, Outcome.FAILED, "never arrived")
            command = Code(waiter.entry.text if waiter.entry else waiter.name, quoted=False)
            error = RootlangError.of("E203", origin.span, command=command, seconds="its time")
            raise _NoAnswer(error)
        return _KEEP_WAITING

    def _ended_stalled(self, waiter: _Waiter, key: tuple[str, int]) -> None:
        """A movement whose answer has not come, but whose motor stalled (the robot said so in
        a stall event): it ends there, as the robot reports it, never as silence (E203) or a
        resend; its answer, if it still comes, is absorbed."""
        self._forget(waiter, key)
        if waiter.entry is not None:
            self.trace.finish(waiter.entry, Outcome.DONE, f"{self.state.pose.text()} (stalled)")
        self._pose_known = False

    def _forget(self, waiter: _Waiter, key: tuple[str, int]) -> None:
        """Stop waiting for an answer that will still come: it is absorbed when it does."""
        if self._waiting.get(key) is waiter:
            del self._waiting[key]
            self._absorb.add(key)

    def _interrupt(self, group: Actuator) -> None:
        older = self._active.pop(group, None)
        if older is None or older.future.done():
            return
        self.stats.interrupted += 1
        if older.entry is not None:
            self.trace.finish(older.entry, Outcome.INTERRUPTED)
        older.future.set_result(None)
        for key, waiter in list(self._waiting.items()):
            if waiter is older:
                self._forget(waiter, key)

    def _fail_all(self, reason: LinkLost) -> None:
        for waiter in self._waiting.values():
            if not waiter.future.done():
                waiter.future.set_exception(RootlangError.of("E208", reason=reason))
                waiter.future.exception()  # retrieved: a waiter may already be cancelled
        self._waiting.clear()

    # ---- reading sensors that send no events ------------------------------------------------

    async def read(self, name: str, origin: Origin, what: str) -> Packet | None:
        """Send the Get command ``name`` and return its response; concurrent readers share one
        request. ``what`` names the sensor for the "this robot can't" error."""
        pending = self._reads.get(name)
        if pending is None:
            pending = asyncio.ensure_future(self._read(name, origin, what))
            self._reads[name] = pending
            pending.add_done_callback(lambda _: self._reads.pop(name, None))
        return await asyncio.shield(pending)

    async def _read(self, name: str, origin: Origin, what: str) -> Packet | None:
        """A Get changes nothing on the robot, so an unanswered one is simply asked again."""
        for _ in range(READ_ATTEMPTS - 1):
            try:
                return await self._command_once(
                    name, {}, origin, what, READ_ANSWER_SECONDS, reading=True
                )
            except _NoAnswer:
                self.stats.resent += 1
        try:
            return await self._command_once(
                name, {}, origin, what, READ_ANSWER_SECONDS, reading=True
            )
        except _NoAnswer as missing:
            raise missing.error from None

    # ---- packets from the robot -------------------------------------------------------------

    def _received(self, data: bytes) -> None:
        try:
            packet = decode(bytes(data), sender="robot", robot=self.model)
        except PacketError:
            self.stats.corrupt_packets += 1
            return
        if isinstance(packet, UnknownPacket):
            self.stats.unknown_packets += 1
            return
        kind = packet.spec.kind
        if kind is Kind.EVENT:
            self._event(packet)
        elif kind is Kind.RESPONSE:
            self._response(packet)

    def _response(self, packet: Packet) -> None:
        key = (packet.name, packet.id)
        self._update_state(packet)
        waiter = self._waiting.pop(key, None)
        if waiter is not None:
            self.stats.responses += 1
            self._answered.add(key)
            if waiter.entry is not None:
                self.trace.finish(waiter.entry, Outcome.DONE, _response_detail(packet))
            if not waiter.future.done():
                waiter.future.set_result(packet)
        elif key in self._absorb:
            self._absorb.discard(key)
            self._answered.add(key)
        elif key in self._answered:
            self.stats.duplicates += 1
        else:  # given up on (timed out), or never asked for
            self.stats.late_responses += 1
            self._answered.add(key)

    def _event(self, packet: Packet) -> None:
        order = self._event_ids.observe(packet.id).order
        if order is EventOrder.REPEAT:
            self.stats.duplicates += 1
            return
        if order is EventOrder.GAP:
            self.stats.event_id_gaps += 1
        self.stats.events += 1
        if packet.spec.role is Role.STALL and packet["cause"] != StallCause.NO_STALL:
            moving = self._active.get(Actuator.MOTION)
            if moving is not None:  # the robot has the movement: it is stuck, not deaf
                moving.stalled = True
        before = self.state
        self._update_state(packet)
        self.on_event(packet, before, self.state)

    def _update_state(self, packet: Packet) -> None:
        new_state = state_after(self.state, packet)
        if new_state is not None:
            self.state = new_state
            if self.on_state is not None:
                self.on_state(new_state)
            if packet.spec.kind is Kind.RESPONSE and packet.fields.keys() >= POSE_FIELDS:
                self._pose_known = not self._wheels_turning


def state_after(state: SensorState, packet: Packet) -> SensorState | None:
    """The sensor state once ``packet`` has been seen (None: the packet tells nothing new)."""
    reader = _PACKET_READERS.get(packet.spec.name)
    return None if reader is None else reader(state, packet.fields)


_Reader = Callable[[SensorState, Mapping[str, Any]], SensorState]


def _pose(state: SensorState, values: Mapping[str, Any]) -> SensorState:
    return _replaced(state, pose=_pose_told(values))


def _pose_told(values: Mapping[str, Any]) -> Pose:
    """The pose a packet with one tells (its heading in decidegrees)."""
    return Pose(float(values["x"]), float(values["y"]), values["heading"] / 10.0)


def _light_percent(values: Mapping[str, Any]) -> tuple[float, float]:
    return (values["left"] / 10.0, values["right"] / 10.0)


def _acceleration(values: Mapping[str, Any]) -> tuple[float, float, float]:
    return (values["x"] / 1000.0, values["y"] / 1000.0, values["z"] / 1000.0)


# What each reading a packet tells (its row of the packet table says which) does to the state
# (a table, not a chain of tests: the simulator sends ~20 colour events a second).
_READERS: dict[Tells, _Reader] = {
    Tells.BUMPERS: lambda state, values: _replaced(state, bumpers=BumperState(values["state"])),
    Tells.TOUCH: lambda state, values: _replaced(state, touch=TouchSensors(values["state"])),
    Tells.COLORS: lambda state, values: _replaced(state, colors=tuple(values["colors"])),
    Tells.LIGHT: lambda state, values: _replaced(
        state, light_state=LightState(values["state"]), light_percent=_light_percent(values)
    ),
    Tells.LIGHT_LEVELS: lambda state, values: _replaced(
        state, light_percent=_light_percent(values)
    ),
    Tells.CLIFF: lambda state, values: _replaced(state, cliff=bool(values["cliff"])),
    Tells.BATTERY: lambda state, values: _replaced(state, battery_percent=float(values["percent"])),
    Tells.DOCKED: lambda state, values: _replaced(state, docked=bool(values["contacts"])),
    Tells.IR: lambda state, values: _replaced(
        state, ir_triggered=int(values["state"]), ir_values=tuple(values["sensors"])
    ),
    Tells.ACCELERATION: lambda state, values: _replaced(
        state, acceleration_g=_acceleration(values)
    ),
}
# every packet with a pose tells it (motion answers, Get Position), whatever else it tells
_PACKET_READERS: dict[str, _Reader] = {
    **{each.name: _READERS[each.tells] for each in PACKETS if each.tells is not None},
    **{each.name: _pose for each in PACKETS if set(each.field_names) >= POSE_FIELDS},
}


def _replaced(state: SensorState, **changes: Any) -> SensorState:
    """``dataclasses.replace`` without its per-call field scan and ``__init__``: events come
    every few tens of milliseconds, and a reading has nothing to check or derive."""
    readings = state.__dict__.copy()  # (a copy of the table: cheaper than filling a new one)
    readings.update(changes)
    if len(readings) != len(state.__dict__):
        raise TypeError(f"SensorState has no reading {set(changes) - set(state.__dict__)}")
    return unchecked(SensorState, readings)


def behaviour(name: str) -> Behaviour:
    """How the command ``name`` behaves: its row of the packet table says."""
    return spec(name).behaviour


def timeout_for(name: str, fields: Mapping[str, Any]) -> float:
    """Seconds to wait for a command's answer: its way (the table's), slowly, plus a margin;
    a turn as its wheels go, on the wider robot; an arc as its outer wheel goes."""
    way = behaviour(name).way(fields)
    seconds = way.along_mm / TIMEOUT_SPEED_MM_S + _turn_seconds(way.turned_degrees) + way.seconds
    return float(seconds) + TIMEOUT_MARGIN_S


def expected_pose(start: Pose, name: str, fields: Mapping[str, Any]) -> Pose:
    """Where the command ``name`` leaves a robot that starts at ``start``, run to its end."""
    return Pose(*behaviour(name).end(start.place, fields))


def same_place(a: Pose, b: Pose) -> bool:
    """Whether two poses are one place, within what odometry and rounding blur."""
    return same_places(a.place, b.place)


def early_check_seconds(name: str, fields: Mapping[str, Any]) -> float:
    """When a movement's missing answer is worth a look at the pose: how long it takes at
    EARLY_CHECK_SPEED_MM_S and EARLY_CHECK_TURN_DEGREES_S (slower than either robot's usual
    pace; an arc's turn while it drives, else one after the other), plus
    EARLY_CHECK_MARGIN_S (longer than a stall takes to end a movement)."""
    way = behaviour(name).way(fields)
    driving = way.along_mm / EARLY_CHECK_SPEED_MM_S
    turning = way.turned_degrees / EARLY_CHECK_TURN_DEGREES_S
    moving = max(driving, turning) if way.at_once else driving + turning
    return float(moving + way.seconds) + EARLY_CHECK_MARGIN_S


def _turn_seconds(degrees: float) -> float:
    return abs(math.radians(degrees)) * TIMEOUT_WHEELBASE_MM / 2 / TIMEOUT_SPEED_MM_S


def _describe(name: str, fields: Mapping[str, Any]) -> str:
    shown = " ".join(f"{key}={value}" for key, value in fields.items())
    return f"{name} {shown}".strip()


def _response_detail(packet: Packet) -> str:
    values = packet.fields
    return _pose_told(values).text() if values.keys() >= POSE_FIELDS else ""


_T = TypeVar("_T")


async def _within(future: asyncio.Future[_T], seconds: float) -> _T:
    """The future's result, or TimeoutError after ``seconds`` (the future goes on). Not
    ``wait_for(shield(...))``: before Python 3.12 that loses a cancellation (a stop) that
    comes just as the answer does, and the script would run on."""
    done, _ = await asyncio.wait((future,), timeout=seconds)
    if not done:
        raise asyncio.TimeoutError
    return future.result()
