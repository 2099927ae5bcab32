"""What a robot tells the world before anyone connects: name, model, robot state, signal.

Two directions: :func:`robot_seen` reads what bleak parsed from an advertisement;
:func:`advertising_data` builds the raw advertising and scan-response bytes the bumble virtual
robot sends. The advertisement follows the spec: the Root Identifier service UUID and the
manufacturer data (id 0x0600, the model code) in the advertising packet; the name and the Robot
State (service data under its 16-bit UUID 0x8BB6) in the scan response.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from rootlang.ble.profile import (
    MANUFACTURER_ID,
    ROBOT_STATE,
    ROBOT_STATE_NUMBER,
    ROOT_IDENTIFIER_SERVICE,
    RobotState,
)
from rootlang.robots import RobotModel

if TYPE_CHECKING:  # bleak is imported only when a command talks to robots
    from bleak.backends.device import BLEDevice
    from bleak.backends.scanner import AdvertisementData


@dataclass(frozen=True)
class RobotSeen:
    """One robot in range, as its latest advertisement describes it."""

    address: str
    name: str
    model: RobotModel | None
    state: RobotState | None
    rssi: int

    @property
    def model_name(self) -> str:
        return self.model.display_name if self.model else "unknown model"

    @property
    def battery_percent(self) -> int | None:
        return self.state.battery_percent if self.state else None

    def describe(self) -> str:
        """``Root RT1 "Rooty" (AA:BB:...)`` — how messages name a robot."""
        return f'{self.model_name} "{self.name}" ({self.address})'

    def to_json(self) -> dict[str, object]:
        return {
            "name": self.name,
            "address": self.address,
            "model": self.model.value if self.model else None,
            "battery": self.battery_percent,
            "rssi": self.rssi,
            "touched": bool(self.state and self.state.is_touched),
        }


def is_robot(advertisement: AdvertisementData) -> bool:
    return ROOT_IDENTIFIER_SERVICE in (uuid.lower() for uuid in advertisement.service_uuids)


def robot_seen(device: BLEDevice, advertisement: AdvertisementData) -> RobotSeen:
    """Reads name, model and state; a field a robot leaves out (or garbles) reads as unknown."""
    state_bytes = advertisement.service_data.get(ROBOT_STATE)
    state: RobotState | None = None
    if state_bytes is not None:
        try:
            state = RobotState.from_bytes(bytes(state_bytes))
        except ValueError:
            state = None
    return RobotSeen(
        address=device.address,
        name=advertisement.local_name or device.name or "",
        model=model_from_manufacturer_data(advertisement.manufacturer_data.get(MANUFACTURER_ID)),
        state=state,
        rssi=advertisement.rssi,
    )


def model_from_manufacturer_data(data: bytes | None) -> RobotModel | None:
    if data is None:
        return None
    code = bytes(data).split(b"\0", 1)[0].decode("ascii", errors="replace").strip()
    try:
        return RobotModel(code)
    except ValueError:
        return None


# Advertising data types (Bluetooth Core Supplement, part A).
_FLAGS, _UUIDS_128_COMPLETE, _COMPLETE_NAME = 0x01, 0x07, 0x09
_SERVICE_DATA_16, _MANUFACTURER_DATA = 0x16, 0xFF
_LE_GENERAL_DISCOVERABLE_NO_BR_EDR = 0x06
LEGACY_ADVERTISING_LIMIT = 31
"""Bytes in one legacy advertising (or scan response) packet."""


def _structure(kind: int, value: bytes) -> bytes:
    return bytes([len(value) + 1, kind]) + value


def advertising_data(name: str, model: RobotModel, state: RobotState) -> tuple[bytes, bytes]:
    """The advertising packet and the scan response, each within the legacy 31 bytes."""
    advertising = (
        _structure(_FLAGS, bytes([_LE_GENERAL_DISCOVERABLE_NO_BR_EDR]))
        + _structure(_UUIDS_128_COMPLETE, _uuid128_wire_bytes(ROOT_IDENTIFIER_SERVICE))
        + _structure(
            _MANUFACTURER_DATA, MANUFACTURER_ID.to_bytes(2, "little") + model.value.encode()
        )
    )
    state_data = ROBOT_STATE_NUMBER.to_bytes(2, "little") + state.to_bytes()
    room_for_name = LEGACY_ADVERTISING_LIMIT - 2 - (len(state_data) + 2)
    scan_response = _structure(_SERVICE_DATA_16, state_data) + _structure(
        _COMPLETE_NAME, _truncate_utf8(name, room_for_name)
    )
    return advertising, scan_response


def _uuid128_wire_bytes(uuid: str) -> bytes:
    """128-bit UUIDs go over the air least significant byte first."""
    return bytes.fromhex(uuid.replace("-", ""))[::-1]


def _truncate_utf8(text: str, limit: int) -> bytes:
    encoded = text.encode()
    while len(encoded) > limit:
        text = text[:-1]
        encoded = text.encode()
    return encoded
