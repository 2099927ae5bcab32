"""Docs as tests: every command and program shown in README.md and docs/*.md runs, so the docs
cannot drift from what rootlang does.

A fenced block says what it is:

- ``sh``: commands, run in order; each must exit 0 (1 when its comment says ``(exit 1)``);
- ``root``: a program; it passes the checks and runs in the simulator without an error;
- ``python``: run as a script; ``toml``: a world file that loads;
- ``yaml``: a CI workflow; its ``run:`` and ``command:`` lines run (``${{ matrix.* }}`` as 1);
- ``text``: output or a diagram; one whose first line is ``$ COMMAND`` is a transcript: the
  command runs and prints exactly the rest of the block;
- ``js``: code for a web page (the blocks editor's browser tests run it there).

An inline command that names a program (`rootlang sim programs/flower.root`, not a placeholder
like ``FILE.root``) runs too. Each runs in a fresh folder holding a copy of ``docs/`` and a small
``programs/``: the programs the docs name (the whole gallery is tested once, by
``tests/golden/test_gallery.py``, not again for every command that names the folder), with this
environment's ``rootlang`` on the PATH. Only what truly needs a robot, a radio or a fresh install
is skipped, with the reason.
"""

from __future__ import annotations

import importlib.util
import os
import re
import shutil
import subprocess
import sys
from dataclasses import dataclass, replace
from pathlib import Path

import pytest

from rootlang.app.session import simulate
from rootlang.checks import diagnose, load_checked
from rootlang.robots import RobotModel
from rootlang.sim.world import default_world, parse_world

REPO = Path(__file__).resolve().parents[2]
DOCS = [REPO / "README.md", *sorted((REPO / "docs").glob("*.md"))]
KINDS = ("sh", "root", "python", "toml", "yaml", "text", "js")
PLACEHOLDER = re.compile(r"\b[A-Z]{2,}\b")  # FILE, NAME, PATH: a command's shape, not one to run
WORKFLOW_STEP = re.compile(r"^\s*(?:-\s*)?(?:run|command):\s*(?P<command>\S.*)$", re.M)
MATRIX_VALUE = re.compile(r"\$\{\{\s*matrix\.\w+\s*\}\}")
PYTHON_MODULE = re.compile(r"\bpython3? -m ([\w.]+)")
FENCE = re.compile(r"^```(?P<kind>[^\n`]*)\n(?P<body>.*?)^```[ \t]*$", re.S | re.M)
INLINE = re.compile(r"`((?:\.venv/bin/)?rootlang [^`]*?\S+\.root\b[^`]*)`")
COMMENT = re.compile(r"\s+#\s.*$")

NEEDS_A_ROBOT = "needs a robot or a Bluetooth radio"
SKIPPED_STEPS = [  # (pattern, why): only what a test machine truly can't do
    (re.compile(r"python3? -m venv|pip install"), "installs packages (.ci/run does it, fresh)"),
    (
        re.compile(r"^(\.venv/bin/)?pytest(\s+-n auto)?\s*$"),
        "runs this whole test suite, which this is in",
    ),
    (re.compile(r"rootlang (scan|robot)\b"), NEEDS_A_ROBOT),
    (re.compile(r"rootlang run (?!.*(--transport virtual|--sim))"), NEEDS_A_ROBOT),
    (re.compile(r"rootlang virtual-robot .*--transport (usb|serial)"), NEEDS_A_ROBOT),
    (re.compile(r"^(bluetoothctl|systemctl|bumble-)"), NEEDS_A_ROBOT),
    (re.compile(r"rootlang studio\b"), "serves a class until Ctrl-C (tests/studio runs it)"),
]


@dataclass(frozen=True)
class Shown:
    doc: str
    line: int
    kind: str
    body: str

    @property
    def id(self) -> str:
        return f"{self.doc}:{self.line}:{self.kind}"


def _shown() -> list[Shown]:
    found: list[Shown] = []
    for path in DOCS:
        text = path.read_text(encoding="utf-8")
        name = path.relative_to(REPO).as_posix()
        for match in FENCE.finditer(text):
            line = text.count("\n", 0, match.start()) + 1
            found.append(Shown(name, line, match["kind"].strip(), match["body"]))
        prose = FENCE.sub(lambda m: "\n" * m.group(0).count("\n"), text)
        for match in INLINE.finditer(prose):
            if PLACEHOLDER.search(match.group(1)):
                continue
            line = prose.count("\n", 0, match.start()) + 1
            found.append(Shown(name, line, "inline", match.group(1) + "\n"))
    return found


SHOWN = _shown()


def _of(*kinds: str) -> list[Shown]:
    return [item for item in SHOWN if item.kind in kinds]


def test_every_block_says_what_it_is() -> None:
    unlabelled = [item.id for item in SHOWN if item.kind not in (*KINDS, "inline")]
    assert unlabelled == [], f"label each fenced block as one of {KINDS}"


def test_the_docs_show_commands_and_programs() -> None:
    assert len(_of("sh", "inline")) >= 8 and len(_of("root")) >= 8


NAMED_PROGRAM = re.compile(r"programs/([\w/]+)\.root")


