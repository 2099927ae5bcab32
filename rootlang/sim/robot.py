"""The virtual robot: takes the same 20-byte packets a real Root or Create 3 takes, and answers.

Any host that speaks the protocol can drive it::

    robot = VirtualRobot(load_world(BUILT_IN_WORLDS / "arena.toml"))
    robot.write(encode("drive_distance", {"distance": 100}, packet_id=1))
    robot.advance(2.0)                       # two simulated seconds
    for packet in robot.read():              # responses and events, oldest first
        print(decode(packet, "robot"))

Time is the robot's own: simulated milliseconds since power-on, moved on only by
:meth:`advance` / :meth:`advance_to` in fixed physics steps (10 ms by default). Nothing here reads
a clock; :class:`rootlang.sim.transport.SimTransport` ties it to one.

The robot is its devices (:mod:`rootlang.sim.devices`, one class per device of the protocol);
this module only moves time on, keeps the timers, steps the body, senses in a fixed order and
hands each packet to the device that acts on it. What each command does, and the choices made
where the spec is silent, are in docs/simulator.md.
"""

from __future__ import annotations

import functools
import heapq
import itertools
import math
from collections.abc import Callable
from typing import NamedTuple

from rootlang.protocol import (
    PACKETS,
    DockStatus,
    Kind,
    Packet,
    PacketError,
    decode,
    encode,
    spec,
)
from rootlang.robots import RobotModel
from rootlang.runtime.transport import RobotInfo
from rootlang.sim.devices import Devices
from rootlang.sim.models import ModelSpec, spec_for
from rootlang.sim.physics import Physics
from rootlang.sim.recording import (
    FRAME_INTERVAL_MS,
    Frame,
    FrameState,
    Happening,
    Recording,
    quantise_heading,
)
from rootlang.sim.world import Stimulus, World, default_world

STEP_MS = 10  # chosen: the physics step, 1 mm of a Root's travel at full speed
SENSE_MS = 40  # chosen: bumpers (debounced), cliff, stall, colour sensors, the ink, recording

OUT_OF_RANGE = "E504"  # the codec's code for a field value beyond its range
Pose = tuple[float, float, float]


