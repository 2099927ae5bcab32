"""What the fork server does once, before it forks any run, conversion worker or check: every
process it starts then begins with the runtime, the simulator and the blocks loaded and warm.

It also runs the parent's main script, once. Each process multiprocessing starts runs the
parent's main script again (as ``__mp_main__``) unless it already has it; the fork server is
meant to run it once for all of them, but CPython's looks for the script under a key its own
preparation data never has (``main_path`` against ``init_main_from_path``, in every version to
3.13), so each run started from a script (a benchmark, a teacher's script that serves the
studio) imported it again: a quarter of a second of CPU a run. The parent names its script in
the environment (:data:`rootlang.studio.runs.MAIN_SCRIPT`) before the fork server starts.
"""

from __future__ import annotations

import json
import os
import sys
from multiprocessing import process, spawn

from rootlang.studio import conversions, worker
from rootlang.studio.runs import MAIN_SCRIPT
from rootlang.testing import tasks


def _run_main_script_once() -> None:
    script = json.loads(os.environ.pop(MAIN_SCRIPT, "null"))
    if script is None:
        return
    sys.argv = script["argv"]  # (as each process gets them: the script may read them)
    process.current_process()._inheriting = True  # type: ignore[attr-defined]
    try:
        spawn.import_main_path(script["path"])  # as the fork server does when it finds it
    except Exception:  # it can't run here: then each process runs it, as before
        pass
    finally:
        del process.current_process()._inheriting  # type: ignore[attr-defined]


_run_main_script_once()
conversions.warm_up()
worker.warm_up()
tasks.warm_up()  # (the adventures' and tasks' checks)
