"""The virtual robot: takes the same 20-byte packets a real Root or Create 3 takes, and answers.

Any host that speaks the protocol can drive it::

    robot = VirtualRobot(load_world(BUILT_IN_WORLDS / "arena.toml"))
    robot.write(encode("drive_distance", {"distance": 100}, packet_id=1))
    robot.advance(2.0)                       # two simulated seconds
    for packet in robot.read():              # responses and events, oldest first
        print(decode(packet, "robot"))

Time is the robot's own: simulated milliseconds since power-on, moved on only by
:meth:`advance` / :meth:`advance_to` in fixed physics steps (5 ms by default). Nothing here reads
a clock; :class:`rootlang.sim.transport.SimTransport` ties it to one.

Dispatch goes by packet name through :data:`rootlang.sim.commands.HANDLERS` (the firmware's
command handlers); no device or command number appears here.
What each command does, and the choices made where the spec is silent, are in docs/simulator.md.
"""

from __future__ import annotations

import functools
import heapq
import itertools
import math
from collections.abc import Callable
from dataclasses import dataclass

from rootlang.protocol import (
    PACKETS,
    BumperState,
    DockResult,
    DockStatus,
    GravityCompensation,
    Kind,
    LightState,
    Motor,
    Packet,
    PacketError,
    StallCause,
    TouchSensors,
    decode,
    encode,
    spec,
)
from rootlang.protocol.fields import COLOR_SENSORS
from rootlang.robots import RobotModel
from rootlang.runtime.transport import RobotInfo
from rootlang.sim import motion
from rootlang.sim.commands import HANDLERS, tool_position
from rootlang.sim.models import (
    COLOR_SENSOR_AHEAD,
    COLOR_SENSOR_SPAN,
    ERASER_BEHIND,
    ERASER_WIDTH,
    EYE_AHEAD,
    EYE_SIDE,
    IR_ANGLES,
    IR_RANGE,
    MARKER_WIDTH,
    ModelSpec,
    spec_for,
)
from rootlang.sim.motion import Movement
from rootlang.sim.physics import Physics
from rootlang.sim.recording import (
    FRAME_INTERVAL_MS,
    Frame,
    Happening,
    LedMode,
    LightChange,
    Note,
    Recording,
    Stroke,
    Tool,
    quantise_heading,
)
from rootlang.sim.sensors import (
    FloorRaster,
    body_point,
    dock_ir,
    docked_pose,
    ir_counts,
    light_level,
    sensor_color,
)
from rootlang.sim.world import Stimulus, World, default_world

STEP_MS = 10  # physics step: 1 mm of a Root's travel at full speed (see docs/simulator.md)
SENSE_MS = 40  # bumpers (debounced), cliff, stall, colour sensors, the marker's ink, recording
LIGHT_MS = 120
IR_MS = 80
BUMPER_MIDDLE = 15.0  # degrees: a touch this near straight ahead presses both bumpers
STALL_MS = 1000  # a wheel held below a quarter of its speed this long has stalled
ALL_EVENTS = (1 << 128) - 1
LIGHT_DARK, LIGHT_DIFFERENCE = 20.0, 5.0  # percent (chosen)
CLIFF_FLOOR_MV, CLIFF_DROP_MV, CLIFF_THRESHOLD_MV = 2000, 100, 1000
IR_DEFAULT_THRESHOLD, IR_DEFAULT_HYSTERESIS = 500, 50
IDLE_BATTERY_SHARE = 1 / 3  # standing still drains a third of what driving does

Pose = tuple[float, float, float]


@dataclass(frozen=True, slots=True)  # one for every packet of a run: slots keep them small
class PacketRecord:
    """One packet that crossed the link: ``->`` to the robot, ``<-`` from it.

    ``note`` says why a packet was dropped; otherwise the packet is decoded only when shown."""

    t_ms: int
    direction: str
    data: bytes
    note: str = ""

    def describe(self) -> str:
        if self.note:
            return self.note
        try:
            return str(decode(self.data, "host" if self.direction == "->" else "robot"))
        except PacketError as error:
            return f"damaged: {error.diagnostics[0].message}"

    def __str__(self) -> str:
        return f"{self.t_ms:>8} ms  {self.direction} {self.data.hex()}  {self.describe()}"


@dataclass
class _Sound:
    packet: Packet
    note: Note | None
    timer: int  # sequence number of its end timer


