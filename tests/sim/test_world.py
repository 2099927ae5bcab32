"""World files: what loads, and the errors a bad file gets (file, key, what was expected)."""

from __future__ import annotations

from pathlib import Path

import pytest

from rootlang.colors import NAMED_COLORS
from rootlang.diagnostics import RootlangError
from rootlang.robots import RobotModel
from rootlang.sim.world import (
    BUILT_IN_WORLDS,
    Circle,
    Line,
    Polygon,
    Rect,
    default_world,
    load_world,
    parse_world,
)

WORLDS = sorted(BUILT_IN_WORLDS.glob("*.toml"))

FULL = """
name = "everything"
time_limit = 12.5

[floor]
width = 1500
height = 1000
color = "#f0f0f0"
walls = false
surface = "whiteboard"
light = 30

[robot]
model = "create3"
x = 200
y = 300
heading = 45
marker_color = "blue"
battery = 80
battery_drain = 2
name = "Zippy"

[[wall]]
from = [0, 500]
to = [700, 500]

[[obstacle]]
shape = "circle"
x = 1000
y = 800
radius = 50

[[mat]]
shape = "polygon"
points = [[0, 0], [100, 0], [50, 80]]
color = "red"

[[mat]]
shape = "line"
points = [[0, 0], [300, 300], [600, 0]]
width = 10
color = "black"

[[light]]
shape = "circle"
x = 100
y = 100
radius = 100
level = 95

[[table]]
x = 0
y = 0
width = 1200
height = 1000

[dock]
x = 1400
y = 500
heading = 180

[[stimulus]]
at = 3
action = "nose"

[[stimulus]]
at = 1
action = "touch"
sensors = "front right"
"""


def test_a_world_with_every_part() -> None:
    world = parse_world(FULL, "full.toml")
    assert world.name == "everything" and world.time_limit == 12.5
    assert (world.width, world.height, world.surface, world.ambient_light) == (
        1500, 1000, "whiteboard", 30,
    )  # fmt: skip
    assert world.robot.model is RobotModel.CREATE3 and world.robot.name == "Zippy"
    assert world.robot.marker_color == NAMED_COLORS["blue"]
    assert isinstance(world.obstacles[0].shape, Circle)
    assert isinstance(world.mat[0].shape, Polygon) and isinstance(world.mat[1].shape, Line)
    assert isinstance(world.table[0], Rect)
    assert world.dock is not None and world.dock.heading == 180
    assert [s.action for s in world.stimuli] == ["touch", "nose"]  # sorted by time
    assert world.all_walls() == world.walls  # no border walls
    assert world.mat_color_at(50, 20) == NAMED_COLORS["red"]
    assert world.mat_color_at(300, 298) == NAMED_COLORS["black"]
    assert world.mat_color_at(900, 900).rgb == (0xF0, 0xF0, 0xF0)
    assert world.on_table(100, 100) and not world.on_table(1300, 100)


def test_the_default_world_and_an_empty_file() -> None:
    world = default_world()
    assert len(world.all_walls()) == 4 and world.robot.model is RobotModel.RT1
    assert (world.robot.x, world.robot.y, world.robot.heading) == (1000, 1000, 90)
    empty = parse_world("", "empty.toml")
    assert empty.name == "empty" and empty.robot == world.robot


@pytest.mark.parametrize("path", WORLDS, ids=[p.stem for p in WORLDS])
def test_every_gallery_world_loads(path: Path) -> None:
    assert load_world(path).path == str(path)


