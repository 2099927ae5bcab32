"""Field types of the packet payloads, and how one field's value goes to and from its bytes.

A :class:`FieldSpec` is one row of a packet's payload in the table. Each field type has one
``struct`` item, so a whole packet packs and unpacks with one precompiled ``struct.Struct``;
types the ``struct`` module cannot express (text, bitfields, nibbles, packed 12-bit values) are
carried as raw bytes and converted by the functions here.
"""

from __future__ import annotations

import builtins
import enum
import ipaddress
import struct
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any

from rootlang.protocol.enums import Device, SensorColor, TouchSensors
from rootlang.robots import RobotModel


class FieldType(enum.Enum):
    """How a field sits in the payload; the value is the name the docs and ``list`` show."""

    UINT8 = "uint8"
    INT8 = "int8"
    UINT16 = "uint16"
    INT16 = "int16"
    UINT32 = "uint32"
    INT32 = "int32"
    UINT16_ARRAY = "uint16[]"
    """``count`` big-endian uint16 values, as a tuple of ints."""
    TEXT = "string"
    """UTF-8, null-terminated when shorter than ``size`` bytes; a ``str``."""
    DEVICES = "uint128 bitfield"
    """Bit n set for device n (device 0 is bit 0 of the last byte); a frozenset of ints."""
    COLORS = "uint4[32]"
    """32 colour nibbles, high nibble first; a tuple of :class:`SensorColor`."""
    PACKED_IR = "uint12[7] packed"
    """Seven 12-bit values: seven high bytes, then four bytes of low nibbles; a tuple of ints."""
    IPV4 = "IPv4 address"
    """A uint32 address; a dotted ``str`` such as ``"192.168.1.20"``."""
    CHAR = "char"
    """One byte read as a character (Latin-1); a one-character ``str``."""
    HIGH_NIBBLE = "uint4 (upper nibble)"
    """The upper four bits of one byte; the lower four are zero on encode, ignored on decode."""


_INTEGER_FORMATS: dict[FieldType, str] = {
    FieldType.UINT8: "B",
    FieldType.INT8: "b",
    FieldType.UINT16: "H",
    FieldType.INT16: "h",
    FieldType.UINT32: "I",
    FieldType.INT32: "i",
}

_INTEGER_BITS: dict[FieldType, tuple[int, bool]] = {
    FieldType.UINT8: (8, False),
    FieldType.INT8: (8, True),
    FieldType.UINT16: (16, False),
    FieldType.INT16: (16, True),
    FieldType.UINT32: (32, False),
    FieldType.INT32: (32, True),
    FieldType.UINT16_ARRAY: (16, False),
    FieldType.HIGH_NIBBLE: (4, False),
    FieldType.PACKED_IR: (12, False),
    FieldType.COLORS: (4, False),
}

DEVICE_BITS = 128
COLOR_SENSORS = 32
PACKED_IR_SENSORS = 7


def integer_range(field_type: FieldType) -> tuple[int, int] | None:
    """The values a field type can hold on the wire (None for text and bitfields)."""
    if field_type not in _INTEGER_BITS:
        return None
    bits, signed = _INTEGER_BITS[field_type]
    if signed:
        return -(1 << (bits - 1)), (1 << (bits - 1)) - 1
    return 0, (1 << bits) - 1


