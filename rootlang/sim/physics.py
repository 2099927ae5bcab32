"""The robot's body in a pymunk world: the tank pattern, walls, obstacles and bumper contacts.

pymunk's ``tank.py`` pattern: an invisible kinematic *control body* moves exactly as the wheels
say, and pulls the robot's dynamic body along through a ``PivotJoint`` (velocity only, with a
force limit) and a ``GearJoint`` (turning). Where nothing is in the way the body follows the
wheels exactly; against a wall the joints give way and the body stays at the wall instead of
sinking into it. Units are millimetres and seconds; masses are nominal (only ratios matter).

pymunk is only stepped while something solid is near. In the open the body follows the wheels
exactly, so the same motion is worked out here in a few lines of Python (:meth:`Physics.glide`),
as pymunk's solver does it for the tank pattern: positions move by last step's velocities, the
body's velocity then takes the control body's, and its turn rate the control's plus the gear
joint's correction of the angle between them. Clearance is asked of pymunk's spatial index (one
call), and only again once the robot may have used it up.

This module knows nothing of packets; :mod:`rootlang.sim.robot` drives it.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping

import pymunk

from rootlang.sim.models import ModelSpec
from rootlang.sim.motion import Speeds, ramp_step
from rootlang.sim.pymunk_fence import calls as pymunk_core
from rootlang.sim.world import Circle, Polygon, Rect, World

Pose = tuple[float, float, float]
CruiseCheck = Callable[[Pose, float, float], int]
"""How many steps from this pose on (this one first) the wheels surely keep their speeds, when
the body moves at most so many mm and turns at most so many radians a step (0: not this one)."""
ROBOT, SOLID = 1, 2  # collision types
PULL_ACCELERATION = 3000.0  # mm/s², chosen: the wheels' grip; enough to follow them, not to sink in
TURN_ACCELERATION = 60.0  # rad/s², chosen
TURN_CORRECTION = 1.2  # rad/s, chosen: the most the gear joint turns the body to catch up
CORNER_RADIUS = 20.0  # mm, chosen: Root's rounded corners
LOOK_AROUND_MM = 200.0  # chosen: how far beyond the body's outline clearance is asked about
OPEN_STEPS = 3  # chosen: at least this many steps' travel clear: step without pymunk
CONTACT_PERSISTENCE = 3  # pymunk's default: steps a contact is remembered after it ends
SOLID_FRICTION = 0.3  # chosen
SOLVER_ITERATIONS = 10  # pymunk's default


class Physics:
    """A world's walls and obstacles, and one robot body driven by wheel speeds."""

    def __init__(self, world: World, spec: ModelSpec, x: float, y: float, heading_deg: float):
        self.spec = spec
        self.space = pymunk.Space()
        self.space.iterations = SOLVER_ITERATIONS
        static = self.space.static_body
        for wall in world.all_walls():
            segment = pymunk.Segment(static, wall.start, wall.end, wall.thickness / 2)
            self._solid(segment)
        for obstacle in world.obstacles:
            self._solid(_static_shape(static, obstacle.shape))

        mass = 1.0
        if spec.round_body:
            moment = pymunk.moment_for_circle(mass, 0, spec.width / 2)
            self.reach = spec.width / 2
        else:
            moment = pymunk.moment_for_box(mass, (spec.length, spec.width))
            r = CORNER_RADIUS
            self.reach = math.hypot(spec.length / 2 - r, spec.width / 2 - r) + r
        self.body = pymunk.Body(mass, moment)
        self.body.position = (x, y)
        self.body.angle = math.radians(heading_deg)
        if spec.round_body:
            shape: pymunk.Shape = pymunk.Circle(self.body, spec.width / 2)
        else:
            r = CORNER_RADIUS
            half_l, half_w = spec.length / 2 - r, spec.width / 2 - r
            corners = [(half_l, half_w), (-half_l, half_w), (-half_l, -half_w), (half_l, -half_w)]
            shape = pymunk.Poly(self.body, corners, radius=r)
        shape.friction = SOLID_FRICTION
        shape.collision_type = ROBOT
        shape.filter = pymunk.ShapeFilter(categories=_ROBOT_CATEGORY)
        self.space.add(self.body, shape)

        self.control = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
        self.control.position = self.body.position
        self.control.angle = self.body.angle
        pivot = pymunk.PivotJoint(self.control, self.body, (0, 0), (0, 0))
        pivot.max_bias = 0  # correct velocity only, never snap position
        pivot.max_force = PULL_ACCELERATION * mass
        gear = pymunk.GearJoint(self.control, self.body, 0.0, 1.0)
        gear.error_bias = 0
        gear.max_bias = TURN_CORRECTION
        gear.max_force = TURN_ACCELERATION * moment
        self.space.add(self.control, pivot, gear)

        self.touching = 0  # how many solid things the robot touches now
        self._drive = (0.0, 0.0, 0.0)  # the control body's velocity x, y and turn (in pymunk)
        self.space.on_collision(ROBOT, SOLID, begin=self._touch, separate=self._untouch)
        # The body's state is here while it is in the open (``_in_pymunk`` False), in pymunk else.
        self._in_pymunk = False
        self._pose = (float(x), float(y), math.radians(heading_deg))
        self._velocity = (0.0, 0.0, 0.0)  # the body's x, y and angular velocity
        self._control_angle = self._pose[2]
        self._clear_for = 0.0  # mm the body may still travel before clearance is asked again
        self._untouched_steps = CONTACT_PERSISTENCE  # steps since the last contact ended
        self._step_reach: dict[float, float] = {}
        # the steps a cruise check vouched for beyond the last glide: (check, target, steps)
        self._vouched: tuple[CruiseCheck, Speeds, int] | None = None

    def _solid(self, shape: pymunk.Shape) -> None:
        shape.friction = SOLID_FRICTION
        shape.collision_type = SOLID
        self.space.add(shape)

    # --- contacts (read by the bumper sensor) ------------------------------------------------
    # Only the start and end of a touch call back into Python: a callback on every step of a
    # touch (pre_solve) would cost several times the physics itself.

    def _touch(self, arbiter: pymunk.Arbiter, space: pymunk.Space, data: object) -> None:
        self.touching += 1

    def _untouch(self, arbiter: pymunk.Arbiter, space: pymunk.Space, data: object) -> None:
        self.touching -= 1

    def contact_angles(self) -> dict[int, float]:
        """Each solid thing touching the robot now (by id) -> the angle of the touch from
        straight ahead, in degrees counterclockwise (positive: the robot's left)."""
        angles: dict[int, float] = {}
        if not self._in_pymunk:
            return angles  # in the open: nothing touches

        def note(arbiter: pymunk.Arbiter) -> None:
            points = arbiter.contact_point_set.points
            if not points:
                return
            px = sum(p.point_a.x + p.point_b.x for p in points) / (2 * len(points))
            py = sum(p.point_a.y + p.point_b.y for p in points) / (2 * len(points))
            local = self.body.world_to_local((px, py))
            first, second = arbiter.shapes  # (a new pair each time it is asked)
            other = second if first.body is self.body else first
            angles[id(other)] = math.degrees(math.atan2(local.y, local.x))

        self.body.each_arbiter(note)
        return angles

    # --- driving ---------------------------------------------------------------------------

    def step(self, left: float, right: float, dt: float) -> None:
        """Move for ``dt`` seconds with these wheel speeds (mm/s)."""
        self.glide((left, right), (left, right), 0.0, dt, 1)

    def glide(
        self, wheels: Speeds, target: Speeds, most_change: float, dt: float, steps: int,
        keep_going: CruiseCheck | None = None,
    ) -> tuple[int, Speeds]:  # fmt: skip
        """Up to ``steps`` steps, the wheel speeds (left, right, mm/s) going from ``wheels``
        towards ``target`` by at most ``most_change`` a step (:func:`motion.ramp_step`, one
        before each step), as long as ``keep_going`` says so: the same as as many calls of
        :meth:`step`, in one call (a robot cruising in the open costs little). Returns how
        many steps it took, and the wheel speeds of the last."""
        taken = wheels  # the speeds of the last step taken (none yet: the wheels' now)
        ramping = wheels != target
        if ramping:
            wheels, ramping, forward, turn = self._ramp(wheels, target, most_change)
        else:
            forward, turn = self._rates(wheels)
        step_reach = self._step_reach.get(dt) or self._reach_in_a_step(dt)
        # steps vouched for by the last call, if it glided on with the same check and target
        vouched, self._vouched = self._vouched, None
        done = 0
        if self._in_pymunk:  # pymunk steps while something solid is near, then the open's below
            sure = steps if keep_going is None else 0
            while True:
                if done >= sure:
                    assert keep_going is not None  # (without it, every step is vouched for)
                    sure = done + self._vouches(keep_going, wheels, target, dt)
                    if done >= sure:
                        break
                self._step_in_pymunk(forward, turn, dt, step_reach)
                done, taken = done + 1, wheels
                if done == steps or not self._in_pymunk:
                    break
                if self.touching and keep_going is not None:
                    sure = done  # a touch can push the body beyond the bounds vouched with
                if ramping:  # the wheels' speeds for the next step
                    wheels, ramping, forward, turn = self._ramp(wheels, target, most_change)
            return done, taken
        most_pull, most_turn = PULL_ACCELERATION * dt, TURN_ACCELERATION * dt
        cos, sin, hypot = math.cos, math.sin, math.hypot
        x, y, angle = self._pose
        vx, vy, w = self._velocity
        control_angle = self._control_angle
        clear_for = self._clear_for
        if keep_going is None:
            sure = steps  # every step is vouched for
        elif vouched is not None and vouched[:2] == (keep_going, target):
            sure = vouched[2]
        else:
            sure = 0
        while True:  # (the first step's wheel speeds are set above; the others' at the end)
            if done >= sure:
                assert keep_going is not None  # (without it, every step is vouched for)
                self._pose, self._velocity = (x, y, angle), (vx, vy, w)
                sure = done + self._vouches(keep_going, wheels, target, dt)
                if done >= sure:
                    break
            moving = forward or vx or vy  # (turning in place, the body's centre stays put)
            if moving:
                clear_for -= (abs(vx) + abs(vy)) * dt  # at least the distance moved
            if clear_for < step_reach:
                clear_for = self._clearance_at(x, y) - step_reach
                if clear_for < step_reach:  # something solid is near: pymunk steps from here
                    self._pose, self._velocity = (x, y, angle), (vx, vy, w)
                    self._control_angle, self._clear_for = control_angle, clear_for
                    self._step_in_pymunk(forward, turn, dt, step_reach)
                    return done + 1, wheels
            # In the open, one step of pymunk's solver for the tank pattern. Positions move
            # first, each body by its velocity of the last step (the control body's just set) ...
            if moving:
                cvx, cvy = forward * cos(angle), forward * sin(angle)
                x, y = x + vx * dt, y + vy * dt
                # ... then the pivot joint gives the body the control body's velocity (within
                # its force) ...
                dvx, dvy = cvx - vx, cvy - vy
                if dvx or dvy:
                    change = hypot(dvx, dvy)
                    if change > most_pull:
                        dvx, dvy = dvx * most_pull / change, dvy * most_pull / change
                    vx, vy = vx + dvx, vy + dvy
            angle += w * dt
            control_angle += turn * dt
            # ... and the gear joint its turn rate, plus a correction of the angle between them
            gap = (angle - control_angle) / dt
            if gap > TURN_CORRECTION:
                gap = TURN_CORRECTION
            elif gap < -TURN_CORRECTION:
                gap = -TURN_CORRECTION
            dw = turn - gap - w
            if dw > most_turn:
                dw = most_turn
            elif dw < -most_turn:
                dw = -most_turn
            w += dw
            done += 1
            taken = wheels
            if done == steps:
                break
            if ramping:  # the wheels' speeds for the next step
                wheels, ramping, forward, turn = self._ramp(wheels, target, most_change)
            elif moving and not (dvx or dvy or dw or turn or w) and angle == control_angle:
                # Driving straight at the wheels' steady speed: the solver changes nothing but
                # the position, by the same amount a step, until the clearance or the vouched
                # steps run out (then the steps above again)
                move_x, move_y, used = vx * dt, vy * dt, (abs(vx) + abs(vy)) * dt
                last = min(steps, sure)
                while done < last and clear_for - used >= step_reach:
                    clear_for -= used
                    x += move_x
                    y += move_y
                    done += 1
                if done == steps:
                    break
        self._pose, self._velocity = (x, y, angle), (vx, vy, w)
        self._control_angle, self._clear_for = control_angle, clear_for
        if keep_going is not None and sure > done:
            self._vouched = (keep_going, target, sure - done)
        return done, taken

    def _ramp(
        self, wheels: Speeds, target: Speeds, most_change: float
    ) -> tuple[Speeds, bool, float, float]:
        """The wheel speeds a step on along the ramp to ``target``, whether it goes on after,
        and what they ask of the body (:meth:`_rates`)."""
        wheels = ramp_step(wheels, target, most_change)
        forward, turn = self._rates(wheels)
        return wheels, wheels != target, forward, turn

    def _rates(self, wheels: Speeds) -> tuple[float, float]:
        """What wheel speeds ask of the body: forward speed (mm/s) and turn rate (rad/s)."""
        left, right = wheels
        return (left + right) / 2, (right - left) / self.spec.wheel_base

    def _vouches(self, keep_going: CruiseCheck, wheels: Speeds, target: Speeds, dt: float) -> int:
        """How many steps ``keep_going`` vouches for from the pose now, the wheels going from
        ``wheels`` towards ``target``: the most the body moves and turns a step bounds its
        progress (the joints only ever bring its velocity towards the wheels', which stay
        between the two, and the gear's correction adds at most ``TURN_CORRECTION``)."""
        vx, vy, w = self._body_velocity()
        (forward, turn), (to_forward, to_turn) = self._rates(wheels), self._rates(target)
        most_forward, most_turn_rate = (
            max(abs(forward), abs(to_forward)),
            max(abs(turn), abs(to_turn)),
        )
        most_travel = max(math.hypot(vx, vy), most_forward) * dt
        most_spin = max(abs(w), most_turn_rate + TURN_CORRECTION) * dt
        return keep_going(self._pose, most_travel, most_spin)

    def _step_in_pymunk(self, forward: float, turn: float, dt: float, step_reach: float) -> None:
        angle = self._pose[2]
        drive = (forward * math.cos(angle), forward * math.sin(angle), turn)
        if not self._in_pymunk:
            self._enter_pymunk(drive)
        elif drive != self._drive:  # often the same (cruising, turning): pymunk's setters are slow
            self._drive = drive
            _set_velocity(self.control, drive[:2])
            _set_turn_rate(self.control, drive[2])
        pymunk_core.step(self.space, dt)
        self._pose = pymunk_core.pose(self.body)
        self._untouched_steps = 0 if self.touching else self._untouched_steps + 1
        self._clear_for += step_reach  # the most the clearance can have grown
        if self._untouched_steps >= CONTACT_PERSISTENCE and self._clear_for >= 0:
            clearance = self._clearance_at(*self._pose[:2])
            if clearance >= OPEN_STEPS * step_reach:
                self._clear_for = clearance - step_reach
                self._leave_pymunk()
            else:  # not before it can have grown enough
                self._clear_for = clearance - OPEN_STEPS * step_reach

    def _reach_in_a_step(self, dt: float) -> float:
        """The farthest the body can move in one step (kept: asked every step)."""
        reach = self._step_reach[dt] = (self.spec.max_speed + PULL_ACCELERATION * dt) * dt
        return reach

    def _clearance_at(self, x: float, y: float) -> float:
        """How far (mm, up to ``LOOK_AROUND_MM``) the nearest solid thing is from the circle
        that holds the body in any heading, centred at (x, y)."""
        nearest = pymunk_core.nearest(self.space, (x, y), self.reach + LOOK_AROUND_MM, _SOLIDS)
        return LOOK_AROUND_MM if nearest is None else nearest - self.reach

    def _enter_pymunk(self, drive: tuple[float, float, float]) -> None:
        x, y, angle = self._pose
        vx, vy, w = self._velocity
        body, control = self.body, self.control
        body.position, body.angle = (x, y), angle
        body.velocity, body.angular_velocity = (vx, vy), w
        control.position, control.angle = (x, y), self._control_angle
        control.velocity, control.angular_velocity = drive[:2], drive[2]
        self._drive = drive
        self._in_pymunk = True

    def _leave_pymunk(self) -> None:
        self._velocity = pymunk_core.velocity(self.body)
        self._control_angle = self.control.angle
        self._in_pymunk = False

    def halt(self) -> None:
        """Stop moving now (the wheels braked)."""
        self._velocity = self._drive = (0.0, 0.0, 0.0)
        self._vouched = None
        if self._in_pymunk:
            for body in (self.body, self.control):
                body.velocity = (0, 0)
                body.angular_velocity = 0

    @property
    def pose(self) -> tuple[float, float, float]:
        """World x, y (mm) and heading (radians, counterclockwise from +x, not wrapped)."""
        return self._pose

    def _body_velocity(self) -> tuple[float, float, float]:
        if self._in_pymunk:
            return pymunk_core.velocity(self.body)
        return self._velocity

    def is_still(self) -> bool:
        vx, vy, w = self._body_velocity()
        return abs(vx) + abs(vy) < 1e-3 and abs(w) < 1e-5

    def wheel_speeds(self) -> tuple[float, float]:
        """The speeds the wheels really have over the floor (slower than asked at a wall)."""
        vx, vy, w = self._body_velocity()
        angle = self._pose[2]
        forward = vx * math.cos(angle) + vy * math.sin(angle)
        turn = w * self.spec.wheel_base / 2
        return forward - turn, forward + turn

    def ray(self, start: tuple[float, float], end: tuple[float, float]) -> float | None:
        """Distance from ``start`` to the first solid thing on the way to ``end``, if any."""
        hit = self.space.segment_query_first(start, end, 0, _SOLIDS)
        if hit is None:
            return None
        return float(hit.alpha) * math.dist(start, end)


# pymunk's bodies pass every attribute assignment through a Python-level ``__setattr__`` (a
# typing helper); calling the properties' own setters skips that, at a quarter of the cost (the
# control body's velocity is set on most steps in pymunk)
def _setter(name: str) -> Callable[[pymunk.Body, object], None]:
    properties: Mapping[str, property] = vars(pymunk.Body)
    setter = properties[name].fset
    assert setter is not None, name
    return setter


_set_velocity, _set_turn_rate = _setter("velocity"), _setter("angular_velocity")

_ROBOT_CATEGORY = 0b10
_SOLIDS = pymunk.ShapeFilter(mask=pymunk.ShapeFilter.ALL_MASKS() ^ _ROBOT_CATEGORY)


def _static_shape(body: pymunk.Body, shape: Rect | Circle | Polygon) -> pymunk.Shape:
    if isinstance(shape, Circle):
        return pymunk.Circle(body, shape.radius, (shape.x, shape.y))
    return pymunk.Poly(body, list(shape.points))
