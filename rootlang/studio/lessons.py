"""Adventures (and a class's tasks) on the studio's page: the list, an adventure's starter
handed out, Check, and which adventures a child has passed.

The same for a class (:class:`rootlang.studio.classroom.Classroom`: each pupil in their own
folder, the class folder's ``_tasks/`` and ``_adventures/``) and for the one-person studio
(:class:`Home`, ``rootlang studio FOLDER``: a child at home works in the folder itself, with
the built-in adventures and the folder's ``_adventures/``). Routes:

- ``GET /api/adventures`` — every adventure, which the child has passed, in the page's words;
- ``POST /api/adventure`` — the child starts one: its starter (and its world) in their folder,
  never over a program of theirs;
- ``POST /api/check`` — their text against its task (an adventure's: with a hint).

Checks run in child processes under ``rootlang test``'s limits (:mod:`rootlang.testing.tasks`),
in a thread so the server serves on, at most one check per core at once. Their children are
started by the fork server the runs' are (:data:`rootlang.studio.runs.CONTEXT`, warm: the
checks' modules loaded), never forked from the studio itself: the studio has threads, and a
child forked while another of them held a lock (an import under way in it) waited for that
lock for ever, until the checks' wall-clock limit (docs/levels.md, "Measured"). Which adventures a
child has passed is kept in their folder (:data:`PROGRESS_FILE`): once passed, it stays passed.
"""

from __future__ import annotations

import asyncio
import contextlib
import json
import os
import shutil
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, TypeVar

from aiohttp import web

from rootlang.adventures import Adventure, find_adventures, with_hint
from rootlang.adventures.picture import goal_svg
from rootlang.blocks.drawings import data_uri
from rootlang.diagnostics import RootlangError
from rootlang.studio import messages as m
from rootlang.studio.conversions import text_field
from rootlang.studio.folder import ClassFolder
from rootlang.studio.pages import json_body, languages_of
from rootlang.studio.runs import CONTEXT
from rootlang.testing.tasks import Checked, CheckJob, Task, check_programs, find_tasks
from rootlang.wording.language import Languages

TASKS = "_tasks"
ADVENTURES = "_adventures"
PROGRESS_FILE = ".adventures.json"  # in a child's folder: the adventures they have passed
WORLDS = "worlds"
Result = TypeVar("Result")


@dataclass
class Learner:
    """A child who checks: their folder, and the adventures they have checked (passed at
    least once), as their folder keeps them."""

    name: str
    folder: ClassFolder
    adventures: dict[str, bool] = field(default_factory=dict)  # checked: passed at least once

    def load_progress(self) -> None:
        """The adventures passed, as their folder keeps them (nothing when it can't be read)."""
        with contextlib.suppress(OSError, ValueError):
            kept = json.loads((self.folder.root / PROGRESS_FILE).read_text(encoding="utf-8"))
            if isinstance(kept, dict):
                self.adventures = {str(k): v for k, v in kept.items() if isinstance(v, bool)}

    def checked_adventure(self, name: str, passed: bool) -> None:
        """A check of an adventure: kept (once passed, it stays passed) in their folder."""
        self.adventures[name] = passed or self.adventures.get(name, False)
        with contextlib.suppress(OSError):
            (self.folder.root / PROGRESS_FILE).write_text(
                json.dumps(self.adventures, ensure_ascii=False, sort_keys=True), encoding="utf-8"
            )


