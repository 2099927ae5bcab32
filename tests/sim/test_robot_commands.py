"""Every command of the protocol table, sent as packets to the virtual robot, and its answer."""

from __future__ import annotations

import math

import pytest

from rootlang.protocol import (
    PACKETS,
    Board,
    BumperState,
    DockResult,
    DockStatus,
    Kind,
    MarkerPosition,
    crc8,
    decode,
    encode,
)
from rootlang.robots import RobotModel
from rootlang.sim.robot import VirtualRobot
from rootlang.sim.world import Stimulus

from .helpers import PLAIN, Host, make_robot


@pytest.mark.parametrize("model", list(RobotModel))
def test_each_model_acts_on_exactly_the_commands_of_the_devices_it_has(model: RobotModel) -> None:
    robot = VirtualRobot(model=model)
    supported = [p for p in PACKETS if model in p.robots]
    assert {p.device for p in supported} == robot.spec.devices
    commands = {p.name for p in supported if p.kind is Kind.COMMAND}
    assert set(robot.devices.commands()) == commands


def test_every_command_of_the_table_has_a_behaviour() -> None:
    handled = {
        name for model in RobotModel for name in VirtualRobot(model=model).devices.commands()
    }
    assert handled == {p.name for p in PACKETS if p.kind is Kind.COMMAND}


def test_a_response_repeats_the_first_three_bytes_of_its_request() -> None:
    robot, _ = make_robot(PLAIN)
    request = encode("get_name", {}, 42)
    robot.write(request)
    (answer,) = robot.read()
    assert answer[:3] == request[:3]
    assert crc8(answer[:19]) == answer[19]


def test_drive_distance_finishes_with_the_pose_and_a_timestamp() -> None:
    robot, host = make_robot(PLAIN)
    packet_id = host.send("drive_distance", distance=150)
    assert host.received == []  # not at once
    host.wait(3)
    done = host.response("drive_distance", packet_id)
    assert (done["x"], done["y"], done["heading"]) == (0, 150, 900)
    assert 1500 <= done["timestamp"] <= 1900  # 1.5 s at 100 mm/s, plus speeding up and braking
    assert robot.world_pose[1] == pytest.approx(1650, abs=1)


def test_drive_backwards_and_rotate_both_ways() -> None:
    robot, host = make_robot(PLAIN)
    host.send("drive_distance", distance=-80)
    host.wait(2)
    assert robot.pose[:2] == (0, -80)
    turn = host.send("rotate_angle", angle=900)  # clockwise
    host.wait(3)
    assert host.response("rotate_angle", turn)["heading"] in (0, 1, 3599)
    turn = host.send("rotate_angle", angle=-1800)
    host.wait(4)
    assert abs(host.response("rotate_angle", turn)["heading"] - 1800) <= 2


def test_drive_arc_follows_its_circle() -> None:
    _, host = make_robot(PLAIN)
    arc = host.send("drive_arc", angle=900, radius=200)  # a quarter turn about a point 20 cm right
    host.wait(8)
    done = host.response("drive_arc", arc)
    assert abs(done["x"] - 200) <= 2 and abs(done["y"] - 200) <= 2
    assert done["heading"] in (0, 1, 2, 3599, 3598)


def test_a_newer_movement_interrupts_the_older_whose_answer_comes_at_once() -> None:
    robot, host = make_robot(PLAIN)
    first = host.send("drive_distance", distance=1000)
    host.wait(1)
    second = host.send("rotate_angle", angle=900)
    interrupted = host.response("drive_distance", first)  # already here, before any waiting
    assert interrupted["timestamp"] == robot.now_ms
    assert 50 < interrupted["y"] < 150
    host.wait(3)
    assert host.response("rotate_angle", second)["heading"] in (0, 1, 3599)


def test_wheel_speeds_drive_until_told_otherwise_and_a_movement_stops_them() -> None:
    robot, host = make_robot(PLAIN)
    host.send("set_wheel_speeds", left=100, right=100)
    host.wait(2)
    y = robot.pose[1]
    assert 170 < y < 200
    host.send("set_left_wheel_speed", left=0)
    host.wait(1)
    assert robot.pose[2] != 900  # turning left about the still left wheel
    host.send("set_right_wheel_speed", right=0)
    host.wait(1)
    still = robot.pose
    host.wait(1)
    assert robot.pose == still


def test_reset_and_get_position() -> None:
    _, host = make_robot(PLAIN)
    host.send("drive_distance", distance=100)
    host.wait(2)
    host.send("reset_position")
    where = host.ask("get_position")
    assert (where["x"], where["y"], where["heading"]) == (0, 0, 900)
    host.send("rotate_angle", angle=900)
    host.wait(2)
    host.send("drive_distance", distance=50)  # now along the robot's own +x
    host.wait(2)
    where = host.ask("get_position")
    assert abs(where["x"] - 50) <= 1 and abs(where["y"]) <= 1