class VirtualRobot:
    """A simulated robot in a world, driven by packets (see the module's docstring)."""

    def __init__(
        self,
        world: World | None = None,
        *,
        model: RobotModel | None = None,
        step_ms: int = STEP_MS,
        on_packet: Callable[[bytes], None] | None = None,
        keep_history: bool = True,
    ) -> None:
        world = world or default_world()
        if model is not None:
            world = world.with_model(model)
        self.world = world
        self.spec: ModelSpec = spec_for(world.robot.model)
        self.model = world.robot.model
        self.step_ms = step_ms
        self.on_packet = on_packet
        self.on_disconnect: Callable[[str], None] | None = None
        self.now_ms = 0
        self.connected = True
        self.name = world.robot.name or self.spec.default_name
        start = world.robot
        self.physics = Physics(world, self.spec, start.x, start.y, start.heading)
        self.raster = FloorRaster(world) if self.spec.has_color_sensor else None
        self._ink = sensor_color(world.robot.marker_color)  # what the colour sensors see of it
        self.recording = Recording(world, self.model)
        # a robot served for hours (rootlang virtual-robot) keeps no packet log, frames or
        # stroke points: they would only grow
        self.keep_history = keep_history
        self.packet_log: list[PacketRecord] = []
        self.ignored: list[str] = []  # packets the robot did not act on, and why
        self._outbox: list[bytes] = []
        self._timers: list[tuple[int, int, Callable[[], None]]] = []
        self._sequence = itertools.count()
        self._cancelled: set[int] = set()
        self._event_id = 0
        self._last_host_id: int | None = None
        self._enabled = ALL_EVENTS
        self._event_bits = {  # the events this model sends -> their device's bit in _enabled
            packet.name: 1 << int(packet.device)
            for packet in PACKETS
            if packet.kind is Kind.EVENT and packet.supported_by(self.model, self.spec.protocol)
        }
        # motion
        self._origin: Pose = self.physics.pose
        self._movement: Movement | None = None
        self._wanted = (0.0, 0.0)  # wheel speeds asked for
        self._wheels = (0.0, 0.0)  # wheel speeds now (ramped)
        self._blocked_ms = [0, 0]
        self._stalled = [False, False]
        # (active, amount): the spec's defaults (on while the marker is down, 50%)
        self.gravity_compensation: tuple[int, int] = (GravityCompensation.MARKER_DOWN, 500)
        # marker, lights, sound
        self._tool: Tool = "up"
        self._marker_move: tuple[Packet, int, Tool] | None = None
        self._stroke: Stroke | None = None
        self._stroke_tip = (0.0, 0.0)  # where the marker (or the eraser's middle) last was
        self._eraser_bar = ((0.0, 0.0), (0.0, 0.0))  # the eraser's ends, last time
        self._led: tuple[LedMode, tuple[int, int, int]] = ("off", (0, 0, 0))
        self._sound: _Sound | None = None
        self._pending_sweep: Packet | None = None
        # sensors (each reads at the first physics step at or after a multiple of its period)
        self._next_sense_ms, self._next_light_ms, self._next_ir_ms = SENSE_MS, LIGHT_MS, IR_MS
        self._sensed_pose: Pose = self.physics.pose
        self._floor_pose: Pose = self._sensed_pose
        self._colors = bytes(COLOR_SENSORS)
        self._color_row = self._color_sensor_row(self._sensed_pose)
        self._bumpers = BumperState.NONE
        self._felt: dict[int, tuple[float, float]] = {}  # touches: lowest, highest angle felt
        self._touch = 0
        self._cliff = False
        self._light_state = self._light_reading(self._sensed_pose)[0]  # known, not announced
        self._ir_state = 0
        self._ir_thresholds = [IR_DEFAULT_THRESHOLD] * 7
        self._ir_hysteresis = IR_DEFAULT_HYSTERESIS
        self._dock: tuple[int, ...] = (0, 0, 0, 0)  # contacts, IR sensors 0-2
        self._picked_up = False
        self._tilt = (0.0, 0.0)
        self._battery = start.battery
        self._battery_reported = start.battery
        self._battery_counted_ms = 0
        self._last_frame_ms = -FRAME_INTERVAL_MS
        self._place_on_dock_if_there()
        self._record_frame(force=True)
        self._first_readings_timer: int | None = self._at(SENSE_MS, self._first_readings)
        for stimulus in world.stimuli:
            self._at(round(stimulus.at * 1000), functools.partial(self.stimulate, stimulus))

    # --- the public packet API ---------------------------------------------------------------

    @property
    def info(self) -> RobotInfo:
        return RobotInfo(
            model=self.model,
            name=self.name,
            serial=self.spec.serial,
            firmware=self.spec.firmware_text,
            hardware=".".join(map(str, self.spec.hardware)),
            protocol_version=self.spec.protocol,
        )

    @property
    def time(self) -> float:
        """Simulated seconds since power-on."""
        return self.now_ms / 1000

    def write(self, data: bytes) -> None:
        """Receive one packet from the host, at the robot's current time."""
        try:
            packet = decode(bytes(data), "host", robot=self.model)
        except PacketError as error:
            self._log("->", bytes(data), f"dropped: {error.diagnostics[0].message}")
            return
        self._log("->", bytes(data))
        if not isinstance(packet, Packet):
            self._ignore(f"{packet}: not a packet this robot knows")
            return
        if packet.id != 0 and packet.id == self._last_host_id:
            self._ignore(f"{packet.name} #{packet.id}: a repeat of the last packet's id")
            return
        self._last_host_id = packet.id
        if not packet.spec.supported_by(self.model, self.spec.protocol):
            needs = ".".join(map(str, packet.spec.min_protocol))
            self._ignore(
                f"{packet.name}: not supported by {self.model.display_name} "
                f"(protocol {'.'.join(map(str, self.spec.protocol))}; needs {needs})"
            )
            return
        if not self.connected:
            self._ignore(f"{packet.name}: the robot has disconnected")
            return
        HANDLERS[packet.name](self, packet)

    def read(self) -> list[bytes]:
        """The packets the robot sent since the last read (when no ``on_packet`` is set)."""
        packets, self._outbox = self._outbox, []
        return packets

    def advance(self, seconds: float) -> None:
        self.advance_to(self.time + seconds)

    def advance_to(self, seconds: float) -> None:
        """Run the world up to ``seconds`` since power-on (in whole physics steps)."""
        target = math.floor(seconds * 1000 + 1e-6)
        step = self.step_ms
        while self.now_ms + step <= target:
            if self._resting():
                self._settle()
                until = target if not self._timers else min(target, self._timers[0][0])
                until -= (until - self.now_ms) % step
                if until > self.now_ms:
                    self.now_ms = until
                    self._drain_battery(moving=False)
                    self._fire_timers()
                    continue
            self._step()
            self._fire_timers()

    def next_wakeup(self) -> float | None:
        """When (simulated seconds) the robot may next have something to say, or None if it
        only will after a packet: its next timer (a note ending, a scripted touch), and while it
        moves also its next sensor reading and about when the movement ends."""
        due = self._timers[0][0] if self._timers else None
        if self._resting():
            battery = self._battery_event_due()
            if battery is not None:
                due = battery if due is None else min(due, battery)
            return None if due is None else due / 1000
        step = self.step_ms
        candidates = [max(self._next_sense_ms, self.now_ms + step)]
        if due is not None:
            candidates.append(due)
        if self._movement is not None:
            leg = self._movement.leg
            left = None if leg is None else leg.seconds_left()
            ahead = step if left is None else max(step, math.ceil(left * 1000 / step) * step)
            candidates.append(self.now_ms + ahead)
        return min(candidates) / 1000

    def press_nose(self) -> None:
        """The nose button (Create 3: power button) is pressed now."""
        self.stimulate(Stimulus(self.time, "nose"))

    def disconnect(self, reason: str = "the host disconnected") -> None:
        """The link is gone: the robot stops, as a real one does when its app goes away."""
        if self.connected:
            self.connected = False
            self._stop_everything(respond=False)
            self.recording.events.append(Happening(self.now_ms, f"disconnected: {reason}"))

    def connect(self) -> None:
        """A (new) connection: the robot resets its position, as the spec says, and tells
        what its sensors found at power-on (if it has not yet)."""
        self.connected = True
        self._reset_origin()
        self._first_readings()

    @property
    def pose(self) -> tuple[int, int, int]:
        """The robot's own estimate, as Get Position reports it: x, y mm and heading decidegrees."""
        return self._odometry(self.physics.pose)

    @property
    def world_pose(self) -> Pose:
        return self.physics.pose

    # --- sending ------------------------------------------------------------------------------

    def _log(self, direction: str, data: bytes, note: str = "") -> None:
        if self.keep_history:
            self.packet_log.append(PacketRecord(self.now_ms, direction, data, note))

    def _ignore(self, why: str) -> None:
        self.ignored.append(why)

    def _emit(self, data: bytes) -> None:
        self._log("<-", data)
        if self.on_packet is not None:
            self.on_packet(data)
        else:
            self._outbox.append(data)

    def _respond(self, request: Packet, **fields: object) -> None:
        answer = request.spec.response
        assert answer is not None, request.name
        data = encode(answer.name, fields, request.id, robot=self.model)
        self._emit(data)

    def _event(self, name: str, **fields: object) -> None:
        device_bit = self._event_bits.get(name)
        if device_bit is None:
            spec(name)  # a misspelt name raises; else the model lacks the event
            return
        if not self.connected or not self._enabled & device_bit:
            return
        data = encode(name, fields, self._event_id, robot=self.model)
        self._emit(data)
        self._event_id = (self._event_id + 1) % 256

    # --- timers (simulated milliseconds) ----------------------------------------------------

    def _at(self, t_ms: int, action: Callable[[], None]) -> int:
        number = next(self._sequence)
        heapq.heappush(self._timers, (max(t_ms, self.now_ms), number, action))
        return number

    def _cancel(self, number: int) -> None:
        self._cancelled.add(number)

    def _fire_timers(self) -> None:
        while self._timers and self._timers[0][0] <= self.now_ms:
            _, number, action = heapq.heappop(self._timers)
            if number in self._cancelled:
                self._cancelled.discard(number)
            else:
                action()

    # --- the world moving on -----------------------------------------------------------------

    def _resting(self) -> bool:
        return (
            self._movement is None
            and self._wanted == (0.0, 0.0)
            and self._wheels == (0.0, 0.0)
            and self.physics.is_still()
        )

    def _step(self) -> None:
        if self._movement is not None:
            self._steer(self._movement)
        (left, right), (want_left, want_right) = self._wheels, self._wanted
        if left != want_left or right != want_right:
            # both wheels change in proportion, so an arc keeps its radius while speeding up
            most = self.spec.acceleration * self.step_ms / 1000
            change = max(abs(want_left - left), abs(want_right - right))
            share = min(1.0, most / change)
            left += (want_left - left) * share
            right += (want_right - right) * share
            self._wheels = (left, right)
        if self._picked_up:  # wheels spin in the air
            self.physics.step(0.0, 0.0, self.step_ms / 1000)
        else:
            self.physics.step(left, right, self.step_ms / 1000)
        self.now_ms += self.step_ms
        if self.now_ms >= self._next_sense_ms:
            self._next_sense_ms = _next_multiple(self.now_ms, SENSE_MS)
            self._sense()

    def _steer(self, movement: Movement) -> None:
        pose = self.physics.pose
        leg = movement.leg
        if leg is not None:
            leg.measure(pose)
            if leg.finished():
                leg = None
                self._brake()  # hard, on the mark
        if leg is None:
            leg = movement.next_leg(pose)
        if leg is None:
            self._finish_movement(DockStatus.SUCCEEDED)
            return
        self._wanted = leg.wheel_targets(
            self.spec.wheel_base, self.spec.max_speed, self.spec.acceleration
        )

    def _drain_battery(self, *, moving: bool) -> None:
        """Use up the battery for the time since it was last counted."""
        ms, self._battery_counted_ms = self.now_ms - self._battery_counted_ms, self.now_ms
        share = 1.0 if moving else IDLE_BATTERY_SHARE
        self._battery = max(
            0.0, self._battery - self.world.robot.battery_drain * share * ms / 60000
        )
        if self._battery_reported - self._battery >= 10:
            self._battery_reported = self._battery
            self._event("battery_level_event", timestamp=self.now_ms, **self._battery_fields())

    def _battery_event_due(self) -> int | None:
        """When, standing still, the battery will have dropped enough for its next event."""
        per_ms = self.world.robot.battery_drain * IDLE_BATTERY_SHARE / 60000
        if per_ms <= 0 or self._battery <= 0:
            return None
        to_go = self._battery - max(0.0, self._battery_reported - 10)
        steps = math.ceil(to_go / per_ms / self.step_ms)
        return self.now_ms + max(1, steps) * self.step_ms

    def _battery_fields(self) -> dict[str, int]:
        low, high = self.spec.battery_mv
        percent = round(self._battery)
        return {"voltage": round(low + (high - low) * self._battery / 100), "percent": percent}

    # --- sensing ------------------------------------------------------------------------------

    def _sense(self) -> None:
        pose = self.physics.pose
        moved = pose != self._sensed_pose
        self._drain_battery(moving=self._wheels != (0.0, 0.0))
        if self.physics.touching or self._felt:  # at the sensing rate: a debounced bumper
            self._sense_bumpers()
        self._check_stall()
        if moved:
            self._sense_floor(pose)
        if moved and self.spec.has_dock:
            self._sense_dock(pose)
        if moved or self._picked_up != self._cliff:
            self._sense_cliff(pose)
        if self._cliff and not self._picked_up and sum(self._wanted) > 0:
            self._stop_wheels(DockStatus.ABORTED)  # and it will not drive on over an edge
        if moved and self.spec.has_light_sensors and self.now_ms >= self._next_light_ms:
            self._next_light_ms = _next_multiple(self.now_ms, LIGHT_MS)
            self._sense_light(pose)
        if moved and self.spec.has_ir_proximity and self.now_ms >= self._next_ir_ms:
            self._next_ir_ms = _next_multiple(self.now_ms, IR_MS)
            self._sense_ir(pose)
        self._sensed_pose = pose
        self._record_frame()

    def _first_readings(self) -> None:
        """Just after power-on, the sensors that found something say so: colours other than
        white, a dock the robot sits on, a cliff it starts over (a host assumes none)."""
        if self._first_readings_timer is None:
            return
        self._cancel(self._first_readings_timer)
        self._first_readings_timer = None
        pose = self.physics.pose
        if self.raster is not None:
            self._sense_colors(pose)
        if self._dock[0]:
            self._event("docking_sensor_event", timestamp=self.now_ms, **self._dock_fields())
        self._sense_cliff(pose)

    def _sense_floor(self, pose: Pose) -> None:
        """Ink and colour sensors, for the path since they last looked."""
        if pose == self._floor_pose:
            return
        self._floor_pose = pose
        self._draw(pose)
        if self.raster is not None:
            self._sense_colors(pose)

    def _settle(self) -> None:
        """The robot has come to rest: finish what the sensors and the recording owe."""
        pose = self.physics.pose
        self._sense_floor(pose)
        self._record_frame()

    def _sense_bumpers(self) -> None:
        # each touch keeps the range of angles it has been felt at: a bumper stays pressed for
        # the whole touch, as a real one does while the robot pushes
        now = self.physics.contact_angles()
        felt = {
            key: (min(angle, self._felt[key][0]), max(angle, self._felt[key][1]))
            if key in self._felt
            else (angle, angle)
            for key, angle in now.items()
        }
        self._felt = felt
        left = right = False
        reach = self.spec.bumper_half_angle
        for lowest, highest in felt.values():
            low, high = max(lowest, -reach), min(highest, reach)
            if low > high:
                continue  # felt only behind the bumper
            left |= high > -BUMPER_MIDDLE
            right |= low < BUMPER_MIDDLE
        state = BumperState((BumperState.LEFT if left else 0) | (BumperState.RIGHT if right else 0))
        if state != self._bumpers:
            self._bumpers = state
            self._happened(f"bumper {str(state.name).lower()}")
            self._event("bumper_event", timestamp=self.now_ms, state=state)

    def _check_stall(self) -> None:
        if self._wanted == (0.0, 0.0) or self._picked_up:
            self._blocked_ms = [0, 0]
            self._stalled = [False, False]
            return
        actual = self.physics.wheel_speeds()
        for motor in (0, 1):
            want = self._wanted[motor]
            if abs(want) > 10 and abs(actual[motor]) < abs(want) / 4:
                self._blocked_ms[motor] += SENSE_MS
            else:
                self._blocked_ms[motor], self._stalled[motor] = 0, False
        if max(self._blocked_ms) < STALL_MS:
            return  # the usual case: neither wheel held back for long
        stalled = [m for m in (0, 1) if self._blocked_ms[m] >= STALL_MS and not self._stalled[m]]
        for motor in stalled:
            self._stalled[motor] = True
            self._happened(f"{Motor(motor).name.lower()} motor stalled")
            self._event(
                "motor_stall_event", timestamp=self.now_ms, motor=Motor(motor),
                cause=StallCause.UNDERSPEED,
            )  # fmt: skip
        if stalled and self._movement is not None:
            self._finish_movement(DockStatus.ABORTED)  # the firmware gives up on a blocked move

    def _color_sensor_row(self, pose: Pose) -> tuple[tuple[float, float], tuple[float, float]]:
        half = COLOR_SENSOR_SPAN / 2
        return (
            body_point(pose, COLOR_SENSOR_AHEAD, half), body_point(pose, COLOR_SENSOR_AHEAD, -half)
        )  # fmt: skip

    def _sense_colors(self, pose: Pose) -> None:
        assert self.raster is not None
        before, after = self._color_row, self._color_sensor_row(pose)
        self._color_row = after
        if self.raster.plain or self._picked_up:
            return
        travel = max(math.dist(before[0], after[0]), math.dist(before[1], after[1]))
        rows = max(1, min(64, math.ceil(travel / 2)))  # a sample every 2 mm of travel
        sampled = self.raster.sweep(before, after, rows)
        final = sampled[-COLOR_SENSORS:]
        if final != self._colors:  # one event a reading for what is under the sensors now ...
            self._colors = final
            self._event("color_sensor_event", colors=final)
            return
        # ... or, if that has not changed, two for a line crossed on the way (a thin line that
        # was under the sensors only for a moment between two readings)
        n = COLOR_SENSORS
        crossed = (sampled[n * k : n * k + n] for k in range(rows - 1))
        passing = next((row for row in crossed if row != final), None)
        if passing is not None:
            self._event("color_sensor_event", colors=passing)
            self._event("color_sensor_event", colors=final)

    def _sense_cliff(self, pose: Pose) -> None:
        if not self.spec.has_cliff_sensor:
            return
        x, y = body_point(pose, self.spec.cliff_ahead, 0)
        cliff = self._picked_up or not self.world.on_table(x, y)
        if cliff == self._cliff:
            return
        self._cliff = cliff
        self._happened("cliff" if cliff else "cliff cleared")
        self._event(
            "cliff_event", timestamp=self.now_ms, cliff=int(cliff),
            sensor=CLIFF_DROP_MV if cliff else CLIFF_FLOOR_MV, threshold=CLIFF_THRESHOLD_MV,
        )  # fmt: skip

    def _eyes(self, pose: Pose) -> tuple[int, int]:
        left = light_level(self.world, body_point(pose, EYE_AHEAD, EYE_SIDE))
        right = light_level(self.world, body_point(pose, EYE_AHEAD, -EYE_SIDE))
        return round(left * 10), round(right * 10)

    def _sense_light(self, pose: Pose) -> None:
        state, left, right = self._light_reading(pose)
        if state != self._light_state:
            self._light_state = state
            self._event("light_event", timestamp=self.now_ms, state=state, left=left, right=right)

    def _light_reading(self, pose: Pose) -> tuple[LightState, int, int]:
        left, right = self._eyes(pose)
        if left < LIGHT_DARK * 10 and right < LIGHT_DARK * 10:
            state = LightState.BOTH_DARK
        elif left - right > LIGHT_DIFFERENCE * 10:
            state = LightState.LEFT_BRIGHTER
        elif right - left > LIGHT_DIFFERENCE * 10:
            state = LightState.RIGHT_BRIGHTER
        else:
            state = LightState.BOTH_BRIGHT
        return state, left, right

    def _ir_values(self, pose: Pose) -> list[int]:
        x, y, heading = pose
        radius = self.spec.width / 2
        values = []
        for angle in IR_ANGLES:
            direction = heading + math.radians(angle)
            c, s = math.cos(direction), math.sin(direction)
            start = (x + radius * c, y + radius * s)
            end = (x + (radius + IR_RANGE) * c, y + (radius + IR_RANGE) * s)
            values.append(ir_counts(self.physics.ray(start, end)))
        return values

    def _ir_bits(self, values: list[int]) -> int:
        state = 0
        for i, value in enumerate(values):
            was_on = self._ir_state >> i & 1
            threshold = self._ir_thresholds[i]
            on = value >= threshold or (was_on and value > threshold - self._ir_hysteresis)
            state |= int(on) << i
        return state

    def _sense_ir(self, pose: Pose) -> None:
        values = self._ir_values(pose)
        state = self._ir_bits(values)
        if state != self._ir_state:
            self._ir_state = state
            self._event("ir_proximity_event", timestamp=self.now_ms, state=state, sensors=values)

    def _sense_dock(self, pose: Pose) -> None:
        reading = (int(self._on_dock(pose)), *dock_ir(self.world, pose))
        if reading != self._dock:
            if reading[0] != self._dock[0]:
                self._happened("docked" if reading[0] else "undocked")
            self._dock = reading
            self._event("docking_sensor_event", timestamp=self.now_ms, **self._dock_fields())

    def _dock_fields(self) -> dict[str, int]:
        contacts, ir0, ir1, ir2 = self._dock
        return {"contacts": contacts, "ir_sensor_0": ir0, "ir_sensor_1": ir1, "ir_sensor_2": ir2}

    def _on_dock(self, pose: Pose) -> bool:
        target = docked_pose(self.world)
        if target is None:
            return False
        close = math.dist(pose[:2], target[:2]) < 30
        return close and abs(motion.wrap(pose[2] - target[2])) < math.radians(15)

    def _place_on_dock_if_there(self) -> None:
        if self.spec.has_dock:
            pose = self.physics.pose
            self._dock = (int(self._on_dock(pose)), *dock_ir(self.world, pose))

    # --- drawing and recording ---------------------------------------------------------------

    def _draw(self, pose: Pose) -> None:
        if self._tool == "up" or self._stroke is None:
            return
        if self._tool == "marker":
            point = (pose[0], pose[1])
            if self.raster is not None:
                self.raster.paint(self._stroke_tip, point, MARKER_WIDTH, self._ink)
        else:
            point = body_point(pose, -ERASER_BEHIND, 0)
            if self.raster is not None:
                half = ERASER_WIDTH / 2
                old = self._eraser_bar
                new = (
                    body_point(pose, -ERASER_BEHIND, half), body_point(pose, -ERASER_BEHIND, -half)
                )  # fmt: skip
                self.raster.erase((old[0], old[1], new[1], new[0]))
                self._eraser_bar = new
        self._stroke_tip = point
        self._add_stroke_point(point)

    def _add_stroke_point(self, point: tuple[float, float]) -> None:
        assert self._stroke is not None
        points = self._stroke.points
        if not self.keep_history and points:
            return
        new = (round(point[0]), round(point[1]))
        if points and new == points[-1]:
            return
        if len(points) >= 2 and _collinear(points[-2], points[-1], new):
            points[-1] = new
        else:
            points.append(new)

    def _set_tool(self, tool: Tool) -> None:
        if tool == self._tool:
            return
        self._sense_floor(self.physics.pose)  # the old tool's stroke up to here
        self._tool = tool
        self._stroke = None
        pose = self.physics.pose
        if tool != "up":
            color = self.world.robot.marker_color if tool == "marker" else self.world.floor_color
            width = MARKER_WIDTH if tool == "marker" else ERASER_WIDTH
            self._stroke = Stroke(tool, color.hex, round(width), self.now_ms)
            self.recording.strokes.append(self._stroke)
            tip = (pose[0], pose[1]) if tool == "marker" else body_point(pose, -ERASER_BEHIND, 0)
            half = ERASER_WIDTH / 2
            self._eraser_bar = (
                body_point(pose, -ERASER_BEHIND, half), body_point(pose, -ERASER_BEHIND, -half)
            )  # fmt: skip
            self._stroke_tip = tip
            self._add_stroke_point(tip)
        self._record_frame(force=True)

    def _record_frame(self, *, force: bool = False) -> None:
        if not self.keep_history and self.recording.frames:  # the first frame only
            return
        if not force and self.now_ms - self._last_frame_ms < FRAME_INTERVAL_MS:
            return
        x, y, heading = self.physics.pose
        frame = Frame(
            self.now_ms, round(x), round(y), quantise_heading(heading), self._tool, *self._led
        )
        frames = self.recording.frames
        if frames and not force and _same_state(frames[-1], frame):
            return
        if frames and frames[-1].t_ms == frame.t_ms:
            frames[-1] = frame
        else:
            frames.append(frame)
        self._last_frame_ms = self.now_ms

    def _happened(self, text: str) -> None:
        self.recording.events.append(Happening(self.now_ms, text))

    def finish(self) -> Recording:
        """Close the recording at the current time (a last frame) and return it."""
        self._settle()
        self._record_frame(force=True)
        return self.recording

    # --- pose ---------------------------------------------------------------------------------

    def _reset_origin(self) -> None:
        self._origin = self.physics.pose

    def _odometry(self, pose: Pose) -> tuple[int, int, int]:
        ox, oy, oheading = self._origin
        turn = math.pi / 2 - oheading
        dx, dy = pose[0] - ox, pose[1] - oy
        x = dx * math.cos(turn) - dy * math.sin(turn)
        y = dx * math.sin(turn) + dy * math.cos(turn)
        return round(x), round(y), quantise_heading(pose[2] + turn)

    def _world_from_odometry(self, x: float, y: float) -> tuple[float, float]:
        ox, oy, oheading = self._origin
        turn = math.pi / 2 - oheading
        return (
            ox + x * math.cos(turn) + y * math.sin(turn),
            oy - x * math.sin(turn) + y * math.cos(turn),
        )

    def _pose_fields(self) -> dict[str, int]:
        x, y, heading = self.pose
        return {"timestamp": self.now_ms, "x": x, "y": y, "heading": heading}

    # --- movements ----------------------------------------------------------------------------

    def _start_movement(
        self, movement: Movement | None, wheels: tuple[float, float] = (0.0, 0.0)
    ) -> None:
        """A new movement command: the one in progress ends now, with its response."""
        self._finish_movement(DockStatus.CANCELED)
        self._movement = movement
        self._wanted = wheels
        self._blocked_ms = [0, 0]

    def _finish_movement(self, status: DockStatus) -> None:
        movement, self._movement = self._movement, None
        if movement is None:
            return
        self._wanted = (0.0, 0.0)
        request = movement.request
        if request.name in ("dock", "undock"):
            docked = self._on_dock(self.physics.pose)
            if request.name == "dock" and status is DockStatus.SUCCEEDED and not docked:
                status = DockStatus.ABORTED
            self._sense_dock(self.physics.pose)
            result = DockResult.DOCKED if docked else DockResult.NOT_DOCKED
            self._respond(request, timestamp=self.now_ms, status=status, result=result)
        else:
            self._respond(request, **self._pose_fields())

    def _stop_wheels(self, status: DockStatus) -> None:
        self._finish_movement(status)
        self._brake()

    def _brake(self) -> None:
        """Stop the wheels at once (the motors brake; the body does not coast on)."""
        self._wanted = self._wheels = (0.0, 0.0)
        self.physics.halt()

    def _move(self, packet: Packet, planners: list[motion.Planner]) -> None:
        self._start_movement(Movement(packet, planners))

    def _stop_everything(self, *, respond: bool) -> None:
        if respond:
            self._finish_movement(DockStatus.CANCELED)
        self._movement = None
        self._brake()
        self._stop_sound(respond=respond)
        if self._marker_move is not None:
            self._cancel(self._marker_move[1])
            self._marker_move = None

    # --- stimuli ------------------------------------------------------------------------------

    def stimulate(self, stimulus: Stimulus) -> None:
        """A person does something to the robot now (its ``at`` is ignored): touches it, presses
        the nose button, picks it up or tilts it, as a world's scripted stimuli do."""
        hold_ms = round(stimulus.duration * 1000)
        if stimulus.action == "touch":
            bits = _touch_bits(tuple(s for s in stimulus.sensors if s in self.spec.touch_sensors))
            if bits:
                self._set_touch(self._touch | bits)
                self._at(self.now_ms + hold_ms, lambda: self._set_touch(self._touch & ~bits))
        elif stimulus.action == "nose":
            self._happened("nose button")
            self._stop_everything(respond=False)
            self._reset_origin()
            self._event("stop_project_event")
        elif stimulus.action == "pick_up":
            self._happened("picked up")
            self._picked_up = True
            self._sense_cliff(self.physics.pose)
            self._at(self.now_ms + hold_ms, self._put_down)
        else:
            self._happened(f"tilted pitch {stimulus.pitch:g} roll {stimulus.roll:g}")
            self._tilt = (stimulus.pitch, stimulus.roll)
            self._at(self.now_ms + hold_ms, lambda: setattr(self, "_tilt", (0.0, 0.0)))

    def _put_down(self) -> None:
        self._happened("put down")
        self._picked_up = False
        self._sense_cliff(self.physics.pose)

    def _set_touch(self, bits: int) -> None:
        if bits != self._touch:
            self._touch = bits
            names = [
                str(flag.name).lower().replace("_", " ") for flag in TouchSensors if flag & bits
            ]
            self._happened("touch " + (", ".join(names) or "released"))
            self._event("touch_sensor_event", timestamp=self.now_ms, state=bits)

    # --- sound --------------------------------------------------------------------------------

    def _play(self, packet: Packet, duration_ms: int, note: Note | None) -> None:
        self._stop_sound(respond=True)
        if note is not None:
            self.recording.notes.append(note)
        timer = self._at(self.now_ms + duration_ms, self._sound_finished)
        self._sound = _Sound(packet, note, timer)

    def _sound_finished(self) -> None:
        sound, self._sound = self._sound, None
        if sound is not None:
            self._respond(sound.packet)
        pending, self._pending_sweep = self._pending_sweep, None
        if pending is not None:
            self._start_sweep(pending)

    def _stop_sound(self, *, respond: bool) -> None:
        sound, self._sound = self._sound, None
        pending, self._pending_sweep = self._pending_sweep, None
        if sound is not None:
            self._cancel(sound.timer)
            if sound.note is not None:  # cut the recorded note short
                played = self.now_ms - sound.note.t_ms
                notes = self.recording.notes
                if notes and notes[-1] is sound.note and played < sound.note.duration_ms:
                    notes[-1] = Note(
                        sound.note.t_ms, sound.note.frequency_hz, played, sound.note.end_hz
                    )
            if respond:
                self._respond(sound.packet)
        if pending is not None and respond:
            self._respond(pending)

    def _start_sweep(self, packet: Packet) -> None:
        start, end = packet["start_frequency"] / 1000, packet["end_frequency"] / 1000
        duration = int(packet["duration"])
        self._play(packet, duration, Note(self.now_ms, start, duration, end))

    # --- lights and marker --------------------------------------------------------------------

    def _set_led(self, mode: LedMode, rgb: tuple[int, int, int]) -> None:
        self._led = (mode, rgb)
        self.recording.lights.append(LightChange(self.now_ms, mode, rgb))
        self._record_frame(force=True)

    def _marker_arrived(self) -> None:
        assert self._marker_move is not None
        packet, _, tool = self._marker_move
        self._marker_move = None
        self._set_tool(tool)
        self._respond(packet, position=tool_position(tool))


