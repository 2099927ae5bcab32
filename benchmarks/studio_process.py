"""The studio as a teacher starts it, for the benchmarks: ``rootlang studio FOLDER`` in a
separate process on a free port, its address read from what it prints."""

from __future__ import annotations

import re
import subprocess
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path


@contextmanager
def served_studio(folder: Path | str, *options: str) -> Iterator[tuple[str, subprocess.Popen[str]]]:
    """The studio serving ``folder`` (with ``options``, e.g. ``--transport virtual``): its
    address (``http://127.0.0.1:PORT``) and its process (for its CPU time), ended when the
    block ends."""
    command = [sys.executable, "-m", "rootlang", "studio", str(folder), "--port", "0"]
    process = subprocess.Popen(
        [*command, "--no-browser", *options], stdout=subprocess.PIPE, text=True, encoding="utf-8"
    )
    try:
        assert process.stdout is not None
        for line in process.stdout:
            found = re.search(r"https?://[\w.:\[\]-]+", line)
            if found:
                yield found.group(0).rstrip("/"), process
                return
        raise SystemExit("the studio did not start")
    finally:
        process.terminate()
        process.wait(10)
