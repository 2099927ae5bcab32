"""`rootlang packet`: encode, decode and list the robot's BLE packets (for people and scripts).

    rootlang packet encode set_wheel_speeds left=100 right=100 [--id 3] [--robot Ci3]
    rootlang packet decode 01040000000064000000640000000000000000d1 [--from host] [--json]
    rootlang packet list [--json]

``decode`` without ``--from`` shows every reading of the bytes: a command and its response
share device and command numbers, so the bytes alone may fit both. Readings whose unused
payload bytes are zero come first, and those that are not are dropped when a clean one exists.
With ``--json`` it prints one object when there is one reading, else a list of objects, each
with a ``"from"`` key; with ``--from`` it is always one object.
"""

from __future__ import annotations

import argparse
import json
import string

from rootlang.protocol import (
    PACKETS,
    Packet,
    PacketError,
    UnknownPacket,
    decode,
    encode,
    interpretations,
    parse_field_value,
    spec,
)
from rootlang.protocol.describe import spec_json, spec_summary
from rootlang.robots import RobotModel


def add_arguments(parser: argparse.ArgumentParser) -> None:
    actions = parser.add_subparsers(dest="action", metavar="ACTION", required=True)
    enc = actions.add_parser(
        "encode", help="print a packet's 20 bytes as 40 hex digits",
        description="Print a packet's 20 bytes as 40 hex digits, "
        "like: rootlang packet encode drive_distance distance=100",
    )  # fmt: skip
    enc.add_argument("name", metavar="NAME", help="the packet's name (see `rootlang packet list`)")
    enc.add_argument(
        "fields",
        metavar="FIELD=VALUE",
        nargs="*",
        help="field values, like left=100, state=LEFT, devices=1,4",
    )
    enc.add_argument(
        "--id", dest="packet_id", default="0", metavar="N", help="the packet id, 0-255 (default 0)"
    )
    enc.add_argument("--robot", metavar="MODEL", help="check ranges for RT0, RT1 or Create3")
    dec = actions.add_parser(
        "decode", help="print a packet's name and fields",
        description="Print a packet's name and fields, "
        "like: rootlang packet decode 01080100000064000000000000000000000000d4",
    )  # fmt: skip
    dec.add_argument(
        "hex", metavar="HEX", nargs="+", help="the 20 bytes in hex (spaces and colons are ignored)"
    )
    dec.add_argument(
        "--from",
        dest="sender",
        choices=("robot", "host"),
        help="who sent it (default: show every reading that fits)",
    )
    dec.add_argument("--json", action="store_true", help="print JSON")
    dec.add_argument("--robot", metavar="MODEL", help="check ranges for RT0, RT1 or Create3")
    lst = actions.add_parser(
        "list", help="list every packet in the protocol table",
        description="List every packet in the protocol table: name, kind, device/command, "
        "robots, protocol versions and fields.",
    )  # fmt: skip
    lst.add_argument("--json", action="store_true", help="print JSON")


def run(args: argparse.Namespace) -> int:
    if args.action == "encode":
        return _encode(args)
    if args.action == "decode":
        return _decode(args)
    return _list(args)


def _robot(text: str | None) -> RobotModel | None:
    if text is None:
        return None
    try:
        return RobotModel.from_name(text)
    except ValueError:
        raise PacketError.of(
            "E511", text=text, field="--robot", reason="the models are RT0, RT1 and Create3"
        ) from None


def _encode(args: argparse.Namespace) -> int:
    packet_spec = spec(args.name)
    fields: dict[str, object] = {}
    for item in args.fields:
        name, equals, text = item.partition("=")
        if not equals:
            raise PacketError.of("E512", text=item)
        try:
            field = packet_spec.field(name)
        except KeyError:
            encode(packet_spec.name, {name: text})  # raises E505 with the field names
            raise
        try:
            fields[name] = parse_field_value(field, text)
        except ValueError as error:
            raise PacketError.of("E511", text=text, field=name, reason=str(error)) from None
    try:
        packet_id = int(args.packet_id, 0)
    except ValueError:
        raise PacketError.of("E507", value=repr(args.packet_id)) from None
    print(encode(packet_spec.name, fields, packet_id, _robot(args.robot)).hex())
    return 0


def _read_hex(parts: list[str]) -> bytes:
    text = "".join(parts).replace(":", "").replace(" ", "").lower().removeprefix("0x")
    bad = sorted(set(text) - set(string.hexdigits))
    if bad:
        raise PacketError.of("E508", text=" ".join(parts), reason=f"{bad[0]!r} is not a hex digit")
    if len(text) % 2:
        raise PacketError.of("E508", text=" ".join(parts), reason="an odd number of digits")
    return bytes.fromhex(text)


def _decode(args: argparse.Namespace) -> int:
    data = _read_hex(args.hex)
    robot = _robot(args.robot)
    if args.sender is not None:
        packet = decode(data, args.sender, robot)
        if isinstance(packet, UnknownPacket):
            kind = "command" if args.sender == "host" else "response or event"
            raise PacketError.of("E509", device=packet.device, command=packet.command, kind=kind)
        print(json.dumps(_json(packet)) if args.json else str(packet))
        return 0
    readings = interpretations(data, robot)
    if args.json:
        objects = [_json(packet) for packet in readings]
        print(json.dumps(objects[0] if len(objects) == 1 else objects))
    else:
        for packet in readings:
            print(f"from {packet.spec.sender}: {packet}")
    return 0


def _json(packet: Packet) -> dict[str, object]:
    return {**packet.to_json(), "from": packet.spec.sender}


def _list(args: argparse.Namespace) -> int:
    if args.json:
        print(json.dumps([spec_json(s) for s in PACKETS], indent=1))
    else:
        for packet_spec in PACKETS:
            print(spec_summary(packet_spec))
    return 0
