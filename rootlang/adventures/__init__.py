"""Adventures: lessons that lead a class from a first move to procedures, over the three levels.

An adventure is a task (:mod:`rootlang.testing.tasks`: a starter, the golden file of a model
solution, ``task.toml``) with an ``adventure.toml`` beside it::

    level = 1                         # the level it is for (docs/levels.md)
    uses = ["repeat"]                 # (optional) what the program must be made of
    [title]                           # its name, in each language (English at least)
    en = "A square"
    [goal]                            # what the robot should do: a few words a child hears
    en = "Draw a square: four sides, all the same."

The built-in ones are in this package's ``built_in/`` (each with its model solution,
``solution.root``, which a test checks passes); a teacher adds their own as folders in the
class folder's ``_adventures/`` (one of a built-in's name replaces it). A check is a task's
check (the program run in the adventure's world, in a child process) followed by a hint
(:mod:`rootlang.adventures.hints`): a run passes when the task's check passes and it does
everything its goal does.
"""

from __future__ import annotations

import contextlib
import functools
import sys
from collections.abc import Sequence
from dataclasses import dataclass, replace
from pathlib import Path

from rootlang.adventures.hints import Summary, hint, missing_parts
from rootlang.diagnostics import RootlangError
from rootlang.testing.runner import Verdict
from rootlang.testing.tasks import Checked, CheckJob, Task, check_programs, load_task

ADVENTURE_FILE = "adventure.toml"
BUILT_IN = Path(__file__).parent / "built_in"
SOLUTION = "solution.root"  # a built-in adventure's model solution
LEVELS = (1, 2, 3)


@dataclass(frozen=True)
class Adventure:
    task: Task
    level: int
    titles: dict[str, str]  # by language
    goals: dict[str, str]
    uses: tuple[str, ...]

    @property
    def name(self) -> str:
        return self.task.name

    def title(self, language: str) -> str:
        return self.titles.get(language) or self.titles.get("en") or self.task.title

    def goal(self, language: str) -> str:
        return self.goals.get(language) or self.goals.get("en", "")

    @property
    def wanted(self) -> Summary:
        """What the goal's robot does (read once from the golden file)."""
        return _summary(self.task.golden, self.task.golden.stat().st_mtime_ns)


@functools.lru_cache(maxsize=256)
def _summary(golden: Path, changed: int) -> Summary:
    return Summary.of(golden.read_text(encoding="utf-8"))


def load_adventure(folder: Path) -> Adventure:
    """The adventure in ``folder``: E840/E841 as for a task, E850 for an ``adventure.toml``
    that can't be used."""
    task = load_task(folder)
    if sys.version_info >= (3, 11):
        import tomllib
    else:  # pragma: no cover - Python 3.10
        import tomli as tomllib
    try:
        settings = tomllib.loads((folder / ADVENTURE_FILE).read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError) as error:
        raise RootlangError.of("E850", adventure=task.name, reason=str(error)) from None
    level, uses = settings.get("level", 2), settings.get("uses", [])
    titles, goals = settings.get("title", {}), settings.get("goal", {})
    if level not in LEVELS or isinstance(level, bool):
        raise RootlangError.of("E850", adventure=task.name, reason="level must be 1, 2 or 3")
    from rootlang.adventures.hints import PARTS

    if not isinstance(uses, list) or any(part not in PARTS for part in uses):
        reason = f"uses may name {', '.join(PARTS)}"
        raise RootlangError.of("E850", adventure=task.name, reason=reason)
    if not _words(titles) or not _words(goals):
        reason = "[title] and [goal] need words in at least one language (en = ...)"
        raise RootlangError.of("E850", adventure=task.name, reason=reason)
    return Adventure(task, level, dict(titles), dict(goals), tuple(uses))


def _words(table: object) -> bool:
    return isinstance(table, dict) and bool(table) and all(
        isinstance(words, str) for words in table.values())  # fmt: skip


def find_adventures(folder: Path | None = None) -> list[Adventure]:
    """The built-in adventures and those in ``folder`` (a class's ``_adventures/``: one of a
    built-in's name replaces it), by level, then name. A folder that is not an adventure yet
    is left out (the teacher is still making it)."""
    found: dict[str, Adventure] = {}
    for place in (BUILT_IN, folder):
        if place is None or not place.is_dir():
            continue
        for below in sorted(place.iterdir()):
            if below.is_dir() and not below.name.startswith((".", "_")):
                adventure = _loaded(below, _fingerprint(below))
                if adventure is not None:
                    found[below.name] = adventure
    return sorted(found.values(), key=lambda adventure: (adventure.level, adventure.name))


def _fingerprint(folder: Path) -> tuple[tuple[str, int, int], ...]:
    """Each file of the folder, with when it last changed and its size."""
    files = []
    for file in folder.iterdir():
        with contextlib.suppress(OSError):
            found = file.stat()
            files.append((file.name, found.st_mtime_ns, found.st_size))
    return tuple(sorted(files))


@functools.lru_cache(maxsize=512)
def _loaded(folder: Path, fingerprint: tuple[tuple[str, int, int], ...]) -> Adventure | None:
    """The adventure in ``folder`` as its files are now (read again when one changes: every
    check asks for the list, 30 at once in a class); None while it is not one."""
    try:
        return load_adventure(folder)
    except RootlangError:
        return None


def check_adventures(
    adventures: Sequence[Adventure], jobs: Sequence[CheckJob], workers: int | None = None
) -> list[Checked]:
    """Check each job (its adventure's, in the same order) as a task, then give it its hint:
    a run the task passes still fails when it does less than the goal does."""
    checked = check_programs(jobs, workers)
    return [
        with_hint(adventure, job, result)
        for adventure, job, result in zip(adventures, jobs, checked, strict=True)
    ]


def with_hint(adventure: Adventure, job: CheckJob, checked: Checked) -> Checked:
    """The check, its first difference told as the goal and the run differ when they do."""
    produced = checked.result.produced
    if produced is None or produced.end in ("check", "error"):
        return checked  # stopped at a limit, or mistakes, or an error: said as it is
    told = missing_parts(job.text, adventure.uses) or hint(
        adventure.wanted, Summary.of(produced.text)
    )
    if told is None:
        return checked
    result = replace(checked.result, verdict=Verdict.FAILED, report=told.english,
                     first_difference=told.english)  # fmt: skip
    return Checked(False, told, result, said_is_difference=True)
