"""The one place that calls pymunk's C core (``pymunk._chipmunk``, private) directly: the
physics step near a wall, reading the body's pose and velocity on it, and how far the nearest
wall is.

Near a wall the robot takes a pymunk step every 10 ms, and reads its body's pose (and, while a leg
vouches for its steps, velocity) after each. Through pymunk's public API ``Space.step`` first works
through shapes added or removed inside callbacks, and every ``Body.position`` builds a ``Vec2d``
(and a clearance query a ``PointQueryInfo`` of them); that bookkeeping cost more than the step
itself (a tenth of the robot alone, driven with packets). The simulator's callbacks only count
touches and its bodies never change, so the C core is called directly — but only once a probe at
import has seen it do exactly what the public API does; on any other pymunk the public calls are
used (same results, slower). ``tests/sim/test_physics.py`` checks both agree, the fallback, and
that this pymunk takes the fast path, so a pymunk upgrade cannot slow the simulator down unnoticed.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import pymunk
from pymunk import _chipmunk  # (pymunk always has it; what it offers may change)

State = tuple[float, float, float]  # x, y and angle; or velocity x, y and angular velocity


def public_step(space: pymunk.Space, dt: float) -> None:
    space.step(dt)


def public_nearest(
    space: pymunk.Space, point: tuple[float, float], most: float, only: pymunk.ShapeFilter
) -> float | None:
    """How far the nearest shape ``only`` lets through is from ``point``, up to ``most``."""
    nearest = space.point_query_nearest(point, most, only)
    return None if nearest is None else nearest.distance


def public_pose(body: pymunk.Body) -> State:
    position = body.position
    return position.x, position.y, body.angle


def public_velocity(body: pymunk.Body) -> State:
    velocity = body.velocity
    return velocity.x, velocity.y, body.angular_velocity


_core, _ffi = _chipmunk.lib, _chipmunk.ffi
_query_answer = _ffi.new("cpPointQueryInfo *")  # one, filled in by every clearance query


def core_step(space: pymunk.Space, dt: float) -> None:
    """``Space.step`` for a space whose callbacks add and remove nothing (a private API)."""
    _core.cpSpaceStep(space._space, dt)


def core_nearest(
    space: pymunk.Space, point: tuple[float, float], most: float, only: pymunk.ShapeFilter
) -> float | None:
    answer = _query_answer
    shape = _core.cpSpacePointQueryNearest(space._space, point, most, only, answer)
    return None if shape == _ffi.NULL else float(answer.distance)


def core_pose(body: pymunk.Body) -> State:
    handle = body._body
    position = _core.cpBodyGetPosition(handle)
    return position.x, position.y, _core.cpBodyGetAngle(handle)


def core_velocity(body: pymunk.Body) -> State:
    handle = body._body
    velocity = _core.cpBodyGetVelocity(handle)
    return velocity.x, velocity.y, _core.cpBodyGetAngularVelocity(handle)


@dataclass(frozen=True)
class Calls:
    """The four calls, all through the C core or all through the public API."""

    step: Callable[[pymunk.Space, float], None]
    pose: Callable[[pymunk.Body], State]
    velocity: Callable[[pymunk.Body], State]
    nearest: Callable[[pymunk.Space, tuple[float, float], float, pymunk.ShapeFilter], float | None]


PUBLIC = Calls(public_step, public_pose, public_velocity, public_nearest)
CORE = Calls(core_step, core_pose, core_velocity, core_nearest)


def choose_calls() -> Calls:
    """The C-core calls when this pymunk has them and they agree with the public API, else the
    public ones: two copies of a small world, one stepped each way, must stay the same."""
    try:
        core, public = _probe(CORE), _probe(PUBLIC)
        if core == public and core[0] != core[-1]:  # (and the probe did move)
            return CORE
    except Exception:  # another pymunk's private API: fall back to the public one
        pass
    return PUBLIC


def _probe(calls: Calls) -> list[tuple[State, State, float | None, float | None]]:
    """What ``calls`` see of a small world: a box that hits a wall at its 6th step and stops
    turning, and how far the nearest shape is from a point between them (and from one far
    behind the box: nothing that near)."""
    space, body = _probe_world()
    everything = pymunk.ShapeFilter()
    seen = []
    for _ in range(12):
        calls.step(space, 0.01)
        ahead, behind = (
            calls.nearest(space, point, 60, everything) for point in ((50, 20), (50, -90))
        )
        seen.append((calls.pose(body), calls.velocity(body), ahead, behind))
    return seen


def _probe_world() -> tuple[pymunk.Space, pymunk.Body]:
    space = pymunk.Space()
    space.add(pymunk.Segment(space.static_body, (0, 50), (100, 50), 2))
    body = pymunk.Body(1.0, 100.0)
    body.position, body.velocity, body.angular_velocity = (40, 0), (10, 600), 3.0
    box = pymunk.Poly.create_box(body, (30, 20))
    box.friction = 0.5
    space.add(body, box)
    return space, body


calls: Calls = choose_calls()
"""How the physics steps pymunk and reads its body (see the module's docstring)."""
