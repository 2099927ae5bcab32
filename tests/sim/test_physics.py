"""The body in the open, worked out in Python, moves as pymunk itself steps it; pymunk's C core,
called directly near walls (sim/pymunk_fence.py), does what its public API does."""

from __future__ import annotations

import math

import pymunk
import pytest

from rootlang.robots import RobotModel
from rootlang.sim import physics as physics_module
from rootlang.sim import pymunk_fence
from rootlang.sim.models import spec_for
from rootlang.sim.physics import Physics
from rootlang.sim.world import default_world

# wheel speeds (mm/s) held for a number of 10 ms steps: ramps, straight, arcs, turns in place,
# a sudden reverse (beyond the joints' force: the body lags), and halts
DRIVING = [
    ((40.0, 40.0), 30), ((100.0, 100.0), 80), ((100.0, 60.0), 120), ((-80.0, 80.0), 90),
    ((100.0, -100.0), 25), ((-100.0, -100.0), 40), ((0.0, 0.0), 10), ((70.0, 100.0), 150),
]  # fmt: skip


@pytest.mark.parametrize("model", [RobotModel.RT1, RobotModel.CREATE3])
def test_the_open_ground_step_moves_the_body_as_pymunk_does(model: RobotModel) -> None:
    world = default_world(model)
    spec = spec_for(model)
    in_the_open = Physics(world, spec, 1000, 1000, 90)
    in_pymunk = Physics(world, spec, 1000, 1000, 90)
    in_pymunk.step(0.0, 0.0, 0.01)  # the first step finds the walls far: then force pymunk
    in_pymunk._clearance_at = lambda x, y: -1.0  # type: ignore[method-assign]  # "a wall is near"
    in_the_open.step(0.0, 0.0, 0.01)
    worst = 0.0
    for (left, right), steps in DRIVING:
        for _ in range(steps):
            in_the_open.step(left, right, 0.01)
            in_pymunk.step(left, right, 0.01)
            (x1, y1, a1), (x2, y2, a2) = in_the_open.pose, in_pymunk.pose
            worst = max(worst, math.hypot(x1 - x2, y1 - y2), abs(a1 - a2) * 1000)
        if (left, right) == (0.0, 0.0):
            in_the_open.halt()
            in_pymunk.halt()
    assert worst < 1e-9  # mm (and radians x 1000): bit for bit on x86-64; rounding at most
    assert in_the_open.touching == in_pymunk.touching == 0
    x, y, _ = in_pymunk.pose
    assert math.dist((x, y), (1000, 1000)) > 100  # it did go somewhere


def test_near_a_wall_pymunk_steps_and_the_body_stops_at_it() -> None:
    world = default_world()
    physics = Physics(world, spec_for(RobotModel.RT1), 1000, 1850, 90)  # facing the top wall
    for _ in range(400):
        physics.step(100.0, 100.0, 0.01)
    _, y, _ = physics.pose
    assert physics.touching == 1
    assert 1900 < y < 2000 - 134 / 2 + 1  # held at the wall, not through it


def test_near_a_wall_a_leg_is_asked_again_after_every_step_that_touches() -> None:
    # Untouched, the joints keep the body within the bounds a leg vouched with; a touch can
    # push it beyond them, so the leg must be asked again before the next step.
    physics = Physics(default_world(), spec_for(RobotModel.RT1), 1000, 1850, 90)  # a wall ahead
    physics.step(0.0, 0.0, 0.01)  # the wall is near: pymunk steps from here
    asked: list[int] = []  # whether the body touched something when asked

    def keep_going(pose: tuple[float, float, float], travel: float, turn: float) -> int:
        asked.append(physics.touching)
        return 1000

    taken = 0
    while taken < 300:  # (a glide returns where pymunk takes over)
        taken += physics.glide((100.0, 100.0), (100.0, 100.0), 0.0, 0.01, 300, keep_going)[0]
    assert physics.touching  # it drove to the wall and pushes it
    clear = asked.count(0)
    assert 1 <= clear <= 2  # once in the open, once as pymunk takes over: for all those steps
    assert len(asked) > 200 and all(asked[clear:])  # then after every step at the wall


def test_this_pymunk_takes_the_fast_path_through_its_c_core() -> None:
    # fails when a pymunk upgrade moves the private calls: the simulator would be slower
    assert pymunk_fence.calls is pymunk_fence.CORE


def test_the_c_core_calls_agree_with_pymunk_public_api_as_a_robot_pushes_and_backs_off(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    runs = []
    for calls in (pymunk_fence.CORE, pymunk_fence.PUBLIC):
        monkeypatch.setattr(physics_module, "pymunk_core", calls)
        physics = Physics(default_world(), spec_for(RobotModel.RT1), 1000, 1880, 90)
        states = []
        for left, right in [(100.0, 100.0)] * 90 + [(-100.0, 80.0)] * 40:  # into the wall, off
            physics.step(left, right, 0.01)
            states.append((physics.pose, physics.wheel_speeds(), physics.touching))
        runs.append(states)
    assert runs[0] == runs[1]
    assert any(touching for _, _, touching in runs[0])  # it did push the wall


def test_on_a_pymunk_whose_c_core_differs_the_public_api_is_used(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    assert pymunk_fence.choose_calls() is pymunk_fence.CORE
    broken_reads = (pymunk_fence.core_pose, lambda body: (0.0, 0.0, 0.0), pymunk_fence.core_nearest)
    monkeypatch.setattr(
        pymunk_fence, "CORE", pymunk_fence.Calls(pymunk_fence.core_step, *broken_reads)
    )
    assert pymunk_fence.choose_calls() is pymunk_fence.PUBLIC

    def missing(space: pymunk.Space, dt: float) -> None:
        raise AttributeError("_space")  # as a pymunk without the private member would

    monkeypatch.setattr(pymunk_fence, "CORE", pymunk_fence.Calls(missing, *broken_reads))
    assert pymunk_fence.choose_calls() is pymunk_fence.PUBLIC
