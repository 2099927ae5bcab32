"""What the commands that take a program share (`check`, `sim`, `run`): showing its warnings,
turning how a run ended into an exit code, the live view, and a robot-model option (reading
its file is :func:`rootlang.app.files.read_program`). Not a subcommand itself."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING

from rootlang import ast
from rootlang.cli import EXIT_FAILED, EXIT_INTERRUPTED, EXIT_OK
from rootlang.diagnostics import Diagnostic, diagnostic, render
from rootlang.robots import RobotModel
from rootlang.wording.language import Languages

if TYPE_CHECKING:  # the runtime loads only when a program runs
    from rootlang.runtime.scheduler import RunResult
    from rootlang.runtime.trace import TraceEntry


def shown_folder(path: str) -> str:
    """A folder as messages name it: "this folder" for ``.``."""
    return "this folder" if path in (".", "./", ".\\") else path


def show_diagnostics(found: Iterable[Diagnostic], source: str, languages: Languages) -> None:
    """On stderr, each followed by a blank line (stdout stays the program's own output)."""
    for item in found:
        print(render(item, source, languages) + "\n", file=sys.stderr)


def summing_up(command: Languages, programs: Iterable[Languages]) -> Languages:
    """The languages of a command's last line about many programs: the programs' when they
    all speak one, else the command's."""
    spoken = set(programs)
    return spoken.pop() if len(spoken) == 1 else command


def exit_code(
    result: RunResult, source: str, path: str, languages: Languages, *, show_error: bool = True
) -> int:
    """1 when the run stopped with an error (shown unless ``show_error`` is False, as when
    ``--json`` carries it), 130 after Ctrl-C, else 0."""
    if result.error is not None:
        if show_error:
            error = result.error
            print(render(error.in_file(error.file or path), source, languages), file=sys.stderr)
        return EXIT_FAILED
    if result.interrupted:
        print(render(diagnostic("E603"), "", languages), file=sys.stderr)
        return EXIT_INTERRUPTED
    return EXIT_OK


def live_view(
    source: str, program: ast.Program, languages: Languages
) -> Callable[[TraceEntry], None]:
    """A trace listener printing the child's view of a run line by line as it happens (a
    line that comes again and again is counted once the next one comes; the last line says
    how the run ended)."""
    from rootlang.runtime.trace import ChildView

    view = ChildView(source, program, languages)

    def show(entry: TraceEntry) -> None:
        for line in view.add(entry):
            print(line.render(languages), flush=True)

    return show


def robot_model(text: str) -> RobotModel:
    """An argparse ``type`` for a robot model: says which models there are, not a traceback."""
    try:
        return RobotModel.from_name(text)
    except ValueError as error:
        raise argparse.ArgumentTypeError(str(error)) from None
