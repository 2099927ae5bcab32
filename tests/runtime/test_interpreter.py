"""Statements, expressions, variables, procedures and sensors at run time."""

from __future__ import annotations

import pytest
from runtime_helpers import run_root

from rootlang import ast
from rootlang.checks import diagnose, load_checked
from rootlang.protocol import BumperState, TouchSensors
from rootlang.robots import RobotModel
from rootlang.runtime.interpreter import split_phrase


def test_a_variable_set_in_two_scripts_is_shared() -> None:
    ran = run_root(
        """
        when started
            set count to 0
            set mine to 1
            send "go" and wait
            print count, mine
        when message "go" received
            change count by 5
            set mine to 100
            print mine
        """
    )
    assert ran.printed == ["100", "5 100"]


def test_procedures_with_parameters_return_values_and_recursion() -> None:
    ran = run_root(
        """
        to factorial n
            if n <= 1
                return 1
            return n * factorial (n - 1)
        to area width, height
            return width + height
        when started
            print factorial 5
            print area(3 cm, 4 cm)
        """
    )
    assert ran.printed == ["120", "7 cm"]


def test_recursion_past_the_limit_is_a_clear_error() -> None:
    ran = run_root(
        """
        to forever_down n
            forever_down n + 1
        when started
            forever_down 1
        """
    )
    assert ran.result.error is not None
    assert ran.result.error.code == "E206"
    assert ran.result.error.span.line == 2


def test_units_broken_late_report_the_checks_message_with_the_line() -> None:
    ran = run_root(
        """
        to add p, q
            print p + q
        when started
            add 10 cm, 3 seconds
        """
    )
    assert ran.result.error is not None
    assert ran.result.error.code == "E110"
    assert ran.result.error.english == "I can't add a distance in cm and a time in seconds."
    assert ran.result.error.span.line == 2


@pytest.mark.parametrize(
    ("line", "value", "code"),
    [
        ("move {}", "10", "E108"),
        ("turn right {}", "10 cm", "E109"),
        ("arc left 90 degrees radius {}", "5 seconds", "E109"),
        ("set left wheel {}", "5", "E108"),
        ("play note C4 for {}", "2", "E108"),
        ("wait {}", "2", "E108"),
        ("repeat {}\n        print 1", "2 cm", "E109"),
        ("light on {}", "5", "E109"),
        ("light on rgb {} 0 0", "(2 cm)", "E109"),
        ("send {}", "3", "E109"),
        ("move {} cm", "(2 cm)", "E114"),
        ("if {}\n        print 1", "3", "E112"),
        ("wait until {}", "3 cm", "E112"),
        ("repeat until {}\n        print 1", '"yes"', "E112"),
    ],
)
def test_a_mistake_only_the_run_sees_reads_like_the_checks_one(
    line: str, value: str, code: str
) -> None:
    """The same rule for both: a value passed through a parameter (kind unknown before the
    run) breaks it at run time with the message `rootlang check` gives for the value written
    in place (which may also say the line to write)."""
    # (through two procedures: a number handed straight to `try` is caught before the run, E122)
    source = f"to try p\n    {line.format('p')}\nto pass q\n    try q\n"
    ran = run_root(source + f"when started\n    pass {value}\n")
    assert ran.result.error is not None
    (checked,) = diagnose(f"when started\n    {line.format(value)}\n")
    same = checked.without_suggestion()  # (the check may add the line to write, with the unit)
    assert (ran.result.error.code, ran.result.error.english) == (same.code, same.english)
    assert checked.code == code


def test_rgb_of_values_known_only_at_run_time_is_a_colour_like_a_written_one() -> None:
    ran = run_root(
        """
        to paint r, g
            light on rgb r g 0
            print rgb r g 300, rgb r g 0 = rgb 200 0 0
        when started
            paint 199.6, -5
        """
    )
    assert ran.result.error is None
    assert ran.printed == ["rgb 200 0 255 true"]
    light = next(e.packet for e in ran.robot.received if e.packet.name == "set_led_animation")
    assert (light["red"], light["green"], light["blue"]) == (200, 0, 0)


@pytest.mark.parametrize(
    ("sensor", "model"),
    [
        ("bumper left pressed", RobotModel.RT1),
        ("touch front left pressed", RobotModel.RT1),
        ("color on left", RobotModel.RT1),
        ("light left", RobotModel.RT1),
        ("battery", RobotModel.RT1),
        ("position x", RobotModel.RT1),
        ("heading", RobotModel.RT1),
        ("tilt z", RobotModel.RT1),
        ("cliff", RobotModel.RT1),
        ("timer", RobotModel.RT1),
        ("obstacle front", RobotModel.CREATE3),
        ("docked", RobotModel.CREATE3),
    ],
)
def test_a_sensor_reads_as_the_kind_the_checks_give_it(sensor: str, model: RobotModel) -> None:
    checked = load_checked(f"when started\n    print {sensor}\n", robot=model)
    (statement,) = checked.scripts[0].body
    assert isinstance(statement, ast.Print)
    kind = checked.kind_of(statement.values[0])
    assert kind is not None
    source = f"when started\n    print ({sensor}) = {kind.example}\n"
    assert diagnose(source, robot=model) == []
    readings = {"get_packed_ir_proximity": {"sensors": [0] * 7}}
    ran = run_root(source, model=model, readings=readings)  # another kind would be E110
    assert ran.result.error is None, ran.result.error


