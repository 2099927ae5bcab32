"""A new statement is a node, a form and a handler, a new robot event a node, a form and its
edge test: the recipes of docs/architecture.md, followed for real. A fresh Python loads
rootlang with exactly those edits made to the source of ``ast.py``, ``forms.py`` and
``runtime/interpreter.py`` (a statement: the checks check its values through its form's
slots, with no edit) or ``runtime/scheduler.py`` (an event), and to no other file, then reads,
checks, prints, turns into blocks and back, and runs a program using the new statement or
event. Should another place be needed (a grammar rule, a builder, a printer, a block
definition), this fails."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import rootlang

PACKAGE = Path(rootlang.__file__).parent

# The recipe's edits: (module, text in it, what goes before that text). Each text is found
# once in its module (the script checks), so a change to those files shows here at once.
EDITS = {
    "rootlang.ast": [
        ("\n\nAnyStatement = (", '''

@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Beep(FormStatement):
    """``beep 3``: a short high note, that many times."""

    count: Expression
'''),
        ("    | Return\n)", "    | Beep\n"),
    ],
    "rootlang.forms": [
        (')  # fmt: skip\n"""Every statement but the few',
         '    Form("root_beep", ast.Beep, _S, (words(Said("beep", "piep", "pita", "bip", "piep")), '
         'Slot("count", Kind.NUMBER, "3", "beep", "beep 3"))),\n'),
    ],
    "rootlang.runtime.interpreter": [
        ("            case _:\n                ast.assert_never(node)\n        return None",
         "            case ast.Beep():\n                await self._beep(node, frame)\n"),
        ("    # ---- waiting and control", '''\
    async def _beep(self, node: ast.Beep, frame: Frame) -> None:
        for _ in range(round((await self.quantity(node, "count", frame)).value)):
            fields = {"frequency": 880, "duration": 100}
            await self.command("play_note", fields, frame, node, "beep")

'''),
    ],
}  # fmt: skip

# A robot event: `when crashed head on|on left|on right`, both bumpers (or that one alone)
# newly pressed; the choice carries its meaning, the bumpers' state by its protocol name. Like
# `beep`, its words say how the other languages write them.
EVENT_EDITS = {
    "rootlang.ast": [
        ("\n\n@dataclass(frozen=True, eq=False, repr=False, slots=True)\n"
         "class MessageReceived(", '''

@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Crashed(Event):
    """``when crashed head on|on left|on right``"""

    side: str
'''),
        ("    | BatteryLowEvent | ObstacleSeen | DockEvent\n", "    | Crashed\n"),
    ],
    "rootlang.forms": [
        ("EVENT_FORMS: tuple[Form, ...] = (",
         'CRASH_SIDE = _meant("side", {"head on": "BOTH", "on left": "LEFT", "on right": "RIGHT"}, '
         'Said("head on", "frontaal", "de frente", "de face", "frontal"), '
         '(ON, LEFT), (ON, RIGHT))\n'),
        (')  # fmt: skip\n"""How each event is written after',
         '    Form("root_when_crashed", ast.Crashed, _E, (words(Said("crashed", "gecrasht", '
         '"chocado", "percuté", "gecrasht")), CRASH_SIDE)),\n'),
        ('}\n"""The events the robot sends',
         '    ast.Crashed: EventSource("bumpers", "bumper_event"),\n'),
    ],
    "rootlang.runtime.scheduler": [
        ("        case _:\n            ast.assert_never(event)\n", '''\
        case ast.Crashed(side=side):
            wanted = BumperState[forms.CRASH_SIDE.meaning(side)]
            return lambda packet, before, after: (
                after.bumpers == wanted and before.bumpers != wanted
            )
'''),
    ],
}  # fmt: skip

LOADER = r'''
import importlib.abc, importlib.machinery, importlib.util, json, sys, tempfile
from pathlib import Path

EDITS = json.loads(sys.argv[1])


class Edited(importlib.abc.SourceLoader):
    """A module's source with the recipe's edits made (no bytecode cache: path_stats is not
    given, so the edited source is what runs)."""

    def __init__(self, name, path):
        self.name, self.path = name, path

    def get_filename(self, fullname):
        return self.path

    def get_data(self, path):
        text = Path(path).read_text(encoding="utf-8")
        for anchor, before in EDITS[self.name]:
            assert text.count(anchor) == 1, (self.name, anchor)
            text = text.replace(anchor, before + anchor)
        return text.encode("utf-8")


class Finder(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path, target=None):
        if name not in EDITS:
            return None
        found = importlib.machinery.PathFinder.find_spec(name, path)
        return importlib.util.spec_from_file_location(
            name, found.origin, loader=Edited(name, found.origin))


sys.meta_path.insert(0, Finder())
'''

