"""``python -m rootlang`` and the ``rootlang`` command.

Ctrl-C while rootlang is still starting up (importing the command line takes ~45 ms) is a clean
stop too, with the same message as later on, never a KeyboardInterrupt traceback.
"""

from __future__ import annotations

import sys

EXIT_INTERRUPTED = 130  # as rootlang.cli says: the shell's code for "stopped by Ctrl-C"


def entry() -> int:
    try:
        from rootlang.cli import main
    except KeyboardInterrupt:
        from rootlang.messages import MESSAGES

        print(MESSAGES["E603"], file=sys.stderr)
        return EXIT_INTERRUPTED
    return main()


if __name__ == "__main__":
    raise SystemExit(entry())
