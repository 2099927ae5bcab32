"""Where the client expects a movement to end (it judges a lost answer by that) agrees with
where the simulated robot really ends, for every movement and direction."""

from __future__ import annotations

from typing import Any

import pytest

from rootlang.protocol import Packet, decode, encode
from rootlang.robots import RobotModel
from rootlang.runtime.client import (
    EARLY_CHECK_MARGIN_S,
    TIMEOUT_MARGIN_S,
    TIMEOUT_SPEED_MM_S,
    TIMEOUT_WHEELBASE_MM,
    Pose,
    early_check_seconds,
    expected_pose,
    same_place,
    timeout_for,
)
from rootlang.sim.robot import VirtualRobot


def _pose(packet: Packet) -> Pose:
    return Pose(float(packet["x"]), float(packet["y"]), packet["heading"] / 10.0)


def _move(robot: VirtualRobot, packet_id: int, name: str, fields: dict[str, Any]) -> Pose:
    robot.write(encode(name, fields, packet_id, robot=robot.model))
    robot.advance(30.0)
    answers = [decode(data, "robot", robot=robot.model) for data in robot.read()]
    ends = [p for p in answers if isinstance(p, Packet) and p.name == f"{name}_response"]
    assert len(ends) == 1
    return _pose(ends[0])


START_MOVES: list[tuple[str, dict[str, Any]]] = [  # leave the start pose first
    ("rotate_angle", {"angle": 300}),
    ("drive_distance", {"distance": 120}),
]
MOVES: list[tuple[str, dict[str, Any]]] = [
    ("drive_distance", {"distance": 150}),
    ("drive_distance", {"distance": -80}),
    ("rotate_angle", {"angle": 900}),
    ("rotate_angle", {"angle": -1350}),
    ("drive_arc", {"angle": 600, "radius": 200}),
    ("drive_arc", {"angle": -900, "radius": -150}),
    ("navigate_to_position", {"x": 300, "y": -200, "heading": -1}),
    ("navigate_to_position", {"x": -100, "y": 250, "heading": 450}),
]


@pytest.mark.parametrize(("name", "fields"), MOVES)
def test_the_expected_end_is_where_the_simulated_robot_ends(
    name: str, fields: dict[str, Any]
) -> None:
    # Navigate needs protocol 1.4+: the Create 3 has it; the rest on the usual Root
    model = RobotModel.CREATE3 if name == "navigate_to_position" else RobotModel.RT1
    robot = VirtualRobot(model=model)
    robot.connect()
    robot.read()
    start = Pose()
    for packet_id, (first, values) in enumerate(START_MOVES, 1):
        start = _move(robot, packet_id, first, values)
    end = _move(robot, 10, name, fields)
    expected = expected_pose(start, name, fields)
    assert same_place(end, expected), (start, end, expected)
    assert not same_place(end, start)  # the judgement can tell a lost command from a lost answer


def test_same_place_is_within_5_mm_and_3_degrees_across_north() -> None:
    here = Pose(0.0, 0.0, 359.0)
    assert same_place(here, Pose(3.0, 4.0, 1.9))
    assert not same_place(here, Pose(3.0, 4.1, 0.0))
    assert not same_place(here, Pose(0.0, 0.0, 2.1))


def test_an_arc_waits_for_its_outer_wheel_at_the_slow_speed() -> None:
    seconds = timeout_for("drive_arc", {"angle": 900, "radius": 100})
    outer = 3.141592653589793 / 2 * (100 + TIMEOUT_WHEELBASE_MM / 2)
    assert seconds == pytest.approx(outer / TIMEOUT_SPEED_MM_S + TIMEOUT_MARGIN_S)


def test_a_turn_waits_for_its_wheels_at_the_slow_speed() -> None:
    seconds = timeout_for("rotate_angle", {"angle": -900})
    wheel = 3.141592653589793 / 2 * TIMEOUT_WHEELBASE_MM / 2
    assert seconds == pytest.approx(wheel / TIMEOUT_SPEED_MM_S + TIMEOUT_MARGIN_S)


def test_a_missing_answer_is_looked_into_once_a_slow_robot_would_be_done() -> None:
    margin = EARLY_CHECK_MARGIN_S
    assert early_check_seconds("drive_distance", {"distance": -100}) == pytest.approx(2 + margin)
    assert early_check_seconds("rotate_angle", {"angle": -900}) == pytest.approx(2 + margin)
    in_place = early_check_seconds("drive_arc", {"angle": 900, "radius": 0})
    assert in_place == pytest.approx(2 + margin)  # 90 degrees at 45 degrees a second
    wide = early_check_seconds("drive_arc", {"angle": -900, "radius": -1000})
    assert wide == pytest.approx(3.141592653589793 / 2 * 1000 / 50 + margin)