SCRIPT = (
    LOADER
    + r"""
from rootlang import ast, forms
from rootlang.blocks import to_text, to_workspace
from rootlang.checks import diagnose, parse
from rootlang.formatting import format_source
from rootlang.testing.produce import produce

source = "when started\n    beep 2\n    repeat 2\n        beep 1 + 1\n"
program = parse("when STARTED\n    BEEP   2\n    repeat 2\n        beep 1 + 1\n")
first = program.scripts[0].body[0]
assert isinstance(first, ast.Beep), first
assert format_source("when started\n    beep   2\n    repeat 2\n        beep 1+1\n") == source
dutch = parse("# language: nl\nwanneer gestart\n    piep 2\n")  # its words, from its form
assert isinstance(dutch.scripts[0].body[0], ast.Beep), dutch
workspace = to_workspace(source)
assert "root_beep" in json.dumps(workspace)
assert to_text(workspace) == source
said = [d.english for d in diagnose("when started\n    beep 2 cm\n")]
assert said == ["beep needs a plain number, like `beep 3`, but this is a distance."], said
folder = Path(tempfile.mkdtemp())
(folder / "beeps.root").write_text(source, encoding="utf-8")
produced = produce(folder / "beeps.root")
assert produced.end == "finished", produced.text
print(produced.text)
"""
)

EVENT_SCRIPT = (
    LOADER
    + r"""
from rootlang import ast, forms
from rootlang.blocks import to_text, to_workspace
from rootlang.checks import diagnose, parse
from rootlang.formatting import format_source
from rootlang.testing.produce import produce

program = parse("when CRASHED  on Left\n    light red\n")
event = program.scripts[0].event
assert isinstance(event, ast.Crashed) and event.side == "on left", event
french = parse("# language: fr\nquand percuté de face\n    lumière rouge\n").scripts[0].event
assert isinstance(french, ast.Crashed) and french.side == "head on", french
source = (
    "# world: arena\nwhen started\n    drive 8 cm/s\n    wait 20 seconds\n\n"
    "when crashed head on\n    print \"crash!\"\n    stop all\n"
)
assert format_source(source.replace("head on", "head   ON")) == source
workspace = to_workspace(source)
assert "root_when_crashed" in json.dumps(workspace)
assert to_text(workspace) == source
said = [d.english for d in diagnose("when crashed on top\n    light red\n")]
assert said == ["I didn't expect `top` here. I was expecting `left` or `right`."], said
assert not diagnose(source)
folder = Path(tempfile.mkdtemp())
(folder / "crash.root").write_text(source, encoding="utf-8")
produced = produce(folder / "crash.root")
assert produced.end == "stopped", produced.text
print(produced.text)
"""
)


def _run(script: str, edits: dict[str, list[tuple[str, str]]], cache: Path, *args: str) -> str:
    """What ``script`` prints, run in a fresh Python with ``edits`` made to rootlang."""
    finished = subprocess.run(
        [sys.executable, "-c", script, json.dumps(edits), *args],
        capture_output=True,
        text=True,
        timeout=120,
        env={"XDG_CACHE_HOME": str(cache), "PATH": "", "PYTHONPATH": str(PACKAGE.parent)},
        check=False,
    )
    assert finished.returncode == 0, finished.stderr
    return finished.stdout


def test_a_new_statement_is_a_node_a_form_and_a_handler(tmp_path: Path) -> None:
    trace = _run(SCRIPT, EDITS, tmp_path)  # the run's golden text: six beeps of 100 ms
    assert trace.startswith("end: finished at 0.600 s"), trace
    assert "command beep -> done at 100 ms" in trace


def test_a_new_robot_event_is_a_node_a_form_and_its_edge_test(tmp_path: Path) -> None:
    trace = _run(EVENT_SCRIPT, EVENT_EDITS, tmp_path)  # the robot drives into the arena's wall
    assert trace.startswith("end: stopped at"), trace
    assert "event   bumper_event state=BOTH" in trace
    assert "start   2:when crashed head on" in trace and 'print   "crash!"' in trace


def test_the_recipes_edits_are_all_it_takes() -> None:
    # the grammar has no rule of its own for a statement a form describes
    grammar = (PACKAGE / "grammar" / "root.lark").read_text(encoding="utf-8")
    assert '"turn"i' not in grammar and '"play"i' not in grammar
    assert '"bumped"i' not in grammar and "LIGHT_STATE" not in grammar  # nor for an event
    # nor a list of the colours or the functions (rootlang.colors, rootlang.units)
    assert '"purple"i' not in grammar and "sqrt" not in grammar
    assert '"while"i' not in grammar and '"until"i' not in grammar  # nor for a loop's header


