"""`rootlang sim PATH...`: try programs on a virtual robot, in virtual time (or ``--realtime``).

A PATH is a program (``hello`` for hello.root) or a folder: its programs run one after another.
The world is ``--world W``, else the one the program names in its opening comments
(``# world: arena``), else the default world; ``--robot`` picks another model.

Prints the child's view of the run (see :class:`~rootlang.runtime.trace.ChildView`): each script
as it starts, the commands as written, what was said and printed, errors and how it ended, in
seconds. ``--full-trace`` prints every trace entry instead (every event, in milliseconds);
``--packets`` adds every packet exchanged to that (time, ``->`` to the robot or ``<-`` from it,
the 40 hex digits, the decoded packet); ``--json`` prints a summary object instead.
``--svg``/``--png``/``--html`` write pictures of the run. Exit 0 unless a program has mistakes
or stops with an error (1), or Ctrl-C (130).
"""

from __future__ import annotations

import argparse
import importlib
import json
import sys
from pathlib import Path

from rootlang.cli import EXIT_FAILED, EXIT_INTERRUPTED, EXIT_OK
from rootlang.cli.programs import (
    exit_code,
    live_view,
    read_program,
    robot_model,
    show_diagnostics,
    shown_folder,
)
from rootlang.diagnostics import RootlangError, render, render_all
from rootlang.runtime.scheduler import RunResult
from rootlang.runtime.trace import TraceEntry, ViewLine, child_view
from rootlang.sim.recording import Recording
from rootlang.sim.robot import PacketRecord, VirtualRobot
from rootlang.sim.simulate import simulate
from rootlang.sim.world import World, load_world_option
from rootlang.testing.files import find_programs, world_for

PICTURES = {
    "svg": "write a picture of what the robot drew to F (.svg)",
    "png": "write a picture of what the robot drew to F (.png)",
    "html": "write a page that replays the run in a browser to F (.html)",
}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "paths", metavar="PATH", nargs="+",
        help="the program (.root), or a folder: each program in it, one after another",
    )  # fmt: skip
    parser.add_argument(
        "--world", metavar="W",
        help="the world to run in: a .toml file, or a world's name (the program's worlds/ folder "
        "first, then rootlang's own: arena, line_mat ...; default: the program's `# world:` "
        "line, else an empty arena)",
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
        "--full-trace", action="store_true",
        help="show every step of the run in milliseconds: every sensor event, every packet's "
        "command and answer (for teachers and rootlang's developers)",
    )  # fmt: skip
    parser.add_argument(
        "--packets", action="store_true",
        help="also show every Bluetooth packet sent and received, in the full trace",
    )  # fmt: skip
    for kind, text in PICTURES.items():
        parser.add_argument(f"--{kind}", metavar="F", help=text)
    parser.add_argument(
        "--realtime", action="store_true",
        help="run at the speed of a real robot, showing each step as it happens (Ctrl-C stops it)",
    )  # fmt: skip


def run(args: argparse.Namespace) -> int:
    programs = find_programs(args.paths, any_suffix=True)
    if not programs:
        raise RootlangError.of("E609", paths=", ".join(map(shown_folder, args.paths)))
    if len(programs) == 1:
        return simulate_file(str(programs[0]), args)
    for_one = [f"--{name}" for name in ("json", *PICTURES) if getattr(args, name)]
    if for_one:
        raise RootlangError.of("E617", option=for_one[0], count=len(programs))
    worst = EXIT_OK
    for number, program in enumerate(programs):
        print(("\n" if number else "") + f"== {program} ==", flush=True)
        try:
            code = simulate_file(str(program), args)
        except RootlangError as error:  # one program's mistakes don't stop the others
            print(error.render(), file=sys.stderr)
            code = EXIT_FAILED
        worst = max(worst, code)
        if code == EXIT_INTERRUPTED:
            break
    return worst


