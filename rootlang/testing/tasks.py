"""Tasks that check themselves: a starter program, a world and a golden outcome.

A task is a folder (in the studio, ``FOLDER/_tasks/NAME/``) holding

- ``NAME.root`` — the starter each pupil gets a copy of, and the name their program keeps;
- ``NAME.golden`` — the outcome wanted: the golden file ``rootlang test --update`` writes for the
  teacher's own solution (put there as ``NAME.root``, run, then replaced by the starter);
- ``task.toml`` (optional) — ``title``, the ``world`` (a file in the task's folder or a world's
  name; default: the one the starter's ``# world:`` line names, else the default world) and
  ``check``: ``"golden"`` (the whole output, byte for byte, as ``rootlang test``), ``"pose"``
  (where the robot ends, within ``tolerance_mm`` and ``tolerance_deg``), ``"drawing"`` (the
  marker's lines, within ``tolerance_mm``) or ``"pose and drawing"`` (the default).

A check is a golden test: the pupil's text runs in the task's world — never one its own
``# world:`` line names — in a child process of :mod:`rootlang.app.sandbox` under the limits
of ``rootlang test``, and :func:`rootlang.testing.produce.produce` writes its golden text. The
run's pose and drawing come with it as data (:class:`rootlang.testing.golden.Ending`),
quantised as its golden text says them; the target's are read from the task's golden file
(the one record a task keeps of the teacher's solution), and the first difference is told in
plain words (catalogue codes V04x/V05x) — "your robot ended 12 cm left of the target".
"""

from __future__ import annotations

import itertools
import math
import multiprocessing
import sys
import tempfile
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path

from rootlang.app.files import PROGRAM_SUFFIX, named_world
from rootlang.app.sandbox import Finished, Limits, run_isolated
from rootlang.diagnostics import Diagnostic, RootlangError, diagnostic
from rootlang.sim.recording import IntPoint
from rootlang.testing import GOLDEN_SUFFIX
from rootlang.testing.golden import Ending, Pose
from rootlang.testing.produce import Produced, produce
from rootlang.testing.runner import (
    ProgramResult,
    Verdict,
    first_difference,
    first_source_line,
    why_unfinished,
)
from rootlang.wording.language import Languages

TASK_FILE = "task.toml"
CHECKS = ("golden", "pose", "drawing", "pose and drawing")
DEFAULT_TOLERANCE_MM = 30.0
DEFAULT_TOLERANCE_DEG = 15.0
SAMPLE_STEP_MM = 10.0  # how finely lines are compared (a point every centimetre)
CHECK_LIMITS = Limits(cpu_seconds=10.0, wall_seconds=60.0, memory_mb=256)  # a pupil waits


@dataclass(frozen=True)
class Task:
    name: str  # the program's name without .root: the starter's, the pupil's, the golden's
    folder: Path
    title: str
    check: str
    tolerance_mm: float
    tolerance_deg: float
    world: Path | None  # None: the default world

    @property
    def program(self) -> str:
        return self.name + PROGRAM_SUFFIX

    @property
    def starter(self) -> Path:
        return self.folder / self.program

    @property
    def golden(self) -> Path:
        return self.folder / (self.name + GOLDEN_SUFFIX)


