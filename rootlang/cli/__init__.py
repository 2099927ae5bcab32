"""The `rootlang` command.

Each subcommand is a module of this package with ``add_arguments(parser)`` and
``run(args) -> int``; its one-line summary lives in ``COMMANDS`` so ``--help`` lists every
command without importing any. Only the chosen subcommand's module is imported, so
``rootlang check`` starts fast and does not load the simulator or bleak.

Every failure a person can cause ends as rendered diagnostics and an exit code, never as a
Python traceback (unless ``--debug``). Ctrl-C exits with 130 after the subcommand has cleaned up.

The languages messages are shown in are decided once, here, from ``--language`` and the system
locale (``args.languages``, a :class:`~rootlang.wording.language.Languages`); a command that
reads a program adds the program's own (:func:`rootlang.locale.translate.about`) and hands them
to whatever it shows.
"""

from __future__ import annotations

import argparse
import gc
import importlib
import os
import sys
from collections.abc import Sequence
from types import ModuleType

from rootlang import __version__
from rootlang.diagnostics import RootlangError, diagnostic, render
from rootlang.locale.keywords import LANGUAGES
from rootlang.wording.language import Languages

# name on the command line -> (module in rootlang.cli, one-line summary), in the order a
# newcomer meets them (`rootlang --help` lists them so)
COMMANDS: dict[str, tuple[str, str]] = {
    "new": ("new", "write a starter program to change and try"),
    "sim": ("sim", "try a program in the simulator"),
    "check": ("check", "find mistakes in programs without running them"),
    "run": ("run", "run a program on a robot over Bluetooth"),
    "scan": ("scan", "list the robots in Bluetooth range"),
    "robot": ("robot", "show a robot's details, or give it a new name"),
    "robots": ("robots", "name a class set of robots Root-01, Root-02, ... by touching each"),
    "studio": ("studio", "write, see and run programs as blocks or text, in the browser"),
    "test": ("test", "run programs in the simulator and compare with their golden output"),
    "format": ("format", "rewrite programs in canonical form, comments kept"),
    "blocks": ("blocks", "show a program as Blockly blocks, or blocks as a program"),
    "packet": ("packet", "encode, decode and list the robot's BLE packets"),
    "virtual-robot": ("virtual_robot", "serve a simulated robot over a real Bluetooth stack"),
    "translate": ("translate", "rewrite a program's keywords in another language"),
}

FIRST_STEPS = """\
first steps:
  rootlang new hello                        write hello.root, a program to start from
  rootlang sim hello.root --svg hello.svg   try it in the simulator; hello.svg shows the drawing
  rootlang run hello.root                   run it on a robot (switch the robot on first)

Run `rootlang COMMAND --help` to learn more about a command."""

DEBUG_HELP = "show Python tracebacks (for rootlang's developers)"
LANGUAGE_HELP = "the language programs are written in and messages shown in: " + ", ".join(
    LANGUAGES
)
EXIT_OK, EXIT_FAILED, EXIT_USAGE, EXIT_INTERRUPTED = 0, 1, 2, 130


def build_parser(command: str | None = None) -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="rootlang",
        description="Write programs for iRobot's Root and Create 3 robots,\n"
        "try them in a simulator, and run them on a robot.",
        epilog=FIRST_STEPS,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("--version", action="version", version=f"rootlang {__version__}")
    parser.add_argument("--debug", action="store_true", help=DEBUG_HELP)
    parser.add_argument("--language", choices=LANGUAGES, help=LANGUAGE_HELP)
    # --debug is accepted after the subcommand too; SUPPRESS keeps it from resetting the flag.
    common = argparse.ArgumentParser(add_help=False)
    common.add_argument("--debug", action="store_true", default=argparse.SUPPRESS, help=DEBUG_HELP)
    common.add_argument(
        "--language", choices=LANGUAGES, default=argparse.SUPPRESS, help=LANGUAGE_HELP
    )
    subparsers = parser.add_subparsers(dest="command", metavar="COMMAND", title="commands")
    for name, (module_name, summary) in COMMANDS.items():
        if name != command:  # only listed in --help: it never parses these arguments
            subparsers.add_parser(name, help=summary, add_help=False)
            continue
        sub = subparsers.add_parser(
            name, help=summary, description=summary[0].upper() + summary[1:], parents=[common]
        )
        _command_module(module_name).add_arguments(sub)
    return parser


def _loaded() -> None:
    """The command's modules are loaded. If the cycle collector was paused for start-up (as
    the `rootlang` process does, see rootlang.__main__), what start-up made is left out of its
    walks from now on (it lives as long as the process), and it resumes."""
    if not gc.isenabled():
        gc.freeze()
        gc.enable()


def _command_module(module_name: str) -> ModuleType:
    return importlib.import_module(f"rootlang.cli.{module_name}")


def _chosen_command(argv: Sequence[str]) -> str | None:
    """The first word that is a command (an option's value may come before it: `rootlang
    --language nl sim hallo.root`)."""
    return next((arg for arg in argv if arg in COMMANDS), None)


def show_error(error: RootlangError, languages: Languages) -> None:
    """A command's mistake on stderr, told in the language of the program it is about."""
    from rootlang.locale.translate import about  # (loaded only when there is one to tell)

    print(error.render(about(languages, error.source)), file=sys.stderr)


def main(argv: Sequence[str] | None = None) -> int:
    try:
        return _main(argv)
    except KeyboardInterrupt:  # at any moment, also while starting up (imports, parsing)
        print(render(diagnostic("E603"), "", Languages.of_command()), file=sys.stderr)
        return EXIT_INTERRUPTED


def _main(argv: Sequence[str] | None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    command = _chosen_command(argv)
    parser = build_parser(command)  # imports the command
    _loaded()
    args = parser.parse_args(argv)
    if args.command is None:
        parser.print_help()
        return EXIT_USAGE
    languages = args.languages = Languages.of_command(args.language)
    if args.debug:
        import logging

        logging.basicConfig(level=logging.DEBUG, format="%(name)s: %(message)s")
    try:
        result: int = _command_module(COMMANDS[args.command][0]).run(args)
        return result
    except RootlangError as error:
        show_error(error, languages)
        return EXIT_FAILED
    except BrokenPipeError:  # `rootlang packet list | head`: the reader left; that is fine
        sys.stdout = open(os.devnull, "w")  # noqa: SIM115 - stays open until the process exits
        return EXIT_OK
    except Exception as error:  # the last line of defence: students never see a traceback
        if args.debug:
            raise
        failed = diagnostic("E699", error=f"{type(error).__name__}: {error}")
        print(render(failed, "", languages), file=sys.stderr)
        return EXIT_FAILED
