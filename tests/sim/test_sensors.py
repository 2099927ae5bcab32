"""Sensors and events of the virtual robot, read through the packets it sends."""

from __future__ import annotations

import dataclasses
import re

import pytest

from rootlang.protocol import BumperState, LightState, Motor, SensorColor
from rootlang.robots import RobotModel

from .helpers import PLAIN, make_robot

WALLED = """
[floor]
width = 1000
height = 1000
[robot]
x = 500
y = 500
heading = 90
"""


def test_a_head_on_wall_presses_both_bumpers_and_backing_off_releases_them() -> None:
    robot, host = make_robot(WALLED)
    host.send("set_wheel_speeds", left=100, right=100)
    host.wait(6)
    bumps = host.events("bumper_event")
    assert bumps[0]["state"] == BumperState.BOTH
    # held at the wall, not sunk into it: front edge at 1000 - 10 (half the wall)
    assert robot.world_pose[1] == pytest.approx(1000 - 10 - 149 / 2, abs=1.5)
    host.send("drive_distance", distance=-50)
    host.wait(2)
    assert host.events("bumper_event")[-1]["state"] == BumperState.NONE


@pytest.mark.parametrize(("heading", "side"), [(60, BumperState.LEFT), (120, BumperState.RIGHT)])
def test_a_wall_met_at_an_angle_presses_the_bumper_on_that_side(
    heading: int, side: BumperState
) -> None:
    # facing up and a little right (60°), the robot's left front corner meets the top wall first
    _, host = make_robot(WALLED.replace("heading = 90", f"heading = {heading}"))
    host.send("set_wheel_speeds", left=100, right=100)
    host.wait(7)
    assert host.events("bumper_event")[0]["state"] == side


def test_pushing_a_wall_stalls_the_motors_and_ends_a_drive() -> None:
    _, host = make_robot(WALLED)
    drive = host.send("drive_distance", distance=2000)
    host.wait(8)
    stalls = host.events("motor_stall_event")
    assert {s["motor"] for s in stalls} == {Motor.LEFT, Motor.RIGHT}
    done = host.response("drive_distance", drive)
    bump_time = host.events("bumper_event")[0]["timestamp"]
    assert stalls[0]["timestamp"] - bump_time >= 900  # a while after the bump
    assert done["timestamp"] == stalls[0]["timestamp"]


LINE = """
[floor]
width = 1000
height = 1000
walls = false
[[mat]]
shape = "line"
points = [[0, 600], [1000, 600]]
width = 3
color = "black"
[robot]
x = 500
y = 450
"""


def test_a_thin_line_is_seen_when_crossed_at_full_speed() -> None:
    _, host = make_robot(LINE)
    host.send("set_wheel_speeds", left=100, right=100)
    host.wait(2.5)
    seen = [e["colors"] for e in host.events("color_sensor_event")]
    assert seen, "no colour events"
    assert all(c == SensorColor.BLACK for c in seen[0])  # the whole row is on the line at once
    assert all(c == SensorColor.WHITE for c in seen[-1])


def test_the_robot_sees_its_own_marker_line() -> None:
    _, host = make_robot(PLAIN)
    host.send("set_marker_position", position=1)
    host.wait(1)
    host.send("drive_distance", distance=100)  # draws from the centre backwards of the sensors
    host.wait(2)
    assert host.events("color_sensor_event") == []  # the sensors are ahead of the marker
    host.send("set_marker_position", position=0)
    host.wait(1)
    host.send("rotate_angle", angle=1800)  # turn round: the line is now ahead ...
    host.wait(4)
    host.send("drive_distance", distance=-200)  # ... and backing over it crosses it
    host.wait(4)
    blacks = [e for e in host.events("color_sensor_event") if SensorColor.BLACK in e["colors"]]
    assert blacks


def test_colours_of_the_mat_are_classified() -> None:
    _, host = make_robot(
        """
        [floor]
        walls = false
        [[mat]]
        shape = "rect"
        x = 0
        y = 0
        width = 2000
        height = 2000
        color = "orange"
        """
    )
    host.wait(0.1)
    (event,) = host.events("color_sensor_event")  # on orange from the start: reads red
    assert set(event["colors"]) == {SensorColor.RED}
    data = host.ask("get_color_sensor_data", bank=0, lighting=1, format=0)["data"]
    assert all(v > 3000 for v in data)  # red under red light reflects a lot
    data = host.ask("get_color_sensor_data", bank=0, lighting=3, format=0)["data"]
    assert all(v < 1000 for v in data)


