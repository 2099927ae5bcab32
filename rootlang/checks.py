"""The semantic pass: names, units, events and robots, checked before a program runs.

``check(program, robot)`` returns a :class:`CheckedProgram` — the AST plus what the runtime
needs without analysing it again — or raises RootlangError with every error found.
``load_program(source, file, robot)`` parses and checks in one call; ``diagnose`` gives every
diagnostic (syntax errors, check errors, warnings) for ``rootlang check``.

Variables (LANGUAGE.md §4, written out plainly in docs/language.md):

- A name that appears in only one script (and in no procedure) is *local* to that script: it
  starts unset each time the script starts.
- A name that appears in two or more scripts, or in a procedure, is *shared*: one value for
  the whole program (like Scratch's "for all sprites").
- Procedure parameters are local to each call.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Callable, Iterable, Iterator, Mapping
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

from rootlang import ast, forms
from rootlang.colors import SENSOR_COLORS, Color, can_be_seen
from rootlang.diagnostics import (
    Diagnostic,
    RootlangError,
    Span,
    diagnostic,
    did_you_mean,
    source_lines,
)
from rootlang.robots import RobotModel
from rootlang.units import (
    FUNCTIONS,
    Kind,
    Quantity,
    UnitError,
    binary_kind,
    expect_kind,
    function_kind,
    kind_of,
    rgb_channel_kind,
    unary_kind,
    unit_named,
    with_unit_kind,
)
from rootlang.wording.shown import Code, Described, Suggestion, write_line

if TYPE_CHECKING:
    from rootlang.grammar import LinesRead
    from rootlang.grammar.habits import Above

__all__ = [
    "ARGUMENT_RULES",
    "EVENT_FEATURES",
    "SENSOR_FEATURES",
    "CheckedProgram",
    "check",
    "diagnose",
    "expect_argument",
    "expect_condition",
    "load_checked",
    "load_program",
    "missing_feature",
    "robots_with",
    "unsupported_action",
]

ARGUMENT_RULES = forms.ARGUMENT_RULES  # (statement, field) -> the kind it needs
# node -> how E112 names its line: the forms' conditions, and `if` (written by hand)
CONDITIONS: dict[type[ast.Node], str] = {**forms.CONDITIONS, ast.Branch: "if"}

# The sensor each robot event and sensor read needs (from rootlang/forms.py): the checks warn
# (W101, W102) and the runtime stops with an error (E202) naming it the same way.
EVENT_FEATURES: dict[type[ast.Event], str] = {
    event: source.feature for event, source in forms.EVENTS.items()
}
SENSOR_FEATURES: dict[ast.SensorKind, str] = {
    kind: sensor.feature for kind, sensor in forms.SENSORS.items() if sensor.feature is not None
}
_SENSOR_KINDS: dict[ast.SensorKind, Kind] = {
    kind: sensor.kind for kind, sensor in forms.SENSORS.items()
}
MOTION = forms.MOTION
STOPPED_SCRIPT_LIMIT = 2.0  # seconds a `when stopped` script may run
MOST_SUGGESTED = 50  # unknown names of one file the grammar is asked about (each parses a line)


def expect_argument(statement: ast.Statement, field: str, actual: Kind) -> Kind:
    """Raise UnitError unless a value of kind ``actual`` fits ``field`` of ``statement``
    (``ARGUMENT_RULES``): the checks call it for kinds known before the run, the runtime for
    values known only while running, so both report the same message. Returns ``actual``."""
    rule = ARGUMENT_RULES.get((type(statement), field))
    if rule is not None:
        expect_kind(rule.command, rule.example, rule.kind, actual)
    return actual


def expect_condition(owner: ast.Node, actual: Kind) -> Kind:
    """Raise UnitError (E112) unless the condition of ``owner`` (a ``CONDITIONS`` node: ``if``,
    ``while``, ``when`` ...) is true or false; used by the checks and the runtime alike."""
    if actual is not Kind.BOOLEAN:
        keyword = Code(CONDITIONS[type(owner)], quoted=False)
        raise UnitError("E112", keyword=keyword, actual=actual.described)
    return actual


def missing_feature(feature: str, robot: RobotModel) -> bool:
    """True when ``robot`` lacks ``feature`` (a key of ``forms.FEATURES``)."""
    return robot not in robots_with(feature)


@functools.cache
def robots_with(feature: str) -> frozenset[RobotModel]:
    """The robots that have ``feature``: those the packet table gives its packet."""
    from rootlang.protocol import spec  # the packet table loads lazily
    from rootlang.protocol.table import ERASERS

    robots = spec(forms.FEATURES[feature]).robots
    return robots & ERASERS if feature == forms.ERASER else robots


@dataclass(frozen=True)
class CheckedProgram:
    """A program that passed the checks, with what the runtime needs to run it.

    - ``scripts`` in source order (their ``event`` is a typed node),
    - ``procedures`` by lower-case name (calls name them; arity already checked),
    - ``shared_variables``: names with one value for the whole program; every other variable
      is local to its script (``script_variables``) or procedure call,
    - ``kinds``: the kind of every expression whose kind is known before the run
      (keyed by the node itself: nodes hash by identity),
    - ``returns_value``: procedures that have a ``return <value>``,
    - ``warnings`` found while checking.
    """

    program: ast.Program
    scripts: tuple[ast.Script, ...]
    procedures: Mapping[str, ast.Procedure]
    shared_variables: frozenset[str]
    script_variables: Mapping[ast.Script, frozenset[str]]
    kinds: Mapping[ast.Expression, Kind]
    returns_value: frozenset[str]
    robot: RobotModel | None = None
    warnings: tuple[Diagnostic, ...] = ()

    def kind_of(self, expression: ast.Expression) -> Kind | None:
        """The kind known before the run, or None if only the run can tell."""
        return self.kinds.get(expression)


def load_checked(source: str, file: str = "", robot: RobotModel | None = None) -> CheckedProgram:
    """Parse and check: the checked program, or RootlangError with every error (syntax and
    checks together). Warnings are in ``CheckedProgram.warnings``."""
    program, found = parse_and_check(source, file, robot)
    errors = [d for d in found if d.severity == "error"]
    if errors or program is None:
        raise RootlangError(errors, source)
    return program


def load_program(source: str, file: str = "", robot: RobotModel | None = None) -> ast.Program:
    """Parse and check, giving the syntax tree (what the scheduler runs) or RootlangError."""
    return load_checked(source, file, robot).program


def diagnose(
    source: str, file: str = "", robot: RobotModel | None = None, language: str | None = None
) -> list[Diagnostic]:
    """Every diagnostic for a source text (written in ``language``, else the one it declares),
    errors and warnings, in source order."""
    return parse_and_check(source, file, robot, language=language)[1]


def parse_and_check(
    source: str,
    file: str = "",
    robot: RobotModel | None = None,
    *,
    language: str | None = None,
    suggest: bool = True,
    unsure: frozenset[str] = frozenset(),
    lines_read: LinesRead | None = None,
) -> tuple[CheckedProgram | None, list[Diagnostic]]:
    """Both answers of one pass: the checked program (None when the text could not be read at
    all) and every diagnostic, errors and warnings, in source order. For callers that need the
    warnings of a program with errors too (``rootlang test``), without parsing twice.
    ``suggest``: look for fixes, and try each in place (off: only where the mistakes are).
    ``unsure``: names that may have a value from lines left out (a fix tried in place).
    ``lines_read``: the lines of this program read before (a fix tried in place reads only
    the line it changes again)."""
    from rootlang.grammar import parse_lines, without_cycle_collector  # lark loads lazily
    from rootlang.grammar.habits import accepted_habits
    from rootlang.locale.translate import suggesting_in_language

    try:
        program, found = parse_lines(source, file, language, suggest=suggest, lines_read=lines_read)
        unsure = unsure | _names_on_broken_lines(source, found)
        checker = _Checker(program, robot, unsure_names=unsure,
                           lines=tuple(source.splitlines()), suggest=suggest)  # fmt: skip
        with without_cycle_collector():
            checked = checker.run()
    except RecursionError:  # nesting deeper than Python's stack: say so, never crash
        return None, [diagnostic("E018", Span(1, 1, 1, 2), limit=ast.NESTING_LIMIT).in_file(file)]
    found = sorted([*found, *checker.diagnostics], key=lambda d: (d.span, d.code))
    if suggest:
        found = sorted([*found, *accepted_habits(*_lines_and_english(source, language))],
                       key=lambda d: (d.span, d.code))  # fmt: skip
        # a Dutch typo gets a Dutch suggestion
        found = suggesting_in_language(found, source, language)
        found = verified_suggestions(found, source, robot, language)
    return checked, [d.in_file(file) for d in found]


def parse(source: str, file: str = "", language: str | None = None) -> ast.Program:
    """Parse a whole program; raises RootlangError with every syntax error found (their
    suggestions tried in place, :mod:`rootlang.verify`)."""
    from rootlang.grammar import parse_lines  # lark loads lazily

    program, diagnostics = parse_lines(source, file, language)
    errors = [d for d in diagnostics if d.severity == "error"]
    if errors:
        errors = verified_suggestions(errors, source, None, language)
        ordered = sorted(errors, key=lambda d: (d.span, d.code))
        raise RootlangError([d.in_file(file) for d in ordered], source)
    return program


def _lines_and_english(source: str, language: str | None) -> tuple[list[str], list[str] | None]:
    """The program's lines, and for a program in another language the same lines with their
    keywords in English (None for an English one)."""
    from rootlang.locale.translate import lines_in_english, program_language

    lines = list(source_lines(source))
    try:
        if program_language(source, language) == "en":
            return lines, None
    except RootlangError:
        return lines, None
    english = lines_in_english(source, range(1, len(lines) + 1), language)
    return lines, [english.get(number, line) for number, line in enumerate(lines, start=1)]


def verified_suggestions(
    found: list[Diagnostic], source: str, robot: RobotModel | None, language: str | None
) -> list[Diagnostic]:
    """``found`` with every suggestion tried in place (:mod:`rootlang.verify`), in the
    program's own language (a suggestion written in English is tried translated)."""
    from rootlang.grammar import LinesRead, prepared_text
    from rootlang.locale.translate import from_english, program_language
    from rootlang.verify import verify_all

    try:
        language = program_language(source, language)
    except RootlangError:
        language = "en"

    lines_read = LinesRead()  # each try changes a line or two: the others are read once

    def read(text: str, unsure: frozenset[str] = frozenset()) -> list[Diagnostic]:
        return parse_and_check(text, robot=robot, language=language, suggest=False,
                               unsure=unsure, lines_read=lines_read)[1]  # fmt: skip

    def in_language(rewrite: str) -> str:
        return from_english(rewrite, language)

    return verify_all(found, prepared_text(source), read, in_language, _habits_ask())


