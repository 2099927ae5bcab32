"""LANGUAGE.md §6, rule by rule, over the loopback robot in virtual time."""

from __future__ import annotations

import asyncio
import os
import signal
import textwrap

import pytest
from runtime_helpers import run_root

from rootlang.checks import EVENT_FEATURES, SENSOR_FEATURES, diagnose, missing_feature, parse
from rootlang.protocol import BumperState, LightState, SensorColor, spec
from rootlang.robots import RobotModel
from rootlang.runtime.clock import VirtualClock, WallClock
from rootlang.runtime.interpreter import SENSOR_PACKETS
from rootlang.runtime.loopback import LoopbackRobot
from rootlang.runtime.scheduler import EVENT_PACKETS, run_program
from rootlang.runtime.stops import StoppedBy, StopReason
from rootlang.runtime.trace import Outcome


def bump(robot: LoopbackRobot) -> None:
    robot.emit("bumper_event", {"state": BumperState.LEFT})


def release(robot: LoopbackRobot) -> None:
    robot.emit("bumper_event", {"state": BumperState.NONE})


# ---- 6.1 scripts start together, in source order ------------------------------------------


def test_all_started_scripts_start_together_in_source_order() -> None:
    ran = run_root(
        """
        when started
            print "a1"
            wait 1 second
            print "a2"
        when started
            print "b1"
            wait 1 second
            print "b2"
        """
    )
    assert ran.print_times() == [(0, "a1"), (0, "b1"), (1000, "a2"), (1000, "b2")]
    assert 'print   "a1"' in ran.result.trace.text()
    assert ran.result.end == "finished"


# ---- 6.2 edge-triggered events, ignored while running --------------------------------------


def test_an_event_script_fires_on_the_edge_and_ignores_its_trigger_while_running() -> None:
    ran = run_root(
        """
        when bumped
            print "ouch"
            wait 1 second
        when bumped
            print "me too"
        """,
        time_limit=3.0,
        happenings=(
            (0.1, bump),
            (0.2, release),
            (0.3, bump),  # the first script is still running: ignored
            (0.4, release),
            (1.5, bump),
        ),
    )
    assert ran.print_times() == [
        (100, "ouch"),
        (100, "me too"),
        (300, "me too"),
        (1500, "ouch"),
        (1500, "me too"),
    ]
    assert ran.result.end == "time_limit"


def test_pressed_and_released_edges_of_one_bumper() -> None:
    ran = run_root(
        """
        when bumper right pressed
            print "right down"
        when bumper right released
            print "right up"
        when bumper both pressed
            print "both"
        """,
        time_limit=2.0,
        happenings=(
            (0.1, lambda r: r.emit("bumper_event", {"state": BumperState.RIGHT})),
            (0.2, lambda r: r.emit("bumper_event", {"state": BumperState.BOTH})),
            (0.3, lambda r: r.emit("bumper_event", {"state": BumperState.NONE})),
        ),
    )
    assert ran.printed == ["right down", "both", "right up"]


def test_colour_and_light_events_fire_when_their_state_begins() -> None:
    red_on_left = [SensorColor.RED] * 4 + [SensorColor.WHITE] * 28
    ran = run_root(
        """
        when color red seen on left
            print "red left"
        when color red seen on right
            print "red right"
        when light dark
            print "dark"
        """,
        time_limit=2.0,
        happenings=(
            (0.1, lambda r: r.emit("color_sensor_event", {"colors": red_on_left})),
            (0.2, lambda r: r.emit("color_sensor_event", {"colors": red_on_left})),
            (0.3, lambda r: r.emit("light_event", {"state": LightState.BOTH_DARK})),
        ),
    )
    assert ran.printed == ["red left", "dark"]


def test_wait_until_wakes_on_the_event() -> None:
    ran = run_root(
        """
        when started
            wait until bumper left pressed
            print timer
        """,
        happenings=((0.25, bump),),
    )
    assert ran.printed == ["0.25 seconds"]


def test_when_condition_fires_once_when_it_turns_true() -> None:
    ran = run_root(
        """
        when timer > 2 seconds
            print "two"
        """,
        time_limit=5.0,
    )
    times = ran.print_times()
    assert [text for _, text in times] == ["two"]
    assert 2000 <= times[0][0] <= 2050  # checked 20 times a second