def test_navigate_on_a_create3_ends_where_asked() -> None:
    _, host = make_robot(PLAIN, RobotModel.CREATE3)
    done_id = host.send("navigate_to_position", x=300, y=400, heading=0)
    host.wait(10)
    done = host.response("navigate_to_position", done_id)
    assert abs(done["x"] - 300) <= 2 and abs(done["y"] - 400) <= 2
    assert done["heading"] in (0, 1, 2, 3599, 3598)


def test_commands_a_model_lacks_are_ignored_and_noted() -> None:
    robot, host = make_robot(PLAIN)  # a Root speaks protocol 1.3
    host.send("navigate_to_position", x=100, y=100, heading=-1)
    host.send("dock")
    host.wait(2)
    assert host.received == []
    assert robot.pose == (0, 0, 900)
    assert "navigate_to_position" in robot.ignored[0] and "needs 1.4" in robot.ignored[0]
    robot, host = make_robot(PLAIN, RobotModel.CREATE3)
    host.send("set_marker_position", position=MarkerPosition.MARKER_DOWN)
    host.wait(1)
    assert host.received == [] and "not supported by Create 3" in robot.ignored[0]


def test_a_repeated_id_is_ignored_but_id_zero_is_always_accepted() -> None:
    robot, _ = make_robot(PLAIN)
    robot.write(encode("get_name", {}, 7))
    robot.write(encode("get_name", {}, 7))
    assert len(robot.read()) == 1
    robot.write(encode("get_name", {}, 0))
    robot.write(encode("get_name", {}, 0))
    assert len(robot.read()) == 2


def test_a_damaged_packet_is_dropped_and_logged() -> None:
    robot, _ = make_robot(PLAIN)
    data = bytearray(encode("drive_distance", {"distance": 100}, 3))
    data[19] ^= 0xFF
    robot.write(bytes(data))
    robot.advance(2)
    assert robot.read() == [] and robot.pose == (0, 0, 900)
    assert "checksum" in robot.packet_log[-1].describe()


def test_marker_moves_take_time_and_a_newer_one_interrupts() -> None:
    robot, host = make_robot(PLAIN)
    first = host.send("set_marker_position", position=MarkerPosition.MARKER_DOWN)
    host.wait(0.1)
    second = host.send("set_marker_position", position=MarkerPosition.ERASER_DOWN)
    assert host.response("set_marker_position", first)["position"] == MarkerPosition.UP
    host.wait(1)
    assert host.response("set_marker_position", second)["position"] == MarkerPosition.ERASER_DOWN
    assert robot.recording.frames[-1].tool == "eraser"


def test_rt0_has_no_eraser_so_the_marker_just_lifts() -> None:
    _, host = make_robot(PLAIN, RobotModel.RT0)
    answer = host.send("set_marker_position", position=MarkerPosition.ERASER_DOWN)
    host.wait(1)
    assert host.response("set_marker_position", answer)["position"] == MarkerPosition.UP


def test_leds_are_recorded() -> None:
    robot, host = make_robot(PLAIN)
    host.send("set_led_animation", state=2, red=0, green=255, blue=0)
    host.wait(0.1)
    host.send("set_led_animation", state=0, red=9, green=9, blue=9)
    assert [(c.mode, c.rgb) for c in robot.recording.lights] == [
        ("blink", (0, 255, 0)),
        ("off", (0, 0, 0)),
    ]
    assert host.received == []  # LEDs have no response


def test_notes_play_for_their_duration_and_interrupt_each_other() -> None:
    robot, host = make_robot(PLAIN)
    first = host.send("play_note", frequency=440, duration=1000)
    host.wait(0.25)
    second = host.send("play_note", frequency=880, duration=500)
    assert host.response("play_note", first).id == first
    host.wait(0.4)
    assert all(p.id != second for p in host.received)
    host.wait(0.2)
    host.response("play_note", second)
    notes = [(n.frequency_hz, n.duration_ms) for n in robot.recording.notes]
    assert notes == [(440, 250), (880, 500)]


def test_stop_sound_and_a_zero_duration_note_cut_the_sound() -> None:
    _, host = make_robot(PLAIN)
    note = host.send("play_note", frequency=440, duration=5000)
    host.wait(0.1)
    host.send("stop_sound")
    host.response("play_note", note)
    note = host.send("play_note", frequency=440, duration=5000)
    cancel = host.send("play_note", frequency=440, duration=0)
    host.response("play_note", note)
    host.response("play_note", cancel)