@functools.cache
def usable_name(name: str, *, procedure: bool = False) -> bool:
    """Whether a name reads back as that name wherever a program uses it (``timer`` would
    read as the sensor, ``not`` as a word of the language): a two-line program with it is
    parsed once and looked at."""
    if procedure:
        source = f"to {name}\n    stop moving\nwhen started\n    {name}\n"
    else:
        source = f"when started\n    set {name} to {name}\n"
    try:
        program = parse(source)
    except RootlangError:
        return False
    statement = program.scripts[0].body[0]
    if procedure:
        return isinstance(statement, ast.CallProcedure) and statement.name == name
    value = statement.value if isinstance(statement, ast.SetVariable) else None
    return isinstance(value, ast.Variable) and value.name == name


@functools.cache
def _language_words() -> frozenset[str]:
    """Every word of the grammar's own (`repeat`, `left`, `this`)."""
    from rootlang.grammar import lark_parser  # lark loads lazily
    from rootlang.grammar.words import terminal_words

    phrases = terminal_words(lark_parser()).values()
    return frozenset(word.lower() for spellings in phrases for p in spellings for word in p.split())


def _holds_alone(text: str) -> bool:
    """Whether a line reads and checks in a script of its own, its names aside."""
    program = "when started\n" + "\n".join(f"    {part}" for part in text.split("\n")) + "\n"
    found = parse_and_check(program, suggest=False)[1]
    return not any(item.severity == "error" and item.code not in ("E102", "E009") for item in found)


