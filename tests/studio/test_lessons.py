"""The studio's checks never hang on a lock another of its threads holds: their children are
started by the fork server, not forked from the studio (docs/levels.md, "Measured")."""

from __future__ import annotations

import asyncio
import importlib._bootstrap  # (the import system's own module locks)
import shutil
import sys
import threading
from pathlib import Path

import pytest

from rootlang.adventures import BUILT_IN, SOLUTION, find_adventures
from rootlang.app.sandbox import Limits
from rootlang.studio.folder import ClassFolder
from rootlang.studio.lessons import Home
from rootlang.testing import tasks
from rootlang.testing.tasks import CheckJob

NEEDED = "rootlang.sim.world"  # a module each check's child imports (tasks._produce_check)


def test_a_check_never_waits_for_a_lock_another_thread_of_the_studio_holds(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Another thread of the studio is importing a module the check's child needs (its import
    lock held) just as the check starts its child: a child forked then would wait for that lock
    for ever (until the checks' wall-clock limit, shortened here); the fork server's does not."""
    monkeypatch.setattr(tasks, "CHECK_LIMITS", Limits(cpu_seconds=10, wall_seconds=20))
    folder = tmp_path / "home"
    folder.mkdir()
    adventure = next(a for a in find_adventures() if a.name == "01-go-forward")
    shutil.copy(adventure.task.starter, folder)
    solution = (BUILT_IN / adventure.name / SOLUTION).read_text(encoding="utf-8")
    home = Home(ClassFolder(folder))
    job = CheckJob(adventure.task, adventure.task.program, solution)
    spec = sys.modules[NEEDED].__spec__
    assert spec is not None
    held, done = threading.Event(), threading.Event()

    def importing() -> None:  # (as the import system holds a module's lock while importing it)
        with importlib._bootstrap._ModuleLockManager(NEEDED):  # type: ignore[attr-defined]
            held.set()
            done.wait(40)  # (longer than the checks' limit here)

    async def check_twice() -> list[bool]:
        first = await home.check([job], [home.learner])  # (whatever warms the checks: done)
        thread = threading.Thread(target=importing)
        thread.start()
        held.wait(10)
        spec._initializing = True  # type: ignore[attr-defined]  # (the import under way)
        try:
            then = await home.check([job], [home.learner])
        finally:
            spec._initializing = False  # type: ignore[attr-defined]
            done.set()
            thread.join()
        return [first[0].passed, then[0].passed]

    assert asyncio.run(check_twice()) == [True, True]
    assert home.learner.adventures == {"01-go-forward": True}
