"""``python -m rootlang`` and the ``rootlang`` command.

Ctrl-C at any moment is a clean stop: "Stopped (Ctrl-C)." and exit code 130, never a
KeyboardInterrupt traceback (docs/architecture.md, the command line). Three phases:

- while the command starts up (this module is the first of rootlang's code to run, as the
  package's ``__init__`` imports nothing), nothing has begun that needs stopping: Ctrl-C says
  so and exits at once (:func:`_stop_now`);
- while the command runs, Ctrl-C is Python's KeyboardInterrupt, or the runtime's own handler,
  so a run stops the robot and `when stopped` runs (:func:`rootlang.cli.main` catches it);
- once the command is done, Ctrl-C changes nothing: what it did stands, and its exit code too.

Before this module runs, a Ctrl-C is Python's own (its start-up, the environment's ``.pth``
files, the installer's launcher line): the process ends as Python ends it (docs/architecture.md).

Python's cycle collector is paused while the command starts up: importing makes tens of
thousands of objects that live as long as the process and no garbage, and the collector would
walk them again and again (and once more at exit) to find none. :func:`rootlang.cli.main`
resumes it once the command's modules are loaded, leaving those objects out of its walks
(``gc.freeze``): about a twentieth of `rootlang sim`'s start-up.
"""

from __future__ import annotations

import gc
import signal
import sys

TYPE_CHECKING = False  # not `typing`'s: importing it would delay the handler below
if TYPE_CHECKING:
    from types import FrameType

EXIT_INTERRUPTED = 130  # as rootlang.cli says: the shell's code for "stopped by Ctrl-C"


def _say_stopped() -> None:
    from rootlang.messages import MESSAGES  # a plain table: no language chosen yet

    print(MESSAGES["E603"], file=sys.stderr, flush=True)


def _stop_now(signum: int, frame: FrameType | None) -> None:
    """Ctrl-C while nothing has begun that needs stopping."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # a second press changes nothing
    _say_stopped()
    raise SystemExit(EXIT_INTERRUPTED)


def _stopping_quietly() -> bool:
    """From here on, Ctrl-C stops the command at once (not on a thread but the main one, where
    Python's handlers can't be set: then Python's own handling stays)."""
    try:
        signal.signal(signal.SIGINT, _stop_now)
    except ValueError:
        return False
    return True


def entry() -> int:
    handled = _stopping_quietly()
    gc.disable()  # until the command's modules are loaded (see above)
    try:
        from rootlang.cli import main

        if handled:  # the command's own handling: main() catches it (and asyncio its own)
            signal.signal(signal.SIGINT, signal.default_int_handler)
        code = main()
        if handled:  # done: a late press changes nothing
            signal.signal(signal.SIGINT, signal.SIG_IGN)
    except KeyboardInterrupt:  # outside main()'s own handling, just before or after it
        if handled:
            signal.signal(signal.SIGINT, signal.SIG_IGN)
        _say_stopped()
        code = EXIT_INTERRUPTED
    return code


def _a_process_of_ours() -> bool:
    """Whether this is a process rootlang started (multiprocessing's spawn imports the
    parent's main module again): its Ctrl-C is its parent's to handle, as before."""
    multiprocessing = sys.modules.get("multiprocessing")
    return multiprocessing is not None and multiprocessing.parent_process() is not None


if not _a_process_of_ours():  # as soon as this module runs (the launcher imports it first)
    _stopping_quietly()

if __name__ == "__main__":
    raise SystemExit(entry())
