"""The Root/Create 3 BLE packet protocol: one declarative table, and everything that reads it.

Every packet is 20 bytes: device, command, id, a 16-byte big-endian payload and a CRC-8.
The table (``table.PACKETS``) lists each command, response and event of the spec with its
fields (type, unit, range), the robots that support it and the minimum protocol version.

Names (``PacketSpec.name``, unique, snake_case):
  - a command is named for what it asks: ``drive_distance``, ``set_wheel_speeds``;
  - its response is the command's name + ``_response``: ``drive_distance_response``
    (same device and command number; the robot repeats the request's id);
  - an event ends in ``_event``: ``bumper_event``, ``color_sensor_event``.

Use:
    >>> from rootlang.protocol import encode, decode
    >>> encode("set_wheel_speeds", {"left": 100, "right": 100}).hex()
    '01040000000064000000640000000000000000d1'
    >>> str(decode(bytes.fromhex("01040000000064000000640000000000000000d1"), sender="host"))
    'set_wheel_speeds #0 left=100 mm/s right=100 mm/s'

API:
  - ``PACKETS``, ``PacketSpec``, ``FieldSpec``, ``FieldType``, ``Kind``, ``spec(name)``
  - ``encode(name, fields, packet_id=0, robot=None) -> bytes``;
    ``decode(data, sender, robot=None) -> Packet | UnknownPacket``; ``make_packet(name, id, **f)``;
    ``interpretations(data)`` (the readings of bytes whose sender is unknown)
  - ``Packet`` (``.spec .id .fields .name .kind .key .encode() .to_json()``), ``UnknownPacket``
  - ``PacketError`` (a RootlangError with an E5xx code): wrong length, bad CRC, unknown name,
    missing/unknown field, value out of range (the message names field, value and range)
  - ``HostPacketIds`` (0..255, wraps), ``EventIdTracker`` (gaps and repeats, logged)
  - ``protocol_version_for(model, firmware)``, ``max_protocol(model)``
  - ``crc8``; the field enums (``BumperState``, ``MarkerPosition``, ``SensorColor`` ...)

Field values are in the protocol's own units (mm, mm/s, decidegrees, ms, Hz ...; each
FieldSpec's ``unit`` says which); enumerated fields decode as the IntEnums of ``enums``; colour
nibbles as ``SensorColor`` (undefined nibbles read as WHITE); device bitfields as frozensets of
device numbers; packed 12-bit IR values and uint16 arrays as tuples of ints; IPv4 addresses and
text as ``str``; timestamps as int milliseconds.
"""

from __future__ import annotations

from rootlang.protocol.codec import (
    PACKET_BYTES,
    SPECS,
    Packet,
    PacketError,
    UnknownPacket,
    crc8,
    decode,
    encode,
    interpretations,
    make_packet,
    spec,
)
from rootlang.protocol.enums import (
    Board,
    BumperState,
    ColorBank,
    ColorFormat,
    ColorLighting,
    Device,
    DockContacts,
    DockResult,
    DockStatus,
    GravityCompensation,
    Kind,
    LedState,
    LightState,
    MarkerPosition,
    ModulationType,
    Motor,
    SensorColor,
    StallCause,
    TouchSensors,
)
from rootlang.protocol.fields import FieldSpec, FieldType, json_value, parse_field_value
from rootlang.protocol.ids import EventCheck, EventIdTracker, EventOrder, HostPacketIds
from rootlang.protocol.specs import PacketSpec, Sender
from rootlang.protocol.table import PACKETS
from rootlang.protocol.versions import max_protocol, protocol_version_for

__all__ = [
    "PACKETS",
    "PACKET_BYTES",
    "SPECS",
    "Board",
    "BumperState",
    "ColorBank",
    "ColorFormat",
    "ColorLighting",
    "Device",
    "DockContacts",
    "DockResult",
    "DockStatus",
    "EventCheck",
    "EventIdTracker",
    "EventOrder",
    "FieldSpec",
    "FieldType",
    "GravityCompensation",
    "HostPacketIds",
    "Kind",
    "LedState",
    "LightState",
    "MarkerPosition",
    "ModulationType",
    "Motor",
    "Packet",
    "PacketError",
    "PacketSpec",
    "Sender",
    "SensorColor",
    "StallCause",
    "TouchSensors",
    "UnknownPacket",
    "crc8",
    "decode",
    "encode",
    "interpretations",
    "json_value",
    "make_packet",
    "max_protocol",
    "parse_field_value",
    "protocol_version_for",
    "spec",
]
