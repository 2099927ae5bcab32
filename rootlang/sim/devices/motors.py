"""Device 1, motors: the wheels, the movement commands, odometry and the stall detector.

A movement command (drive, rotate, arc, navigate, dock, undock) becomes a
:class:`~rootlang.sim.motion.Movement`; every physics step the robot asks :meth:`Motors.step_speeds`
for the wheel speeds, which steer the movement and follow a ramp at the model's acceleration.
"""

from __future__ import annotations

import math
import struct
from collections.abc import Mapping

from rootlang.protocol import (
    DockResult,
    DockStatus,
    GravityCompensation,
    Motor,
    Packet,
    PacketSpec,
    StallCause,
    decode,
    encode,
)
from rootlang.protocol.codec import HEADER_BYTES
from rootlang.sim import motion
from rootlang.sim.devices.base import Context, Handler, Pose, SimDevice
from rootlang.sim.devices.docking import Docking
from rootlang.sim.motion import Leg, Movement, Speeds, ramp_step
from rootlang.sim.physics import CruiseCheck
from rootlang.sim.recording import quantise_heading
from rootlang.sim.sensors import docked_pose

STALL_MS = 1000  # chosen: a wheel held below STALL_SHARE of its speed this long has stalled
STALL_SHARE = 0.25  # chosen
STALL_MIN_SPEED = 10.0  # mm/s, chosen: slower than this a wheel is not watched for stalls
DOCK_APPROACH_MM = 350.0  # chosen: Dock lines up this far in front of its docked place first
UNDOCK_BACK_MM = 250.0  # chosen: Undock backs this far off the dock, then turns round
# spec: Set Gravity Compensation's defaults (on while the marker is down, 50% = 500 per mille)
DEFAULT_GRAVITY_COMPENSATION = (int(GravityCompensation.MARKER_DOWN), 500)
STILL = (0.0, 0.0)
# The wheel speed commands: a speed beyond the model's range is clamped to it, not refused, as
# the firmware does (iRobot's own SDK sends up to 500 mm/s to any robot).