def load_task(folder: Path) -> Task:
    """The task in ``folder`` (named after it); E840 for a folder that is not a task, E841
    for a ``task.toml`` that can't be used."""
    name = folder.name
    starter, golden = folder / (name + PROGRAM_SUFFIX), folder / (name + GOLDEN_SUFFIX)
    if not starter.is_file() or not golden.is_file():
        raise RootlangError.of("E840", task=name, program=starter.name, golden=golden.name)
    settings: dict[str, object] = {}
    if (folder / TASK_FILE).is_file():
        if sys.version_info >= (3, 11):
            import tomllib
        else:  # pragma: no cover - Python 3.10
            import tomli as tomllib
        try:
            settings = tomllib.loads((folder / TASK_FILE).read_text(encoding="utf-8"))
        except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError) as error:
            raise RootlangError.of("E841", task=name, reason=str(error)) from None
    check = settings.get("check", "pose and drawing")
    if check not in CHECKS:
        reason = f"check must be one of {', '.join(repr(c) for c in CHECKS)}, not {check!r}"
        raise RootlangError.of("E841", task=name, reason=reason)
    return Task(
        name=name,
        folder=folder,
        title=str(settings.get("title", name)),
        check=str(check),
        tolerance_mm=_number(settings, "tolerance_mm", DEFAULT_TOLERANCE_MM, name),
        tolerance_deg=_number(settings, "tolerance_deg", DEFAULT_TOLERANCE_DEG, name),
        world=_task_world(folder, starter, settings.get("world")),
    )


def _number(settings: dict[str, object], key: str, default: float, task: str) -> float:
    value = settings.get(key, default)
    if isinstance(value, bool) or not isinstance(value, (int, float)) or value < 0:
        raise RootlangError.of("E841", task=task, reason=f"{key} must be a number of 0 or more")
    return float(value)


def _task_world(folder: Path, starter: Path, named: object) -> Path | None:
    """The task's world: task.toml's, else the starter's ``# world:`` line's (both found from
    the task's folder, never outside it), else None (the default world)."""
    if named is None:
        return named_world(starter, starter.read_text(encoding="utf-8"))
    return named_world(starter, f"# world: {named}\n")


def find_tasks(folder: Path) -> list[Task]:
    """The tasks in the subfolders of ``folder`` (those that are tasks), by name."""
    if not folder.is_dir():
        return []
    found = []
    for below in sorted(folder.iterdir()):
        if below.is_dir() and not below.name.startswith("."):
            try:
                found.append(load_task(below))
            except RootlangError:
                continue  # not (yet) a task: the teacher is still putting it together
    return found


# --- checking ---------------------------------------------------------------------------------


@dataclass(frozen=True)
class CheckJob:
    """One pupil's program for a task: ``who`` names it in reports (``anna/square.root``)."""

    task: Task
    who: str
    text: str


@dataclass(frozen=True)
class Checked:
    """A check's result: passed or not, the first difference as a message (V040 when it
    passed; shown in the language of whoever reads it), and the golden test's own result (for
    CSV and JUnit)."""

    passed: bool
    said: Diagnostic
    result: ProgramResult
    said_is_difference: bool = False  # the report's difference is what was said (not a diff)

    def report(self, languages: Languages) -> ProgramResult:
        """The golden test's result as a report gives it, what the check said shown in
        ``languages`` where that is the difference (a pose or drawing missed, a limit)."""
        if not self.said_is_difference:
            return self.result
        told = self.said.shown(languages)
        return replace(self.result, report=told, first_difference=told)


def check_programs(
    jobs: Sequence[CheckJob],
    workers: int | None = None,
    context: multiprocessing.context.DefaultContext | None = None,
) -> list[Checked]:
    """Check each job as ``rootlang test`` tests a program (a child process each, under its
    limits, started as ``context`` starts processes: see :func:`run_isolated`); the results
    in the order of ``jobs``. Blocking: the studio calls it in a thread."""
    results: list[Checked | None] = [None] * len(jobs)
    for finished in run_isolated(_produce_check, jobs, CHECK_LIMITS, workers, context):
        results[finished.index] = judge(finished.job, finished)
    return [result for result in results if result is not None]


def warm_up() -> None:
    """Check a one-line program once in this process (no limits: nothing of the pupil's), so
    that the checks' children, forked from it, start with the parser, the runtime and the
    simulator loaded and warm (measured: a check 0.13 s of a child's time, 0.035 s warm)."""
    with tempfile.TemporaryDirectory(prefix="rootlang-warm-") as scratch:
        program = Path(scratch) / ("warm" + PROGRAM_SUFFIX)
        program.write_text("when started\n    move 10 cm\n", encoding="utf-8")
        produce(program)


