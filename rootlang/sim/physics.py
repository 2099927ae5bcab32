"""The robot's body in a pymunk world: the tank pattern, walls, obstacles and bumper contacts.

pymunk's ``tank.py`` pattern: an invisible kinematic *control body* moves exactly as the wheels
say, and pulls the robot's dynamic body along through a ``PivotJoint`` (velocity only, with a
force limit) and a ``GearJoint`` (turning). Where nothing is in the way the body follows the
wheels exactly; against a wall the joints give way and the body stays at the wall instead of
sinking into it. Units are millimetres and seconds; masses are nominal (only ratios matter).

This module knows nothing of packets; :mod:`rootlang.sim.robot` drives it.
"""

from __future__ import annotations

import math

import pymunk

from rootlang.sim.models import ModelSpec
from rootlang.sim.world import Circle, Polygon, Rect, World

ROBOT, SOLID = 1, 2  # collision types
_PULL_ACCELERATION = 3000.0  # mm/s²: the wheels' grip; enough to follow them, not to sink in
_TURN_ACCELERATION = 60.0  # rad/s²
_CORNER_RADIUS = 20.0  # Root's rounded corners (chosen)


class Physics:
    """A world's walls and obstacles, and one robot body driven by wheel speeds."""

    def __init__(self, world: World, spec: ModelSpec, x: float, y: float, heading_deg: float):
        self.spec = spec
        self.space = pymunk.Space()
        self.space.iterations = 10
        static = self.space.static_body
        for wall in world.all_walls():
            segment = pymunk.Segment(static, wall.start, wall.end, wall.thickness / 2)
            self._solid(segment)
        for obstacle in world.obstacles:
            self._solid(_static_shape(static, obstacle.shape))

        mass = 1.0
        if spec.round_body:
            moment = pymunk.moment_for_circle(mass, 0, spec.width / 2)
        else:
            moment = pymunk.moment_for_box(mass, (spec.length, spec.width))
        self.body = pymunk.Body(mass, moment)
        self.body.position = (x, y)
        self.body.angle = math.radians(heading_deg)
        if spec.round_body:
            shape: pymunk.Shape = pymunk.Circle(self.body, spec.width / 2)
        else:
            r = _CORNER_RADIUS
            half_l, half_w = spec.length / 2 - r, spec.width / 2 - r
            corners = [(half_l, half_w), (-half_l, half_w), (-half_l, -half_w), (half_l, -half_w)]
            shape = pymunk.Poly(self.body, corners, radius=r)
        shape.friction = 0.3
        shape.collision_type = ROBOT
        shape.filter = pymunk.ShapeFilter(categories=_ROBOT_CATEGORY)
        self.space.add(self.body, shape)

        self.control = pymunk.Body(body_type=pymunk.Body.KINEMATIC)
        self.control.position = self.body.position
        self.control.angle = self.body.angle
        pivot = pymunk.PivotJoint(self.control, self.body, (0, 0), (0, 0))
        pivot.max_bias = 0  # correct velocity only, never snap position
        pivot.max_force = _PULL_ACCELERATION * mass
        gear = pymunk.GearJoint(self.control, self.body, 0.0, 1.0)
        gear.error_bias = 0
        gear.max_bias = 1.2
        gear.max_force = _TURN_ACCELERATION * moment
        self.space.add(self.control, pivot, gear)

        self.touching = 0  # how many solid things the robot touches now
        self._drive = (0.0, 0.0, 0.0)  # the control body's velocity x, y and angular velocity
        self._pose: tuple[float, float, float] | None = None  # None: moved since last read
        self.space.on_collision(ROBOT, SOLID, begin=self._touch, separate=self._untouch)

    def _solid(self, shape: pymunk.Shape) -> None:
        shape.friction = 0.3
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

        def note(arbiter: pymunk.Arbiter) -> None:
            points = arbiter.contact_point_set.points
            if not points:
                return
            px = sum(p.point_a.x + p.point_b.x for p in points) / (2 * len(points))
            py = sum(p.point_a.y + p.point_b.y for p in points) / (2 * len(points))
            local = self.body.world_to_local((px, py))
            other = arbiter.shapes[1] if arbiter.shapes[0].body is self.body else arbiter.shapes[0]
            angles[id(other)] = math.degrees(math.atan2(local.y, local.x))

        self.body.each_arbiter(note)
        return angles

    # --- driving ---------------------------------------------------------------------------

    def step(self, left: float, right: float, dt: float) -> None:
        """Move for ``dt`` seconds with these wheel speeds (mm/s)."""
        forward = (left + right) / 2
        angle = self.pose[2]
        turn = (right - left) / self.spec.wheel_base
        drive = (forward * math.cos(angle), forward * math.sin(angle), turn)
        if drive != self._drive:  # often the same (cruising, turning): pymunk's setters are slow
            self._drive = drive
            self.control.velocity = drive[:2]
            self.control.angular_velocity = drive[2]
        self.space.step(dt)
        self._pose = None

    def halt(self) -> None:
        """Stop moving now (the wheels braked)."""
        for body in (self.body, self.control):
            body.velocity = (0, 0)
            body.angular_velocity = 0
        self._drive = (0.0, 0.0, 0.0)

    @property
    def pose(self) -> tuple[float, float, float]:
        """World x, y (mm) and heading (radians, counterclockwise from +x, not wrapped)."""
        if self._pose is None:  # read from pymunk once a step (steering and sensing ask often)
            x, y = self.body.position
            self._pose = (x, y, self.body.angle)
        return self._pose

    def is_still(self) -> bool:
        velocity = self.body.velocity
        return abs(velocity.x) + abs(velocity.y) < 1e-3 and abs(self.body.angular_velocity) < 1e-5

    def wheel_speeds(self) -> tuple[float, float]:
        """The speeds the wheels really have over the floor (slower than asked at a wall)."""
        velocity = self.body.velocity
        angle = self.pose[2]
        forward = velocity.x * math.cos(angle) + velocity.y * math.sin(angle)
        turn = self.body.angular_velocity * self.spec.wheel_base / 2
        return forward - turn, forward + turn

    def ray(self, start: tuple[float, float], end: tuple[float, float]) -> float | None:
        """Distance from ``start`` to the first solid thing on the way to ``end``, if any."""
        hit = self.space.segment_query_first(start, end, 0, _SOLIDS)
        if hit is None:
            return None
        return float(hit.alpha) * math.dist(start, end)


_ROBOT_CATEGORY = 0b10
_SOLIDS = pymunk.ShapeFilter(mask=pymunk.ShapeFilter.ALL_MASKS() ^ _ROBOT_CATEGORY)


def _static_shape(body: pymunk.Body, shape: Rect | Circle | Polygon) -> pymunk.Shape:
    if isinstance(shape, Circle):
        return pymunk.Circle(body, shape.radius, (shape.x, shape.y))
    return pymunk.Poly(body, list(shape.points))
