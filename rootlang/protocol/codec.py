"""Encoding and decoding the 20-byte packets, driven only by the table in ``table.py``.

Each spec gets one precompiled ``struct.Struct`` (header, fields, zero padding) and, per field,
a checking encoder and a decoder; encode and decode are then one pack/unpack, a few small
function calls and a CRC-8 from crcmod's C extension.
"""

from __future__ import annotations

import enum
import struct
import sys
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from typing import Any, ClassVar, Final, TypeVar

import crcmod.predefined

from rootlang.diagnostics import NO_SPAN, RootlangError, did_you_mean
from rootlang.protocol.enums import Device, Kind, TouchSensors
from rootlang.protocol.fields import (
    COLOR_SENSORS,
    DEVICE_BITS,
    PACKED_IR_SENSORS,
    FieldSpec,
    FieldType,
    colors_from_bytes,
    colors_to_bytes,
    devices_from_bytes,
    devices_to_bytes,
    integer_range,
    ipv4_from_int,
    ipv4_to_int,
    json_value,
    packed_ir_from_bytes,
    packed_ir_to_bytes,
    text_from_bytes,
    text_value,
)
from rootlang.protocol.specs import PacketSpec, Sender
from rootlang.protocol.table import PACKETS
from rootlang.robots import RobotModel
from rootlang.wording.shown import Suggestion, suggestion

PACKET_BYTES: Final = 20
HEADER_LAYOUT: Final = ">BBB"  # device, command, packet id; big-endian, as the fields are
HEADER_BYTES: Final = struct.calcsize(HEADER_LAYOUT)
MAX_PACKET_ID: Final = 255

crc8: Callable[[bytes], int] = crcmod.predefined.mkCrcFun("crc-8")
"""CRC-8, polynomial 0x07, initial value 0, no reflection, no final xor: crc8(b"123456789") == 0xF4.
Over a whole valid packet (payload and its CRC) it gives 0, which is how decode checks it."""

CRC_C_EXTENSION: bool = bool(getattr(sys.modules["crcmod.crcmod"], "_usingExtension", False))
"""Whether crcmod found its C extension (about twice as fast; pure Python works too)."""


class PacketError(RootlangError):
    """A packet that cannot be built or read: wrong length, bad CRC, a bad field value, ...

    ``spec`` and ``packet_id`` say which packet it was when that is known (a decoded packet with
    a value out of range), so a robot client can still fail the request that waits for it.
    """

    spec: PacketSpec | None = None
    packet_id: int | None = None


def _error(code: str, **values: object) -> PacketError:
    error = PacketError.of(code, NO_SPAN, **values)
    assert isinstance(error, PacketError)
    return error


# --- decoded packets ----------------------------------------------------------------------


@dataclass(frozen=True, eq=True)
class Packet:
    """A packet with its spec, id and field values (protocol units: mm, decidegrees, ms ...)."""

    spec: PacketSpec
    id: int
    fields: Mapping[str, Any]

    @property
    def name(self) -> str:
        return self.spec.name

    @property
    def kind(self) -> Kind:
        return self.spec.kind

    @property
    def device(self) -> Device:
        return self.spec.device

    @property
    def command(self) -> int:
        return self.spec.command

    @property
    def key(self) -> tuple[int, int, int]:
        """(device, command, id): a response carries its request's key."""
        return (self.spec.device, self.spec.command, self.id)

    def __getitem__(self, field_name: str) -> Any:
        return self.fields[field_name]

    def encode(self, robot: RobotModel | None = None) -> bytes:
        return _CODECS[self.spec.name].encode(self.fields, self.id, robot)

    def to_json(self) -> dict[str, object]:
        return {
            "name": self.spec.name,
            "device": int(self.spec.device),
            "command": self.spec.command,
            "id": self.id,
            "kind": self.spec.kind.value,
            "fields": {name: json_value(value) for name, value in self.fields.items()},
        }

    def __str__(self) -> str:
        parts = [f"{self.spec.name} #{self.id}"]
        parts += [
            f"{f.name}={text_value(self.fields[f.name], f)}"
            for f in self.spec.fields
            if f.name in self.fields
        ]
        return " ".join(parts)


