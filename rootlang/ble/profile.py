"""The robots' Bluetooth profile as data: services, characteristics and the Robot State bits.

Read by the bleak transport (which characteristic to use), by the advertisement parser and by the
bumble virtual robot (which builds its GATT server from :data:`ROOT_PROFILE`), so the UUIDs live
here once. Source: the BLE Profile part of the Root protocol spec.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from rootlang.protocol.enums import TouchSensors


def uuid16(number: int) -> str:
    """A Bluetooth SIG 16-bit UUID in the 128-bit form bleak reports."""
    return f"{number:08x}-0000-1000-8000-00805f9b34fb"


ROOT_IDENTIFIER_SERVICE = "48c5d828-ac2a-442d-97a3-0c9822b04979"
DEVICE_INFORMATION_SERVICE = uuid16(0x180A)
SERIAL_NUMBER = uuid16(0x2A25)
FIRMWARE_VERSION = uuid16(0x2A26)
HARDWARE_VERSION = uuid16(0x2A27)
MANUFACTURER = uuid16(0x2A29)
ROBOT_STATE_NUMBER = 0x8BB6
"""Also the 16-bit service-data UUID under which the advertisement carries the robot state."""
ROBOT_STATE = uuid16(ROBOT_STATE_NUMBER)
UART_SERVICE = "6e400001-b5a3-f393-e0a9-e50e24dcca9e"
RX = "6e400002-b5a3-f393-e0a9-e50e24dcca9e"
"""Packets to the robot (the UART is named from the robot's side)."""
TX = "6e400003-b5a3-f393-e0a9-e50e24dcca9e"
"""Packets from the robot: responses and events."""

MANUFACTURER_ID = 0x0600
"""iRobot's company id; its manufacturer data is the model code (``RT0``, ``RT1``, ``Ci3``)."""

Property = Literal["read", "write", "write-without-response", "notify", "indicate"]


@dataclass(frozen=True)
class CharacteristicSpec:
    uuid: str
    name: str
    properties: tuple[Property, ...]


@dataclass(frozen=True)
class ServiceSpec:
    uuid: str
    name: str
    characteristics: tuple[CharacteristicSpec, ...] = ()


DEVICE_INFORMATION_STRINGS: tuple[CharacteristicSpec, ...] = (
    CharacteristicSpec(SERIAL_NUMBER, "serial number", ("read",)),
    CharacteristicSpec(FIRMWARE_VERSION, "firmware version", ("read",)),
    CharacteristicSpec(HARDWARE_VERSION, "hardware version", ("read",)),
    CharacteristicSpec(MANUFACTURER, "manufacturer", ("read",)),
)

ROOT_PROFILE: tuple[ServiceSpec, ...] = (
    ServiceSpec(ROOT_IDENTIFIER_SERVICE, "Root Identifier"),
    ServiceSpec(
        DEVICE_INFORMATION_SERVICE,
        "Device Information",
        (
            *DEVICE_INFORMATION_STRINGS,
            CharacteristicSpec(ROBOT_STATE, "robot state", ("read",)),
        ),
    ),
    ServiceSpec(
        UART_SERVICE,
        "UART",
        (
            CharacteristicSpec(RX, "RX", ("write", "write-without-response")),
            CharacteristicSpec(TX, "TX", ("notify", "indicate")),
        ),
    ),
)


# Robot State, first byte: 0b00<Cliff><L_Bump><R_Bump><RL_Touch><RR_Touch><FL_Touch><FR_Touch>
_TOUCH_BITS: tuple[tuple[TouchSensors, int], ...] = (
    (TouchSensors.FRONT_RIGHT, 0x01),
    (TouchSensors.FRONT_LEFT, 0x02),
    (TouchSensors.REAR_RIGHT, 0x04),
    (TouchSensors.REAR_LEFT, 0x08),
)
_RIGHT_BUMPER_BIT, _LEFT_BUMPER_BIT, _CLIFF_BIT = 0x10, 0x20, 0x40
_BATTERY_MASK = 0x7F


@dataclass(frozen=True)
class RobotState:
    """The two bytes a robot advertises (and serves) so a host can see it before connecting."""

    touched: TouchSensors = TouchSensors.NONE
    left_bumper: bool = False
    right_bumper: bool = False
    cliff: bool = False
    battery_percent: int = 100

    @classmethod
    def from_bytes(cls, data: bytes) -> RobotState:
        """Decodes the characteristic; raises ValueError when it is not two bytes."""
        if len(data) != 2:
            raise ValueError(f"robot state is 2 bytes, got {len(data)}")
        sensors, battery = data
        touched = TouchSensors.NONE
        for sensor, bit in _TOUCH_BITS:
            if sensors & bit:
                touched |= sensor
        return cls(
            touched=touched,
            left_bumper=bool(sensors & _LEFT_BUMPER_BIT),
            right_bumper=bool(sensors & _RIGHT_BUMPER_BIT),
            cliff=bool(sensors & _CLIFF_BIT),
            battery_percent=battery & _BATTERY_MASK,
        )

    def to_bytes(self) -> bytes:
        sensors = sum(bit for sensor, bit in _TOUCH_BITS if sensor in self.touched)
        sensors |= _LEFT_BUMPER_BIT if self.left_bumper else 0
        sensors |= _RIGHT_BUMPER_BIT if self.right_bumper else 0
        sensors |= _CLIFF_BIT if self.cliff else 0
        return bytes([sensors, max(0, min(self.battery_percent, 100)) & _BATTERY_MASK])

    @property
    def is_touched(self) -> bool:
        return self.touched != TouchSensors.NONE