def _habits_ask() -> Above:
    """What the habits ask of the checks (the grammar imports no checks)."""
    from rootlang.grammar.habits import Above

    return Above(_language_words, _holds_alone)


def _names_on_broken_lines(source: str, found: list[Diagnostic]) -> frozenset[str]:
    lines = source_lines(source)
    broken = {d.span.line for d in found if d.severity == "error" and d.span.line >= 1}
    text = " ".join(lines[line - 1] for line in broken if line <= len(lines))
    return frozenset(word.lower() for word in re.findall(r"[A-Za-z][A-Za-z0-9_]*", text))


def check(program: ast.Program, robot: RobotModel | None = None) -> CheckedProgram:
    """Check a parsed program; raises RootlangError listing every error."""
    checker = _Checker(program, robot)
    checked = checker.run()
    errors = [d.in_file(program.file) for d in checker.diagnostics if d.severity == "error"]
    if errors:
        raise RootlangError(errors)
    return checked


@dataclass
class _Scope:
    """What one script or procedure body can see while it is checked."""

    owner: ast.Script | ast.Procedure
    parameters: frozenset[str] = frozenset()
    in_procedure: bool = False
    stopped_script: bool = False


@dataclass
class _Checker:
    """One program's checks: what they found, and what they learnt about its names."""

    program: ast.Program
    robot: RobotModel | None
    # names written on lines that did not parse: they may have been set or defined there
    unsure_names: frozenset[str] = frozenset()
    lines: tuple[str, ...] = ()  # the source, for suggestions that rewrite a line
    diagnostics: list[Diagnostic] = field(default_factory=list)
    kinds: dict[ast.Expression, Kind] = field(default_factory=dict)
    variable_kinds: dict[str, Kind | None] = field(default_factory=dict)
    procedures: dict[str, ast.Procedure] = field(default_factory=dict)
    returns_value: set[str] = field(default_factory=set)
    parameter_uses: dict[str, dict[str, tuple[Kind, ast.Statement]]] = field(default_factory=dict)
    suggested: int = 0  # unknown names the grammar was asked about
    suggest: bool = True  # ask the grammar what an unknown name could be

    def run(self) -> CheckedProgram:
        if not self.program.scripts and not self.unsure_names:  # (a broken line may be its `when`)
            first = self.program.procedures[0].span if self.program.procedures else Span(1, 1, 1, 1)
            self.warn("W104", first)
        self._collect_procedures()
        owners = self._variable_owners()
        self._infer_variable_kinds()
        for script in self.program.scripts:
            stopped = isinstance(script.event, ast.Stopped)
            scope = _Scope(script, stopped_script=stopped)
            self._event(script.event, scope)
            self._block(script.body, scope)
        for procedure in self.program.procedures:
            names = frozenset(parameter.name for parameter in procedure.parameters)
            self._block(procedure.body, _Scope(procedure, names, in_procedure=True))
        procedure_ids = {id(procedure) for procedure in self.program.procedures}
        shared = frozenset(
            name for name, users in owners.items() if len(users) > 1 or users & procedure_ids
        )
        script_variables = {
            script: frozenset(name for name, users in owners.items() if users == {id(script)})
            for script in self.program.scripts
        }
        return CheckedProgram(
            program=self.program,
            scripts=self.program.scripts,
            procedures=dict(self.procedures),
            shared_variables=shared,
            script_variables=script_variables,
            kinds=dict(self.kinds),
            returns_value=frozenset(self.returns_value),
            robot=self.robot,
            warnings=tuple(
                d.in_file(self.program.file) for d in self.diagnostics if d.severity == "warning"
            ),
        )

    def report(self, code: str, span: Span, **values: object) -> None:
        self.diagnostics.append(Diagnostic(code, span, tuple(sorted(values.items()))))

    def warn(self, code: str, span: Span, **values: object) -> None:
        self.diagnostics.append(diagnostic(code, span, severity="warning", **values))

    # ---- names ---------------------------------------------------------------------------

    def _collect_procedures(self) -> None:
        for procedure in self.program.procedures:
            if procedure.name in self.procedures:
                self.report("E104", procedure.span, name=procedure.name)
                continue
            self.procedures[procedure.name] = procedure
            seen: set[str] = set()
            for parameter in procedure.parameters:
                if parameter.name in seen:
                    self.report("E105", parameter.span, name=procedure.name,
                                parameter=parameter.name)  # fmt: skip
                seen.add(parameter.name)
            if any(isinstance(node, ast.Return) and node.value is not None
                   for node in _walk_block(procedure.body)):  # fmt: skip
                self.returns_value.add(procedure.name)

    def _variable_owners(self) -> dict[str, set[int]]:
        """Which scripts and procedures (by id) mention each variable name."""
        owners: dict[str, set[int]] = {}
        bodies: list[tuple[ast.Node, ast.Block, frozenset[str]]] = [
            (script, script.body, frozenset()) for script in self.program.scripts
        ]
        for procedure in self.program.procedures:
            parameters = frozenset(parameter.name for parameter in procedure.parameters)
            bodies.append((procedure, procedure.body, parameters))
        for owner, body, parameters in bodies:
            nodes = _walk_block(body)
            if isinstance(owner, ast.Script):
                nodes = [*ast.walk(owner.event), *nodes]
            for node in nodes:
                name = _variable_name(node)
                if name is not None and name not in parameters:
                    owners.setdefault(name, set()).add(id(owner))
        return owners

    def _infer_variable_kinds(self) -> None:
        """A variable's kind is known when every `set` gives it the same known kind."""
        assignments = [
            node
            for node in self._all_nodes()
            if isinstance(node, ast.SetVariable) and node.name not in self.procedures
        ]
        for _ in range(3):  # a few rounds: one variable's kind may come from another's
            kinds: dict[str, Kind | None] = {}
            for assignment in assignments:
                kind = self._quiet_kind(assignment.value)
                if assignment.name in kinds and kinds[assignment.name] is not kind:
                    kinds[assignment.name] = None
                else:
                    kinds.setdefault(assignment.name, kind)
            if kinds == self.variable_kinds:
                break
            self.variable_kinds = kinds

    def _all_nodes(self) -> Iterator[ast.Node]:
        for script in self.program.scripts:
            yield from _walk_block(script.body)
        for procedure in self.program.procedures:
            yield from _walk_block(procedure.body)

    def _quiet_kind(self, expression: ast.Expression) -> Kind | None:
        """The kind, without reporting anything (used while variable kinds are inferred)."""
        saved = len(self.diagnostics)
        kind = self._expression(expression, None)
        del self.diagnostics[saved:]
        return kind

    # ---- events and statements -----------------------------------------------------------

    def _event(self, event: ast.Event, scope: _Scope) -> None:
        feature = EVENT_FEATURES.get(type(event))
        if feature and self.robot is not None and missing_feature(feature, self.robot):
            self.warn("W101", event.span, robot=self.robot.display_name, sensor=feature)
        if isinstance(event, ast.ColorSeen) and event.color not in SENSOR_COLORS:
            self.report("E111", event.span, color=event.color)
        if isinstance(event, ast.ConditionBecomesTrue):
            condition = event.condition
            missing = self._missing_sensor(condition)
            if missing is not None and self.robot is not None:  # `when docked` on a Root
                self.warn("W101", event.span, robot=self.robot.display_name, sensor=missing)
                return
            unknown_word = (
                isinstance(condition, ast.Variable) and condition.name not in self.variable_kinds
            )
            if unknown_word and isinstance(condition, ast.Variable):
                fix = self._suggestion(condition.span, condition.name, ())
                named = dict(fix.values) if fix is not None else {}  # the grammar's event word
                suggestion = str(named.get("replacement") or named.get("word") or "") or (
                    did_you_mean(condition.name, forms.EVENT_WORDS)
                )
                found = diagnostic("E011", event.span, word=condition.name,
                                   suggestion=_suggest(suggestion))  # fmt: skip
                if _suggest(suggestion):
                    found = self._offer(found, condition.span, _suggested(_suggest(suggestion)))
                self.diagnostics.append(found)
                return
            self._condition(event, condition, scope)

    def _missing_sensor(self, condition: ast.Expression) -> str | None:
        for node in ast.walk(condition):
            feature = SENSOR_FEATURES.get(node.sensor) if isinstance(node, ast.SensorRead) else None
            if feature and self.robot is not None and missing_feature(feature, self.robot):
                return feature
        return None

    def _block(self, block: ast.Block, scope: _Scope) -> None:
        for statement in block:
            self._statement(statement, scope)

    def _statement(self, statement: ast.Statement, scope: _Scope) -> None:
        if scope.stopped_script and isinstance(statement, MOTION):
            self.report("E117", statement.span)
        self._robot_support(statement)
        self._speed_limit(statement)
        node = ast.statement(statement)
        match node:
            case ast.CallProcedure():
                self._call(node.name, node.arguments, node.name_span, node.span, scope,
                           as_value=False)  # fmt: skip
            case ast.Return(value=value):
                if not scope.in_procedure:
                    self.report("E106", node.span)
                if value is not None:
                    self._expression(value, scope)
            case ast.SetVariable():
                if node.name in self.procedures:
                    self.report("E116", node.span, name=node.name)
                elif not usable_name(node.name):
                    self.report("E128", node.span, name=node.name)
                self._expression(node.value, scope)
            case ast.ChangeVariable():
                self._change(node, scope)
            case ast.If():
                for branch in node.branches:
                    self._condition(branch, branch.condition, scope)
                    self._block(branch.body, scope)
                if node.otherwise is not None:
                    self._block(node.otherwise, scope)
            case ast.Print():
                for value in node.values:
                    self._expression(value, scope)
            case ast.Say(text=ast.Variable() as text):
                self._variable(text, scope, said=True)
            case ast.Say():
                self._expression(node.text, scope)
            case ast.FormStatement():
                self._arguments(node, scope)  # each value of the kind its form's slot needs
            case _:
                ast.assert_never(node)
        if scope.stopped_script and isinstance(statement, ast.Wait):
            self._stopped_wait(statement)
        body = forms.body_of(statement)
        if body is not None:
            self._block(body, scope)

    def _arguments(self, statement: ast.Statement, scope: _Scope) -> None:
        """Check each expression of a command against the kind it needs."""
        for name in statement.__dataclass_fields__:
            value = getattr(statement, name)
            if not isinstance(value, ast.Expression):
                continue
            if type(statement) in CONDITIONS:
                self._condition(statement, value, scope)
                continue
            if _is_colour(statement, name) and isinstance(value, ast.Variable):
                self._colour_name(value, scope)
                continue
            kind = self._expression(value, scope)
            if kind is not None:
                self._apply(value.span, functools.partial(expect_argument, statement, name, kind))
                self._unit_left_out(value)

    def _unit_left_out(self, value: ast.Expression) -> None:
        """`turn right 45`: the line with the example's unit after the child's own number,
        shown as the line to write once tried in place (rootlang.verify), and followed from a
        suggestion that leads to this line (`mve 10` -> `move 10` -> `move 10 cm`)."""
        last = self.diagnostics[-1] if self.diagnostics else None
        if last is None or last.code != "E108" or last.span != value.span:
            return
        if isinstance(value, ast.Literal) and not isinstance(value.value, bool):
            unit = str(dict(last.values)["example"]).rsplit(" ", 1)[-1]
            text = f"{self._source(value.span)} {unit}"
            line = self._rewritten(value.span, text)
            offered = last.with_values(write=write_line(line)) if line else last
            self.diagnostics[-1] = self._offer(offered, value.span, text, last)

    def _suggestion(
        self, span: Span, name: str, names: Iterable[str], *, colour: bool = False
    ) -> Diagnostic | None:
        """What the grammar takes in place of an unknown name, for the first few of a file."""
        self.suggested += 1
        if self.suggested > MOST_SUGGESTED or not self.suggest:
            return None
        return _grammar_suggestion(self.lines, span, name, names, colour=colour)

    def _colour_name(self, value: ast.Variable, scope: _Scope) -> None:
        """`light gren`: a colour misspelt, or one the light doesn't know, before a variable."""
        if value.name in self.variable_kinds or value.name in scope.parameters:
            self._expression(value, scope)
        elif value.name not in self.unsure_names:
            self._unknown_name(value.name, value.span, scope, colour=True)

    def _condition(self, owner: ast.Node, condition: ast.Expression, scope: _Scope) -> None:
        kind = self._expression(condition, scope)
        if kind is not None:
            self._apply(condition.span, functools.partial(expect_condition, owner, kind))

    def _change(self, statement: ast.ChangeVariable, scope: _Scope) -> None:
        by = self._expression(statement.by, scope)
        known = statement.name in self.variable_kinds or statement.name in scope.parameters
        if not known and statement.name not in self.unsure_names:
            self._unknown_name(statement.name, statement.span, scope)
            return
        current = self.variable_kinds.get(statement.name)
        if current is not None and by is not None:
            self._binary_kinds("+", current, by, statement.by.span)

    def _stopped_wait(self, statement: ast.Wait) -> None:
        value = statement.duration
        if isinstance(value, ast.Literal) and isinstance(value.value, Quantity):
            seconds = value.value
            if seconds.kind is Kind.TIME and seconds.value > STOPPED_SCRIPT_LIMIT:
                self.warn("W103", statement.span, duration=str(seconds))

    def _speed_limit(self, statement: ast.Statement) -> None:
        """`drive 30 cm/s` on a Root: the robot's top speed (the protocol table's wheel-speed
        range), said in the unit the child wrote, before the run: an error for the robot
        checked for (E123), a warning naming the robots it is too fast for when none is (W105)."""
        if not isinstance(statement, ast.Drive | ast.SetWheels):
            return
        fields = ("speed",) if isinstance(statement, ast.Drive) else ("left", "right")
        for field_name in fields:
            value = getattr(statement, field_name)
            speed = value.value if isinstance(value, ast.Literal) else None
            if not isinstance(speed, Quantity) or speed.kind is not Kind.SPEED:
                continue
            robots = [self.robot] if self.robot is not None else list(RobotModel)
            too_fast: dict[float, list[str]] = {}
            for robot in robots:
                low, high = wheel_speed_range(robot)
                if not low <= speed.value <= high:
                    top = float(high if speed.value > 0 else -low)
                    too_fast.setdefault(top, []).append(robot.display_name)
            for top, names in too_fast.items():
                limit = str(speed.with_value(top))
                if self.robot is not None:
                    self.report("E123", value.span, robot=names[0], limit=limit, value=str(speed))
                else:
                    robot_names = " and ".join(names)
                    self.warn("W105", value.span, robots=robot_names, limit=limit,
                              value=str(speed))  # fmt: skip

    def _robot_support(self, statement: ast.Statement) -> None:
        if self.robot is None:
            return
        action = unsupported_action(statement, self.robot)
        if action is not None:
            self.warn(
                "W102", statement.span, robot=self.robot.display_name, action=Described(action)
            )

    # ---- expressions ---------------------------------------------------------------------

    def _expression(self, expression: ast.Expression, scope: _Scope | None) -> Kind | None:
        kind = self._compute(expression, scope)
        if kind is not None:
            self.kinds[expression] = kind
        return kind

    def _compute(self, expression: ast.Expression, scope: _Scope | None) -> Kind | None:
        if not isinstance(expression, ast.AnyExpression):
            return None  # `(1 cm, 2 cm)`, a node only a syntax error leaves: already reported
        node = expression
        match node:
            case ast.Literal(value=value):
                return kind_of(value)
            case ast.Variable():
                return self._variable(node, scope)
            case ast.SensorRead():
                self._sensor_support(node)
                return _SENSOR_KINDS[node.sensor]
            case ast.WithUnit():
                return self._with_unit(node, scope)
            case ast.Unary():
                operand = self._expression(node.operand, scope)
                if operand is None:
                    return None
                return self._apply(node.span, lambda: unary_kind(node.op, operand))
            case ast.Binary():
                return self._binary(node, scope)
            case ast.FunctionCall():
                return self._function(node, scope)
            case ast.ProcedureCall():
                return self._call(node.name, node.arguments, node.span, node.span, scope,
                                  as_value=True)  # fmt: skip
            case _:
                ast.assert_never(node)

    def _variable(
        self, variable: ast.Variable, scope: _Scope | None, *, said: bool = False
    ) -> Kind | None:
        if scope is not None and variable.name in scope.parameters:
            return None
        if variable.name in self.variable_kinds:
            return self.variable_kinds[variable.name]
        if scope is not None and variable.name not in self.unsure_names:
            self._unknown_name(variable.name, variable.span, scope, said=said)
        return None

    def _unknown_name(
        self, name: str, span: Span, scope: _Scope, *, said: bool = False, colour: bool = False
    ) -> None:
        candidates = [*self.variable_kinds, *scope.parameters, *self.procedures]
        better = self._suggestion(span, name, candidates, colour=colour)
        if better is not None and not said:
            self.diagnostics.append(better)
            return
        suggestion = _suggest(did_you_mean(name, candidates))
        plain = diagnostic("E102", span, name=name, suggestion="")
        if said and not suggestion:  # `say hello`: words that lost their quotes, not a variable
            words = self._source(span)
            line = self._rewritten(span, f'"{words}"')
            found = diagnostic("E118", span, words=words, write=write_line(line) if line else "")
            self.diagnostics.append(self._offer(found, span, f'"{words}"', plain))
        elif suggestion:
            found = diagnostic("E102", span, name=name, suggestion=suggestion)
            self.diagnostics.append(self._offer(found, span, _suggested(suggestion), plain))
        else:
            self.diagnostics.append(plain)

    def _with_unit(self, expression: ast.WithUnit, scope: _Scope | None) -> Kind | None:
        operand = self._expression(expression.operand, scope)
        if operand is not None:
            self._apply(expression.span, lambda: with_unit_kind(expression.unit, operand))
        return unit_named(expression.unit).kind  # even after a mistake: no knock-on errors

    def _binary(self, expression: ast.Binary, scope: _Scope | None) -> Kind | None:
        parts = _added(expression)
        if len(parts) > 2 and self._mixes_text(parts):  # `"I bumped " + n + " times"`
            for part in parts:
                self._expression(part, scope)
            self._join(expression, parts)
            return None
        left = self._expression(expression.left, scope)
        right = self._expression(expression.right, scope)
        if expression.op in ("=", "!="):
            self._sensor_colour(expression.left, expression.right)
            self._sensor_colour(expression.right, expression.left)
        if left is None or right is None:
            return Kind.BOOLEAN if expression.op in ("=", "!=", "<", ">", "<=", ">=") else None
        if expression.op == "+" and Kind.TEXT in (left, right) and left is not right:
            self._join(expression, [expression.left, expression.right])
            return None
        left_unit = _written_unit(expression.left)
        right_unit = _written_unit(expression.right)
        if self._unit_missing(expression, left, right):
            return Kind.BOOLEAN
        return self._apply(
            expression.span,
            lambda: binary_kind(expression.op, left, right, left_unit, right_unit),
        )

    def _unit_missing(self, expression: ast.Binary, left: Kind, right: Kind) -> bool:
        """A bare number compared with a value that has a unit (`timer > 10`, Scratch's way):
        E127 proposes the number with the unit the other side's kind is written in (`10
        seconds`); when that doesn't hold, E110 says what can't be compared."""
        if expression.op not in ("=", "!=", "<", ">", "<=", ">="):
            return False
        sides = ((expression.left, left, right), (expression.right, right, left))
        for number, kind, other in sides:
            if not (kind is Kind.NUMBER and other.is_quantity and other is not Kind.NUMBER):
                continue
            if not isinstance(number, ast.Literal) or _written_unit(number):
                continue
            written = self._source_of(number)
            with_unit = f"{written} {other.example.split(' ', 1)[1]}"
            plain = diagnostic("E110", expression.span, action=Described("compare"),
                               left=left.described, right=right.described)  # fmt: skip
            found = diagnostic("E127", number.span, number=written, wanted=other.described,
                               example=Code(with_unit, quoted=False), write="")  # fmt: skip
            rewrite = self._rewritten(number.span, with_unit)
            if rewrite is not None:
                found = found.with_values(write=write_line(rewrite))
            self.diagnostics.append(self._offer(found, number.span, with_unit, plain))
            return True
        return False

    def _mixes_text(self, parts: list[ast.Expression]) -> bool:
        kinds = [self._quiet_kind(part) for part in parts]
        return Kind.TEXT in kinds and any(kind not in (None, Kind.TEXT) for kind in kinds)

    def _join(self, expression: ast.Binary, parts: list[ast.Expression]) -> None:
        """Text put together with `+`: the whole of it as `join(...)` (numbers added before
        the first text stay one sum, as `+` read them)."""
        kinds = [self.kinds.get(part) for part in parts]
        first_text = kinds.index(Kind.TEXT) if Kind.TEXT in kinds else 0
        if first_text > 1:
            start, end = parts[0].span, parts[first_text - 1].span
            summed = Span(start.line, start.column, end.end_line, end.end_column)
            values = [self._source(summed), *map(self._source_of, parts[first_text:])]
        else:
            values = [self._source_of(part) for part in parts]
        joined = f"join({', '.join(values)})"
        found = diagnostic("E121", expression.span, values=", ".join(values))
        self.diagnostics.append(
            self._offer(found, expression.span, joined, diagnostic("E125", expression.span))
        )

    def _offer(
        self, found: Diagnostic, span: Span, text: str, plain: Diagnostic | None = None
    ) -> Diagnostic:
        """``found`` proposing its line with ``span`` written as ``text`` (rootlang.verify);
        as it is when the span is not on one line."""
        rewrite = self._rewritten(span, text)
        if rewrite is None:
            return found.without_suggestion() if plain is None else plain
        return found.offering(rewrite, plain)

    def _rewritten(self, span: Span, text: str) -> str | None:
        """The line of a one-line ``span`` with the span written as ``text``."""
        if span.line != span.end_line or not 0 < span.line <= len(self.lines):
            return None
        line = self.lines[span.line - 1]
        return (line[: span.column - 1] + text + line[span.end_column - 1 :]).strip()

    def _source_of(self, expression: ast.Expression) -> str:
        return self._source(expression.span)

    def _source(self, span: Span) -> str:
        """The text of a one-line span, as the child wrote it."""
        if span.line != span.end_line or not 0 < span.line <= len(self.lines):
            return "..."
        return self.lines[span.line - 1][span.column - 1 : span.end_column - 1].strip()

    def _binary_kinds(self, op: str, left: Kind, right: Kind, span: Span) -> Kind | None:
        return self._apply(span, lambda: binary_kind(op, left, right))

    def _sensor_colour(self, sensor: ast.Expression, other: ast.Expression) -> None:
        reads_colour = isinstance(sensor, ast.SensorRead) and sensor.sensor is ast.SensorKind.COLOR
        colour = other.value if isinstance(other, ast.Literal) else None
        if reads_colour and isinstance(colour, Color) and not can_be_seen(colour):
            self.report("E111", other.span, color=str(colour))

    def _function(self, call: ast.FunctionCall, scope: _Scope | None) -> Kind | None:
        kinds = [self._expression(argument, scope) for argument in call.arguments]
        wanted = FUNCTIONS[call.function]
        if call.function == "rgb":  # each channel, so the mistake is underlined where it is
            for argument, kind in zip(call.arguments, kinds, strict=True):
                if kind is not None:
                    self._apply(argument.span, functools.partial(rgb_channel_kind, kind))
            return Kind.COLOR
        if not wanted.takes(len(call.arguments)):
            self.report("E103", call.span, name=call.function, expected=_values(wanted.values),
                        given=len(call.arguments))  # fmt: skip
            return None
        if any(kind is None for kind in kinds):
            return Kind.TEXT if call.function == "join" else None
        known = [kind for kind in kinds if kind is not None]
        return self._apply(call.span, lambda: function_kind(call.function, known))

    def _call(
        self,
        name: str,
        arguments: tuple[ast.Expression, ...],
        name_span: Span,
        span: Span,
        scope: _Scope | None,
        *,
        as_value: bool,
    ) -> Kind | None:
        procedure = self.procedures.get(name)
        if procedure is None and scope is not None and name not in self.unsure_names:
            better = self._suggestion(name_span, name, self.procedures)
            if better is not None and better.code == "E023":  # `stopp moving`: one mistake
                self.diagnostics.append(better)
                return None
        for argument in arguments:
            self._expression(argument, scope)
        if procedure is None:
            if scope is not None and name not in self.unsure_names:
                candidates = [*forms.STATEMENT_WORDS, *self.procedures]
                suggestion = _suggest(did_you_mean(name, candidates))
                found = diagnostic("E101", name_span, name=name, suggestion=suggestion)
                self.diagnostics.append(
                    self._offer(found, name_span, _suggested(suggestion)) if suggestion else found
                )
            return None
        if len(arguments) != len(procedure.parameters):
            if scope is not None:
                self.report("E103", span, name=name, expected=_values(len(procedure.parameters)),
                            given=len(arguments))  # fmt: skip
            return None
        if as_value and name not in self.returns_value and scope is not None:
            self.report("E107", span, name=name)
        if scope is not None:
            self._argument_kinds(procedure, arguments)
        return None

    def _argument_kinds(
        self, procedure: ast.Procedure, arguments: tuple[ast.Expression, ...]
    ) -> None:
        """`square 20` where `square` does `move size`: said at the call, in the child's words."""
        if procedure.name not in self.parameter_uses:
            self.parameter_uses[procedure.name] = _parameter_uses(procedure)
        uses = self.parameter_uses[procedure.name]
        for parameter, argument in zip(procedure.parameters, arguments, strict=True):
            kind = self.kinds.get(argument)
            use = uses.get(parameter.name)
            if kind is None or use is None or kind is use[0]:
                continue
            wanted, statement = use
            example = wanted.example
            if kind is Kind.NUMBER and isinstance(argument, ast.Literal) and wanted.is_quantity:
                line = self._source(Span(argument.span.line, 1, argument.span.line, 10_000))
                text = self._source(argument.span)
                unit = wanted.example.split(" ", 1)[-1]
                example = line.replace(text, f"{text} {unit}", 1)
            inside = self._source(statement.span)
            plain = diagnostic("E126", argument.span, name=procedure.name,
                               wanted=wanted.described, parameter=parameter.name,
                               line=statement.span.line, inside=inside)  # fmt: skip
            if example == wanted.example:  # not the line written right: nothing to try
                self.diagnostics.append(plain)
                continue
            found = plain.with_values(example=Code(example, quoted=False))
            self.diagnostics.append(replace(found, code="E122").offering(example, plain))

    def _sensor_support(self, read: ast.SensorRead) -> None:
        feature = SENSOR_FEATURES.get(read.sensor)
        if feature and self.robot is not None and missing_feature(feature, self.robot):
            action = f"read the {feature}"
            self.warn("W102", read.span, robot=self.robot.display_name, action=Described(action))

    def _apply(self, span: Span, rule: Callable[[], Kind]) -> Kind | None:
        try:
            return rule()
        except UnitError as error:
            self.report(error.code, span, **error.values)
            return None