@dataclass(frozen=True)
class UnknownPacket:
    """A well-formed packet (length and CRC fine) whose device/command the table lacks.

    Newer firmware may send such packets; callers log and skip them.
    """

    device: int
    command: int
    id: int
    payload: bytes
    sender: Sender

    name: ClassVar[str] = "unknown"
    kind: ClassVar[None] = None

    @property
    def key(self) -> tuple[int, int, int]:
        return (self.device, self.command, self.id)

    def to_json(self) -> dict[str, object]:
        return {
            "name": None,
            "device": self.device,
            "command": self.command,
            "id": self.id,
            "kind": None,
            "fields": {},
            "payload": self.payload.hex(),
        }

    def __str__(self) -> str:
        return (
            f"unknown packet from the {self.sender}: device {self.device}, "
            f"command {self.command}, id {self.id}, payload {self.payload.hex()}"
        )


# --- per-field encoders and decoders --------------------------------------------------------

Encoder = Callable[[Any], Any]
Decoder = Callable[[Any], Any] | None


def _is_int(value: object) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


def _is_int_type(kind: type) -> bool:
    return issubclass(kind, int) and not issubclass(kind, bool)


def _int_list(value: object, count: int) -> list[int] | None:
    if isinstance(value, (str, bytes)) or not isinstance(value, Iterable):
        return None
    items = list(value)
    # checked by type, not item by item: a colour event's 32 items have one or two types
    if len(items) != count or not all(map(_is_int_type, set(map(type, items)))):
        return None
    return items


def shown_value(value: object) -> str:
    """A value as a message shows it: no Python set or tuple syntax (``999``, ``1, 2``), text in
    double quotes with what is not UTF-8 written as escapes."""
    if isinstance(value, (set, frozenset)):
        value = sorted(value, key=str)
    if isinstance(value, (list, tuple)):
        return ", ".join(shown_value(item) for item in value) or "nothing"
    if isinstance(value, str):
        return '"' + value.encode("utf-8", "backslashreplace").decode("utf-8") + '"'
    if isinstance(value, (bytes, bytearray)):
        return value.hex(" ")
    return str(value)


def _out_of_range(
    packet: PacketSpec, spec: FieldSpec, value: object, robot: RobotModel | None = None
) -> PacketError:
    """E504: ``value`` (as the message shows it) is not allowed in this field."""
    return _error(
        "E504",
        packet=packet.name,
        field=spec.name,
        allowed=spec.describe_range(robot),
        value=value,
    )


