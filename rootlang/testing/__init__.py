"""Golden-output tests of programs: ``rootlang test`` and the pytest plugin.

``golden.py`` writes what a run did as text, ``produce.py`` checks and runs one program (through
:mod:`rootlang.app.session`), ``runner.py`` runs many in the sandbox and compares,
``reports.py`` writes the reports, ``pytest_plugin.py`` collects ``.root`` files. Kept light:
the pytest plugin loads it in every pytest run.
"""

from __future__ import annotations

from pathlib import Path

GOLDEN_SUFFIX = ".golden"


def golden_path(program: Path) -> Path:
    """Where a program's golden file lives: next to it, ``.root`` replaced by ``.golden``."""
    return program.with_suffix(GOLDEN_SUFFIX)
