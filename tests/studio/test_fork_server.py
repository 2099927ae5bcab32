"""The fork server that starts every run: the parent's main script runs there once, not again
in each run (multiprocessing's own fork server never does that part)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

SCRIPT = """
import os, sys
with open(sys.argv[1], "a") as log:
    log.write(__name__ + "\\n")

if __name__ == "__main__":
    from rootlang.studio.runs import CONTEXT

    for _ in range(3):
        process = CONTEXT.Process(target=os.getpid)
        process.start()
        process.join()
        assert process.exitcode == 0, process.exitcode
"""


def test_a_script_that_starts_runs_is_run_once_by_the_fork_server(tmp_path: Path) -> None:
    script, log = tmp_path / "serve.py", tmp_path / "log.txt"
    script.write_text(SCRIPT, "utf-8")
    subprocess.run([sys.executable, str(script), str(log)], check=True, timeout=60)
    # the script itself, then once as the fork server loads it; never again per process
    assert log.read_text("utf-8").split() == ["__main__", "__mp_main__"]