# ---- 6.3 actuators follow the robot: interruption -----------------------------------------


def test_a_newer_motion_interrupts_the_older_and_its_script_goes_on() -> None:
    ran = run_root(
        """
        when started
            move 100 cm
            print "after the move"
        when bumped
            turn right 90 degrees
        """,
        time_limit=5.0,
        happenings=((1.0, bump),),
    )
    commands = {e.text: e for e in ran.result.trace.of_kind("command")}
    assert commands["move 1000 mm"].outcome is Outcome.INTERRUPTED
    assert commands["move 1000 mm"].end_ms == 1000
    assert commands["turn right 90°"].outcome is Outcome.DONE
    assert ran.print_times() == [(1000, "after the move")]


def test_marker_and_sound_interrupt_only_their_own_kind() -> None:
    ran = run_root(
        """
        when started
            play note A4 for 2 seconds
            print "note ended", timer
        when started
            wait 0.5 seconds
            marker down
            play note C5 for 0.1 seconds
        """
    )
    # the marker (0.25 s) did not end the note; the newer note did
    assert ran.printed == ["note ended 0.75 seconds"]
    outcomes = [(e.text, e.outcome) for e in ran.result.trace.of_kind("command")]
    assert ("play 440 Hz for 2000 ms", Outcome.INTERRUPTED) in outcomes
    assert ("marker down", Outcome.DONE) in outcomes


# ---- 6.4 yields: no program can starve the others --------------------------------------------


def test_an_empty_forever_cannot_starve_other_scripts_or_hang_virtual_time() -> None:
    ran = run_root(
        """
        when started
            forever
                set x to 1
        when started
            wait 1 second
            print "still here"
            stop all
        """
    )
    assert ran.printed == ["still here"]
    assert ran.result.end == "stopped"
    assert 1.0 <= ran.result.sim_time_s < 1.1


def test_every_loop_round_lasts_at_least_ten_milliseconds() -> None:
    ran = run_root(
        """
        when started
            set n to 0
            repeat 100
                change n by 1
            print n, timer
        """
    )
    assert ran.printed == ["100 1 seconds"]


def test_a_forever_loop_is_ended_by_the_time_limit() -> None:
    ran = run_root(
        """
        when started
            forever
                light red
                light blue
        """,
        time_limit=0.5,
    )
    assert ran.result.end == "time_limit"
    assert ran.result.sim_time_s >= 0.5


# ---- 6.5 stopping ------------------------------------------------------------------------------


def stopped_cleanly(ran_robot: LoopbackRobot) -> bool:
    names = ran_robot.names_received()
    return "stop_and_reset" in names and not ran_robot.is_moving() and not ran_robot.connected


def test_stop_all_cancels_everything_stops_the_robot_and_runs_when_stopped() -> None:
    ran = run_root(
        """
        when started
            drive 5 cm/s
            wait 1 second
            stop all
            print "never"
        when started
            move 100 cm
            print "never either"
        when stopped
            light red
            print "bye"
        """
    )
    assert ran.result.end == "stopped"
    assert ran.result.stopped_by == StoppedBy(StopReason.STOP_ALL)
    assert ran.result.stopped_by.english() == "stop all"
    assert ran.printed == ["bye"]
    assert stopped_cleanly(ran.robot)
    names = ran.robot.names_received()
    assert names.index("stop_and_reset") < names.index("set_led_animation")
    move = next(e for e in ran.result.trace.of_kind("command") if e.text == "move 1000 mm")
    assert move.outcome is Outcome.CANCELLED


def test_the_robots_stop_button_stops_the_program() -> None:
    ran = run_root(
        """
        when started
            move 100 cm
        when stopped
            print "stopped"
        """,
        happenings=((2.0, lambda r: r.emit("stop_project_event")),),
    )
    assert ran.result.end == "stopped"
    assert ran.result.stopped_by.reason is StopReason.ROBOT_STOP_BUTTON
    assert ran.printed == ["stopped"]
    assert round(ran.result.sim_time_s, 3) == 2.0
    assert stopped_cleanly(ran.robot)


