"""The table described for people and scripts: JSON rows, one-line summaries, a Markdown reference.

``python -m rootlang.protocol.describe > docs/protocol-packets.md`` regenerates the reference
page; a test checks it matches the table.
"""

from __future__ import annotations

from rootlang.protocol.fields import FieldSpec
from rootlang.protocol.specs import PacketSpec
from rootlang.protocol.table import PACKETS
from rootlang.robots import RobotModel


def version_text(version: tuple[int, int]) -> str:
    return f"{version[0]}.{version[1]}"


def robots_text(robots: frozenset[RobotModel]) -> str:
    return ", ".join(model.value for model in RobotModel if model in robots)


def field_json(field: FieldSpec) -> dict[str, object]:
    row: dict[str, object] = {"name": field.name, "type": field.type_name, "unit": field.unit}
    if field.range is not None:
        row["minimum"], row["maximum"] = field.range
    if field.enum is not None:
        row["choices"] = {member.name: int(member) for member in field.enum}
    if field.robot_ranges:
        row["robot_ranges"] = {m.value: list(r) for m, r in field.robot_ranges.items()}
    row["doc"] = field.doc
    return row


def spec_json(spec: PacketSpec) -> dict[str, object]:
    return {
        "name": spec.name,
        "kind": spec.kind.value,
        "device": int(spec.device),
        "device_name": spec.device.name.lower(),
        "command": spec.command,
        "id": spec.id_kind,
        "robots": [m.value for m in RobotModel if m in spec.robots],
        "min_protocol": version_text(spec.min_protocol),
        "response": spec.response.name if spec.response else None,
        "fields": [field_json(f) for f in spec.fields],
        "doc": spec.doc,
        "errata": spec.errata,
    }


def field_summary(field: FieldSpec) -> str:
    unit = f" {field.unit}" if field.unit else ""
    return f"{field.name}:{field.type_name}{unit}"


def spec_summary(spec: PacketSpec) -> str:
    """One line: ``drive_distance  command  1/8  RT0,RT1,Ci3 >=1.0  distance:int32 mm``."""
    fields = " ".join(field_summary(f) for f in spec.fields) or "-"
    where = f"{int(spec.device)}/{spec.command}"
    robots = robots_text(spec.robots).replace(" ", "")
    return (
        f"{spec.name:<32} {spec.kind.value:<8} {where:>6}  {robots:<11} "
        f">={version_text(spec.min_protocol)}  {fields}"
    )


def _range_text(field: FieldSpec) -> str:
    text = field.describe_range()
    for model, (lo, hi) in field.robot_ranges.items():
        text += f" ({model.display_name}: {lo} to {hi})"
    return text


def markdown_reference() -> str:
    """The whole table as Markdown, device by device."""
    lines = [
        "# Packet reference",
        "",
        "Generated from `rootlang/protocol/table.py` by "
        "`python -m rootlang.protocol.describe > docs/protocol-packets.md`; do not edit by hand.",
        "",
    ]
    device = None
    for spec in PACKETS:
        if spec.device != device:
            device = spec.device
            title = device.name.replace("_", " ").title()
            lines += [f"## Device {int(device)}: {title}", ""]
        lines += [
            f"### `{spec.name}` ({spec.kind.value}, {int(spec.device)}/{spec.command}, "
            f"id {spec.id_kind})",
            "",
            spec.doc,
            "",
            f"Robots: {robots_text(spec.robots)}; protocol {version_text(spec.min_protocol)} "
            "or newer." + (f" Response: `{spec.response.name}`." if spec.response else ""),
            "",
        ]
        if spec.errata:
            lines += [f"Erratum: {spec.errata}", ""]
        if spec.behaviour.described():
            lines += [f"Behaviour: {spec.behaviour.described()}.", ""]
        if spec.fields:
            lines += ["| field | type | unit | allowed | meaning |", "|---|---|---|---|---|"]
            lines += [
                f"| `{f.name}` | {f.type_name} | {f.unit} | {_range_text(f)} | {f.doc} |"
                for f in spec.fields
            ]
            lines.append("")
    return "\n".join(lines)


if __name__ == "__main__":
    print(markdown_reference())