@functools.cache
def wheel_speed_range(robot: RobotModel) -> tuple[int, int]:
    """The wheel speeds ``robot`` takes, in mm/s, from the protocol's packet table."""
    from rootlang.protocol import spec  # the packet table loads lazily

    allowed = spec("set_wheel_speeds").field("left").range_for(robot)
    assert allowed is not None
    return allowed


def unsupported_action(statement: ast.Node, robot: RobotModel) -> str | None:
    """What ``statement`` does that ``robot`` can't ("use the eraser"), or None: the checks warn
    (W102) and the runtime stops with an error (E201) by this one rule."""
    feature, action = _statement_feature(statement)
    return action if feature and missing_feature(feature, robot) else None


def _statement_feature(statement: ast.Node) -> tuple[str | None, str]:
    """The feature a statement needs and what it does with it, as its form says."""
    needs = forms.NEEDS.get(type(statement))
    return (None, "") if needs is None else needs.of(statement)


def _parameter_uses(procedure: ast.Procedure) -> dict[str, tuple[Kind, ast.Statement]]:
    """Parameters a command inside uses on their own (`move size`): the kind it needs there."""
    names = {parameter.name for parameter in procedure.parameters}
    uses: dict[str, tuple[Kind, ast.Statement]] = {}
    for node in _walk_block(procedure.body):
        if not isinstance(node, ast.Statement):
            continue
        for (owner, field_name), rule in ARGUMENT_RULES.items():
            value = getattr(node, field_name, None) if isinstance(node, owner) else None
            if isinstance(value, ast.Variable) and value.name in names:
                uses.setdefault(value.name, (rule.kind, node))
    return uses


