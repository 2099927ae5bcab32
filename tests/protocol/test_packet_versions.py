"""Firmware versions map to protocol versions as the spec's tables say."""

from __future__ import annotations

import pytest

from rootlang.diagnostics import RootlangError
from rootlang.protocol import max_protocol, protocol_version_for
from rootlang.protocol.versions import CREATE3_FIRMWARE_PROTOCOLS, ROOT_FIRMWARE_PROTOCOLS
from rootlang.robots import RobotModel


@pytest.mark.parametrize(("firmware", "protocol"), ROOT_FIRMWARE_PROTOCOLS)
def test_every_root_row(firmware: str, protocol: tuple[int, int]) -> None:
    assert protocol_version_for(RobotModel.RT1, firmware) == protocol
    assert protocol_version_for(RobotModel.RT0, firmware) == protocol


@pytest.mark.parametrize(("firmware", "protocol"), CREATE3_FIRMWARE_PROTOCOLS)
def test_every_create3_row(firmware: str, protocol: tuple[int, int]) -> None:
    assert protocol_version_for(RobotModel.CREATE3, firmware) == protocol


@pytest.mark.parametrize(
    ("model", "firmware", "protocol"),
    [
        (RobotModel.RT1, "1.9", (1, 1)),  # between 1.8 and 1.10: numbers, not text, compare
        (RobotModel.RT1, "1.10", (1, 1)),
        (RobotModel.RT1, "2.5", (1, 3)),
        (RobotModel.RT1, "2.7.1", (1, 3)),
        (RobotModel.RT1, "3.0", (1, 3)),  # newer than the table: the newest listed
        (RobotModel.CREATE3, "G.5.3", (1, 5)),
        (RobotModel.CREATE3, "h.0", (1, 5)),
        (RobotModel.CREATE3, "J.1", (1, 5)),
        (RobotModel.CREATE3, "F.9", (1, 3)),  # older than the table: the oldest listed
    ],
)
def test_versions_between_and_beyond_the_rows(
    model: RobotModel, firmware: str, protocol: tuple[int, int]
) -> None:
    assert protocol_version_for(model, firmware) == protocol


@pytest.mark.parametrize(
    ("model", "firmware"),
    [
        (RobotModel.RT1, "G.5"),
        (RobotModel.CREATE3, "2.7"),
        (RobotModel.RT0, ""),
        (RobotModel.RT0, "beta"),
    ],
)
def test_unreadable_firmware_is_an_error(model: RobotModel, firmware: str) -> None:
    with pytest.raises(RootlangError) as caught:
        protocol_version_for(model, firmware)
    assert caught.value.diagnostics[0].code == "E510"


def test_max_protocol() -> None:
    assert max_protocol(RobotModel.RT1) == (1, 3)
    assert max_protocol(RobotModel.CREATE3) == (1, 5)