@dataclass(frozen=True)
class FieldSpec:
    """One payload field: its name, wire type, unit, allowed range and meaning.

    ``minimum``/``maximum`` bound each integer (each element for arrays); for enumerated fields
    the allowed values are ``enum``'s members. ``robot_ranges`` narrows or widens the range for
    one robot model (the Create 3 drives faster than a Root).
    """

    name: str
    type: FieldType
    unit: str = ""
    minimum: int | None = None
    maximum: int | None = None
    enum: builtins.type[enum.IntEnum] | None = None
    size: int = 0
    """Bytes of a TEXT field."""
    count: int = 1
    """Elements of a UINT16_ARRAY field."""
    doc: str = ""
    robot_ranges: Mapping[RobotModel, tuple[int, int]] = field(default_factory=dict)

    def __post_init__(self) -> None:
        wire = integer_range(self.type)
        if wire is not None:
            if self.minimum is None:
                object.__setattr__(self, "minimum", wire[0])
            if self.maximum is None:
                object.__setattr__(self, "maximum", wire[1])

    @property
    def range(self) -> tuple[int, int] | None:
        """(minimum, maximum) of an integer field, None for text, bitfields and enums."""
        if self.enum is not None or self.minimum is None or self.maximum is None:
            return None
        return self.minimum, self.maximum

    def range_for(self, robot: RobotModel | None) -> tuple[int, int] | None:
        if robot is not None and robot in self.robot_ranges:
            return self.robot_ranges[robot]
        return self.range

    @property
    def struct_format(self) -> str:
        """This field's one item in the packet's ``struct`` format."""
        if self.type in _INTEGER_FORMATS:
            return _INTEGER_FORMATS[self.type]
        return {
            FieldType.UINT16_ARRAY: f"{2 * self.count}s",
            FieldType.TEXT: f"{self.size}s",
            FieldType.DEVICES: "16s",
            FieldType.COLORS: "16s",
            FieldType.PACKED_IR: "11s",
            FieldType.IPV4: "I",
            FieldType.CHAR: "c",
            FieldType.HIGH_NIBBLE: "B",
        }[self.type]

    @property
    def byte_size(self) -> int:
        return struct.calcsize(">" + self.struct_format)

    @property
    def type_name(self) -> str:
        if self.enum is not None:
            return f"{self.type.value} ({self.enum.__name__})"
        if self.type is FieldType.TEXT:
            return f"string[{self.size}]"
        if self.type is FieldType.UINT16_ARRAY:
            return f"uint16[{self.count}]"
        return str(self.type.value)

    def describe_range(self, robot: RobotModel | None = None) -> str:
        """The allowed values in words, for errors and docs."""
        if self.enum is not None:
            return ", ".join(f"{m.name} ({m.value})" for m in self.enum)
        if self.type is FieldType.TEXT:
            return f"UTF-8 text of at most {self.size} bytes"
        if self.type is FieldType.DEVICES:
            return f"device numbers 0 to {DEVICE_BITS - 1}"
        if self.type is FieldType.IPV4:
            return "an IPv4 address such as 192.168.1.20"
        if self.type is FieldType.CHAR:
            return "one character"
        limits = self.range_for(robot)
        assert limits is not None
        text = f"{limits[0]} to {limits[1]}"
        count = {FieldType.COLORS: COLOR_SENSORS, FieldType.PACKED_IR: PACKED_IR_SENSORS}.get(
            self.type, self.count
        )
        return f"{count} values, each {text}" if count > 1 else text


# --- conversions between Python values and struct items -------------------------------------


def _sensor_color(nibble: int) -> SensorColor:
    return SensorColor(nibble) if nibble <= max(SensorColor) else SensorColor.WHITE


_COLOR_OF_NIBBLE: tuple[SensorColor, ...] = tuple(_sensor_color(n) for n in range(16))


def devices_to_bytes(devices: Iterable[int]) -> bytes:
    bits = 0
    for number in devices:
        bits |= 1 << number
    return bits.to_bytes(16, "big")


def devices_from_bytes(raw: bytes) -> frozenset[int]:
    bits = int.from_bytes(raw, "big")
    return frozenset(n for n in range(DEVICE_BITS) if bits >> n & 1)