def simulate_file(path: str, args: argparse.Namespace) -> int:
    """Run one program as the options say; its exit code."""
    source = ""
    checks = importlib.import_module("rootlang.checks")  # lark loads only here
    try:
        source = read_program(path)
        world = choose_world(Path(path), source, args.world)
        if args.robot is not None:
            world = world.with_model(args.robot)
        checked = checks.load_checked(source, path, world.robot.model)
    except RootlangError as mistakes:
        if not args.json:
            raise
        # Scripts reading --json get JSON even when the program never ran.
        errors = [d.in_file(d.file or path) for d in mistakes.diagnostics]
        print(
            json.dumps(
                {
                    "end": "error",
                    "error": render_all(errors, source),
                    "errors": [d.to_json() for d in errors],
                },
                indent=2,
                ensure_ascii=False,
            )
        )
        return EXIT_FAILED
    show_diagnostics(checked.warnings, source)
    full = args.full_trace or args.packets
    live = args.realtime and not (args.json or full)  # else the view is printed at the end
    robot = VirtualRobot(world, keep_history=shows_history(args))
    result, recording = simulate(
        checked.program, source=source, robot=robot, realtime=args.realtime,
        handle_ctrl_c=True, on_trace=live_view(source, checked.program) if live else None,
    )  # fmt: skip
    story = child_view(result.trace.entries, source, checked.program)
    if args.json:
        print(json.dumps(summary(result, recording, robot, source), indent=2, ensure_ascii=False))
    elif full:
        packets = robot.packet_log if args.packets else []
        print(trace_text(result.trace.entries, packets), end="")
    elif not live:
        print("".join(line.render() + "\n" for line in story), end="")
    for kind in PICTURES:
        target = getattr(args, kind, None)
        if target:
            write_picture(kind, recording, target, program_title(path), story)
    return exit_code(result, source, path, show_error=not args.json)


def shows_history(args: argparse.Namespace) -> bool:
    """Whether the options show the robot's history (its packets, frames, strokes): if not, it
    keeps none (less work on a long run, and its memory stays flat: docs/simulator.md)."""
    return bool(args.json or args.packets or any(getattr(args, kind) for kind in PICTURES))


def program_title(path: str) -> str:
    """A program as a page's title names it: its file name, without the folder."""
    return Path(path).name


def choose_world(program: Path, source: str, option: str | None) -> World:
    """``--world``, else the world named in the program's opening comments, else the default.

    ``--world`` is a file, or a world's name: the ``worlds`` folder next to the program first
    (``--world arena`` for ``worlds/arena.toml``), then rootlang's own worlds."""
    if option is None:
        return world_for(program, source)
    return load_world_option(option, program.parent)


def trace_text(entries: list[TraceEntry], packets: list[PacketRecord]) -> str:
    """The trace, with packet lines (if any) merged in by time (trace lines first)."""
    lines: list[tuple[int, int, str]] = [(e.time_ms, 0, e.render()) for e in entries]
    lines += [(p.t_ms, 1, str(p)) for p in packets]
    lines.sort(key=lambda line: (line[0], line[1]))  # stable: each kind keeps its own order
    return "".join(text + "\n" for _, _, text in lines)


def summary(
    result: RunResult, recording: Recording, robot: VirtualRobot, source: str
) -> dict[str, object]:
    """The ``--json`` object. ``pose`` is the robot's own estimate when the program ended (as
    ``position x``, ``heading`` read it; asked afresh when the run finished or reached its time
    limit), not after the runtime's final Stop and Reset zeroed it; ``world_pose`` and the
    strokes are in world millimetres (as in the pictures)."""
    if result.pose is not None:
        pose = result.pose
        x, y, heading = round(pose.x_mm), round(pose.y_mm), round(pose.heading_degrees, 1)
    else:  # no answer from the robot at all
        x, y, tenths = robot.pose
        heading = tenths / 10
    final = recording.final_frame
    recorded = recording.to_json()
    strokes = [stroke for stroke in recorded["strokes"] if len(stroke["points"]) > 1]
    return {
        "end": result.end,
        "sim_time_s": round(result.sim_time_s, 3),
        "robot": robot.model.value,
        "world": robot.world.name,
        "pose": {"x_mm": x, "y_mm": y, "heading_deg": heading},
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


def write_picture(
    kind: str, recording: Recording, target: str, title: str, story: list[ViewLine]
) -> None:
    """Write a picture with the render package's ``write_<kind>`` (imported only when a picture
    is asked for); the HTML replay also gets the program's name and the child's view."""
    render_module = importlib.import_module("rootlang.sim.render")
    try:
        if kind == "html":
            render_module.write_html(recording, target, title=title, story=story)
        else:
            getattr(render_module, f"write_{kind}")(recording, target)
    except OSError as error:
        raise RootlangError.of("E312", path=target, reason=str(error)) from None