def _is_colour(statement: ast.Statement, field: str) -> bool:
    rule = ARGUMENT_RULES.get((type(statement), field))
    return rule is not None and rule.kind is Kind.COLOR


def _grammar_suggestion(
    lines: tuple[str, ...], span: Span, name: str, names: Iterable[str], *, colour: bool = False
) -> Diagnostic | None:
    """What the grammar takes in place of an unknown name (rootlang.grammar.suggest)."""
    if not 0 < span.line <= len(lines):
        return None
    from rootlang.grammar import lark_parser  # lark loads lazily
    from rootlang.grammar.suggest import unknown_word

    return unknown_word(lark_parser(), lines[span.line - 1], span, name, names, colour=colour)


def _walk_block(block: ast.Block) -> list[ast.Node]:
    nodes: list[ast.Node] = []
    for statement in block:
        nodes.extend(ast.walk(statement))
    return nodes


def _variable_name(node: ast.Node) -> str | None:
    if isinstance(node, ast.Variable | ast.SetVariable | ast.ChangeVariable):
        return node.name
    return None


def _added(expression: ast.Expression) -> list[ast.Expression]:
    """The values of ``a + b + c`` in order (a bracketed sum on the right stays one value)."""
    rights: list[ast.Expression] = []
    while isinstance(expression, ast.Binary) and expression.op == "+":
        rights.append(expression.right)
        expression = expression.left
    return [expression, *reversed(rights)]


def _written_unit(expression: ast.Expression) -> str:
    if isinstance(expression, ast.Literal) and isinstance(expression.value, Quantity):
        return expression.value.unit
    if isinstance(expression, ast.WithUnit):
        return expression.unit
    return ""


def _values(count: int) -> str:
    if count == 0:
        return "no values"
    return "1 value" if count == 1 else f"{count} values"


def _suggested(suggestion: Suggestion | str) -> str:
    """The word a " Did you mean ...?" suggests."""
    return suggestion.word if isinstance(suggestion, Suggestion) else ""


def _suggest(word: str | None) -> Suggestion | str:
    """Suggestions for one- and two-letter names would be guesses, not help."""
    return Suggestion(word) if word and len(word) > 2 else ""