def test_say_takes_longer_for_longer_text() -> None:
    robot, host = make_robot(PLAIN)
    short = host.send("say_phrase", phrase="hi")
    host.wait(3)
    long = host.send("say_phrase", phrase="hello everyone")
    start = robot.now_ms
    host.wait(5)
    answered = {decode(r.data, "robot").id: r.t_ms for r in robot.packet_log if r.direction == "<-"}
    assert answered[short] < 1000
    assert answered[long] - start > 1000
    assert [s.text for s in robot.recording.said] == ["hi", "hello everyone"]


def test_an_appended_sweep_waits_for_the_playing_one() -> None:
    robot, host = make_robot(PLAIN)
    sweep = {"start_frequency": 200_000, "end_frequency": 800_000, "duration": 1000,
             "attack": 0, "release": 0, "volume": 200, "modulation_type": 0,
             "modulation_rate": 0}  # fmt: skip
    first = host.send("play_sweep", append=0, **sweep)
    second = host.send("play_sweep", append=1, **sweep)
    host.wait(1.5)
    host.response("play_sweep", first)
    assert all(p.id != second for p in host.received)
    host.wait(1)
    host.response("play_sweep", second)
    assert [n.end_hz for n in robot.recording.notes] == [800, 800]


def test_versions_name_serial_sku() -> None:
    robot, host = make_robot(PLAIN)
    versions = host.ask("get_versions", board=Board.MAIN)
    assert (versions["protocol_major"], versions["protocol_minor"]) == (1, 3)
    assert (versions["firmware_major"], versions["firmware_minor"]) == (2, 7)
    robot.write(encode("set_name", {"name": "Rooty"}, 99))
    assert host.ask("get_name")["name"] == "Rooty"
    assert host.ask("get_serial_number")["serial"] == "RT1SIMULATED"
    assert host.ask("get_sku")["sku"] == "RT1-SIM"
    robot, host = make_robot(PLAIN, RobotModel.RT0)
    host.send("get_versions", board=Board.COLOR)  # an RT0 has no colour board
    assert host.received == []


def test_events_can_be_disabled_and_enabled_but_not_general() -> None:
    _, host = make_robot(PLAIN)
    host.send("disable_events", devices=[0, 12])
    enabled = host.ask("get_enabled_events")["devices"]
    assert 0 in enabled and 12 not in enabled and 1 in enabled
    host.send("set_wheel_speeds", left=100, right=100)
    host.wait(20)  # drives off the floor's edge... into nothing: PLAIN has no walls
    host.send("enable_events", devices=[12])
    assert 12 in host.ask("get_enabled_events")["devices"]


def test_disabled_bumper_events_are_not_sent() -> None:
    robot, host = make_robot("[floor]\nwidth=600\nheight=600\n[robot]\nx=300\ny=300")
    host.send("disable_events", devices=[12])
    host.send("set_wheel_speeds", left=100, right=100)
    host.wait(4)
    assert host.events("bumper_event") == []
    assert any(e.text.startswith("bumper") for e in robot.recording.events)


def test_stop_and_reset_stops_everything_and_answers_what_it_cancelled() -> None:
    # as iRobot's SDK expects: a Drive Distance cut short by a Stop and Reset is answered
    robot, host = make_robot(PLAIN)
    host.send("drive_distance", distance=500)
    host.send("play_note", frequency=440, duration=5000)
    host.wait(1)
    host.send("stop_and_reset")
    answers = [(p.name, p.fields.get("y")) for p in host.received]
    assert [name for name, _ in answers] == ["drive_distance_response", "play_note_response"]
    assert 0 < int(answers[0][1] or 0) < 500  # where it was stopped, before the reset
    host.received.clear()
    host.wait(6)
    assert host.received == []  # nothing more: the drive and the note were cancelled
    assert robot.pose == (0, 0, 900)  # reset here
    assert robot.world_pose[1] > 1550  # it did drive first


def test_gravity_compensation_is_accepted_and_recorded() -> None:
    robot, host = make_robot(PLAIN)
    host.send("set_gravity_compensation", active=1, amount=700)
    assert robot.gravity_compensation == (1, 700)


def test_disconnect_stops_the_robot_and_tells_the_host() -> None:
    robot, host = make_robot(PLAIN)
    reasons: list[str] = []
    robot.on_disconnect = reasons.append
    host.send("set_wheel_speeds", left=100, right=100)
    host.wait(0.5)
    host.send("disconnect")
    where = robot.world_pose
    robot.advance(2)
    assert reasons and not robot.connected
    assert math.dist(robot.world_pose[:2], where[:2]) < 1


