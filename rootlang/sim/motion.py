"""How the robot's firmware turns a movement command into wheel speeds, step by step.

A movement is a list of *legs* — drive straight, or turn about a point (radius 0: in place) —
each planned when the previous one ends, from the pose the robot really has then (navigate and
dock need that). A leg's progress is measured on the body itself, so a robot held at a wall makes
no progress; the robot's stall detector then ends it (see ``robot.py``). Speeds follow a
trapezoid: accelerate at the model's limit, cruise, and brake so as to stop on the mark.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from rootlang.protocol import Packet

Pose = tuple[float, float, float]  # world x, y (mm), heading (radians, counterclockwise)
Speeds = tuple[float, float]  # left and right wheel, mm/s
FINISH_MM = 0.5  # a leg is done this close to its end (and at once if it overshoots)
FINISH_RAD = math.radians(0.1)
CRUISE_MARGIN = 1 + 1e-9  # beyond the braking distance by this factor, sqrt is surely above top


@dataclass
class Leg:
    """Drive ``amount`` mm straight (``radius is None``), or turn ``amount`` radians clockwise
    about a point ``radius`` mm to the robot's right (0: in place; negative: to its left)."""

    amount: float
    radius: float | None = None
    start: Pose = (0.0, 0.0, 0.0)
    done: float = 0.0  # progress so far (mm or radians, same sign as amount when going right)
    rate: float = 0.0  # progress per second asked for last
    _ahead: tuple[float, float] = (1.0, 0.0)  # the start heading's cos and sin (asked every step)
    _limits: tuple[float, float, float, float] | None = None  # wheel factors, top rate, braking

    def begin(self, pose: Pose) -> None:
        self.start = pose
        self.done = 0.0
        self._ahead = (math.cos(pose[2]), math.sin(pose[2]))

    def measure(self, pose: Pose) -> None:
        """Progress at ``pose``: a function of the pose alone (so a pose may go unmeasured)."""
        if self.radius is None:
            x0, y0, _ = self.start
            cos, sin = self._ahead
            self.done = (pose[0] - x0) * cos + (pose[1] - y0) * sin
        else:
            self.done = self.start[2] - pose[2]  # clockwise is positive; headings are unwrapped

    def reached(self, pose: Pose) -> bool:
        """Measure the progress at ``pose``; whether the leg is then done (both asked every
        step, so in one call)."""
        self.measure(pose)
        return self.finished()

    def cruise_steps(self, pose: Pose, most_travel: float, most_turn: float) -> int:
        """How many steps from ``pose`` on (this one first) the leg surely goes on at the top
        rate it went at, far from its end, so the wheel targets stay those of the last step;
        the body moving at most ``most_travel`` mm and turning at most ``most_turn`` radians a
        step. 0: not even from this pose."""
        if self.reached(pose) or self._limits is None:
            return 0
        _, _, top_rate, braking = self._limits
        remaining = self.amount - self.done
        far = 2 * braking * abs(remaining) > top_rate * top_rate * CRUISE_MARGIN  # as steered
        if not (far and math.copysign(top_rate, remaining) == self.rate):
            return 0
        most = most_travel if self.radius is None else most_turn
        if most <= 0:
            return 1
        braking_from = top_rate * top_rate * CRUISE_MARGIN / (2 * braking)
        # a step to spare for rounding: the test above is the exact one, asked again after
        return max(1, math.floor((abs(remaining) - braking_from) / most) - 1)

    def at_top_rate(self) -> bool:
        """Whether the rate asked for last was the leg's top one (not braking, not planned)."""
        return self._limits is not None and abs(self.rate) == self._limits[2]

    @property
    def remaining(self) -> float:
        return self.amount - self.done

    def finished(self) -> bool:
        tolerance = FINISH_MM if self.radius is None else FINISH_RAD
        remaining = self.remaining
        return abs(remaining) <= tolerance or (remaining > 0) != (self.amount > 0)

    def wheel_factors(self, wheel_base: float) -> tuple[float, float]:
        """Wheel speeds (mm/s) per unit of progress rate (mm/s or clockwise rad/s)."""
        if self.radius is None:
            return 1.0, 1.0
        return self.radius + wheel_base / 2, self.radius - wheel_base / 2

    def wheel_targets(
        self, wheel_base: float, max_speed: float, acceleration: float
    ) -> tuple[float, float]:
        if self._limits is None:  # the same for every step of the leg: worked out once
            left_factor, right_factor = self.wheel_factors(wheel_base)
            biggest = max(abs(left_factor), abs(right_factor))
            top_rate = max_speed / biggest
            braking = 0.9 * acceleration / biggest  # a margin so the ramp can always follow
            self._limits = (left_factor, right_factor, top_rate, braking)
        left_factor, right_factor, top_rate, braking = self._limits
        remaining = self.amount - self.done
        stopping = 2 * braking * abs(remaining)
        if stopping > top_rate * top_rate * CRUISE_MARGIN:  # far from the mark: no root needed
            rate = math.copysign(top_rate, remaining)
        else:
            rate = math.copysign(min(top_rate, math.sqrt(stopping)), remaining)
        self.rate = rate
        return rate * left_factor, rate * right_factor

    def seconds_left(self) -> float | None:
        """At least how long the leg still takes at its present pace (None: not moving yet)."""
        if self.rate == 0:
            return None
        return abs(self.remaining / self.rate)


def ramp_step(wheels: Speeds, target: Speeds, most_change: float) -> Speeds:
    """The wheel speeds a step on from ``wheels`` on the ramp towards ``target``, neither
    changing by more than ``most_change`` mm/s: both change in proportion, so an arc keeps its
    radius while speeding up."""
    (left, right), (want_left, want_right) = wheels, target
    change = max(abs(want_left - left), abs(want_right - right))
    share = min(1.0, most_change / change)
    return left + (want_left - left) * share, right + (want_right - right) * share


Planner = Callable[[Pose], "Leg | None"]
"""Plans the next leg from the pose the robot has when the previous one ends (None: skip)."""


@dataclass
class Movement:
    """A movement command in progress (``request``: its packet): legs planned one at a time."""

    request: Packet
    planners: list[Planner]
    leg: Leg | None = None

    def next_leg(self, pose: Pose) -> Leg | None:
        while self.planners:
            leg = self.planners.pop(0)(pose)
            if leg is not None and leg.amount != 0:
                leg.begin(pose)
                self.leg = leg
                return leg
        self.leg = None
        return None


def fixed(leg: Leg) -> Planner:
    return lambda pose: leg


def turn_towards(x: float, y: float) -> Planner:
    """Turn in place to face the point (x, y)."""

    def plan(pose: Pose) -> Leg | None:
        if math.hypot(x - pose[0], y - pose[1]) < FINISH_MM:
            return None
        return Leg(-wrap(math.atan2(y - pose[1], x - pose[0]) - pose[2]), 0.0)

    return plan


def drive_to(x: float, y: float) -> Planner:
    """Drive straight to (x, y), assuming the robot faces it."""
    return lambda pose: Leg(math.hypot(x - pose[0], y - pose[1]))


def turn_to(heading: float) -> Planner:
    """Turn in place to a world heading (radians)."""
    return lambda pose: Leg(-wrap(heading - pose[2]), 0.0)


def wrap(angle: float) -> float:
    """An angle in radians brought into (-pi, pi]."""
    wrapped = math.remainder(angle, math.tau)
    return math.pi if wrapped == -math.pi else wrapped