class Motors(SimDevice):
    def __init__(self, robot: Context, docking: Docking | None) -> None:
        super().__init__(robot)
        self.docking = docking
        self.origin: Pose = robot.physics.pose  # where odometry counts from
        self.movement: Movement | None = None
        self.wanted = STILL  # wheel speeds asked for
        self.wheels = STILL  # wheel speeds now (ramped)
        self._blocked_ms = [0, 0]
        self._stalled = [False, False]
        self.gravity_compensation: tuple[int, int] = DEFAULT_GRAVITY_COMPENSATION

    def commands(self) -> Mapping[str, Handler]:
        extra: dict[str, Handler] = {}
        if self.docking is not None:
            extra |= {"dock": self._dock, "undock": self._undock}
        if self.robot.spec.model.is_root:  # for driving on a whiteboard
            extra["set_gravity_compensation"] = self._set_gravity_compensation
        return extra | {
            "set_wheel_speeds": self._set_wheel_speeds,
            "set_left_wheel_speed": self._set_left_wheel_speed,
            "set_right_wheel_speed": self._set_right_wheel_speed,
            "drive_distance": self._drive_distance,
            "rotate_angle": self._rotate_angle,
            "reset_position": self._reset_position,
            "get_position": self._get_position,
            "navigate_to_position": self._navigate_to_position,
            "drive_arc": self._drive_arc,
        }

    def clamped_to_range(self, spec: PacketSpec, data: bytes) -> tuple[Packet, str] | None:
        """A wheel speed command with a speed beyond this model's range, as the packet with the
        speed clamped into it, and a note of what changed; None for any other packet."""
        if not spec.behaviour.sets_wheels:
            return None
        layout = struct.Struct(">" + "".join(f.struct_format for f in spec.fields))
        raw = layout.unpack_from(data, HEADER_BYTES)
        sent = dict(zip((f.name for f in spec.fields), raw, strict=True))
        model = self.robot.spec.model
        kept: dict[str, int] = {}
        for field in spec.fields:
            low, high = field.range_for(model) or (sent[field.name], sent[field.name])
            kept[field.name] = max(low, min(high, sent[field.name]))
        packet = decode(encode(spec.name, kept, data[2], robot=model), "host", robot=model)
        assert isinstance(packet, Packet)
        changes = ", ".join(
            f"{name} {sent[name]} -> {kept[name]}" for name in kept if sent[name] != kept[name]
        )
        return (
            packet,
            f"{spec.name} #{data[2]}: clamped to {model.display_name}'s range ({changes} mm/s)",
        )

    # --- what the robot asks every step -------------------------------------------------------

    def resting(self) -> bool:
        """Nothing asked of the wheels and they stand still."""
        return self.movement is None and self.wanted == STILL and self.wheels == STILL

    def step_speeds(self, step_ms: int) -> tuple[float, float]:
        """The wheel speeds for the next physics step: steer, then ramp towards what is wanted."""
        if self.movement is not None:
            self._steer(self.movement)
        if self.wheels != self.wanted:
            self.wheels = ramp_step(self.wheels, self.wanted, self.most_change(step_ms))
        return self.wheels

    def most_change(self, step_ms: int) -> float:
        """The most a wheel's speed changes in a step (mm/s): the model's acceleration."""
        return self.robot.spec.acceleration * step_ms / 1000

    def steady(self) -> bool:
        """Whether the wheel speeds of the next steps can be told now: they ramp towards speeds
        asked for, or a leg's top speeds (the leg then vouches for its steps), rather than
        towards a stop (a body coming to rest is watched step by step), or a leg brakes on its
        mark or is still to be planned."""
        if self.movement is None:
            return self.wanted != STILL
        leg = self.movement.leg
        return leg is not None and leg.at_top_rate()

    def cruise(self) -> tuple[Speeds, CruiseCheck | None] | None:
        """While the wheel speeds of the next steps can be told now (:meth:`steady`): the
        speeds they ramp to (or turn at), and what tells how many steps the movement surely
        goes on so (None: until a packet or a sensor changes it). None when they cannot: steps
        must then be taken one by one."""
        if not self.steady():
            return None
        leg = None if self.movement is None else self.movement.leg
        return self.wanted, None if leg is None else leg.cruise_steps

    def ms_to_finish(self, step_ms: int) -> int | None:
        """About how long the movement's present leg still takes, in whole steps (at least one);
        None when there is no movement."""
        if self.movement is None:
            return None
        leg = self.movement.leg
        left = None if leg is None else leg.seconds_left()
        return step_ms if left is None else max(step_ms, math.ceil(left * 1000 / step_ms) * step_ms)

    def driving_forwards(self) -> bool:
        return sum(self.wanted) > 0

    def _steer(self, movement: Movement) -> None:
        pose = self.robot.physics.pose
        leg = movement.leg
        if leg is not None and leg.reached(pose):
            leg = None
            self.brake()  # hard, on the mark
        if leg is None:
            leg = movement.next_leg(pose)
        if leg is None:
            self._finish_movement(DockStatus.SUCCEEDED)
            return
        spec = self.robot.spec
        self.wanted = leg.wheel_targets(spec.wheel_base, spec.max_speed, spec.acceleration)

    def check_stall(self, period_ms: int) -> None:
        """The stall detector, run every ``period_ms``: a wheel held back too long has stalled,
        and a movement that needs it gives up."""
        if self.wanted == STILL or self.robot.picked_up:
            self._blocked_ms = [0, 0]
            self._stalled = [False, False]
            return
        actual = self.robot.physics.wheel_speeds()
        for motor in (0, 1):
            want = self.wanted[motor]
            if abs(want) > STALL_MIN_SPEED and abs(actual[motor]) < abs(want) * STALL_SHARE:
                self._blocked_ms[motor] += period_ms
            else:
                self._blocked_ms[motor], self._stalled[motor] = 0, False
        if max(self._blocked_ms) < STALL_MS:
            return  # the usual case: neither wheel held back for long
        stalled = [m for m in (0, 1) if self._blocked_ms[m] >= STALL_MS and not self._stalled[m]]
        for motor in stalled:
            self._stalled[motor] = True
            self.robot.happened(f"{Motor(motor).name.lower()} motor stalled")
            self.robot.event(
                "motor_stall_event", timestamp=self.robot.now_ms, motor=Motor(motor),
                cause=StallCause.UNDERSPEED,
            )  # fmt: skip
        if stalled and self.movement is not None:
            self._finish_movement(DockStatus.ABORTED)  # the firmware gives up on a blocked move

    # --- stopping -----------------------------------------------------------------------------

    def stop(self, *, respond: bool) -> None:
        """Stop at once (``respond``: answer the movement in progress as cancelled)."""
        if respond:
            self._finish_movement(DockStatus.CANCELED)
        self.movement = None
        self.brake()

    def stop_wheels(self, status: DockStatus) -> None:
        """End the movement with ``status`` and brake."""
        self._finish_movement(status)
        self.brake()

    def brake(self) -> None:
        """Stop the wheels at once (the motors brake; the body does not coast on)."""
        self.wanted = self.wheels = STILL
        self.robot.physics.halt()

    def _start_movement(
        self, movement: Movement | None, wheels: tuple[float, float] = STILL
    ) -> None:
        """A new movement command: the one in progress ends now, with its response."""
        self._finish_movement(DockStatus.CANCELED)
        self.movement = movement
        self.wanted = wheels
        # watched afresh: a move still against the wall that stalled the last one stalls too,
        # and is answered so (not left unanswered, which the host would take for a lost move)
        self._blocked_ms = [0, 0]
        self._stalled = [False, False]

    def _finish_movement(self, status: DockStatus) -> None:
        movement, self.movement = self.movement, None
        if movement is None:
            return
        self.wanted = STILL
        request = movement.request
        if request.name in ("dock", "undock"):
            docking = self._docking()
            pose = self.robot.physics.pose
            docked = docking.on_dock(pose)
            if request.name == "dock" and status is DockStatus.SUCCEEDED and not docked:
                status = DockStatus.ABORTED
            docking.sense(pose)
            result = DockResult.DOCKED if docked else DockResult.NOT_DOCKED
            self.robot.respond(request, timestamp=self.robot.now_ms, status=status, result=result)
        else:
            self.robot.respond(request, **self._pose_fields())

    def _move(self, packet: Packet, planners: list[motion.Planner]) -> None:
        self._start_movement(Movement(packet, planners))

    def _docking(self) -> Docking:
        assert self.docking is not None, "Dock and Undock are offered only with a dock"
        return self.docking

    # --- odometry -----------------------------------------------------------------------------

    def reset_origin(self) -> None:
        self.origin = self.robot.physics.pose

    def odometry(self, pose: Pose) -> tuple[int, int, int]:
        """The robot's own estimate of ``pose``: x, y mm and heading decidegrees, counted from
        where it was at the last reset, facing +y (the spec's frame)."""
        return odometry_from(self.origin, pose)

    def _world_from_odometry(self, x: float, y: float) -> tuple[float, float]:
        ox, oy, oheading = self.origin
        turn = math.pi / 2 - oheading
        return (
            ox + x * math.cos(turn) + y * math.sin(turn),
            oy - x * math.sin(turn) + y * math.cos(turn),
        )

    def _pose_fields(self) -> dict[str, int]:
        x, y, heading = self.odometry(self.robot.physics.pose)
        return {"timestamp": self.robot.now_ms, "x": x, "y": y, "heading": heading}

    # --- commands -----------------------------------------------------------------------------

    def _clamp(self, speed: int) -> float:
        top = self.robot.spec.max_speed
        return float(max(-top, min(top, speed)))

    def _set_wheel_speeds(self, packet: Packet) -> None:
        self._start_movement(None, (self._clamp(packet["left"]), self._clamp(packet["right"])))

    def _set_left_wheel_speed(self, packet: Packet) -> None:
        right = self.wanted[1] if self.movement is None else 0.0
        self._start_movement(None, (self._clamp(packet["left"]), right))

    def _set_right_wheel_speed(self, packet: Packet) -> None:
        left = self.wanted[0] if self.movement is None else 0.0
        self._start_movement(None, (left, self._clamp(packet["right"])))

    def _drive_distance(self, packet: Packet) -> None:
        self._move(packet, [motion.fixed(Leg(float(packet["distance"])))])

    def _rotate_angle(self, packet: Packet) -> None:
        self._move(packet, [motion.fixed(Leg(math.radians(packet["angle"] / 10), 0.0))])

    def _drive_arc(self, packet: Packet) -> None:
        angle, radius = math.radians(packet["angle"] / 10), float(packet["radius"])
        self._move(packet, [motion.fixed(Leg(angle, radius))])

    def _navigate_to_position(self, packet: Packet) -> None:
        x, y = self._world_from_odometry(packet["x"], packet["y"])
        planners = [motion.turn_towards(x, y), motion.drive_to(x, y)]
        if packet["heading"] >= 0:
            heading = math.radians(packet["heading"] / 10) - math.pi / 2 + self.origin[2]
            planners.append(motion.turn_to(heading))
        self._move(packet, planners)

    def _dock(self, packet: Packet) -> None:
        target = docked_pose(self.robot.world)
        if target is None or self._docking().on_dock(self.robot.physics.pose):
            self._start_movement(None)
            docked = target is not None
            status = DockStatus.SUCCEEDED if docked else DockStatus.ABORTED
            result = DockResult.DOCKED if docked else DockResult.NOT_DOCKED
            self.robot.respond(packet, timestamp=self.robot.now_ms, status=status, result=result)
            return
        x, y, heading = target
        ax = x - DOCK_APPROACH_MM * math.cos(heading)
        ay = y - DOCK_APPROACH_MM * math.sin(heading)
        self._move(
            packet,
            [motion.turn_towards(ax, ay), motion.drive_to(ax, ay), motion.turn_to(heading),
             motion.drive_to(x, y)],
        )  # fmt: skip

    def _undock(self, packet: Packet) -> None:
        if not self._docking().on_dock(self.robot.physics.pose):
            self._start_movement(None)
            self.robot.respond(
                packet, timestamp=self.robot.now_ms, status=DockStatus.ABORTED,
                result=DockResult.NOT_DOCKED,
            )  # fmt: skip
            return
        self._move(packet, [motion.fixed(Leg(-UNDOCK_BACK_MM)), motion.fixed(Leg(math.pi, 0.0))])

    def _set_gravity_compensation(self, packet: Packet) -> None:
        self.gravity_compensation = (int(packet["active"]), int(packet["amount"]))
        self.robot.happened(f"gravity compensation {int(packet['active'])} {packet['amount']}")

    def _reset_position(self, packet: Packet) -> None:
        self.reset_origin()

    def _get_position(self, packet: Packet) -> None:
        self.robot.respond(packet, **self._pose_fields())


def odometry_from(origin: Pose, pose: Pose) -> tuple[int, int, int]:
    """The robot's own estimate of ``pose`` (x, y mm and heading decidegrees), counted from
    ``origin`` facing +y (the spec's frame)."""
    ox, oy, oheading = origin
    turn = math.pi / 2 - oheading
    dx, dy = pose[0] - ox, pose[1] - oy
    x = dx * math.cos(turn) - dy * math.sin(turn)
    y = dx * math.sin(turn) + dy * math.cos(turn)
    return round(x), round(y), quantise_heading(pose[2] + turn)