@pytest.fixture
def sandbox(tmp_path: Path) -> Path:
    """A copy of the files the docs' commands use, and this environment as `.venv`."""
    shutil.copytree(REPO / "docs", tmp_path / "docs")
    named = {name for path in DOCS for name in NAMED_PROGRAM.findall(path.read_text("utf-8"))}
    for name in named:
        for suffix in (".root", ".golden"):
            copy = tmp_path / "programs" / (name + suffix)
            copy.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy(REPO / "programs" / (name + suffix), copy)
    (tmp_path / ".venv").symlink_to(sys.prefix, target_is_directory=True)
    return tmp_path


def _environment(sandbox: Path) -> dict[str, str]:
    bin_folder = str(Path(sys.executable).parent)
    return {
        **os.environ,
        "PATH": bin_folder + os.pathsep + os.environ.get("PATH", ""),
        "XDG_CACHE_HOME": str(sandbox / ".cache"),
    }


def _run(step: str, sandbox: Path, *, merged: bool = False) -> subprocess.CompletedProcess[str]:
    """Run a shell command in the sandbox (``merged``: stderr into stdout, as a terminal shows
    them)."""
    return subprocess.run(
        step, shell=True, cwd=sandbox, env=_environment(sandbox), text=True, timeout=120,
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT if merged else subprocess.PIPE,
    )  # fmt: skip


def _steps(body: str) -> list[tuple[str, int]]:
    """Each command of a block (a line, split at ``&&``) with the exit status it should have."""
    steps = []
    for raw in body.splitlines():
        if not raw.strip() or raw.lstrip().startswith("#"):
            continue
        comment = raw[len(COMMENT.sub("", raw)) :]
        status = 1 if "(exit 1)" in comment else 0
        steps += [(part.strip(), status) for part in COMMENT.sub("", raw).split("&&")]
    return steps


def _why_skipped(step: str) -> str | None:
    return next((why for pattern, why in SKIPPED_STEPS if pattern.search(step)), None)


def _commands(shown: Shown) -> list[tuple[str, int]]:
    if shown.kind != "yaml":
        return _steps(shown.body)
    lines = [MATRIX_VALUE.sub("1", m["command"]) for m in WORKFLOW_STEP.finditer(shown.body)]
    return _steps("\n".join(lines))


@pytest.mark.slow
@pytest.mark.parametrize("shown", _of("sh", "inline", "yaml"), ids=lambda shown: shown.id)
def test_every_command_runs(shown: Shown, sandbox: Path) -> None:
    ran, skipped = 0, []
    for step, status in _commands(shown):
        why = _why_skipped(step)
        if why:
            skipped.append(f"{step}: {why}")
            continue
        result = _run(step, sandbox)
        said = result.stdout[-3000:] + result.stderr[-3000:]
        assert result.returncode == status, f"{step}\n{said}"
        assert "Traceback" not in said and "inside rootlang itself" not in said, f"{step}\n{said}"
        ran += 1
    if not ran:
        pytest.skip("; ".join(skipped))


TRANSCRIPTS = [item for item in _of("text") if item.body.startswith("$ ")]


@pytest.mark.parametrize("shown", TRANSCRIPTS, ids=lambda shown: shown.id)
def test_every_transcript_shows_what_the_command_prints(shown: Shown, sandbox: Path) -> None:
    command, _, expected = shown.body.partition("\n")
    result = _run(command.removeprefix("$ "), sandbox, merged=True)
    assert "Traceback" not in result.stdout, result.stdout
    printed = [line.rstrip() for line in result.stdout.splitlines()]
    assert printed == [line.rstrip() for line in expected.splitlines()]


@pytest.mark.parametrize("shown", _of("root"), ids=lambda shown: shown.id)
def test_every_program_checks_and_runs_without_an_error(shown: Shown) -> None:
    errors = [d for d in diagnose(shown.body, shown.doc) if d.severity == "error"]
    assert errors == []
    # Create 3 examples (obstacles, the dock) run on a Create 3; the rest on a Root RT1.
    for_root = not diagnose(shown.body, shown.doc, RobotModel.RT1)
    model = RobotModel.RT1 if for_root else RobotModel.CREATE3
    checked = load_checked(shown.body, shown.doc, model)
    world = replace(default_world(model), time_limit=10.0)  # examples waiting for events idle
    result, _ = simulate(checked, world, source=shown.body)
    assert result.error is None, result.error.english


def test_every_python_module_shown_exists() -> None:
    texts = (path.read_text(encoding="utf-8") for path in DOCS)
    modules = {module for text in texts for module in PYTHON_MODULE.findall(text)}
    assert "bumble.apps.controllers" in modules
    if importlib.util.find_spec("bumble") is None:  # the optional extra rootlang[virtual]
        modules = {module for module in modules if module.split(".")[0] != "bumble"}
    assert sorted(m for m in modules if importlib.util.find_spec(m) is None) == []


@pytest.mark.parametrize("shown", _of("python"), ids=lambda shown: shown.id)
def test_every_python_example_runs(shown: Shown, sandbox: Path) -> None:
    script = sandbox / "example.py"
    script.write_text(shown.body, encoding="utf-8")
    result = _run(f"{sys.executable} example.py", sandbox)
    assert result.returncode == 0, result.stderr[-3000:]


@pytest.mark.parametrize("shown", _of("toml"), ids=lambda shown: shown.id)
def test_every_world_file_loads(shown: Shown) -> None:
    parse_world(shown.body, shown.id)