def test_a_run_time_error_stops_the_program_and_points_at_the_line() -> None:
    ran = run_root(
        """
        when started
            drive 5 cm/s
            set zero to 0
            wait 1 second
            print 10 / zero
        when stopped
            print "cleaning up"
        """
    )
    assert ran.result.end == "error"
    assert ran.result.error is not None
    assert ran.result.error.code == "E204"
    assert ran.result.error.span.line == 5
    assert ran.printed == ["cleaning up"]
    assert stopped_cleanly(ran.robot)


def test_an_unexpected_disconnect_ends_the_run_without_a_traceback() -> None:
    ran = run_root(
        """
        when started
            move 100 cm
        """,
        happenings=((1.0, lambda r: r.drop_link("the robot was switched off")),),
    )
    assert ran.result.end == "disconnected"
    assert ran.result.error is not None and ran.result.error.code == "E207"
    assert "switched off" in ran.result.error.english


def test_when_stopped_may_not_move_and_is_limited_to_two_seconds() -> None:
    ran = run_root(
        """
        when started
            stop all
        when stopped
            forever
                light blink green
                wait 0.5 seconds
        when stopped
            wiggle
        to wiggle
            move 10 cm
        """
    )
    assert ran.result.end == "stopped"
    assert ran.result.error is not None and ran.result.error.code == "E117"
    assert 2.0 <= ran.result.sim_time_s < 2.1
    assert "took longer than 2 seconds, so I ended them" in ran.result.trace.text()
    assert "drive_distance" not in ran.robot.names_received()


def test_when_stopped_may_stop_moving_as_the_checks_allow_even_in_a_procedure() -> None:
    source = """
        when started
            stop all
        when stopped
            halt
        to halt
            stop moving
            print "halted"
        """
    assert diagnose(textwrap.dedent(source)) == []
    ran = run_root(source)
    assert ran.result.error is None
    assert ran.printed == ["halted"]


def test_ctrl_c_in_the_middle_of_a_move_stops_the_robot() -> None:
    ran = run_root(
        """
        when started
            move 100 cm
        when stopped
            print "bye"
        """,
        ctrl_c=True,
        happenings=((1.5, lambda r: os.kill(os.getpid(), signal.SIGINT)),),
    )
    assert ran.result.end == "stopped"
    assert ran.result.interrupted
    assert ran.printed == ["bye"]
    assert stopped_cleanly(ran.robot)
    assert abs(ran.result.sim_time_s - 1.5) < 0.01


# ---- 6.6 when a program ends ----------------------------------------------------------------


def test_a_program_with_event_scripts_waits_for_events_until_the_time_limit() -> None:
    ran = run_root(
        """
        when started
            print "hi"
        when bumped
            print "bump"
        """,
        time_limit=4.0,
    )
    assert ran.result.end == "time_limit"
    assert ran.result.sim_time_s >= 4.0


def test_a_program_without_event_scripts_ends_when_its_scripts_do() -> None:
    ran = run_root(
        """
        when started
            send "go" and wait
            print "all done"
        when message "go" received
            wait 1 second
            print "went"
        """
    )
    assert ran.result.end == "finished"
    assert ran.printed == ["went", "all done"]
    assert "stop_and_reset" in ran.robot.names_received()


def test_a_program_that_ends_driving_leaves_the_robot_stopped() -> None:
    ran = run_root(
        """
        when started
            drive 5 cm/s
            wait 1 second
        """
    )
    assert ran.result.end == "finished"
    assert ran.robot.wheel_speeds == (0, 0)
    assert stopped_cleanly(ran.robot)
    assert ran.result.pose is not None


# ---- 6.7 run-time errors -------------------------------------------------------------------


def test_a_command_the_robot_lacks_is_an_error_naming_the_model() -> None:
    ran = run_root(
        """
        when started
            dock
        """
    )
    assert ran.result.error is not None
    assert ran.result.error.english == "The Root RT1 can't do `dock`."
    assert ran.result.error.span.line == 2


