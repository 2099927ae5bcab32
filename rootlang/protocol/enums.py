"""The protocol's devices and enumerated field values, named as the spec describes them.

Decoded packets carry these enums, so a value prints as ``BumperState.LEFT`` instead of ``128``;
they are ``int`` subclasses, so arithmetic and JSON still see the wire value.
"""

from __future__ import annotations

import enum


class Device(enum.IntEnum):
    """The robot's logical devices (byte 0 of every packet)."""

    GENERAL = 0
    MOTORS = 1
    MARKER = 2
    LEDS = 3
    COLOR_SENSOR = 4
    SOUND = 5
    IR_PROXIMITY = 11
    BUMPERS = 12
    LIGHT_SENSORS = 13
    BATTERY = 14
    ACCELEROMETER = 16
    TOUCH_SENSORS = 17
    DOCKING_SENSORS = 19
    CLIFF_SENSOR = 20
    CONNECTIVITY = 100


class Kind(enum.Enum):
    """Who sends a packet and why: the host's commands, the robot's responses and events."""

    COMMAND = "command"
    RESPONSE = "response"
    EVENT = "event"


class Board(enum.IntEnum):
    MAIN = 0xA5
    COLOR = 0xC6


class GravityCompensation(enum.IntEnum):
    OFF = 0
    ON = 1
    MARKER_DOWN = 2


class DockStatus(enum.IntEnum):
    """A Create 3 dock/undock action's ROS 2 action status."""

    SUCCEEDED = 0
    ABORTED = 1
    CANCELED = 2


class DockResult(enum.IntEnum):
    NOT_DOCKED = 0
    DOCKED = 1


class Motor(enum.IntEnum):
    LEFT = 0
    RIGHT = 1
    MARKER = 2


class StallCause(enum.IntEnum):
    NO_STALL = 0
    OVERCURRENT = 1
    UNDERCURRENT = 2
    UNDERSPEED = 3
    SATURATED_PID = 4
    TIMEOUT = 5


class MarkerPosition(enum.IntEnum):
    UP = 0
    MARKER_DOWN = 1
    ERASER_DOWN = 2


class LedState(enum.IntEnum):
    OFF = 0
    ON = 1
    BLINK = 2
    SPIN = 3


class ColorBank(enum.IntEnum):
    """Which 8 of the 32 colour sensors a Get Color Sensor Data request reads."""

    SENSORS_0_TO_7 = 0
    SENSORS_8_TO_15 = 1
    SENSORS_16_TO_23 = 2
    SENSORS_24_TO_31 = 3


class ColorLighting(enum.IntEnum):
    OFF = 0
    RED = 1
    GREEN = 2
    BLUE = 3
    ALL = 4


class ColorFormat(enum.IntEnum):
    ADC_COUNTS = 0
    MILLIVOLTS = 1


class SensorColor(enum.IntEnum):
    """A colour a colour sensor identified; any nibble other than 0-4 reads as WHITE (spec)."""

    WHITE = 0
    BLACK = 1
    RED = 2
    GREEN = 3
    BLUE = 4


class ModulationType(enum.IntEnum):
    DISABLED = 0
    VOLUME = 1
    PULSE_WIDTH = 2
    FREQUENCY = 3


class BumperState(enum.IntEnum):
    NONE = 0x00
    RIGHT = 0x40
    LEFT = 0x80
    BOTH = 0xC0


class LightState(enum.IntEnum):
    BOTH_DARK = 4
    RIGHT_BRIGHTER = 5
    LEFT_BRIGHTER = 6
    BOTH_BRIGHT = 7


class TouchSensors(enum.IntFlag):
    """The four top touch sensors (Create 3: button 1 is FRONT_LEFT, button 2 FRONT_RIGHT)."""

    NONE = 0
    REAR_LEFT = 0b0001
    REAR_RIGHT = 0b0010
    FRONT_RIGHT = 0b0100
    FRONT_LEFT = 0b1000


class DockContacts(enum.IntEnum):
    DISCONNECTED = 0
    CONNECTED = 1