TABLE = """
[floor]
width = 2000
height = 2000
walls = false
[[table]]
x = 500
y = 500
width = 1000
height = 1000
[robot]
x = 1000
y = 1000
"""


@pytest.mark.parametrize("walls", ["false", "true"])  # walls round the floor, not the table
def test_a_table_edge_is_a_cliff_and_the_robot_stops_at_it(walls: str) -> None:
    robot, host = make_robot(TABLE.replace("walls = false", f"walls = {walls}"))
    host.send("set_wheel_speeds", left=100, right=100)
    host.wait(8)
    (cliff,) = host.events("cliff_event")
    assert cliff["cliff"] != 0
    assert robot.world_pose[1] < 1500  # stopped on the table
    host.send("drive_distance", distance=-100)
    host.wait(3)
    assert host.events("cliff_event")[-1]["cliff"] == 0
    robot, host = make_robot(TABLE, RobotModel.RT0)  # no cliff sensor: drives off
    host.send("set_wheel_speeds", left=100, right=100)
    host.wait(8)
    assert host.events("cliff_event") == [] and robot.world_pose[1] > 1500


@pytest.mark.parametrize(("walls", "drop"), [("false", True), ("true", False)])
def test_the_floor_s_edge_is_a_cliff_unless_walls_stand_round_it(walls: str, drop: bool) -> None:
    robot, host = make_robot(
        f"[floor]\nwidth = 600\nheight = 600\nwalls = {walls}\n[robot]\nx = 300\ny = 300\n"
    )
    host.send("set_wheel_speeds", left=100, right=100)
    host.wait(5)  # to the edge (pushing the wall, if there is one)
    assert [event["cliff"] != 0 for event in host.events("cliff_event")] == [True] * drop
    assert robot.world_pose[1] < 600


def test_light_regions_and_light_events() -> None:
    _, host = make_robot(
        """
        [floor]
        walls = false
        light = 10
        [[light]]
        shape = "rect"
        x = 0
        y = 1200
        width = 990
        height = 800
        level = 90
        """
    )
    dark = host.ask("get_light_values")
    assert dark["left"] == dark["right"] == 100  # 10 %, in decipercent
    host.send("set_wheel_speeds", left=100, right=100)
    host.wait(4)  # only the left eye (30 mm left of the middle) comes under the light
    (event,) = host.events("light_event")
    assert event["state"] == LightState.LEFT_BRIGHTER
    assert (event["left"], event["right"]) == (900, 100)


def test_battery_drains_and_reports_each_ten_percent() -> None:
    _, host = make_robot(
        PLAIN.replace("heading = 90", "heading = 90\nbattery = 50\nbattery_drain = 60")
    )
    host.send("set_wheel_speeds", left=50, right=-50)  # spin in place: 60 % a minute
    host.wait(11)
    (event,) = host.events("battery_level_event")
    assert event["percent"] == 40
    assert host.ask("get_battery_level")["percent"] < 40


def test_scripted_touches_nose_pick_up_and_tilt() -> None:
    robot, host = make_robot(
        PLAIN
        + """
        [[stimulus]]
        at = 1.0
        action = "touch"
        sensors = ["front left", "back right"]
        duration = 0.5
        [[stimulus]]
        at = 2.0
        action = "pick up"
        duration = 1.0
        [[stimulus]]
        at = 4.0
        action = "tilt"
        pitch = 30
        duration = 1.0
        [[stimulus]]
        at = 6.0
        action = "nose"
        """
    )
    host.wait(1.2)
    (touch,) = host.events("touch_sensor_event")
    assert touch["state"] == 0b1010 and touch["timestamp"] == 1000
    # the replay's timeline names them as the world file and the stage's buttons do ("back")
    assert "touch back right, front left" in [event.text for event in robot.recording.events]
    host.wait(1.0)
    assert host.events("touch_sensor_event")[-1]["state"] == 0
    assert host.events("cliff_event")[-1]["cliff"] != 0  # lifted: the floor is gone
    host.wait(1.5)
    assert host.events("cliff_event")[-1]["cliff"] == 0
    host.wait(1.0)
    tilted = host.ask("get_accelerometer")
    assert tilted["y"] == 500 and tilted["z"] == 866
    host.send("set_wheel_speeds", left=100, right=100)
    host.wait(1.5)
    assert host.events("stop_project_event")
    moved = robot.world_pose
    host.wait(1)
    assert robot.world_pose == moved  # the nose button stopped it
    assert host.ask("get_position")["y"] == 0  # and reset its position