@pytest.mark.parametrize(
    ("line", "model", "message"),
    [
        ("eraser down", RobotModel.RT0, "The Root RT0 can't do `eraser down`."),
        ("marker down", RobotModel.CREATE3, "The Create 3 can't do `marker down`."),
        ("undock", RobotModel.RT1, "The Root RT1 can't do `undock`."),
    ],
)
def test_a_line_the_checks_warn_about_stops_the_run_with_an_error(
    line: str, model: RobotModel, message: str
) -> None:
    source = f"when started\n    {line}\n"
    assert [d.code for d in diagnose(source, robot=model)] == ["W102"]
    ran = run_root(source, model=model)
    assert ran.result.error is not None
    assert (ran.result.error.code, ran.result.error.english) == ("E201", message)


def test_a_script_for_a_missing_sensor_never_runs_and_the_rest_does() -> None:
    """As the checks' warning says (W101): the script is left out, the program is not stopped."""
    ran = run_root(
        """
        when color red seen
            print "red"
        when started
            print "go"
        """,
        model=RobotModel.RT0,
    )
    assert ran.result.error is None and ran.result.end == "finished"
    assert ran.result.printed == ["go"]


@pytest.mark.parametrize(
    ("source", "model"),
    [
        ("when obstacle seen\n    print 1\n", RobotModel.RT1),
        ("when docked\n    print 1\n", RobotModel.RT0),
    ],
)
def test_an_event_script_for_a_missing_sensor_is_warned_about_and_left_out(
    source: str, model: RobotModel
) -> None:
    (warning,) = diagnose(source, robot=model)
    assert warning.code == "W101" and model.display_name in warning.english
    ran = run_root(source, model=model)
    assert ran.result.error is None and ran.result.printed == []


def test_a_missing_sensor_read_is_named_as_the_checks_warning_names_it() -> None:
    source, model = "when started\n    print light left\n", RobotModel.CREATE3
    ran = run_root(source, model=model)
    (warning,) = diagnose(source, robot=model)
    assert ran.result.error is not None and ran.result.error.code == "E202"
    sensor = str(dict(ran.result.error.values)["sensor"])
    assert sensor in warning.english
    assert ran.result.error.english == f"The {model.display_name} has no {sensor}."


def test_the_checks_and_the_protocol_agree_which_robot_has_which_sensor() -> None:
    needs = [(EVENT_FEATURES[event], packet) for event, (packet, _) in EVENT_PACKETS.items()]
    needs += [(SENSOR_FEATURES[sensor], packet) for sensor, packet in SENSOR_PACKETS.items()]
    for feature, packet in needs:
        for model in RobotModel:
            assert missing_feature(feature, model) == (model not in spec(packet).robots), (
                feature,
                model,
            )


def test_too_fast_for_this_robot_names_the_range() -> None:
    ran = run_root(
        """
        when started
            drive 50 cm/s
        """
    )
    assert ran.result.error is not None
    assert ran.result.error.code == "E217"  # in the child's units, not the packet's mm/s
    said = "The left wheel's speed can be -10 cm/s to 10 cm/s, not 50 cm/s."
    assert ran.result.error.english == said


# ---- 6.8 determinism -----------------------------------------------------------------------


def test_the_same_program_and_events_give_the_same_trace() -> None:
    source = """
        when started
            repeat 3
                move (random 1 to 20) cm
                turn left 30 degrees
            say "that is all, folks, thank you"
        when bumped
            play note C4 for 0.5 seconds
        """
    happenings = ((0.7, bump), (0.9, release), (2.2, bump))
    first = run_root(source, happenings=happenings, time_limit=20.0)
    second = run_root(source, happenings=happenings, time_limit=20.0)
    assert first.result.trace.text() == second.result.trace.text()
    assert first.result.trace.to_json() == second.result.trace.to_json()


def test_create_3_obstacle_and_dock_events_and_root_stall_and_battery() -> None:
    ran = run_root(
        """
        when obstacle seen on left
            print "left obstacle"
        when obstacle seen on right
            print "right obstacle"
        when docked
            print "docked"
        when undocked
            print "undocked"
        when battery low
            print "low"
        """,
        model=RobotModel.CREATE3,
        time_limit=2.0,
        happenings=(
            (0.1, lambda r: r.emit("ir_proximity_event", {"state": 0b1, "sensors": [900] * 7})),
            (0.2, lambda r: r.emit("ir_proximity_event", {"state": 0b1, "sensors": [900] * 7})),
            (0.3, lambda r: r.emit("ir_proximity_event", {"state": 0b1000001, "sensors": [0] * 7})),
            (0.4, lambda r: r.emit("docking_sensor_event", {"contacts": 1})),
            (0.5, lambda r: r.emit("docking_sensor_event", {"contacts": 0})),
            (0.6, lambda r: r.emit("battery_level_event", {"percent": 50})),
            (0.7, lambda r: r.emit("battery_level_event", {"percent": 15})),
        ),
    )
    assert ran.printed == ["left obstacle", "right obstacle", "docked", "undocked", "low"]


