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
or stops with an error (1), or Ctrl-C (130). A run that keeps the computer busy for
``--cpu-limit`` seconds of CPU time stops with a message (E220; ``rootlang.app.sandbox``).
"""

from __future__ import annotations

import argparse
import importlib
import json
import sys
from pathlib import Path
from types import ModuleType
from typing import TYPE_CHECKING

from rootlang import ast
from rootlang.app.files import find_programs, read_program
from rootlang.app.sandbox import Limits, cpu_backstop
from rootlang.cli import EXIT_FAILED, EXIT_INTERRUPTED, EXIT_OK, show_error
from rootlang.cli.numbers import positive_seconds
from rootlang.cli.programs import (
    exit_code,
    live_view,
    robot_model,
    show_diagnostics,
    shown_folder,
)
from rootlang.diagnostics import RootlangError, file_problem
from rootlang.locale.translate import about
from rootlang.runtime.trace import ChildView, TraceEntry, ViewLine, child_view
from rootlang.sim.recording import Recording
from rootlang.sim.robot import PacketRecord, VirtualRobot

if TYPE_CHECKING:  # the session loads only when a program runs
    from rootlang.app.session import Program
    from rootlang.runtime.debugger import Debugger, Go, Pause
    from rootlang.wording.language import Languages

CPU_SECONDS = Limits.cpu_seconds  # as `rootlang test` and the studio: one minute of CPU

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
    parser.add_argument(
        "--watch", metavar="NAME", nargs="+", action="extend", default=[],
        help="add each change of these variables (or parameters) to the run's story, on the line "
        "that changed it (put it after the program: --watch count size)",
    )  # fmt: skip
    parser.add_argument(
        "--until", metavar="SECONDS", type=positive_seconds,
        help="stop the run after SECONDS of it and say where each script is, every value, "
        "the sensors and where the robot is then",
    )  # fmt: skip
    parser.add_argument(
        "--cpu-limit", type=positive_seconds, metavar="SECONDS", default=CPU_SECONDS,
        help="stop a program that keeps the computer busy longer than this, with a message "
        "(CPU time; with --realtime its world's time limit is added; default: %(default)g)",
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
            show_error(error, args.languages)
            code = EXIT_FAILED
        worst = max(worst, code)
        if code == EXIT_INTERRUPTED:
            break
    return worst


def simulate_file(path: str, args: argparse.Namespace) -> int:
    """Run one program as the options say; its exit code."""
    # the session (the runtime, the simulator and lark) loads only here
    session = importlib.import_module("rootlang.app.session")
    try:
        source = read_program(path)
    except RootlangError as unread:
        if not args.json:
            raise
        return _mistakes(session, unread, path, args.languages)
    languages = about(args.languages, source)  # its messages speak the program's language
    try:
        program = session.load(path, source=source, world=args.world, model=args.robot,
                               language=args.language)  # fmt: skip
    except RootlangError as mistakes:
        if args.json:  # scripts reading --json get JSON even when the program never ran
            return _mistakes(session, mistakes, path, languages)
        print(mistakes.render(languages), file=sys.stderr)
        return EXIT_FAILED
    try:
        return _simulate(session, program, path, args, languages)
    except RootlangError as error:
        print(error.render(languages), file=sys.stderr)
        return EXIT_FAILED


def _mistakes(session: ModuleType, error: RootlangError, path: str, languages: Languages) -> int:
    outcome = session.mistakes_json(error, path, languages)
    print(json.dumps(outcome, indent=2, ensure_ascii=False))
    return EXIT_FAILED


def _simulate(
    session: ModuleType, program: Program, path: str, args: argparse.Namespace,
    languages: Languages,
) -> int:  # fmt: skip
    source, checked = program.source, program.checked
    show_diagnostics(program.warnings, source, languages)
    full = args.full_trace or args.packets
    live = args.realtime and not (args.json or full)  # else the view is printed at the end
    robot = VirtualRobot(program.world, keep_history=shows_history(args))
    looking = Looking(args.watch, args.until, languages, live=live)
    paced = robot.world.time_limit if args.realtime else 0.0  # it may compute all along
    with cpu_backstop(args.cpu_limit + paced) as budget:
        result, recording = session.simulate(
            checked, source=source, robot=robot, realtime=args.realtime,
            handle_ctrl_c=True,
            on_trace=live_view(source, checked.program, languages) if live else None,
            debugger=looking.debugger, cpu_budget=budget,
        )  # fmt: skip
    story = looking.story(result.trace.entries, source, checked.program)
    if args.json:
        outcome = session.outcome_json(program, result, languages, recording, robot)
        print(json.dumps(outcome, indent=2, ensure_ascii=False))
    elif full:
        packets = robot.packet_log if args.packets else []
        print(trace_text(result.trace.entries, packets), end="")
    elif not live:
        print("".join(line.render(languages) + "\n" for line in story), end="")
    if looking.paused is not None and not args.json:
        print("\n" + looking.paused_text(), end="")
    for kind in PICTURES:
        target = getattr(args, kind, None)
        if target:
            write_picture(kind, recording, target, program_title(path), story, languages)
    return exit_code(result, source, path, languages, show_error=not args.json)


class Looking:
    """``--watch`` and ``--until``: a debugger that tells the watched names' changes and stops
    the run at a time, to say where everything is then (:mod:`rootlang.runtime.debugger`)."""

    def __init__(
        self, names: list[str], until: float | None, languages: Languages, *, live: bool
    ) -> None:
        from rootlang.runtime.debugger import Debugger, NameWatch  # (with the session)

        self.languages = languages
        self.paused: Pause | None = None
        self.watching = (
            NameWatch(tuple(names), languages, on_line=self._live if live else None)
            if names
            else None
        )
        self.debugger: Debugger | None = None
        if names or until is not None:
            on_pause = self._stop_there if until is not None else None
            self.debugger = Debugger(on_pause, pause_at=until, watching=self.watching)

    def _live(self, line: ViewLine) -> None:
        print(line.render(self.languages), flush=True)

    def _stop_there(self, pause: Pause) -> Go:
        from rootlang.runtime.debugger import Go

        self.paused = pause
        return Go.STOP

    def story(self, entries: list[TraceEntry], source: str, program: ast.Program) -> list[ViewLine]:
        """The child's view with the watched names' changes in it, each where it was found
        among the trace's entries (the last look, at the run's end, too)."""
        watching = self.watching
        if watching is None or self.debugger is None:
            return child_view(entries, source, program, self.languages)
        watching.look(self.debugger)
        changes = (
            []
            if watching.on_line is not None
            else list(zip(watching.after, watching.lines, strict=True))
        )
        view = ChildView(source, program, self.languages)  # (changes printed as they came: none)
        story: list[ViewLine] = []
        for index, entry in enumerate(entries):
            while changes and changes[0][0] <= index:
                story.append(changes.pop(0)[1])
            story += view.add(entry)
        return story + [line for _, line in changes] + view.finish()

    def paused_text(self) -> str:
        """Where every script was when the run stopped, its values and where the robot was."""
        assert self.paused is not None
        lines = self.paused.lines(self.languages)
        return lines[0] + "\n" + "".join(f"  {line}\n" for line in lines[1:])


def shows_history(args: argparse.Namespace) -> bool:
    """Whether the options show the robot's history (its packets, frames, strokes): if not, it
    keeps none (less work on a long run, and its memory stays flat: docs/simulator.md)."""
    return bool(args.json or args.packets or any(getattr(args, kind) for kind in PICTURES))


def program_title(path: str) -> str:
    """A program as a page's title names it: its file name, without the folder."""
    return Path(path).name


def trace_text(entries: list[TraceEntry], packets: list[PacketRecord]) -> str:
    """The trace, with packet lines (if any) merged in by time (trace lines first)."""
    lines: list[tuple[int, int, str]] = [(e.time_ms, 0, e.render()) for e in entries]
    lines += [(p.t_ms, 1, str(p)) for p in packets]
    lines.sort(key=lambda line: (line[0], line[1]))  # stable: each kind keeps its own order
    return "".join(text + "\n" for _, _, text in lines)


def write_picture(
    kind: str,
    recording: Recording,
    target: str,
    title: str,
    story: list[ViewLine],
    languages: Languages,
) -> None:
    """Write a picture with the render package's ``write_<kind>`` (imported only when a picture
    is asked for); the HTML replay also gets the program's name and the child's view."""
    render_module = importlib.import_module("rootlang.sim.render")
    try:
        if kind == "html":
            render_module.write_html(
                recording, target, title=title, story=story, languages=languages
            )
        else:
            getattr(render_module, f"write_{kind}")(recording, target)
    except OSError as error:
        raise RootlangError.of("E312", path=target, reason=file_problem(error)) from None