def test_accelerometer_on_a_floor_and_on_a_whiteboard() -> None:
    _, host = make_robot(PLAIN)
    flat = host.ask("get_accelerometer")
    assert (flat["x"], flat["y"], flat["z"]) == (0, 0, 1000)
    _, host = make_robot(PLAIN.replace("walls = false", 'walls = false\nsurface = "whiteboard"'))
    up = host.ask("get_accelerometer")
    assert (up["x"], up["y"], up["z"]) == (0, 1000, 0)


def test_create3_ir_proximity_sees_a_wall_ahead_with_hysteresis() -> None:
    _, host = make_robot(
        "[floor]\nwidth = 2000\nheight = 1000\n[robot]\nx = 1000\ny = 300\nheading = 90\n",
        RobotModel.CREATE3,
    )
    assert host.ask("get_packed_ir_proximity")["state"] == 0
    host.send("set_wheel_speeds", left=100, right=100)
    host.wait(4.5)
    events = host.events("ir_proximity_event")
    assert events and events[0]["state"] & 0b0001000  # sensor 3 looks straight ahead
    values = host.ask("get_ir_proximity_values")["sensors"]
    assert values[3] > 500


def test_events_carry_the_robots_own_incrementing_ids() -> None:
    _, host = make_robot(WALLED)
    host.send("set_wheel_speeds", left=100, right=100)
    host.wait(5)
    events = [p for p in host.received if p.name.endswith("_event")]
    assert [e.id for e in events] == list(range(len(events)))


@pytest.mark.parametrize("erase", [False, True])
def test_the_eraser_wipes_the_robots_line_so_the_sensors_no_longer_see_it(erase: bool) -> None:
    robot, host = make_robot(PLAIN)
    host.send("set_marker_position", position=1)
    host.wait(1)
    host.send("drive_distance", distance=100)  # a line under the robot's middle
    host.wait(2)
    host.send("set_marker_position", position=2 if erase else 0)
    host.wait(1)
    host.send("drive_distance", distance=50)  # the eraser, 31 mm behind, covers the line's end
    host.wait(1.5)
    host.send("drive_distance", distance=-300)  # ... and the rest of it
    host.wait(4)
    host.send("set_marker_position", position=0)
    host.wait(1)
    before = len(host.received)
    host.send("drive_distance", distance=300)  # the sensors pass along where the line was
    host.wait(4)
    seen = [e for e in host.received[before:] if e.name == "color_sensor_event"]
    assert any(SensorColor.BLACK in e["colors"] for e in seen) is not erase
    kinds = [s.kind for s in robot.recording.strokes]
    assert kinds == (["marker", "eraser"] if erase else ["marker"])


def test_a_stimulus_has_one_spelling_and_the_page_offers_those_of_the_table() -> None:
    # the world file's `pick up` is the simulator's, and the studio's stimuli and the touch and
    # bumper names its worker takes (read during a run by rootlang.studio.debugging) are the
    # world's table
    from rootlang.sim.world import STIMULI, parse_world
    from rootlang.studio import debugging, server

    world = parse_world(PLAIN + '\n[[stimulus]]\nat = 1.0\naction = "pick up"\n')
    (picked,) = world.stimuli
    assert picked.action == "pick up" and picked.action in STIMULI
    assert {"touch", "bump", "nose"} == server.STIMULI
    assert all(STIMULI[action].on_the_page for action in server.STIMULI)
    touched = debugging.stimulus_from({"action": "touch", "sensors": ["back left", "nowhere"]})
    assert touched.sensors == ("back left",)
    bumped = debugging.stimulus_from({"action": "bump", "sensors": ["right"]})
    assert (bumped.action, bumped.sensors) == ("bump", ("right",))


def test_the_stages_buttons_are_written_from_the_stimuli_table(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """The page keeps no copy of the names: the studio writes its buttons from the table, and
    each sends the parts as the simulator spells them."""
    from rootlang.sim.world import STIMULI
    from rootlang.studio import pages

    page = pages.page("index.html").text or ""
    assert re.findall(r'data-touch="([^"]+)"', page) == list(STIMULI["touch"].parts)
    bumped = re.findall(r'data-bump="([^"]+)"', page)
    assert bumped == ["left", "left right", "right"] and "data-nose" in page
    # (the table's order, names the robot's drawings know: each button shows its zone lit)
    reordered = tuple(reversed(STIMULI["touch"].parts))
    renamed = dataclasses.replace(STIMULI["touch"], parts=reordered)
    monkeypatch.setitem(STIMULI, "touch", renamed)
    assert re.findall(r'data-touch="([^"]+)"', pages.stage_buttons()) == list(reordered)
