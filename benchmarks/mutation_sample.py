"""Mutation testing on a seeded sample (cosmic-ray 8.7; slow, so not in CI).

A full cosmic-ray session of ``units.py`` alone is ~850 mutants, hours on two cores; this keeps
a seeded random sample of a session's mutants and marks the rest skipped, so a run fits in
minutes and is the same sample every time. How to rerun (in a copy of the repo, so the mutated
files never touch your work tree; the project's venv runs the tests, cosmic-ray has its own)::

    git archive HEAD | tar -x -C /tmp/mut && cd /tmp/mut
    python3 -m venv /tmp/crvenv && /tmp/crvenv/bin/pip install cosmic-ray==8.7.0
    /tmp/crvenv/bin/cosmic-ray init benchmarks/mutation/units.toml units.sqlite
    python3 benchmarks/mutation_sample.py units.sqlite 100
    PATH=$REPO/.venv/bin:$PATH nice /tmp/crvenv/bin/cosmic-ray exec \
        benchmarks/mutation/units.toml units.sqlite
    /tmp/crvenv/bin/cr-report units.sqlite | tail -3

The configs in benchmarks/mutation/ name the tests each module's mutants run against
(``-x``: the first failing test kills a mutant); ``python`` there must be the project's venv
(hence the PATH), and ``PYTHONPATH=.`` makes it import the mutated copy.
"""

from __future__ import annotations

import random
import sqlite3
import sys


def keep_sample(session: str, size: int, seed: int = 16) -> tuple[int, int]:
    """Mark all but ``size`` seeded-random pending mutants of ``session`` as skipped."""
    with sqlite3.connect(session) as db:
        done = {row[0] for row in db.execute("SELECT job_id FROM work_results")}
        pending = sorted(row[0] for row in db.execute("SELECT job_id FROM work_items"))
        pending = [job for job in pending if job not in done]
        kept = set(random.Random(seed).sample(pending, min(size, len(pending))))
        db.executemany(
            "INSERT INTO work_results (worker_outcome, output, test_outcome, diff, job_id) "
            "VALUES ('SKIPPED', 'not in the sample', NULL, '', ?)",
            [(job,) for job in pending if job not in kept],
        )
    return len(kept), len(pending)


if __name__ == "__main__":
    kept, total = keep_sample(sys.argv[1], int(sys.argv[2]))
    print(f"kept {kept} of {total} pending mutants")