def _encoder(packet: PacketSpec, spec: FieldSpec, robot: RobotModel | None) -> Encoder:
    """A function that checks one field's value and returns its ``struct`` item."""

    def bad(value: object) -> PacketError:
        return _out_of_range(packet, spec, shown_value(value), robot)

    if spec.enum is not None:
        allowed = frozenset(int(member) for member in spec.enum)

        def encode_member(value: Any) -> Any:
            if not _is_int(value) or value not in allowed:
                raise bad(value)
            return value

        return encode_member

    kind = spec.type
    limits = spec.range_for(robot)
    lo, hi = limits if limits is not None else (0, 0)
    if kind in (
        FieldType.UINT8,
        FieldType.INT8,
        FieldType.UINT16,
        FieldType.INT16,
        FieldType.UINT32,
        FieldType.INT32,
        FieldType.HIGH_NIBBLE,
    ):
        shift = 4 if kind is FieldType.HIGH_NIBBLE else 0

        def encode_int(value: Any) -> Any:
            if type(value) is not int and not _is_int(value):
                raise bad(value)
            if value < lo or value > hi:
                raise bad(value)
            return value << shift if shift else value

        return encode_int

    if kind in (FieldType.UINT16_ARRAY, FieldType.PACKED_IR, FieldType.COLORS):
        count = {FieldType.PACKED_IR: PACKED_IR_SENSORS, FieldType.COLORS: COLOR_SENSORS}.get(
            kind, spec.count
        )
        array = struct.Struct(f">{spec.count}H")
        pack: Callable[[Iterable[int]], bytes] = {
            FieldType.PACKED_IR: packed_ir_to_bytes,
            FieldType.COLORS: colors_to_bytes,
        }.get(kind, lambda items: array.pack(*items))

        # colours may come as bytes, one a sensor: in range if deleting the allowed values
        # leaves nothing (one C call; the simulator sends ~20 colour events a second)
        in_range = bytes(range(max(lo, 0), min(hi, 255) + 1)) if kind is FieldType.COLORS else None

        def encode_list(value: Any) -> Any:
            if in_range is not None and type(value) is bytes and len(value) == count:
                if value.translate(None, in_range):
                    raise bad(value)
                return pack(value)
            items = _int_list(value, count)
            if items is None or (items and (min(items) < lo or max(items) > hi)):
                raise bad(value)
            return pack(items)

        return encode_list

    if kind is FieldType.TEXT:

        def encode_text(value: Any) -> Any:
            if not isinstance(value, str) or "\0" in value:
                raise bad(value)
            try:
                raw = value.encode("utf-8")
            except UnicodeEncodeError:  # bytes that were not UTF-8 (from a command line)
                raise bad(value) from None
            if len(raw) > spec.size:
                raise _out_of_range(packet, spec, f"{shown_value(value)} ({len(raw)} bytes)")
            return raw

        return encode_text

    if kind is FieldType.DEVICES:

        def encode_devices(value: Any) -> Any:
            if isinstance(value, (str, bytes)) or not isinstance(value, Iterable):
                raise bad(value)
            numbers = list(value)
            if not all(_is_int(n) and 0 <= n < DEVICE_BITS for n in numbers):
                raise bad(value)
            return devices_to_bytes(numbers)

        return encode_devices

    if kind is FieldType.IPV4:

        def encode_ipv4(value: Any) -> Any:
            try:
                return ipv4_to_int(value)
            except (ValueError, TypeError):
                raise bad(value) from None

        return encode_ipv4

    assert kind is FieldType.CHAR

    def encode_char(value: Any) -> Any:
        if not isinstance(value, str) or len(value) != 1 or ord(value) > 255:
            raise bad(value)
        return value.encode("latin-1")

    return encode_char


def _decoder(packet: PacketSpec, spec: FieldSpec, robot: RobotModel | None) -> Decoder:
    """A function from one ``struct`` item to the field's value, or None if it is the item."""
    if spec.enum is not None:
        members: dict[int, enum.IntEnum] = {int(m): m for m in spec.enum}

        def decode_member(raw: int) -> enum.IntEnum:
            member = members.get(raw)
            if member is None:
                raise _out_of_range(packet, spec, raw, robot)
            return member

        return decode_member
    kind = spec.type
    limits = spec.range_for(robot)
    if kind is FieldType.UINT16_ARRAY:
        array = struct.Struct(f">{spec.count}H")
        lo, hi = limits or (0, 0xFFFF)

        def decode_array(raw: bytes) -> tuple[int, ...]:
            values = array.unpack(raw)
            if any(v < lo or v > hi for v in values):
                raise _out_of_range(packet, spec, shown_value(values), robot)
            return values

        return decode_array
    converters: dict[FieldType, Callable[[Any], Any]] = {
        FieldType.TEXT: text_from_bytes,
        FieldType.DEVICES: devices_from_bytes,
        FieldType.COLORS: colors_from_bytes,
        FieldType.PACKED_IR: packed_ir_from_bytes,
        FieldType.IPV4: ipv4_from_int,
        FieldType.CHAR: lambda raw: raw.decode("latin-1"),
        FieldType.HIGH_NIBBLE: lambda raw: TouchSensors(raw >> 4),
    }
    if kind in converters:
        return converters[kind]
    if limits is None or limits == integer_range(kind):
        return None  # every wire value is allowed: the struct item is the value
    lo, hi = limits

    def decode_int(raw: int) -> int:
        if raw < lo or raw > hi:
            raise _out_of_range(packet, spec, raw, robot)
        return raw

    return decode_int