# A word that was another tool's: `spin 3 turns`, three whole turns on the spot. Its first word
# is a habit of Scratch's and a synonym of `turn` (grammar/habits.py); taken up by rootlang it
# stops being either at once. Its form says it moves the robot (not in `when stopped`).
SPIN_EDITS = {
    "rootlang.ast": [
        ("\n\nAnyStatement = (", '''

@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Spin(FormStatement):
    """``spin 3 turns``: whole turns on the spot, clockwise."""

    count: Expression
'''),
        ("    | Return\n)", "    | Spin\n"),
    ],
    "rootlang.forms": [
        (')  # fmt: skip\n"""Every statement but the few',
         '    Form("root_spin", ast.Spin, _M, (words(Said("spin", "rond", "remolino", '
         '"tourbillon", "kreise")), Slot("count", Kind.NUMBER, "3", "spin", "spin 3 turns"), '
         'words(Said("turns", "rondjes", "vueltas", "tours", "runden"))), moves=True),\n'),
    ],
    "rootlang.runtime.interpreter": [
        ("            case _:\n                ast.assert_never(node)\n        return None",
         "            case ast.Spin():\n                await self._spin(node, frame)\n"),
        ("    # ---- waiting and control", '''\
    async def _spin(self, node: ast.Spin, frame: Frame) -> None:
        turns = round((await self.quantity(node, "count", frame)).value)
        fields = {"angle": turns * 3600}
        await self.command("rotate_angle", fields, frame, node, f"spin {turns} turns")

'''),
    ],
}  # fmt: skip

SPIN_SCRIPT = (
    LOADER
    + r"""
from rootlang import ast
from rootlang.checks import diagnose, parse
from rootlang.grammar.habits import HABITS, SYNONYMS
from rootlang.locale.keywords import markdown_table, with_table
from rootlang.testing.produce import produce
import importlib, inspect, shutil

source = "# spin.root: whole turns on the spot\nwhen started\n    spin 2 turns\n    move 5 cm\n"
assert isinstance(parse(source).scripts[0].body[0], ast.Spin)
assert not diagnose(source)
# a broken `spin` line is rootlang's own mistake now, not "written that way in other languages"
for broken in ("spin", "spin 3", "spin around", "spin right 90"):
    said = [d.english for d in diagnose(f"when started\n    {broken}\n")]
    assert said and not any("other languages" in s or "Scratch" in s for s in said), said
assert not any(habit.written.split()[0] == "spin" for habit in HABITS)
assert "spin" not in "|".join(words for words, _ in SYNONYMS).split("|")
said = [d.code for d in diagnose("when stopped\n    spin 1 turns\n")]
assert said == ["E117"], said  # its form says it moves
assert "| `turns` | `rondjes` | `vueltas` | `tours` | `runden` |" in markdown_table()
# the gallery: a program that uses it, its golden file and its line in the index, cover it
folder = Path(tempfile.mkdtemp())
programs = folder / "programs"
shutil.copytree(sys.argv[2], programs)
(programs / "spin.root").write_text(source, encoding="utf-8")
index = (programs / "README.md").read_text(encoding="utf-8")
line = "| [spin.root](spin.root) | whole turns on the spot | default | `spin`, `move` |\n"
(programs / "README.md").write_text(index.replace("| [square.root]", line + "| [square.root]"))
produced = produce(programs / "spin.root")
assert produced.end == "finished", produced.text
gallery = sorted(programs.glob("*.root"))
used = {type(node) for program in gallery
        for node in ast.walk(parse(program.read_text(encoding="utf-8"), str(program)))}
assert ast.Spin in used
# and the suite's own checks of what the recipe touches hold with these files alone: the
# keyword table of docs/languages.md regenerated (`python -m rootlang.locale`), the
# gallery's index, the words of the language (a word it has already keeps its translations:
# `spin`, of `light spin`), the habits, the statements that move
root = Path(sys.argv[2]).parent
docs = folder / "languages.md"
docs.write_text(with_table((root / "docs" / "languages.md").read_text(encoding="utf-8")))
keyword_tests = importlib.import_module("tests.languages.test_keyword_tables")
keyword_tests.DOCS = docs
gallery_tests = importlib.import_module("tests.golden.test_gallery_coverage")
gallery_tests.PROGRAMS, gallery_tests.GALLERY = programs, gallery
for module in (keyword_tests, gallery_tests, importlib.import_module("tests.language.test_habits"),
               importlib.import_module("tests.language.test_forms")):
    for name, check in vars(module).items():
        needs = list(inspect.signature(check).parameters) if name.startswith("test_") else None
        if needs == ["language"]:
            for language in keyword_tests.OTHER_LANGUAGES:
                check(language)
        elif needs == []:
            check()
print(produced.text)
"""
)


