"""``python -m rootlang`` and the ``rootlang`` command.

Ctrl-C while rootlang is still starting up (importing the command line takes ~45 ms) is a clean
stop too, with the same message as later on, never a KeyboardInterrupt traceback.

Python's cycle collector is paused while the command starts up: importing makes tens of
thousands of objects that live as long as the process and no garbage, and the collector would
walk them again and again (and once more at exit) to find none. :func:`rootlang.cli.main`
resumes it once the command's modules are loaded, leaving those objects out of its walks
(``gc.freeze``): about a twentieth of `rootlang sim`'s start-up.
"""

from __future__ import annotations

import gc
import sys

EXIT_INTERRUPTED = 130  # as rootlang.cli says: the shell's code for "stopped by Ctrl-C"


def entry() -> int:
    gc.disable()  # until the command's modules are loaded (see above)
    try:
        from rootlang.cli import main
    except KeyboardInterrupt:
        from rootlang.messages import MESSAGES

        print(MESSAGES["E603"], file=sys.stderr)
        return EXIT_INTERRUPTED
    return main()


if __name__ == "__main__":
    raise SystemExit(entry())