class PacketRecord(NamedTuple):  # one for every packet of a run: small, and quick to make
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
            return f"damaged: {error.diagnostics[0].english}"

    def __str__(self) -> str:
        return f"{self.t_ms:>8} ms  {self.direction} {self.data.hex()}  {self.describe()}"


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
        self.on_advanced: Callable[[], None] | None = None  # the world has moved on (to now)
        self.now_ms = 0
        self.connected = True
        self.picked_up = False
        start = world.robot
        self.physics = Physics(world, self.spec, start.x, start.y, start.heading)
        self.recording = Recording(world, self.model)
        # a robot served for hours (rootlang virtual-robot), or a `rootlang sim` run that shows
        # none of it, keeps no packet log, frames (but the first) or stroke points
        self.keep_history = keep_history
        self.packet_log: list[PacketRecord] = []
        self.ignored: list[str] = []  # packets the robot did not act on, and why
        self._outbox: list[bytes] = []
        self._timers: list[tuple[int, int, Callable[[], None]]] = []
        self._sequence = itertools.count()
        self._cancelled: set[int] = set()
        self._event_id = 0
        self._last_host_id: int | None = None
        self._event_bits = {  # the events this model sends -> their device's bit
            packet.name: 1 << int(packet.device)
            for packet in PACKETS
            if packet.kind is Kind.EVENT and packet.supported_by(self.model, self.spec.protocol)
        }
        # sensing: at the first physics step at or after each multiple of SENSE_MS
        self._next_sense_ms = SENSE_MS
        self._sensed_pose: Pose = self.physics.pose
        self._floor_pose: Pose = self._sensed_pose
        self._last_frame_ms = -FRAME_INTERVAL_MS
        self._framed: FrameState | None = None  # what the last frame shows (all but its time)
        self.devices = Devices(self, world.robot.name or self.spec.default_name)
        self._handlers = self.devices.commands()
        self.record_frame(force=True)
        self._first_readings_timer: int | None = self.at(SENSE_MS, self._first_readings)
        for stimulus in world.stimuli:
            self.at(round(stimulus.at * 1000), functools.partial(self.stimulate, stimulus))

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
    def name(self) -> str:
        return self.devices.general.name

    @name.setter
    def name(self, name: str) -> None:
        self.devices.general.name = name

    @property
    def gravity_compensation(self) -> tuple[int, int]:
        """(active, amount) as last set (the spec's defaults at first)."""
        return self.devices.motors.gravity_compensation

    @property
    def time(self) -> float:
        """Simulated seconds since power-on."""
        return self.now_ms / 1000

    def write(self, data: bytes) -> None:
        """Receive one packet from the host, at the robot's current time."""
        data = bytes(data)
        try:
            packet = decode(data, "host", robot=self.model)
            note = ""
        except PacketError as error:
            clamped = self._clamped(data, error)
            if clamped is None:
                self._log("->", data, f"dropped: {error.diagnostics[0].english}")
                return
            packet, note = clamped
            self.happened(note)
        self._log("->", data, note)
        if not isinstance(packet, Packet):
            self.ignore(f"{packet}: not a packet this robot knows")
            return
        if packet.id != 0 and packet.id == self._last_host_id:
            self.ignore(f"{packet.name} #{packet.id}: a repeat of the last packet's id")
            return
        self._last_host_id = packet.id
        if not packet.spec.supported_by(self.model, self.spec.protocol):
            self.ignore(f"{packet.name}: {self._why_unsupported(packet)}")
            return
        if not self.connected:
            self.ignore(f"{packet.name}: the robot has disconnected")
            return
        self._handlers[packet.name](packet)

    def _clamped(self, data: bytes, error: PacketError) -> tuple[Packet, str] | None:
        """A command with a value beyond this model's range that its device clamps instead."""
        if error.spec is None or error.diagnostics[0].code != OUT_OF_RANGE:
            return None
        return self.devices.motors.clamped_to_range(error.spec, data)

    def _why_unsupported(self, packet: Packet) -> str:
        """The model lacks the packet, or its protocol version is too old for it."""
        name = self.model.display_name
        if self.model not in packet.spec.robots:
            return f"not supported by {name} (no {name} has it)"
        speaks, needs = (
            ".".join(map(str, v)) for v in (self.spec.protocol, packet.spec.min_protocol)
        )
        return f"not supported by {name}'s protocol {speaks} (it needs {needs})"

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
        timers = self._timers
        while self.now_ms + step <= target:
            limit = min(target, timers[0][0]) if timers else target
            if self._resting():
                self._settle()
                until = limit - (limit - self.now_ms) % step
                if until > self.now_ms:
                    self.now_ms = until
                    self.devices.battery.drain(moving=False)
                    self._fire_timers()
                    continue
                self._walk_to(limit)  # a timer less than a step away: one step to it
            elif not self._cruise_to(limit):
                self._walk_to(limit)
            if timers and timers[0][0] <= self.now_ms:
                self._fire_timers()
        if self.on_advanced is not None:
            self.on_advanced()

    def next_wakeup(self) -> float | None:
        """When (simulated seconds) the robot may next have something to say, or None if it
        only will after a packet: its next timer (a note ending, a scripted touch), and while it
        moves also its next sensor reading and about when the movement ends."""
        due = self._timers[0][0] if self._timers else None
        step = self.step_ms
        if self._resting():
            battery = self.devices.battery.event_due(step)
            if battery is not None:
                due = battery if due is None else min(due, battery)
            return None if due is None else due / 1000
        soonest = max(self._next_sense_ms, self.now_ms + step)
        if due is not None and due < soonest:
            soonest = due
        if soonest > self.now_ms + step:  # (a movement ends a step from now at the soonest)
            finish = self.devices.motors.ms_to_finish(step)
            if finish is not None:
                soonest = min(soonest, self.now_ms + finish)
        return soonest / 1000

    def press_nose(self) -> None:
        """The nose button (Create 3: power button) is pressed now."""
        self.stimulate(Stimulus(self.time, "nose"))

    def stimulate(self, stimulus: Stimulus) -> None:
        """A person does something to the robot now (its ``at`` is ignored): touches it, presses
        a bumper or the nose button, picks it up or tilts it, as a world's scripted stimuli do."""
        hold_ms = round(stimulus.duration * 1000)
        if stimulus.action == "touch":
            self.devices.touch.touched(stimulus.sensors, hold_ms)
        elif stimulus.action == "bump":
            self.devices.bumpers.pressed_by_hand(stimulus.sensors, hold_ms)
        elif stimulus.action == "nose":
            self.devices.general.nose_pressed()
        elif stimulus.action == "pick up":
            self.happened("picked up")
            self._set_picked_up(True)
            self.at(self.now_ms + hold_ms, self._put_down)
        else:
            self.devices.accelerometer.tilted(stimulus.pitch, stimulus.roll, hold_ms)

    def disconnect(self, reason: str = "the host disconnected") -> None:
        """The link is gone: the robot stops, as a real one does when its app goes away."""
        if self.connected:
            self.connected = False
            self.stop_everything(respond=False)
            self.happened(f"disconnected: {reason}")

    def connect(self) -> None:
        """A (new) connection: the robot resets its position, as the spec says, and tells
        what its sensors found at power-on (if it has not yet)."""
        self.connected = True
        self.reset_origin()
        self._first_readings()

    @property
    def pose(self) -> tuple[int, int, int]:
        """The robot's own estimate, as Get Position reports it: x, y mm and heading decidegrees."""
        return self.devices.motors.odometry(self.physics.pose)

    @property
    def world_pose(self) -> Pose:
        return self.physics.pose

    def finish(self) -> Recording:
        """Close the recording at the current time (a last frame) and return it."""
        self._settle()
        self.record_frame(force=True)
        return self.recording

    # --- what the devices see (rootlang.sim.devices.base.Context) ---------------------------

    def respond(self, request: Packet, **fields: object) -> None:
        answer = request.spec.response
        assert answer is not None, request.name
        self._emit(encode(answer.name, fields, request.id, robot=self.model))

    def event(self, name: str, **fields: object) -> None:
        device_bit = self._event_bits.get(name)
        if device_bit is None:
            spec(name)  # a misspelt name raises; else the model lacks the event
            return
        if not self.connected or not self.devices.general.allows(device_bit):
            return
        self._emit(encode(name, fields, self._event_id, robot=self.model))
        self._event_id = (self._event_id + 1) % 256

    def ignore(self, why: str) -> None:
        self.ignored.append(why)

    def happened(self, text: str) -> None:
        self.recording.events.append(Happening(self.now_ms, text))

    def at(self, t_ms: int, action: Callable[[], None]) -> int:
        number = next(self._sequence)
        heapq.heappush(self._timers, (max(t_ms, self.now_ms), number, action))
        return number

    def cancel(self, timer: int) -> None:
        self._cancelled.add(timer)

    def record_frame(self, *, force: bool = False) -> None:
        if not force and self.now_ms - self._last_frame_ms < FRAME_INTERVAL_MS:
            return
        frames = self.recording.frames
        if not self.keep_history and frames:  # the first frame only
            return
        x, y, heading = self.physics.pose
        marker, lights = self.devices.marker, self.devices.lights
        tool = "up" if marker is None else marker.tool
        state = (round(x), round(y), quantise_heading(heading), tool, lights.mode, lights.rgb)
        if frames and not force and state == self._framed:
            return  # (no frame made to find it is the same: one every 50 ms of a run)
        frame = Frame(self.now_ms, *state)
        if frames and frames[-1].t_ms == frame.t_ms:
            frames[-1] = frame
        else:
            frames.append(frame)
        self._last_frame_ms = self.now_ms
        self._framed = state

    def sense_floor(self) -> None:
        self._sense_floor(self.physics.pose)

    def stop_everything(self, *, respond: bool) -> None:
        self.devices.motors.stop(respond=respond)
        self.devices.sound.stop(respond=respond)
        if self.devices.marker is not None:
            self.devices.marker.stop()

    def reset_origin(self) -> None:
        self.devices.motors.reset_origin()

    def end_connection(self, reason: str) -> None:
        self.disconnect(reason)
        if self.on_disconnect is not None:
            self.on_disconnect("the robot ended the connection, as asked")

    # --- sending ------------------------------------------------------------------------------

    def _log(self, direction: str, data: bytes, note: str = "") -> None:
        if self.keep_history:
            self.packet_log.append(PacketRecord(self.now_ms, direction, data, note))

    def _emit(self, data: bytes) -> None:
        self._log("<-", data)
        if self.on_packet is not None:
            self.on_packet(data)
        else:
            self._outbox.append(data)

    # --- timers (simulated milliseconds) ----------------------------------------------------

    def _fire_timers(self) -> None:
        while self._timers and self._timers[0][0] <= self.now_ms:
            _, number, action = heapq.heappop(self._timers)
            if number in self._cancelled:
                self._cancelled.discard(number)
            else:
                action()

    # --- the world moving on -----------------------------------------------------------------

    def _resting(self) -> bool:
        return self.devices.motors.resting() and self.physics.is_still()

    def _walk_to(self, limit_ms: int) -> None:
        """Steps one by one while the wheel speeds cannot be told ahead (braking on the mark,
        planning a leg, stopping): at least one, then up to ``limit_ms`` and the next reading,
        or until they can be or the wheels stop. Then the reading, if one is due."""
        step, dt = self.step_ms, self.step_ms / 1000
        last = min(limit_ms, self._next_sense_ms)
        motors, physics = self.devices.motors, self.physics
        while True:
            left, right = motors.step_speeds(step)
            if self.picked_up:  # wheels spin in the air
                left = right = 0.0
            physics.step(left, right, dt)
            self.now_ms += step
            if self.now_ms + step > last or motors.resting() or motors.steady():
                break
        self._sense_if_due()

    def _sense_if_due(self) -> None:
        if self.now_ms >= self._next_sense_ms:
            self._next_sense_ms = (self.now_ms // SENSE_MS + 1) * SENSE_MS
            self._sense()

    def _cruise_to(self, limit_ms: int) -> bool:
        """The steps up to ``limit_ms`` and the next reading in one go, if the wheel speeds can
        be told ahead (ramping to, or turning at, steady speeds): before the last no sensor
        reads and no timer fires, so nothing but the body's motion happens. Then the reading,
        if one is due. Whether any steps were taken."""
        step = self.step_ms
        steps = (min(limit_ms, self._next_sense_ms) - self.now_ms) // step
        motors = self.devices.motors
        cruise = None if steps <= 0 or self.picked_up else motors.cruise()
        if cruise is None:
            return False
        target, keep_going = cruise
        taken, wheels = self.physics.glide(
            motors.wheels, target, motors.most_change(step), step / 1000, steps, keep_going
        )
        if taken == 0:
            return False
        motors.wheels = wheels
        self.now_ms += taken * step
        self._sense_if_due()
        return True

    def _sense(self) -> None:
        """Every sensor, in a fixed order (the order of the events they send)."""
        devices = self.devices
        motors = devices.motors
        pose = self.physics.pose
        moved = pose != self._sensed_pose
        devices.battery.drain(moving=motors.wheels != (0.0, 0.0))
        devices.bumpers.sense()
        motors.check_stall(SENSE_MS)
        cliff = devices.cliff
        if moved:
            self._sense_floor(pose)
            if devices.docking is not None:
                devices.docking.sense(pose)
        if cliff is not None:
            if moved or self.picked_up != cliff.over_edge:
                cliff.sense(pose)
            if cliff.over_edge and not self.picked_up and motors.driving_forwards():
                motors.stop_wheels(DockStatus.ABORTED)  # and it will not drive on over an edge
        if moved and devices.light_sensors is not None:
            devices.light_sensors.sense(pose)
        if moved and devices.ir_proximity is not None:
            devices.ir_proximity.sense(pose)
        self._sensed_pose = pose
        self.record_frame()

    def _first_readings(self) -> None:
        """Just after power-on, the sensors that found something say so: colours other than
        white, a dock the robot sits on, a cliff it starts over (a host assumes none)."""
        if self._first_readings_timer is None:
            return
        self.cancel(self._first_readings_timer)
        self._first_readings_timer = None
        pose = self.physics.pose
        devices = self.devices
        if devices.color_sensor is not None:
            devices.color_sensor.sense(pose)
        if devices.docking is not None:
            devices.docking.first_reading()
        if devices.cliff is not None:
            devices.cliff.sense(pose)

    def _sense_floor(self, pose: Pose) -> None:
        """Ink and colour sensors, for the path since they last looked."""
        if pose == self._floor_pose:
            return
        self._floor_pose = pose
        if self.devices.marker is not None:
            self.devices.marker.draw(pose)
        if self.devices.color_sensor is not None:
            self.devices.color_sensor.sense(pose)

    def _settle(self) -> None:
        """The robot has come to rest: finish what the sensors and the recording owe."""
        self._sense_floor(self.physics.pose)
        self.record_frame()

    def _set_picked_up(self, up: bool) -> None:
        self.picked_up = up
        if self.devices.cliff is not None:
            self.devices.cliff.sense(self.physics.pose)

    def _put_down(self) -> None:
        self.happened("put down")
        self._set_picked_up(False)
