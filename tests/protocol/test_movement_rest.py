"""What finishes a movement a pause cut short, from where the robot came to rest (each
movement's row of the packet table: ``Behaviour.rest``)."""

from __future__ import annotations

import pytest

from rootlang.protocol import spec
from rootlang.protocol.behaviour import START

ARC_REST = {"angle": 900, "radius": 100}  # half of a half circle to the right done
GOAL = {"x": 100, "y": 200, "heading": -1}


@pytest.mark.parametrize(
    ("name", "fields", "now", "rest"),
    [
        ("drive_distance", {"distance": 400}, (0.0, 150.0, 90.0), {"distance": 250}),
        ("drive_distance", {"distance": -400}, (0.0, -100.0, 90.0), {"distance": -300}),
        ("drive_distance", {"distance": 400}, (0.0, 400.4, 90.0), None),  # there already
        ("rotate_angle", {"angle": 900}, (0.0, 0.0, 60.0), {"angle": 600}),  # 30° of 90° right
        ("rotate_angle", {"angle": -900}, (0.0, 0.0, 120.0), {"angle": -600}),  # left
        ("rotate_angle", {"angle": 900}, (0.0, 0.0, 0.0), None),
        ("drive_arc", {"angle": 1800, "radius": 100}, (100.0, -100.0, 0.0), ARC_REST),
        ("navigate_to_position", GOAL, (10.0, 20.0, 45.0), GOAL),  # the same again
    ],
)
def test_a_movement_cut_short_is_finished_from_where_it_stopped(
    name: str, fields: dict[str, int], now: tuple[float, float, float], rest: object
) -> None:
    finish = spec(name).behaviour.rest
    assert finish is not None
    assert finish(fields, START, now) == rest


def test_wheel_speeds_and_sounds_have_no_rest() -> None:
    assert spec("set_wheel_speeds").behaviour.rest is None
    assert spec("play_note").behaviour.rest is None