@pytest.mark.parametrize(
    ("text", "code", "words"),
    [
        ("[floor]\nwidht = 3", "E304", ["`floor.widht`", 'Did you mean "width"']),
        ("speed = 3", "E304", ["`speed`", "I know: name"]),
        ('time_limit = "long"', "E303", ["`time_limit`", "a number", '"long"']),
        ("time_limit = -1", "E303", ["a number above 0"]),
        ("[floor]\nlight = 150", "E303", ["`floor.light`", "from 0 to 100"]),
        ('[robot]\nmodel = "RT9"', "E303", ["`robot.model`", '"RT0", "RT1" or "Create3"']),
        ("[[mat]]\nx = 1\ny = 1\nwidth = 2\nheight = 2", "E305", ["`mat[0].color`", "#rrggbb"]),
        ('[[mat]]\nshape = "blob"\ncolor = "red"', "E303", ["`mat[0].shape`", "rect, circle"]),
        ('[[mat]]\nshape = "circle"\nx = 1\ny = 1\ncolor = "red"', "E305", ["`mat[0].radius`"]),
        ('[[mat]]\nshape="line"\npoints=[[0,0]]\ncolor="red"', "E303", ["at least 2 points"]),
        ('[[mat]]\nshape="polygon"\npoints=[[0,0],[1,"a"],[2,2]]\ncolor="red"', "E303",
         ["`mat[0].points[1]`", "a point [x, y]"]),
        ('[[mat]]\nx=0\ny=0\nwidth=5\nheight=5\ncolor="mauve"', "E303", ["a colour name"]),
        ("[[wall]]\nfrom = [0, 0]", "E305", ["`wall[0].to`"]),
        ('[[stimulus]]\nat = 1\naction = "poke"', "E303", ["`stimulus[0].action`", "pick up"]),
        ('[[stimulus]]\nat=1\naction="touch"\nsensors=["nose"]', "E303", ["front left"]),
        ("floor = 3", "E303", ["`floor`", "a [floor] table"]),
        ("[floor]\nwalls = 1", "E303", ["true or false"]),
        ("[robot]\nx = 5000", "E303", ["`robot.x`", "from 0 to 2000"]),
        ("name = ", "E302", ["bad.toml"]),
    ],
)  # fmt: skip
def test_a_bad_world_names_the_file_the_key_and_what_was_expected(
    text: str, code: str, words: list[str]
) -> None:
    with pytest.raises(RootlangError) as caught:
        parse_world(text, "bad.toml")
    (found,) = caught.value.diagnostics
    assert found.code == code
    message = found.english
    assert "bad.toml" in message
    for word in words:
        assert word in message


def test_a_missing_or_unreadable_world_file(tmp_path: Path) -> None:
    with pytest.raises(RootlangError) as caught:
        load_world(tmp_path / "nowhere.toml")
    assert caught.value.diagnostics[0].code == "E301"
    binary = tmp_path / "binary.toml"
    binary.write_bytes(b"\xff\xfe\x00")
    with pytest.raises(RootlangError) as caught:
        load_world(binary)
    assert caught.value.diagnostics[0].code == "E302"


def test_shapes_contain_points() -> None:
    assert Rect(0, 0, 10, 5).contains(10, 5) and not Rect(0, 0, 10, 5).contains(11, 0)
    assert Circle(0, 0, 5).contains(3, 4) and not Circle(0, 0, 5).contains(4, 4)
    triangle = Polygon(((0, 0), (10, 0), (0, 10)))
    assert triangle.contains(2, 2) and not triangle.contains(8, 8)
    assert Line(((0, 0), (10, 0)), 4).contains(5, 1.9) and not Line(((0, 0), (10, 0)), 4).contains(
        5, 2.5
    )


def test_a_world_can_script_a_hand_on_the_bumper() -> None:
    from rootlang.app.session import simulate
    from rootlang.checks import load_checked

    world = parse_world(
        '[[stimulus]]\nat = 0.5\naction = "bump"\nsensors = ["right"]\n', "bump.toml"
    )
    program = load_checked(
        'when started\n    wait 5 seconds\n\nwhen bumper right pressed\n    print "bumped"\n'
    )
    result, _ = simulate(program, world)
    assert list(result.printed) == ["bumped"]


def test_a_bump_names_only_bumper_sides() -> None:
    with pytest.raises(RootlangError, match="bumper sides"):
        parse_world('[[stimulus]]\nat = 1\naction = "bump"\nsensors = ["front"]\n', "b.toml")