def test_create3_dock_and_undock() -> None:
    text = PLAIN + "[dock]\nx = 1500\ny = 2400\nheading = 270\n"
    _, host = make_robot(text, RobotModel.CREATE3)
    docking = host.ask("get_docking_values")
    assert docking["contacts"] == 0
    dock = host.send("dock")
    host.wait(20)
    done = host.response("dock", dock)
    assert (done["status"], done["result"]) == (DockStatus.SUCCEEDED, DockResult.DOCKED)
    assert host.events("docking_sensor_event")[-1]["contacts"] == 1
    undock = host.send("undock")
    host.wait(10)
    done = host.response("undock", undock)
    assert (done["status"], done["result"]) == (DockStatus.SUCCEEDED, DockResult.NOT_DOCKED)


def test_create3_dock_without_a_dock_aborts() -> None:
    _, host = make_robot(PLAIN, RobotModel.CREATE3)
    done = host.ask("dock")
    assert (done["status"], done["result"]) == (DockStatus.ABORTED, DockResult.NOT_DOCKED)


def test_create3_ipv4_and_ir_thresholds() -> None:
    _, host = make_robot(PLAIN, RobotModel.CREATE3)
    assert host.ask("get_ipv4_addresses")["wlan0"] == "0.0.0.0"
    host.send("set_ir_event_thresholds", hysteresis=20, thresholds=[100] * 7)
    answer = host.ask("get_ir_event_thresholds")
    assert answer["hysteresis"] == 20 and list(answer["thresholds"]) == [100] * 7


def test_the_public_api_without_a_world() -> None:
    robot = VirtualRobot()
    host = Host(robot)
    assert robot.info.model is RobotModel.RT1 and robot.info.protocol_version == (1, 3)
    assert host.ask("get_battery_level")["percent"] == 100


def test_a_create3_that_starts_on_its_dock_says_so() -> None:
    text = "[dock]\nx = 1000\ny = 150\nheading = 90\n[robot]\nx = 1000\ny = 350\nheading = 270\n"
    robot, host = make_robot(text, RobotModel.CREATE3)
    host.wait(0.1)
    (docked,) = host.events("docking_sensor_event")
    assert docked["contacts"] == 1 and docked["timestamp"] == 40
    undock = host.send("undock")
    host.wait(8)
    assert host.response("undock", undock)["result"] == DockResult.NOT_DOCKED
    assert host.events("docking_sensor_event")[1]["contacts"] == 0
    assert robot.pose[1] < -200  # backed off the dock


def test_a_host_can_press_the_nose_button() -> None:
    robot, host = make_robot(PLAIN)
    host.send("set_wheel_speeds", left=100, right=100)
    host.wait(1)
    robot.press_nose()
    host.wait(0.5)
    assert [p.name for p in host.received] == ["stop_project_event"]
    assert robot.pose == (0, 0, 900)


def test_a_robot_served_for_hours_can_keep_no_history() -> None:
    robot = VirtualRobot(keep_history=False)
    host = Host(robot)
    host.send("set_marker_position", position=MarkerPosition.MARKER_DOWN)
    host.send("set_wheel_speeds", left=100, right=-100)
    host.wait(600)
    assert robot.packet_log == [] and len(robot.recording.frames) == 1
    assert all(len(stroke.points) <= 1 for stroke in robot.recording.strokes)
    assert host.received  # it still answers


@pytest.mark.parametrize("step_ms", [3, 5, 7, 10])
def test_any_physics_step_reads_the_sensors_and_drives_true(step_ms: int) -> None:
    robot = VirtualRobot(world=None, step_ms=step_ms)
    host = Host(robot)
    drive = host.send("drive_distance", distance=2000)  # into the wall
    host.wait(12)
    assert host.events("bumper_event")[0]["state"] == BumperState.BOTH
    assert host.response("drive_distance", drive)  # ended by the stall
    robot = VirtualRobot(step_ms=step_ms)
    host = Host(robot)
    turn = host.send("rotate_angle", angle=-900)
    host.wait(3)
    assert host.response("rotate_angle", turn)["heading"] in (1799, 1800, 1801)


def test_a_host_can_touch_the_robot() -> None:
    robot, host = make_robot(PLAIN)
    robot.stimulate(Stimulus(0, "touch", ("back left",), duration=0.5))
    host.wait(1)
    assert [e["state"] for e in host.events("touch_sensor_event")] == [0b0001, 0]


def test_a_touch_between_two_steps_of_a_robot_at_rest_comes_at_the_next_step() -> None:
    robot, host = make_robot(PLAIN)
    robot.at(1005, lambda: robot.stimulate(Stimulus(0, "touch", ("front left",), duration=0.2)))
    host.wait(2)
    assert [e["state"] for e in host.events("touch_sensor_event")] == [0b1000, 0]
    assert robot.now_ms == 2000
