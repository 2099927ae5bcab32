"""`rootlang sim FILE`: try a program on a virtual robot, in virtual time (or ``--realtime``).

The world is ``--world W``, else the one the program names in its opening comments
(``# world: worlds/arena.toml``), else the default world; ``--robot`` picks another model.
Prints the run's trace; ``--packets`` interleaves every packet exchanged (time, ``->`` to the
robot or ``<-`` from it, the 40 hex digits, the decoded packet); ``--json`` prints a summary
object instead. ``--svg``/``--png``/``--html`` write pictures of the run. Exit 0 unless the
program has mistakes or stops with an error (1), or Ctrl-C (130).
"""

from __future__ import annotations

import argparse
import importlib
import json
from pathlib import Path

from rootlang.cli import EXIT_FAILED
from rootlang.cli.programs import exit_code, read_program, robot_model, show_diagnostics
from rootlang.diagnostics import RootlangError, render, render_all
from rootlang.runtime.scheduler import RunResult
from rootlang.runtime.trace import TraceEntry
from rootlang.sim.recording import Recording
from rootlang.sim.robot import PacketRecord, VirtualRobot
from rootlang.sim.simulate import simulate
from rootlang.sim.world import World
from rootlang.testing.files import world_for

PICTURES = {
    "svg": "write a picture of what the robot drew to F (.svg)",
    "png": "write a picture of what the robot drew to F (.png)",
    "html": "write a page that replays the run in a browser to F (.html)",
}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("file", metavar="FILE", help="the program (.root)")
    parser.add_argument(
        "--world", metavar="W",
        help="the world to run in: a .toml file, or a name from the program's worlds/ folder "
        "(default: the program's `# world:` line, else an empty arena)",
    )  # fmt: skip
    parser.add_argument(
        "--robot", type=robot_model, metavar="MODEL",
        help="the robot model: RT0, RT1 or Create3 (default: the world's)",
    )  # fmt: skip
    parser.add_argument(
        "--json", action="store_true",
        help="print how the run ended, where the robot is and what it drew, as JSON, "
        "instead of the trace",
    )  # fmt: skip
    parser.add_argument(
        "--packets", action="store_true",
        help="also show every Bluetooth packet sent and received, in the trace",
    )  # fmt: skip
    for kind, text in PICTURES.items():
        parser.add_argument(f"--{kind}", metavar="F", help=text)
    parser.add_argument(
        "--realtime", action="store_true",
        help="run at the speed of a real robot (Ctrl-C stops it)",
    )  # fmt: skip


def run(args: argparse.Namespace) -> int:
    source = read_program(args.file)
    world = choose_world(Path(args.file), source, args.world)
    if args.robot is not None:
        world = world.with_model(args.robot)
    checks = importlib.import_module("rootlang.checks")  # lark loads only here
    try:
        checked = checks.load_checked(source, args.file, world.robot.model)
    except RootlangError as mistakes:
        if not args.json:
            raise
        # Scripts reading --json get JSON even when the program never ran.
        errors = [d.in_file(d.file or args.file) for d in mistakes.diagnostics]
        print(json.dumps({
            "end": "error",
            "error": render_all(errors, source),
            "errors": [d.to_json() for d in errors],
        }, indent=2, ensure_ascii=False))
        return EXIT_FAILED
    show_diagnostics(checked.warnings, source)
    as_json, realtime = args.json, args.realtime
    robot = VirtualRobot(world)
    live = _print_live if realtime and not as_json else None  # else the trace shows the prints
    result, recording = simulate(
        checked.program, source=source, robot=robot, realtime=realtime, on_print=live,
        handle_ctrl_c=True,
    )  # fmt: skip
    if as_json:
        print(json.dumps(summary(result, recording, robot, source), indent=2, ensure_ascii=False))
    else:
        packets = robot.packet_log if args.packets else []
        print(trace_text(result.trace.entries, packets), end="")
    for kind in PICTURES:
        target = getattr(args, kind, None)
        if target:
            write_picture(kind, recording, target)
    return exit_code(result, source, args.file, show_error=not as_json)


def _print_live(text: str) -> None:
    print(text, flush=True)


def choose_world(program: Path, source: str, option: str | None) -> World:
    """``--world``, else the world named in the program's opening comments, else the default.

    ``--world`` is a file, or the name of one in the ``worlds`` folder next to the program
    (``--world arena`` for ``worlds/arena.toml``)."""
    return world_for(program, source, _world_file(program, option) if option else None)


def _world_file(program: Path, option: str) -> Path:
    given = Path(option)
    if given.exists() or given.suffix or len(given.parts) > 1:
        return given  # a path (loading it says if it is missing)
    folder = program.parent / "worlds"
    candidate = folder / f"{option}.toml"
    if candidate.is_file():
        return candidate
    known = sorted(p.stem for p in folder.glob("*.toml")) if folder.is_dir() else []
    raise RootlangError.of("E306", name=option, known=", ".join(known) or "none")


def trace_text(entries: list[TraceEntry], packets: list[PacketRecord]) -> str:
    """The trace, with packet lines (if any) merged in by time (trace lines first)."""
    lines: list[tuple[int, int, str]] = [(e.time_ms, 0, e.render()) for e in entries]
    lines += [(p.t_ms, 1, str(p)) for p in packets]
    lines.sort(key=lambda line: (line[0], line[1]))  # stable: each kind keeps its own order
    return "".join(text + "\n" for _, _, text in lines)


def summary(
    result: RunResult, recording: Recording, robot: VirtualRobot, source: str
) -> dict[str, object]:
    """The ``--json`` object. ``pose`` is the robot's own estimate (as ``position x``, ``heading``
    read it); ``world_pose`` and the strokes are in world millimetres (as in the pictures)."""
    x, y, heading = robot.pose
    final = recording.final_frame
    recorded = recording.to_json()
    strokes = [stroke for stroke in recorded["strokes"] if len(stroke["points"]) > 1]
    return {
        "end": result.end,
        "sim_time_s": round(result.sim_time_s, 3),
        "robot": robot.model.value,
        "world": robot.world.name,
        "pose": {"x_mm": x, "y_mm": y, "heading_deg": heading / 10},
        "world_pose": None
        if final is None
        else {"x_mm": final.x_mm, "y_mm": final.y_mm, "heading_deg": final.heading_deg},
        "strokes": strokes,
        "said": [s.text for s in recording.said],
        "notes": recorded["notes"],
        "lights": recorded["lights"],
        "printed": list(result.printed),
        "error": None if result.error is None else render(result.error, source),
    }


def write_picture(kind: str, recording: Recording, target: str) -> None:
    """Write a picture with the render package's ``write_<kind>(recording, path)`` (imported
    only when a picture is asked for)."""
    writer = getattr(importlib.import_module("rootlang.sim.render"), f"write_{kind}")
    try:
        writer(recording, target)
    except OSError as error:
        raise RootlangError.of("E312", path=target, reason=str(error)) from None