class Lessons:
    """The tasks and adventures of the folder ``root``, handed out and checked. Who asks is
    :meth:`learner_of`'s to say (a class: the pupil of the page's cookie)."""

    def __init__(self, root: Path, *, with_tasks: bool) -> None:
        self.root = root
        self.with_tasks = with_tasks  # (a class's: its _tasks/)
        self._checks: asyncio.Semaphore | None = None

    def learner_of(self, request: web.Request) -> Learner:
        """The child asking; refused (401, or E845 for a change in a locked class) if none."""
        raise NotImplementedError

    def tasks(self) -> list[Task]:
        return find_tasks(self.root / TASKS) if self.with_tasks else []

    def adventures(self) -> list[Adventure]:
        return find_adventures(self.root / ADVENTURES)

    def task_for(self, program: str) -> Task | None:
        """The task, or the adventure's task, whose program is ``program``."""
        tasks = [*self.tasks(), *(adventure.task for adventure in self.adventures())]
        return next((task for task in tasks if task.program == program), None)

    def hand_out_adventure(self, learner: Learner, name: str) -> Adventure:
        """The adventure's starter (and its world) in the child's folder, unless they have a
        program of its name already; E851 for no adventure of that name."""
        adventure = next((a for a in self.adventures() if a.name == name), None)
        if adventure is None:
            raise RootlangError.of("E851", name=str(name)[:80])
        target = learner.folder.root / adventure.task.program
        if not target.exists():
            shutil.copyfile(adventure.task.starter, target)
        world = adventure.task.world
        if world is not None and world.parent == adventure.task.folder:
            (learner.folder.root / WORLDS).mkdir(exist_ok=True)
            shutil.copyfile(world, learner.folder.root / WORLDS / world.name)
        return adventure

    async def check(self, jobs: Sequence[CheckJob], learners: Sequence[Learner]) -> list[Checked]:
        """Check each job, one child process per core at once, an adventure's with its hint
        and kept in its learner's progress (what each check said is kept as data: each page
        shows it in its own language)."""
        if self._checks is None:
            self._checks = asyncio.Semaphore(os.cpu_count() or 1)
        adventures = {a.task.folder: a for a in self.adventures()}

        def checked() -> list[Checked]:  # (in a thread: a hint reads both runs and the text)
            results = check_programs(jobs, os.cpu_count(), CONTEXT)
            return [
                with_hint(adventures[job.task.folder], job, result)
                if job.task.folder in adventures else result
                for job, result in zip(jobs, results, strict=True)
            ]  # fmt: skip

        async with self._checks:
            results = await in_thread(checked)
        for job, learner, result in zip(jobs, learners, results, strict=True):
            if job.task.folder in adventures:
                learner.checked_adventure(job.task.name, result.passed)
            self.checked(learner, job, result)
        return results

    def checked(self, learner: Learner, job: CheckJob, result: Checked) -> None:
        """A check's result, told (a class keeps it for the teacher's page)."""

    def add_routes(self, app: web.Application) -> None:
        app[LESSONS] = self
        app.router.add_post("/api/check", _check)
        app.router.add_get("/api/adventures", _adventures)
        app.router.add_post("/api/adventure", _adventure)


class Home(Lessons):
    """The one-person studio's adventures: one child, working in the studio's folder, their
    progress kept there."""

    def __init__(self, folder: ClassFolder) -> None:
        super().__init__(folder.root, with_tasks=False)
        self.learner = Learner("", folder)
        self.learner.load_progress()

    def learner_of(self, request: web.Request) -> Learner:
        return self.learner


LESSONS = web.AppKey("lessons", Lessons)


def task_json(task: Task) -> m.TaskJson:
    check: Any = task.check  # (one of tasks.CHECKS, as load_task made sure)
    return {"name": task.name, "program": task.program, "title": task.title, "check": check}


def checked_json(checked: Checked, languages: Languages) -> m.CheckedJson:
    return {"passed": checked.passed, "said": checked.said.shown(languages),
            "first_difference": checked.result.first_difference}  # fmt: skip


async def in_thread(work: Callable[[], Result]) -> Result:
    """``work`` in a thread, off the event loop."""
    return await asyncio.get_running_loop().run_in_executor(None, work)


async def _check(request: web.Request) -> web.StreamResponse:
    """The child's Check: their text (as it is in the page, saved or not) against the task
    whose program it is."""
    lessons = request.app[LESSONS]
    learner = lessons.learner_of(request)
    data = await json_body(request)
    name, text = text_field(data, "name"), text_field(data, "text")
    learner.folder.path_of(name)
    task = lessons.task_for(name)
    if task is None:
        raise RootlangError.of("E848", name=name)
    job = CheckJob(task, f"{learner.name}/{name}" if learner.name else name, text)
    languages = languages_of(request)
    checked = (await lessons.check([job], [learner]))[0]
    reply: m.CheckReply = {"task": task_json(task), **checked_json(checked, languages)}
    return web.json_response(reply)


def adventure_json(adventure: Adventure, learner: Learner, language: str) -> m.AdventureJson:
    world = adventure.task.world
    return {
        "name": adventure.name, "program": adventure.task.program, "level": adventure.level,
        "title": adventure.title(language), "goal": adventure.goal(language),
        "picture": data_uri(goal_svg(adventure.wanted, adventure.goal(language))),
        "world": "" if world is None else world.stem,
        "passed": learner.adventures.get(adventure.name, False),
    }  # fmt: skip


async def _adventures(request: web.Request) -> web.StreamResponse:
    """Every adventure, for the child asking (which they have passed), in their words."""
    lessons = request.app[LESSONS]
    learner = lessons.learner_of(request)
    language = languages_of(request).messages
    reply: m.AdventuresReply = {
        "adventures": [adventure_json(a, learner, language) for a in lessons.adventures()]
    }
    return web.json_response(reply)


async def _adventure(request: web.Request) -> web.StreamResponse:
    """The child starts an adventure: its starter in their folder (never over their work)."""
    lessons = request.app[LESSONS]
    learner = lessons.learner_of(request)
    name = text_field(await json_body(request), "name")
    adventure = await in_thread(lambda: lessons.hand_out_adventure(learner, name))
    reply: m.AdventureReply = {"program": adventure.task.program}
    return web.json_response(reply)
