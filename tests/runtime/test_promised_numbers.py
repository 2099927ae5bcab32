"""Numbers the language documents, pinned by what a program does with them (each kills a hand-made
mutant that survived the whole suite: `inches` as 25.0 mm, the left colour zone as 0-8)."""

from __future__ import annotations

import pytest
from runtime_helpers import run_root

from rootlang.protocol.enums import LightState, SensorColor
from rootlang.protocol.fields import COLOR_SENSORS


@pytest.mark.parametrize(
    ("written", "mm"),
    [("1 inch", 25), ("10 inches", 254), ("2 cm", 20), ("0.5 m", 500), ("7 mm", 7)],
)
def test_a_move_in_each_unit_sends_the_documented_millimetres(written: str, mm: int) -> None:
    ran = run_root(f"when started\n    move {written}\n")
    sent = [p.packet for p in ran.robot.received if p.packet.name == "drive_distance"]
    assert [packet["distance"] for packet in sent] == [mm]


@pytest.mark.parametrize(
    ("sensor", "zone"),
    [(0, "left"), (9, "left"), (10, "middle"), (21, "middle"), (22, "right"), (31, "right")],
)
def test_each_colour_zone_ends_at_the_documented_sensor(sensor: int, zone: str) -> None:
    colors = [SensorColor.WHITE] * COLOR_SENSORS
    colors[sensor] = SensorColor.RED
    others = {"left", "middle", "right"} - {zone}
    source = "\n".join(
        f'when color red seen on {side}\n    print "{side}"' for side in ("left", "middle", "right")
    )
    ran = run_root(
        source,
        happenings=((0.5, lambda robot: robot.emit("color_sensor_event", {"colors": colors})),),
        time_limit=2,
    )
    assert zone in ran.printed
    assert not others & set(ran.printed)


def test_true_and_false_compare_as_themselves() -> None:
    # kills a mutant that survived the suite: `=` on two booleans answered the opposite
    ran = run_root(
        "when started\n    print true = true, false = false, true = false, true != false\n"
    )
    assert ran.printed == ["true true false true"]


def test_values_print_and_convert_as_documented() -> None:
    # each line kills a mutant of units.py that the language and interpreter tests let live
    ran = run_root(
        "when started\n"
        "    print round (2.6 cm)\n"  # Quantity.with_shown
        '    print join("ro", "ot")\n'
        "    print 12345\n"  # whole numbers print whole
        "    turn right 90 deg\n"  # deg is a degree
        "    play note C#4 for 0.1 seconds\n"  # a sharp is a semitone up
    )
    assert ran.printed == ["3 cm", "root", "12345"]
    sent = {p.packet.name: p.packet for p in ran.robot.received}
    assert sent["rotate_angle"]["angle"] == 900
    assert sent["play_note"]["frequency"] == 277


def test_logic_equality_and_arithmetic_by_zero_as_documented() -> None:
    # kills further units.py mutants the narrow mutation test selection let live
    ran = run_root(
        "when started\n"
        "    print true and false, true or false, false or false, false and false\n"
        "    print 10 cm = 100 mm, 10 cm = 10 mm\n"
        "    print abs (-2.5 cm), 5 + 0, 5 - 0, 1.2345, 0.00012345\n"
        "    move 2 m\n"
    )
    assert ran.printed == ["false true false false", "true false", "2.5 cm 5 5 1.234 0.000123"]
    sent = [p.packet for p in ran.robot.received if p.packet.name == "drive_distance"]
    assert [packet["distance"] for packet in sent] == [2000]


def test_division_square_roots_and_sec_as_documented() -> None:
    ran = run_root(
        "when started\n    print 10 / 4, sqrt 9, 7 mod 4\n    wait 2 sec\n    print timer\n"
    )
    assert ran.printed == ["2.5 3 3", "2 seconds"]


def test_not_and_minus_keep_their_kinds() -> None:
    ran = run_root("when started\n    print not true, not (1 > 2), -(3 cm)\n")
    assert ran.printed == ["false true -3 cm"]


def test_comparisons_and_text_equality_as_documented() -> None:
    ran = run_root(
        "when started\n"
        '    print "Go" = "go", "go" = "stop", 2 <= 3, 3 <= 3, 4 <= 3, 3 > 2, 2 > 3, 2 < 3\n'
    )
    assert ran.printed == ["true false true true false true false true"]


def test_mid_and_huge_numbers_print_as_documented_and_mod_by_zero_is_e204() -> None:
    ran = run_root("when started\n    print 0.12345, 10000000000 * 1000000\n    print 5 mod 0\n")
    assert ran.printed == ["0.1235 1e+16"]
    assert ran.result.error is not None and ran.result.error.code == "E204"


def test_cliff_and_light_events_start_a_script_only_when_their_state_changes() -> None:
    # kills two mutants that survived the suite: the cliff's and the light's edge tests without
    # their "before" half, which started the script again at a packet that changed nothing
    cliff = {"sensor": 100, "threshold": 200}
    ran = run_root(
        """
        when cliff detected
            print "cliff"
        when cliff cleared
            print "cleared"
        when light dark
            print "dark"
        when light bright
            print "bright"
        """,
        time_limit=2.0,
        happenings=(
            (0.1, lambda r: r.emit("cliff_event", {"cliff": 1, **cliff})),
            (0.2, lambda r: r.emit("cliff_event", {"cliff": 1, **cliff})),  # still a cliff
            (0.3, lambda r: r.emit("cliff_event", {"cliff": 0, **cliff})),
            (0.4, lambda r: r.emit("cliff_event", {"cliff": 0, **cliff})),  # still none
            (0.5, lambda r: r.emit("cliff_event", {"cliff": 1, **cliff})),
            (0.6, lambda r: r.emit("light_event", {"state": LightState.BOTH_DARK})),
            (0.7, lambda r: r.emit("light_event", {"state": LightState.BOTH_DARK})),  # still dark
            (0.8, lambda r: r.emit("light_event", {"state": LightState.BOTH_BRIGHT})),
            (0.9, lambda r: r.emit("light_event", {"state": LightState.BOTH_BRIGHT})),
        ),
    )
    assert ran.print_times() == [
        (100, "cliff"),
        (300, "cleared"),
        (500, "cliff"),
        (600, "dark"),
        (800, "bright"),
    ]


@pytest.mark.parametrize(("percent", "low"), [(21, False), (20, False), (19, True), (0, True)])
def test_battery_low_is_under_20_percent(percent: int, low: bool) -> None:
    # kills a mutant that survived the suite: "battery low" at 20 % and under (the language
    # says under 20 %: docs/language.md)
    ran = run_root(
        'when battery low\n    print "low"\n',
        time_limit=1.0,
        happenings=((0.5, lambda r: r.emit("battery_level_event", {"percent": percent})),),
    )
    assert ran.printed == (["low"] if low else [])


@pytest.mark.parametrize(
    ("written", "wheels"), [("50 mm/s", 50), ("5 cm/s", 50), ("-30 mm/s", -30)]
)
def test_a_speed_in_each_unit_sends_the_documented_millimetres_a_second(
    written: str, wheels: int
) -> None:
    # kills a mutant that survived the suite: `mm/s` read as 10 mm/s
    ran = run_root(f"when started\n    drive {written}\n    print {written}\n", time_limit=1.0)
    sent = [p.packet for p in ran.robot.received if p.packet.name == "set_wheel_speeds"]
    assert [(packet["left"], packet["right"]) for packet in sent][:1] == [(wheels, wheels)]
    assert ran.printed == [written]