def test_a_stall_event_starts_when_stalled() -> None:
    ran = run_root(
        """
        when stalled
            print "stuck"
        """,
        time_limit=1.0,
        happenings=((0.5, lambda r: r.emit("motor_stall_event", {"motor": 0, "cause": 3})),),
    )
    assert ran.print_times() == [(500, "stuck")]


def test_ctrl_c_on_the_wall_clock_stops_a_real_time_move() -> None:
    ran = run_root(
        """
        when started
            move 100 cm
        """,
        clock=WallClock(),
        ctrl_c=True,
        happenings=((0.2, lambda r: os.kill(os.getpid(), signal.SIGINT)),),
    )
    assert ran.result.interrupted
    # stopped where Ctrl-C came, not when the move (10 s long) would have ended: the move's
    # own outcome says so; the time only bounds it (a busy machine takes a moment to stop)
    (move,) = [e for e in ran.result.trace.of_kind("command") if e.packet == "drive_distance"]
    assert move.outcome is not Outcome.DONE and move.end_ms is not None and move.end_ms < 5000
    assert 0.2 <= ran.result.sim_time_s < 5
    assert stopped_cleanly(ran.robot)


def test_a_cancelled_run_still_stops_the_robot() -> None:
    clock = VirtualClock()
    robot = LoopbackRobot(clock)
    source = "when started\n    drive 5 cm/s\n    wait 10 seconds\n"

    async def main() -> None:
        running = asyncio.ensure_future(run_program(parse(source), robot, clock, source=source))
        await clock.sleep(1.0)
        running.cancel()
        with pytest.raises(asyncio.CancelledError):
            await running

    clock.run(main())
    assert stopped_cleanly(robot)


def test_trace_tells_black_from_blue_in_colour_events() -> None:
    from rootlang.protocol import SensorColor, make_packet
    from rootlang.runtime.scheduler import event_text

    colors = (SensorColor.BLACK,) * 10 + (SensorColor.BLUE,) * 12 + (SensorColor.WHITE,) * 10
    packet = make_packet("color_sensor_event", colors=colors)
    assert event_text(packet).endswith("colors=" + "K" * 10 + "B" * 12 + "W" * 10)


def test_message_names_compare_without_regard_to_case() -> None:
    """docs/runtime.md: "Message texts compare without regard to case"."""
    ran = run_root(
        """
        when started
            send "Go Now" and wait
            send "GO NOW"
            print "sent"
        when message "go now" received
            print "went"
        """
    )
    assert sorted(ran.printed) == ["sent", "went", "went"]  # both sends reached the script


def test_a_sweeps_frequencies_go_to_the_robot_in_millihertz() -> None:
    """The protocol table's Play Sweep takes mHz: 200 Hz is 200,000 (not 200)."""
    ran = run_root(
        """
        when started
            play sweep from 200 Hz to 800 Hz for 1 second
        """
    )
    # (the first: the runtime's own silent sweeps come after, at the end of the run)
    sweep = next(item.packet for item in ran.robot.received if item.packet.name == "play_sweep")
    assert (sweep.fields["start_frequency"], sweep.fields["end_frequency"]) == (200_000, 800_000)
    assert sweep.fields["duration"] == 1000


def test_gravity_compensation_goes_to_the_robot_in_tenths_of_a_percent() -> None:
    """The protocol table's amount is in decipercent (0-1000): 75 % is 750 (not 75)."""
    ran = run_root(
        """
        when started
            set gravity compensation on 75 %
            set gravity compensation auto
        """
    )
    sent = [item.packet for item in ran.robot.received
            if item.packet.name == "set_gravity_compensation"]  # fmt: skip
    assert [packet.fields["amount"] for packet in sent] == [750, 500]