def colors_to_bytes(colors: Iterable[int]) -> bytes:
    """32 colours (0-15 each), two a byte, the first in the high nibble."""
    nibbles = colors if isinstance(colors, (bytes, list, tuple)) else list(colors)
    # As whole numbers: the even sensors' bytes moved up 4 bits, or'ed with the odd sensors'
    # (each below 16, so nothing carries into the next byte). A few C calls, not 16 steps.
    high = int.from_bytes(bytes(nibbles[0:COLOR_SENSORS:2]), "big")
    low = int.from_bytes(bytes(nibbles[1:COLOR_SENSORS:2]), "big")
    return (high << 4 | low).to_bytes(COLOR_SENSORS // 2, "big")


_COLOR_QUARTERS = struct.Struct(">4I")  # the 32 sensors' nibbles as four 8-sensor quarters
_QUARTER_COLORS: dict[int, tuple[SensorColor, ...]] = {}  # a quarter's nibbles -> colours
_QUARTERS_KEPT = 4096  # a bound; 10 minutes of drawing on a colour mat meets about 1,000
_SHIFTS = range(28, -1, -4)  # a quarter's eight nibbles, the first sensor's the highest


def colors_from_bytes(raw: bytes) -> tuple[SensorColor, ...]:
    """Nibbles other than 0-4 are undefined; the spec says to read them as white."""
    # a robot drawing sends ~20 colour events a second, made of quarters met before: four
    # lookups and a few concatenations, not 32 Python steps
    a, b, c, d = _COLOR_QUARTERS.unpack(raw)
    known = _QUARTER_COLORS
    try:
        return known[a] + known[b] + known[c] + known[d]
    except KeyError:
        if len(known) > _QUARTERS_KEPT:
            known.clear()
        for quarter in (a, b, c, d):
            known[quarter] = tuple(_COLOR_OF_NIBBLE[quarter >> shift & 15] for shift in _SHIFTS)
        return known[a] + known[b] + known[c] + known[d]


def packed_ir_to_bytes(values: Iterable[int]) -> bytes:
    v = list(values)
    low = [x & 15 for x in v] + [0]
    return bytes([x >> 4 for x in v] + [(low[i] << 4) | low[i + 1] for i in range(0, 8, 2)])


def packed_ir_from_bytes(raw: bytes) -> tuple[int, ...]:
    lows = [n for byte in raw[7:] for n in (byte >> 4, byte & 15)]
    return tuple((raw[i] << 4) | lows[i] for i in range(PACKED_IR_SENSORS))


def text_from_bytes(raw: bytes) -> str:
    """Up to the first null; bytes that are not UTF-8 show as U+FFFD rather than failing."""
    return raw.split(b"\0", 1)[0].decode("utf-8", "replace")


def ipv4_to_int(address: str | int) -> int:
    return int(ipaddress.IPv4Address(address))


def ipv4_from_int(number: int) -> str:
    return str(ipaddress.IPv4Address(number))


# --- text on the command line -> field values --------------------------------------------


def _parse_int(text: str) -> int:
    try:
        return int(text.strip().replace("_", ""), 0)
    except ValueError:
        raise ValueError("expected a whole number (like 42, -7 or 0x2a)") from None


def _parse_member(enum_type: type[enum.IntEnum] | type[enum.IntFlag], text: str) -> int:
    key = text.strip().upper().replace("-", "_").replace(" ", "_")
    if key in enum_type.__members__:
        return int(enum_type.__members__[key])
    try:
        return _parse_int(text)
    except ValueError:
        names = ", ".join(name for name in enum_type.__members__)
        raise ValueError(f"expected a number or one of {names}") from None


def _split(text: str) -> list[str]:
    return [part for part in text.replace(" ", ",").split(",") if part]


def parse_field_value(spec: FieldSpec, text: str) -> Any:
    """Read a value written on the command line (``left=100``, ``state=LEFT``, ``devices=1,4``).

    Raises ValueError with a short reason; range checks happen later, on encode.
    """
    if spec.enum is not None:
        return _parse_member(spec.enum, text)
    parsers: dict[FieldType, Callable[[str], Any]] = {
        FieldType.TEXT: lambda t: t,
        FieldType.CHAR: lambda t: t,
        FieldType.IPV4: lambda t: t.strip(),
        FieldType.DEVICES: lambda t: frozenset(_parse_member(Device, p) for p in _split(t)),
        FieldType.COLORS: lambda t: tuple(_parse_member(SensorColor, p) for p in _split(t)),
        FieldType.PACKED_IR: lambda t: tuple(_parse_int(p) for p in _split(t)),
        FieldType.UINT16_ARRAY: lambda t: tuple(_parse_int(p) for p in _split(t)),
        FieldType.HIGH_NIBBLE: lambda t: sum(
            _parse_member(TouchSensors, p) for p in _split(t.replace("|", ","))
        ),
    }
    return parsers.get(spec.type, _parse_int)(text)


def json_value(value: object) -> object:
    """A decoded value as plain JSON data: enums by name, sets and tuples as lists."""
    if isinstance(value, enum.IntFlag):
        return [m.name for m in type(value) if m.value and value & m.value == m.value]
    if isinstance(value, enum.IntEnum):
        return value.name
    if isinstance(value, frozenset):
        return sorted(value)
    if isinstance(value, tuple):
        return [json_value(v) for v in value]
    return value


def text_value(value: object, spec: FieldSpec) -> str:
    """A decoded value for people: ``left=100 mm/s``, ``state=LEFT``, ``colors=WWKK…``."""
    if isinstance(value, enum.IntFlag):
        names = json_value(value)
        assert isinstance(names, list)
        return "|".join(names) or "NONE"
    if isinstance(value, enum.IntEnum):
        return value.name
    if spec.type is FieldType.COLORS:
        assert isinstance(value, tuple)
        return "".join("WKRGB"[int(c)] for c in value)
    if isinstance(value, frozenset):
        return "{" + ", ".join(str(n) for n in sorted(value)) + "}"
    if isinstance(value, str):
        return repr(value)
    return f"{value} {spec.unit}" if spec.unit else str(value)