class _Codec:
    """One spec, compiled: its struct and its fields' encoders and decoders per robot model."""

    def __init__(self, spec: PacketSpec) -> None:
        self.spec = spec
        fields = "".join(f.struct_format for f in spec.fields)
        padding = PACKET_BYTES - 1 - struct.calcsize(HEADER_LAYOUT + fields)  # (then the CRC)
        self.struct = struct.Struct(f"{HEADER_LAYOUT}{fields}{padding}x")
        self.payload = struct.Struct(f">{fields}")  # the fields alone, read after the header
        self.names = spec.field_names
        self.device = int(spec.device)
        self.command = spec.command
        encoders = tuple(_encoder(spec, f, None) for f in spec.fields)
        decoders = tuple(_decoder(spec, f, None) for f in spec.fields)
        self.encoders = dict.fromkeys((None, *RobotModel), encoders)
        self.decoders = dict.fromkeys((None, *RobotModel), decoders)
        robots = {r for f in spec.fields for r in f.robot_ranges}
        for robot in robots:
            self.encoders[robot] = tuple(_encoder(spec, f, robot) for f in spec.fields)
            self.decoders[robot] = tuple(_decoder(spec, f, robot) for f in spec.fields)
        # most packets are the same for every model: then no lookup by model (an enum's hash is
        # a Python call, and the simulator encodes and decodes ~20 colour events a second)
        self.same_for_all = None if robots else (encoders, decoders)

    def encode(self, values: Mapping[str, Any], packet_id: int, robot: RobotModel | None) -> bytes:
        if type(packet_id) is not int or not 0 <= packet_id <= MAX_PACKET_ID:
            raise _error("E507", value=repr(packet_id))
        names = self.names
        if len(values) != len(names):
            self._explain_field_names(values)
        try:
            same = self.same_for_all
            encoders = zip(names, self.encoders[robot] if same is None else same[0], strict=True)
            items = [encode(values[name]) for name, encode in encoders]
        except KeyError:
            self._explain_field_names(values)
            raise
        body = self.struct.pack(self.device, self.command, packet_id, *items)
        return body + crc8(body).to_bytes(1, "big")

    def _explain_field_names(self, values: Mapping[str, Any]) -> None:
        for name in values:
            if name not in self.names:
                hint = did_you_mean(name, self.names)
                raise _error(
                    "E505",
                    packet=self.spec.name,
                    field=name,
                    hint=suggestion(hint),
                    fields=", ".join(self.names) or "none",
                )
        for field_spec in self.spec.fields:
            if field_spec.name not in values:
                raise _error(
                    "E506",
                    packet=self.spec.name,
                    field=field_spec.name,
                    allowed=field_spec.describe_range(),
                )

    def decode(self, data: bytes, robot: RobotModel | None) -> Packet:
        items = self.payload.unpack_from(data, HEADER_BYTES)
        same = self.same_for_all
        decoders = self.decoders[robot] if same is None else same[1]
        try:
            values = {
                name: item if decode is None else decode(item)
                for name, decode, item in zip(self.names, decoders, items, strict=True)
            }
        except PacketError as error:
            error.spec, error.packet_id = self.spec, data[2]
            raise
        return _decoded(self.spec, data[2], values)


def _decoded(spec: PacketSpec, packet_id: int, values: dict[str, Any]) -> Packet:
    """``Packet(spec, packet_id, values)``, unchecked: a decoded packet has nothing to check
    (~20 colour events a second)."""
    return unchecked(Packet, {"spec": spec, "id": packet_id, "fields": values})


T = TypeVar("T")


def unchecked(cls: type[T], attributes: dict[str, Any]) -> T:
    """An instance of the frozen dataclass ``cls`` with these attributes (all of them), made
    without ``__init__`` and its ``object.__setattr__`` for each field: for the objects made
    for every packet, where there is nothing to check or derive."""
    instance = object.__new__(cls)
    object.__setattr__(instance, "__dict__", attributes)  # (frozen: a plain = is refused)
    return instance


