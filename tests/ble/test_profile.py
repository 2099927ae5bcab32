"""The BLE profile as data: Robot State bits and the advertisement bytes, without any stack."""

from __future__ import annotations

import pytest

from rootlang.ble.advertisement import (
    LEGACY_ADVERTISING_LIMIT,
    advertising_data,
    model_from_manufacturer_data,
)
from rootlang.ble.profile import ROBOT_STATE, ROOT_PROFILE, RX, TX, RobotState, uuid16
from rootlang.protocol.enums import TouchSensors
from rootlang.robots import RobotModel


@pytest.mark.parametrize(
    ("raw", "state"),
    [
        (b"\x00\x64", RobotState()),
        (b"\x01\x32", RobotState(touched=TouchSensors.FRONT_RIGHT, battery_percent=50)),
        (b"\x02\x00", RobotState(touched=TouchSensors.FRONT_LEFT, battery_percent=0)),
        (
            b"\x0c\x05",
            RobotState(touched=TouchSensors.REAR_LEFT | TouchSensors.REAR_RIGHT, battery_percent=5),
        ),
        (b"\x30\x64", RobotState(left_bumper=True, right_bumper=True)),
        (b"\x40\x64", RobotState(cliff=True)),
        (b"\x7f\x63", RobotState(TouchSensors(15), True, True, True, 99)),
    ],
)
def test_robot_state_bits_follow_the_spec(raw: bytes, state: RobotState) -> None:
    # MSB 0b00<Cliff><L_Bump><R_Bump><RL_Touch><RR_Touch><FL_Touch><FR_Touch>, LSB 0b0<Battery>
    assert RobotState.from_bytes(raw) == state
    assert state.to_bytes() == raw


def test_robot_state_rejects_the_wrong_length() -> None:
    with pytest.raises(ValueError):
        RobotState.from_bytes(b"\x00")


@pytest.mark.parametrize("name", ["R", "Rooty", "A name of exactly 23 ch", "ßüper long ñame " * 3])
@pytest.mark.parametrize("model", list(RobotModel))
def test_advertisement_fits_legacy_packets_and_keeps_the_name_whole_characters(
    name: str, model: RobotModel
) -> None:
    advertising, scan_response = advertising_data(name, model, RobotState())
    assert len(advertising) <= LEGACY_ADVERTISING_LIMIT
    assert len(scan_response) <= LEGACY_ADVERTISING_LIMIT
    assert model.value.encode() in advertising
    advertised_name = scan_response[scan_response.index(b"\x09") + 1 :].decode()
    assert name.startswith(advertised_name) and advertised_name


@pytest.mark.parametrize(
    ("data", "model"),
    [
        (b"RT0", RobotModel.RT0),
        (b"RT1\x00\x00", RobotModel.RT1),
        (b"Ci3", RobotModel.CREATE3),
        (b"XYZ", None),
        (b"\xff\xfe", None),
        (None, None),
    ],
)
def test_model_from_manufacturer_data(data: bytes | None, model: RobotModel | None) -> None:
    assert model_from_manufacturer_data(data) is model


def test_profile_lists_each_uuid_once_with_the_uart_directions() -> None:
    uuids = [c.uuid for s in ROOT_PROFILE for c in s.characteristics] + [
        s.uuid for s in ROOT_PROFILE
    ]
    assert len(uuids) == len(set(uuids))
    by_uuid = {c.uuid: c for s in ROOT_PROFILE for c in s.characteristics}
    assert set(by_uuid[RX].properties) == {"write", "write-without-response"}
    assert set(by_uuid[TX].properties) == {"notify", "indicate"}
    assert ROBOT_STATE == uuid16(0x8BB6) == "00008bb6-0000-1000-8000-00805f9b34fb"


def test_reading_programs_never_loads_a_bluetooth_stack() -> None:
    """`rootlang check` and the simulator must not pay for bleak or bumble."""
    import subprocess
    import sys

    code = (
        "import sys, rootlang.cli.run, rootlang.cli.scan, rootlang.cli.robot, rootlang.ble.select;"
        "print('bleak' in sys.modules, 'bumble' in sys.modules)"
    )
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert result.stdout.split() == ["False", "False"], result.stderr
