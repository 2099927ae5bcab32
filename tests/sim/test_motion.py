"""A movement's legs vouch for the steps they surely cruise: the body then glides through them
without asking each step, and ends exactly where asking every step takes it."""

from __future__ import annotations

import pytest

from rootlang.protocol import encode
from rootlang.robots import RobotModel
from rootlang.sim import motion
from rootlang.sim.devices.motors import Motors
from rootlang.sim.motion import Leg
from rootlang.sim.robot import VirtualRobot
from rootlang.sim.world import default_world

# drive, rotate (both ways), arcs, a drive interrupted by another, a long drive into a wall
MOVES: list[tuple[str, dict[str, int]]] = [
    ("drive_distance", {"distance": 300}), ("rotate_angle", {"angle": 1440}),
    ("drive_distance", {"distance": -170}), ("rotate_angle", {"angle": -2950}),
    ("drive_arc", {"angle": 900, "radius": 200}), ("drive_arc", {"angle": -450, "radius": -80}),
    ("drive_distance", {"distance": 1200}), ("drive_distance", {"distance": 700}),
    ("navigate_to_position", {"x": 150, "y": -260, "heading": 450}),
    ("drive_distance", {"distance": 2500}),
]  # fmt: skip


def drive(robot: VirtualRobot) -> list[str]:
    for number, (name, fields) in enumerate(MOVES, start=1):
        robot.write(encode(name, fields, number, robot=robot.model))
        robot.advance(1.7 if number == 7 else 9.0)  # the 7th is cut short by the 8th
    return [str(record) for record in robot.packet_log]


@pytest.mark.parametrize("model", [RobotModel.RT1, RobotModel.CREATE3])
def test_vouched_steps_end_where_asking_every_step_does(
    model: RobotModel, monkeypatch: pytest.MonkeyPatch
) -> None:
    vouched = drive(VirtualRobot(default_world(model)))
    original = Leg.cruise_steps
    calls = 0

    def one_at_a_time(leg: Leg, pose: motion.Pose, travel: float, turn: float) -> int:
        nonlocal calls
        calls += 1
        return min(1, original(leg, pose, travel, turn))

    monkeypatch.setattr(Leg, "cruise_steps", one_at_a_time)
    asked_every_step = drive(VirtualRobot(default_world(model)))
    assert calls > 1000  # the legs did cruise, and were asked every step
    assert vouched == asked_every_step  # same packets, same times, same poses to the bit


def test_a_leg_vouches_for_many_steps_far_from_its_end_and_none_near_it() -> None:
    leg = Leg(1000.0)
    leg.begin((0.0, 0.0, 0.0))
    leg.wheel_targets(102.0, 100.0, 400.0)  # asks the top rate: far from the end
    far = leg.cruise_steps((10.0, 0.0, 0.0), 1.0, 0.0)
    assert 900 < far < 990  # about (990 mm - the braking distance) at 1 mm a step
    leg.wheel_targets(102.0, 100.0, 400.0)
    assert leg.cruise_steps((995.0, 0.0, 0.0), 1.0, 0.0) == 0  # braking: steps one by one


# wheel speed commands ramp: up from a standstill, from forwards to backwards, to an arc, down
# to a stop; a movement after them ramps up from the speeds they left
RAMPS: list[tuple[str, dict[str, int]]] = [
    ("set_wheel_speeds", {"left": 100, "right": 100}),
    ("set_wheel_speeds", {"left": -80, "right": -80}), ("set_left_wheel_speed", {"left": 30}),
    ("set_wheel_speeds", {"left": 0, "right": 0}),
    ("set_wheel_speeds", {"left": 60, "right": -60}), ("drive_distance", {"distance": 250}),
    ("set_right_wheel_speed", {"right": 90}), ("drive_arc", {"angle": -900, "radius": 150}),
]  # fmt: skip


@pytest.mark.parametrize("model", [RobotModel.RT1, RobotModel.CREATE3])
def test_ramps_glide_to_where_stepping_one_by_one_takes_the_robot(
    model: RobotModel, monkeypatch: pytest.MonkeyPatch
) -> None:
    def run() -> tuple[list[str], tuple[float, float, float]]:
        robot = VirtualRobot(default_world(model))
        for number, (name, fields) in enumerate(RAMPS, start=1):
            robot.write(encode(name, fields, number, robot=robot.model))
            robot.advance(0.13 * number)  # cut short mid-ramp, or after the ramp's end
        robot.advance(5.0)
        return [str(record) for record in robot.packet_log], robot.world_pose

    glided = run()
    monkeypatch.setattr(Motors, "steady", lambda motors: False)  # every step one by one
    assert run() == glided  # same packets, times and pose to the bit