_CODECS: dict[str, _Codec] = {spec.name: _Codec(spec) for spec in PACKETS}
_BY_SENDER: dict[str, dict[tuple[int, int], _Codec]] = {
    sender: {(int(s.device), s.command): _CODECS[s.name] for s in PACKETS if s.sender == sender}
    for sender in ("robot", "host")
}
SPECS: dict[str, PacketSpec] = {spec.name: spec for spec in PACKETS}


# --- the public functions ---------------------------------------------------------------------


def spec(name: str) -> PacketSpec:
    """The table row called ``name``; an unknown name raises PacketError naming close ones."""
    found = SPECS.get(name)
    if found is not None:
        return found
    guess = did_you_mean(name, SPECS, max_distance=3)
    similar = [n for n in SPECS if name and (name in n or n in name)][:6]
    if guess:
        hint: Suggestion | str = Suggestion(guess)
    elif similar:
        hint = " Close names: " + ", ".join(similar) + "."
    else:
        hint = " Run `rootlang packet list` to see them all."
    raise _error("E503", name=name, hint=hint)


def encode(
    name: str,
    fields: Mapping[str, object] | None = None,
    packet_id: int = 0,
    robot: RobotModel | None = None,
) -> bytes:
    """The 20 bytes of packet ``name`` with these field values and id.

    Every field must be given, in range (``robot`` selects a model's own range where it has one,
    like the Create 3's faster wheels); otherwise PacketError names the field, value and range.
    """
    codec = _CODECS.get(name)
    if codec is None:
        spec(name)  # raises with suggestions
    assert codec is not None
    return codec.encode(fields or {}, packet_id, robot)


def decode(
    data: bytes | bytearray | memoryview, sender: Sender, robot: RobotModel | None = None
) -> Packet | UnknownPacket:
    """Read 20 bytes sent by ``sender`` ("robot": a response or event; "host": a command).

    Raises PacketError for a wrong length, a bad CRC or a field value out of its range; returns
    an UnknownPacket for a device/command the table lacks.
    """
    if type(data) is not bytes:
        data = bytes(data)
    if len(data) != PACKET_BYTES:
        raise _error("E501", length=len(data))
    if crc8(data):
        raise _error("E502", found=f"0x{data[19]:02x}", expected=f"0x{crc8(data[:19]):02x}")
    table = _BY_SENDER.get(sender)
    if table is None:
        raise ValueError(f"sender must be 'robot' or 'host', not {sender!r}")
    codec = table.get((data[0], data[1]))
    if codec is None:
        return UnknownPacket(data[0], data[1], data[2], data[HEADER_BYTES:19], sender)
    return codec.decode(data, robot)


def make_packet(name: str, packet_id: int = 0, **fields: object) -> Packet:
    """A Packet for ``name``, checked now (so a bad value fails here, not when it is sent)."""
    encode(name, fields, packet_id)
    return Packet(spec(name), packet_id, fields)


def interpretations(data: bytes, robot: RobotModel | None = None) -> list[Packet]:
    """The known packets ``data`` can be when its sender is not known, most likely first.

    A command and its response share device and command numbers; a reading whose unused payload
    bytes are zero (as the spec asks) is preferred. Raises PacketError for a wrong length or bad
    CRC, or when no reading works (the first reading's error, or E509 if none is known).
    """
    readings: list[tuple[bool, Packet]] = []
    first_error: PacketError | None = None
    for sender in ("host", "robot"):
        try:
            packet = decode(data, sender, robot)
        except PacketError as error:
            if error.spec is None:
                raise  # length or CRC: no reading can work
            first_error = first_error or error
            continue
        if isinstance(packet, Packet):
            unused = data[HEADER_BYTES + packet.spec.payload_size : PACKET_BYTES - 1]
            readings.append((not any(unused), packet))
    if not readings:
        if first_error is not None:
            raise first_error
        raise _error("E509", device=data[0], command=data[1], kind="command, response or event")
    tidy = [packet for clean, packet in readings if clean]
    return tidy or [packet for _, packet in readings]
