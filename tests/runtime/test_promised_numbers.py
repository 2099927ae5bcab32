"""Numbers the language documents, pinned by what a program does with them (each kills a hand-made
mutant that survived the whole suite: `inches` as 25.0 mm, the left colour zone as 0-8)."""

from __future__ import annotations

import pytest
from runtime_helpers import run_root

from rootlang.protocol.enums import SensorColor
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
