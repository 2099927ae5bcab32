"""What one row of the packet table says, and the small helpers the table is written with."""

from __future__ import annotations

import enum
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Literal

from rootlang.protocol.behaviour import TRUSTED, Behaviour, Role, Tells
from rootlang.protocol.enums import Device, Kind
from rootlang.protocol.fields import FieldSpec, FieldType
from rootlang.robots import RobotModel

Sender = Literal["robot", "host"]

PAYLOAD_BYTES = 16

ALL_ROBOTS = frozenset(RobotModel)
ROOT_ROBOTS = frozenset({RobotModel.RT0, RobotModel.RT1})
RT1_ONLY = frozenset({RobotModel.RT1})
CREATE3_ONLY = frozenset({RobotModel.CREATE3})
NOT_RT0 = frozenset({RobotModel.RT1, RobotModel.CREATE3})


@dataclass(frozen=True)
class PacketSpec:
    """One packet of the protocol: a command the host sends, or a response or event it gets.

    Names are snake_case: a command is named for what it asks (``drive_distance``), its
    response is the command's name plus ``_response`` (``drive_distance_response``, with the same
    device and command number), and an event ends in ``_event`` (``bumper_event``).
    """

    name: str
    device: Device
    command: int
    kind: Kind
    fields: tuple[FieldSpec, ...]
    robots: frozenset[RobotModel]
    min_protocol: tuple[int, int]
    doc: str
    response: PacketSpec | None = None
    """For a command the robot answers, the spec of that answer."""
    errata: str = ""
    """How the table differs from the published spec here, and why."""
    behaviour: Behaviour = TRUSTED
    """For a command: how it behaves on the robot (its actuator, what its silence means ...)."""
    role: Role | None = None
    """What the client needs it for, if it needs it by name."""
    tells: Tells | None = None
    """For an event or a response: which of the robot's readings it tells."""
    field_names: tuple[str, ...] = field(init=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "field_names", tuple(f.name for f in self.fields))

    @property
    def sender(self) -> Sender:
        return "host" if self.kind is Kind.COMMAND else "robot"

    @property
    def id_kind(self) -> str:
        """The spec's name for the id byte: Inc. (host counter), Req. (echo), Evt. (robot)."""
        return {Kind.COMMAND: "Inc.", Kind.RESPONSE: "Req.", Kind.EVENT: "Evt."}[self.kind]

    @property
    def payload_size(self) -> int:
        return sum(f.byte_size for f in self.fields)

    def field(self, name: str) -> FieldSpec:
        for candidate in self.fields:
            if candidate.name == name:
                return candidate
        raise KeyError(name)

    def supported_by(self, robot: RobotModel, protocol: tuple[int, int]) -> bool:
        """Whether ``robot`` speaking protocol version ``protocol`` knows this packet."""
        return robot in self.robots and protocol >= self.min_protocol


# --- helpers for writing the table -------------------------------------------------------


class _IntegerField:
    """A helper for one integer type: ``int32("x", "doc", "mm", lo, hi)``; the range defaults to
    everything the type holds."""

    def __init__(self, field_type: FieldType) -> None:
        self.field_type = field_type

    def __call__(
        self,
        name: str,
        doc: str = "",
        unit: str = "",
        lo: int | None = None,
        hi: int | None = None,
        *,
        robot_ranges: Mapping[RobotModel, tuple[int, int]] | None = None,
    ) -> FieldSpec:
        return FieldSpec(
            name, self.field_type, unit, lo, hi, doc=doc, robot_ranges=dict(robot_ranges or {})
        )


uint8 = _IntegerField(FieldType.UINT8)
int8 = _IntegerField(FieldType.INT8)
uint16 = _IntegerField(FieldType.UINT16)
int16 = _IntegerField(FieldType.INT16)
uint32 = _IntegerField(FieldType.UINT32)
int32 = _IntegerField(FieldType.INT32)


def choice(
    name: str, enum_type: type[enum.IntEnum], doc: str = "", wire: FieldType = FieldType.UINT8
) -> FieldSpec:
    return FieldSpec(name, wire, enum=enum_type, doc=doc)


def text(name: str, size: int, doc: str) -> FieldSpec:
    return FieldSpec(name, FieldType.TEXT, size=size, doc=doc)


def uint16_array(
    name: str, count: int, doc: str, unit: str = "", lo: int | None = None, hi: int | None = None
) -> FieldSpec:
    return FieldSpec(name, FieldType.UINT16_ARRAY, unit, lo, hi, count=count, doc=doc)


def special(name: str, field_type: FieldType, doc: str, unit: str = "") -> FieldSpec:
    """A field of one of the non-integer types (bitfield, colours, packed IR, IPv4, ...)."""
    return FieldSpec(name, field_type, unit, doc=doc)


def timestamp() -> FieldSpec:
    return uint32("timestamp", "milliseconds since the robot powered on", "ms")


@dataclass(frozen=True)
class Reply:
    """The response a command gets, as written inside the command's row of the table."""

    doc: str
    fields: tuple[FieldSpec, ...] = ()
    min_protocol: tuple[int, int] | None = None
    errata: str = ""
    tells: Tells | None = None


def reply(
    doc: str,
    *fields: FieldSpec,
    min_protocol: tuple[int, int] | None = None,
    errata: str = "",
    tells: Tells | None = None,
) -> Reply:
    return Reply(doc, fields, min_protocol, errata, tells)


def command(
    device: Device,
    number: int,
    name: str,
    doc: str,
    *fields: FieldSpec,
    response: Reply | None = None,
    robots: frozenset[RobotModel] = ALL_ROBOTS,
    min_protocol: tuple[int, int] = (1, 0),
    behaviour: Behaviour = TRUSTED,
    role: Role | None = None,
) -> tuple[PacketSpec, ...]:
    """A command, and its response if it gets one (same device and number, ``_response``)."""
    answer = None
    if response is not None:
        answer = PacketSpec(
            f"{name}_response",
            device,
            number,
            Kind.RESPONSE,
            response.fields,
            robots,
            response.min_protocol or min_protocol,
            response.doc,
            errata=response.errata,
            tells=response.tells,
        )
    asked = PacketSpec(
        name, device, number, Kind.COMMAND, fields, robots, min_protocol, doc,
        response=answer, behaviour=behaviour, role=role,
    )  # fmt: skip
    return (asked,) if answer is None else (asked, answer)


def event(
    device: Device,
    number: int,
    name: str,
    doc: str,
    *fields: FieldSpec,
    robots: frozenset[RobotModel] = ALL_ROBOTS,
    min_protocol: tuple[int, int] = (1, 0),
    role: Role | None = None,
    tells: Tells | None = None,
) -> tuple[PacketSpec, ...]:
    return (
        PacketSpec(
            name, device, number, Kind.EVENT, fields, robots, min_protocol, doc,
            role=role, tells=tells,
        ),
    )  # fmt: skip