def _produce_check(job: CheckJob) -> Produced:
    """In the child process: the pupil's text as a file of its own, run in the task's world."""
    from rootlang.sim.world import default_world, load_world

    world = default_world() if job.task.world is None else load_world(job.task.world)
    with tempfile.TemporaryDirectory(prefix="rootlang-check-") as scratch:
        program = Path(scratch) / job.task.program
        program.write_text(job.text, encoding="utf-8")
        return produce(program, world=world, cpu_seconds=CHECK_LIMITS.cpu_seconds)


def judge(job: CheckJob, finished: Finished[CheckJob, Produced]) -> Checked:
    """Compare a run with the task's golden file, as the task says to."""
    shown = Path(job.who)
    seconds = finished.wall_seconds
    produced = finished.result
    stopped = why_unfinished(finished)  # at a limit, or crashed: as `rootlang test` says it
    if stopped is not None or produced is None:
        assert stopped is not None
        verdict, found = stopped
        told = found.english
        result = ProgramResult(shown, verdict, told, None, seconds, told)
        return Checked(False, found, result, said_is_difference=True)
    expected = job.task.golden.read_text(encoding="utf-8")
    said, difference = _first_difference(job.task, expected, produced)
    verdict = Verdict.PASSED if said is None else Verdict.FAILED
    result = ProgramResult(shown, verdict, difference, produced, seconds, difference)
    outcome = job.task.check != "golden" and produced.end not in ("check", "error")
    return Checked(
        said is None,
        said or diagnostic("V040"),
        result,
        said_is_difference=outcome and said is not None,
    )


def _first_difference(
    task: Task, expected: str, produced: Produced
) -> tuple[Diagnostic | None, str]:
    """(the first difference as a message, and as a report's one line); (None, "") when the
    run did what the task asks."""
    if produced.end == "check":  # the program has mistakes: what `rootlang check` says
        return diagnostic("V041"), " ".join(produced.text.split("\n")[:2]).strip()
    if task.check == "golden":
        difference = first_difference(expected, produced.text)
        if not difference:
            return None, ""
        line = first_source_line(expected.splitlines(), produced.text.splitlines(),
                                 produced.source_lines)  # fmt: skip
        told = _outcome_difference(task, Ending.read(expected), _ending(produced))
        return told or diagnostic("V055" if line else "V056", line=line), difference
    if produced.end == "error":
        line = next((n for n in produced.source_lines if n), 0)
        return diagnostic("V057", line=line), produced.text.splitlines()[0]
    told = _outcome_difference(task, Ending.read(expected), _ending(produced))
    return told, "" if told is None else told.english


def _ending(produced: Produced) -> Ending:
    return produced.ending or Ending(None, ())


def _outcome_difference(task: Task, want: Ending, got: Ending) -> Diagnostic | None:
    """The first way the run's pose or drawing misses the target (beyond the task's
    tolerances), as a message; None when it does not."""
    if task.check in ("pose", "pose and drawing", "golden") and want.pose is not None:
        told = _pose_difference(task, want.pose, got.pose)
        if told:
            return told
    if task.check in ("drawing", "pose and drawing", "golden"):
        return _drawing_difference(task, want.strokes, got.strokes)
    return None


def _pose_difference(task: Task, want: Pose, got: Pose | None) -> Diagnostic | None:
    if got is None:
        return diagnostic("V056")
    dx, dy = got[0] - want[0], got[1] - want[1]
    if math.hypot(dx, dy) > task.tolerance_mm:
        return _where(dx, dy, task.tolerance_mm)
    turned = abs((got[2] - want[2] + 180) % 360 - 180)
    if turned > task.tolerance_deg:
        return diagnostic("V050", degrees=turned)
    return None