# --- helpers -------------------------------------------------------------------------------


def _next_multiple(now_ms: int, period_ms: int) -> int:
    return (now_ms // period_ms + 1) * period_ms


def _same_state(a: Frame, b: Frame) -> bool:
    return (a.x_mm, a.y_mm, a.heading_ddeg, a.tool, a.led_mode, a.led_rgb) == (
        b.x_mm, b.y_mm, b.heading_ddeg, b.tool, b.led_mode, b.led_rgb
    )  # fmt: skip


def _collinear(a: tuple[int, int], b: tuple[int, int], c: tuple[int, int]) -> bool:
    """True when b lies on the straight line from a to c (within half a millimetre)."""
    length = math.dist(a, c)
    if length == 0:
        return True
    cross = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    dot = (b[0] - a[0]) * (c[0] - a[0]) + (b[1] - a[1]) * (c[1] - a[1])
    return abs(cross) / length <= 0.5 and 0 <= dot <= length * length


def _touch_bits(names: tuple[str, ...]) -> int:
    flags = {
        "front left": TouchSensors.FRONT_LEFT, "front right": TouchSensors.FRONT_RIGHT,
        "back left": TouchSensors.REAR_LEFT, "back right": TouchSensors.REAR_RIGHT,
    }  # fmt: skip
    bits = 0
    for name in names:
        bits |= flags[name]
    return bits