def test_a_new_word_that_was_a_habit_is_rootlangs_with_the_three_files(tmp_path: Path) -> None:
    trace = _run(SPIN_SCRIPT, SPIN_EDITS, tmp_path, str(PACKAGE.parent / "programs"))
    assert trace.startswith("end: finished at"), trace
    assert "command spin 2 turns -> done at" in trace


# A new packet that moves (`scribble`: drive while the marker wiggles, a made-up command of
# Root's) and the statement that sends it, which needs the marker: the table's row says how it
# behaves (its actuator, a lost answer judged by the pose, its timeout), the form says it moves
# and needs the marker, the handler sends it. Run on the loopback robot, which answers any
# command of the table.
SCRIBBLE_EDITS = {
    "rootlang.protocol.table": [
        ("    *event(\n        MOTORS,\n        29,", '''\
    *command(
        MOTORS,
        40,
        "scribble",
        "Drive straight while the marker wiggles.",
        int32("distance", "positive is forwards", "mm"),
        response=reply("Finished scribbling.", *_POSE),
        behaviour=movement(drives, drive_end, drive_rest),
        robots=ROOT_ROBOTS,
    ),
'''),
    ],
    "rootlang.ast": [
        ("\n\nAnyStatement = (", '''

@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Scribble(FormStatement):
    """``scribble 10 cm``"""

    distance: Expression
'''),
        ("    | Return\n)", "    | Scribble\n"),
    ],
    "rootlang.forms": [
        (')  # fmt: skip\n"""Every statement but the few',
         '    Form("root_scribble", ast.Scribble, _D, (words(Said("scribble", "krabbel", '
         '"garabatea", "gribouille", "kritzle")), Slot("distance", Kind.LENGTH, "10 cm", '
         '"scribble", "scribble 10 cm")), moves=True, needs=Needs("marker", "use the marker")),\n'),
    ],
    "rootlang.runtime.interpreter": [
        ("            case _:\n                ast.assert_never(node)\n        return None",
         "            case ast.Scribble():\n                await self._scribble(node, frame)\n"),
        ("    # ---- waiting and control", '''\
    async def _scribble(self, node: ast.Scribble, frame: Frame) -> None:
        mm = round((await self.quantity(node, "distance", frame)).value)
        await self.command("scribble", {"distance": mm}, frame, node, f"scribble {mm} mm")

'''),
    ],
}  # fmt: skip

SCRIBBLE_SCRIPT = (
    LOADER
    + r"""
import asyncio
from rootlang.checks import diagnose, parse
from rootlang.protocol import spec
from rootlang.robots import RobotModel
from rootlang.runtime.client import timeout_for
from rootlang.runtime.clock import VirtualClock
from rootlang.runtime.loopback import LoopbackRobot
from rootlang.runtime.scheduler import run_program

source = "when started\n    scribble 10 cm\n    marker up\n"
assert not diagnose(source, robot=RobotModel.RT1)
said = [(d.code, d.english) for d in diagnose(source, robot=RobotModel.CREATE3)]
assert said[0][0] == "W102" and "marker" in said[0][1], said
assert [d.code for d in diagnose("when stopped\n    scribble 1 cm\n")] == ["E117"]
assert spec("scribble").behaviour.moves
way = {"distance": 400}  # the timeout is the table's: as long as a drive's
assert timeout_for("scribble", way) == timeout_for("drive_distance", way)


def run(model):
    clock = VirtualClock()
    robot = LoopbackRobot(clock, model=model, protocol_version=(1, 5))
    result = clock.run(run_program(parse(source), robot, clock, source=source, time_limit=10))
    return result, robot


result, robot = run(RobotModel.RT1)
assert result.end == "finished", result.end
assert "scribble" in robot.names_received()
sent = [entry for entry in result.trace.entries if entry.text == "scribble 100 mm"]
assert [entry.group for entry in sent] == ["motion"], sent
result, robot = run(RobotModel.CREATE3)
assert result.error is not None and result.error.code == "E201", result.error
assert "scribble" not in robot.names_received()
print("ok")
"""
)


def test_a_new_packet_that_moves_and_a_statement_needing_the_marker(tmp_path: Path) -> None:
    assert _run(SCRIBBLE_SCRIPT, SCRIBBLE_EDITS, tmp_path).strip().endswith("ok")