def test_stop_this_script_and_stop_other_scripts() -> None:
    ran = run_root(
        """
        when started
            wait 1 second
            stop other scripts
            print "only me"
        when started
            wait 0.5 seconds
            print "half"
            wait 1 second
            print "never"
        when started
            stop this script
            print "never either"
        """
    )
    assert ran.printed == ["half", "only me"]
    assert ran.result.end == "finished"


def test_if_else_and_loops() -> None:
    ran = run_root(
        """
        when started
            set n to 0
            while n < 3
                change n by 1
            repeat until n >= 6
                change n by 1
            if n = 5
                print "five"
            else if n = 6
                print "six"
            else
                print "other"
        """
    )
    assert ran.printed == ["six"]


def test_say_splits_long_text_on_word_boundaries_and_awaits_each_part() -> None:
    ran = run_root(
        """
        when started
            say "hello, I am Root and I like to draw"
        """
    )
    phrases = [
        e.packet.fields["phrase"] for e in ran.robot.received if e.packet.name == "say_phrase"
    ]
    assert phrases == ["hello, I am Root", "and I like to", "draw"]
    times = [e.time for e in ran.robot.received if e.packet.name == "say_phrase"]
    assert times == sorted(times) and len(set(times)) == 3  # one after the other


def test_split_phrase_cuts_words_longer_than_a_packet() -> None:
    assert split_phrase("a" * 20, 16) == ["a" * 16, "a" * 4]
    assert split_phrase("", 16) == [""]
    assert all(len(part.encode()) <= 16 for part in split_phrase("héllo wörld ünïcödé ok", 16))


def test_go_to_on_a_root_is_a_turn_and_a_move_computed_on_the_host() -> None:
    ran = run_root(
        """
        when started
            go to x 10 cm y 10 cm
            print position x, position y
        """
    )
    names = ran.robot.names_received()
    assert "navigate_to_position" not in names
    turn = next(e.packet for e in ran.robot.received if e.packet.name == "rotate_angle")
    move = next(e.packet for e in ran.robot.received if e.packet.name == "drive_distance")
    assert turn["angle"] == 450  # from facing +y (90°) to 45°: 45° clockwise
    assert move["distance"] == 141
    assert ran.printed == ["10 cm 10 cm"]


def test_go_to_on_a_create_3_uses_navigate() -> None:
    ran = run_root(
        """
        when started
            go to x 20 cm y -10 cm facing 180 degrees
        """,
        model=RobotModel.CREATE3,
    )
    navigate = next(e.packet for e in ran.robot.received if e.packet.name == "navigate_to_position")
    assert (navigate["x"], navigate["y"], navigate["heading"]) == (200, -100, 1800)


def test_sensors_without_events_are_read_with_get_packets() -> None:
    ran = run_root(
        """
        when started
            print light left, light right, battery
            print tilt z
        """,
        readings={
            "get_light_values": {"left": 250, "right": 900},
            "get_battery_level": {"percent": 64},
            "get_accelerometer": {"z": 1000},
        },
    )
    assert ran.printed == ["25% 90% 64%", "1"]


def test_sensors_with_events_read_the_latest_state() -> None:
    ran = run_root(
        """
        when started
            wait 1 second
            print bumper left pressed, bumper right pressed, touch front left pressed
        """,
        happenings=(
            (0.2, lambda r: r.emit("bumper_event", {"state": BumperState.LEFT})),
            (0.3, lambda r: r.emit("touch_sensor_event", {"state": TouchSensors.FRONT_LEFT})),
        ),
    )
    assert ran.printed == ["true false true"]


def test_unknown_and_corrupt_packets_do_not_stop_a_program() -> None:
    ran = run_root(
        """
        when started
            move 10 cm
            print "fine"
        """,
        happenings=(
            (0.1, lambda r: r.deliver(b"\x0c" * 20)),
            (0.2, lambda r: r.deliver(b"short")),
        ),
    )
    assert ran.printed == ["fine"]
    assert ran.result.stats.corrupt_packets == 2
    assert "ignored 2 corrupt packets" in ran.result.trace.text()


@pytest.mark.parametrize(
    ("line", "code"),
    [
        ("repeat 2.5\n        wait 1 second", "E211"),
        ("print random 6 to 1", "E210"),
        ("if false\n        set x to 1\n    print x", "E209"),
    ],
)
def test_run_time_mistakes_have_their_own_codes(line: str, code: str) -> None:
    ran = run_root(f"when started\n    {line}\n")
    assert ran.result.error is not None
    assert ran.result.error.code == code


def test_a_create_3_drives_faster_than_a_root_can() -> None:
    ran = run_root(
        """
        when started
            drive 25 cm/s
        """,
        model=RobotModel.CREATE3,
    )
    speeds = next(e.packet for e in ran.robot.received if e.packet.name == "set_wheel_speeds")
    assert (speeds["left"], speeds["right"]) == (250, 250)
