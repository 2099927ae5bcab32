"""The table covers the spec: every packet definition in its text, with the errata corrected."""

from __future__ import annotations

import re
from collections import Counter
from pathlib import Path

import pytest

from rootlang.protocol import PACKETS, Device, FieldType, Kind, PacketSpec, spec
from rootlang.protocol.specs import PAYLOAD_BYTES
from rootlang.robots import RobotModel

SPEC_TEXT = (Path(__file__).parent / "data" / "root-ble-protocol.txt").read_text(encoding="utf-8")

# A packet definition in the spec text is its layout row: "device | command | id-kind |".
DEFINITION = re.compile(r"^(\d+) \| (\d+) \| (Inc\.|Req\.|Evt\.) \|", re.MULTILINE)
KIND_OF_ID = {"Inc.": Kind.COMMAND, "Req.": Kind.RESPONSE, "Evt.": Kind.EVENT}

# The spec's two misprints (DESIGN.md section 3), as (printed, meant) definitions.
ERRATA = {
    "undock_response": ((1, 19, Kind.RESPONSE), (1, 20, Kind.RESPONSE)),
    "get_ipv4_addresses_response": ((100, 1, Kind.COMMAND), (100, 1, Kind.RESPONSE)),
}


def spec_definitions() -> Counter[tuple[int, int, Kind]]:
    return Counter(
        (int(device), int(command), KIND_OF_ID[id_kind])
        for device, command, id_kind in DEFINITION.findall(SPEC_TEXT)
    )


def table_definitions() -> Counter[tuple[int, int, Kind]]:
    return Counter((int(p.device), p.command, p.kind) for p in PACKETS)


def test_the_spec_text_has_76_packet_definitions() -> None:
    assert sum(spec_definitions().values()) == 76


def test_table_has_one_row_per_spec_definition() -> None:
    assert len(PACKETS) == sum(spec_definitions().values())


def test_table_matches_the_spec_after_the_errata() -> None:
    corrected = spec_definitions()
    for printed, meant in ERRATA.values():
        assert corrected[printed] >= 1, f"the spec no longer prints {printed}"
        corrected[printed] -= 1
        corrected[meant] += 1
    assert +corrected == table_definitions()


def test_misprinted_definitions_appear_twice_in_the_spec_text() -> None:
    # Undock's response is printed with Dock's number; Get IPv4's response with a command id.
    assert spec_definitions()[(1, 19, Kind.RESPONSE)] == 2
    assert spec_definitions()[(100, 1, Kind.COMMAND)] == 2


@pytest.mark.parametrize("name", sorted(ERRATA))
def test_errata_are_noted_in_the_table(name: str) -> None:
    assert spec(name).errata


def test_every_device_of_the_spec_is_in_the_table() -> None:
    spec_devices = {device for device, _, _ in spec_definitions()}
    assert spec_devices == {int(d) for d in Device}
    assert {int(p.device) for p in PACKETS} == spec_devices


def test_names_are_unique_and_follow_the_scheme() -> None:
    names = [p.name for p in PACKETS]
    assert len(names) == len(set(names))
    for packet in PACKETS:
        assert re.fullmatch(r"[a-z][a-z0-9_]*", packet.name)
        assert packet.name.endswith("_event") == (packet.kind is Kind.EVENT)
        assert packet.name.endswith("_response") == (packet.kind is Kind.RESPONSE)


def test_decoding_needs_only_the_sender_to_tell_packets_apart() -> None:
    keys = Counter((p.sender, p.device, p.command) for p in PACKETS)
    assert max(keys.values()) == 1


@pytest.mark.parametrize("packet", PACKETS, ids=lambda p: p.name)
def test_row_is_consistent(packet: PacketSpec) -> None:
    assert packet.payload_size <= PAYLOAD_BYTES
    assert packet.robots
    assert packet.min_protocol >= (1, 0)
    assert packet.doc
    for field in packet.fields:
        assert field.doc, f"{packet.name}.{field.name} has no doc"
        if field.range is not None:
            assert field.range[0] <= field.range[1]
    if packet.response is not None:
        assert packet.kind is Kind.COMMAND
        answer = packet.response
        assert answer.name == f"{packet.name}_response"
        assert (answer.device, answer.command, answer.kind) == (
            packet.device,
            packet.command,
            Kind.RESPONSE,
        )
        assert answer in PACKETS


def test_every_response_belongs_to_a_command() -> None:
    answers = {p.response.name for p in PACKETS if p.response is not None}
    assert answers == {p.name for p in PACKETS if p.kind is Kind.RESPONSE}


@pytest.mark.parametrize(
    ("device", "robots"),
    [
        # The spec's device notes: "This device is not supported on ..."
        (Device.MARKER, {RobotModel.RT0, RobotModel.RT1}),
        (Device.COLOR_SENSOR, {RobotModel.RT1}),
        (Device.IR_PROXIMITY, {RobotModel.CREATE3}),
        (Device.LIGHT_SENSORS, {RobotModel.RT0, RobotModel.RT1}),
        (Device.DOCKING_SENSORS, {RobotModel.CREATE3}),
        (Device.CONNECTIVITY, {RobotModel.CREATE3}),
    ],
)
def test_device_support_follows_the_spec_notes(device: Device, robots: set[RobotModel]) -> None:
    rows = [p for p in PACKETS if p.device == device]
    assert rows
    assert all(p.robots == robots for p in rows)


@pytest.mark.parametrize(
    ("name", "version"),
    [
        ("navigate_to_position", (1, 4)),
        ("navigate_to_position_response", (1, 4)),
        ("get_ir_proximity_values", (1, 4)),
        ("get_packed_ir_proximity", (1, 5)),
        ("set_ir_event_thresholds", (1, 5)),
        ("ir_proximity_event", (1, 5)),
        ("dock", (1, 5)),
        ("undock_response", (1, 5)),
        ("docking_sensor_event", (1, 5)),
        ("drive_distance", (1, 0)),
    ],
)
def test_minimum_protocol_versions_follow_the_spec(name: str, version: tuple[int, int]) -> None:
    assert spec(name).min_protocol == version


def test_supported_by_checks_robot_and_version() -> None:
    dock = spec("dock")
    assert dock.supported_by(RobotModel.CREATE3, (1, 5))
    assert not dock.supported_by(RobotModel.CREATE3, (1, 4))
    assert not dock.supported_by(RobotModel.RT1, (1, 5))
    assert spec("set_marker_position").supported_by(RobotModel.RT0, (1, 0))


def test_wheel_speeds_follow_the_spec_and_the_create3_docs() -> None:
    left = spec("set_wheel_speeds").field("left")
    assert left.range == (-100, 100)
    assert left.unit == "mm/s"
    assert left.range_for(RobotModel.CREATE3) == (-306, 306)
    assert left.range_for(RobotModel.RT1) == (-100, 100)


def test_field_types_cover_every_special_layout() -> None:
    used = {f.type for p in PACKETS for f in p.fields}
    assert used == set(FieldType)
