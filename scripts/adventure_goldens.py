#!/usr/bin/env python3
"""The built-in adventures' golden files, from their model solutions (``solution.root``), as
``rootlang test --update`` writes a task's: the solution run in the adventure's world under
the adventure's own program name. Run it after changing a solution or a world:

    .venv/bin/python scripts/adventure_goldens.py
"""

from __future__ import annotations

import shutil
import tempfile
from pathlib import Path

from rootlang.adventures import BUILT_IN, SOLUTION, find_adventures
from rootlang.sim.world import default_world, load_world
from rootlang.testing.produce import produce


def main() -> None:
    for folder in sorted(BUILT_IN.iterdir()):
        golden = folder / (folder.name + ".golden")
        if not golden.exists():
            golden.write_text("end: finished at 0.000 s\n", encoding="utf-8")  # (to load it)
    for adventure in find_adventures():
        task = adventure.task
        world = default_world() if task.world is None else load_world(task.world)
        with tempfile.TemporaryDirectory() as scratch:
            program = Path(scratch) / task.program
            shutil.copyfile(task.folder / SOLUTION, program)
            produced = produce(program, world=world)
        task.golden.write_text(produced.text, encoding="utf-8")
        print(f"{task.golden.name}: {produced.end}")


if __name__ == "__main__":
    main()