def _where(dx: int, dy: int, tolerance: float) -> Diagnostic:
    """ "12 cm left of the target", "5 cm right of and 8 cm below the target" (as on the
    stage: x to the right, y up). A side within the tolerance is not named."""
    across = "" if abs(dx) <= tolerance / 2 else ("left" if dx < 0 else "right")
    along = "" if abs(dy) <= tolerance / 2 else ("below" if dy < 0 else "above")
    if not across and not along:  # each side small, together too far: the farther one
        across, along = ("left" if dx < 0 else "right", "") if abs(dx) >= abs(dy) else (
            "", "below" if dy < 0 else "above")  # fmt: skip
    code = _WHERE[(across, along)]
    return diagnostic(code, across=_length(abs(dx)), along=_length(abs(dy)))


_WHERE = {
    ("left", ""): "V042", ("right", ""): "V043", ("", "above"): "V044", ("", "below"): "V045",
    ("left", "above"): "V046", ("left", "below"): "V047", ("right", "above"): "V048",
    ("right", "below"): "V049",
}  # fmt: skip


def _length(mm: float) -> str:
    return f"{round(mm / 10)} cm" if mm >= 10 else f"{round(mm)} mm"


def _drawing_difference(
    task: Task, want: tuple[tuple[IntPoint, ...], ...], got: tuple[tuple[IntPoint, ...], ...]
) -> Diagnostic | None:
    wanted, drawn = _segments(want), _segments(got)
    if wanted and not drawn:
        return diagnostic("V051")
    missed = _farthest_off(wanted, drawn, task.tolerance_mm)
    if missed is not None:
        point, off = missed
        return diagnostic("V052", x=_length(point[0]), y=_length(point[1]), distance=_length(off))
    extra = _farthest_off(drawn, wanted, task.tolerance_mm)
    if extra is not None:
        point, off = extra
        if not wanted:
            return diagnostic("V054", x=_length(point[0]), y=_length(point[1]))
        return diagnostic("V053", x=_length(point[0]), y=_length(point[1]), distance=_length(off))
    return None


Segment = tuple[IntPoint, IntPoint]


def _segments(strokes: tuple[tuple[IntPoint, ...], ...]) -> list[Segment]:
    return [(a, b) for stroke in strokes for a, b in itertools.pairwise(stroke)]


def _farthest_off(
    these: Sequence[Segment], others: Sequence[Segment], tolerance: float
) -> tuple[tuple[float, float], float] | None:
    """The point along ``these`` (looked at every centimetre) farthest from every segment of
    ``others``, and how far, when that is beyond ``tolerance``; None when all lie within it."""
    worst: tuple[tuple[float, float], float] | None = None
    for (ax, ay), (bx, by) in these:
        steps = max(1, math.ceil(math.hypot(bx - ax, by - ay) / SAMPLE_STEP_MM))
        for step in range(steps + 1):
            point = (ax + (bx - ax) * step / steps, ay + (by - ay) * step / steps)
            off = min((_distance(point, segment) for segment in others), default=math.inf)
            if off > tolerance and (worst is None or off > worst[1]):
                worst = point, off
    if worst is not None and worst[1] == math.inf:
        return worst[0], 0.0
    return worst


def _distance(point: tuple[float, float], segment: Segment) -> float:
    (px, py), ((ax, ay), (bx, by)) = point, segment
    dx, dy = bx - ax, by - ay
    length = dx * dx + dy * dy
    t = 0.0 if length == 0 else max(0.0, min(1.0, ((px - ax) * dx + (py - ay) * dy) / length))
    return math.hypot(px - ax - t * dx, py - ay - t * dy)


@dataclass
class Progress:
    """The class's latest check of each pupil's program for each task (for the teacher)."""

    results: dict[tuple[str, str], Checked] = field(default_factory=dict)  # (task, pupil)

    def rows(self) -> list[ProgramResult]:
        return [self.results[key].result for key in sorted(self.results)]
