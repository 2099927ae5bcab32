"""The grammar's rules for what the forms describe, written from them when the grammar loads.

Each statement form (:data:`rootlang.forms.STATEMENT_FORMS`) becomes one alternative of the
``form_statement`` rule, or of ``form_header`` for a form with a body (``repeat 4``, ``while
x < 3``: the header's line, its body nested afterwards by :mod:`rootlang.grammar.blocks`), each
event form (:data:`rootlang.forms.EVENT_FORMS`:
what a ``when`` line waits for) one of ``form_event``, each sensor's form
(:data:`rootlang.forms.SENSORS`) one of ``form_sensor``, named after its block (``root_turn``):
a word is written as the grammar's keywords (``"go"i "to"i "x"i``) or as the token it names
(``AND_WAIT``); a choice is the token it names, whose pattern is made here from the words of
every choice that names it (``DIRECTION.2: /(left|right)(?![\\w])/i``), or a rule of
``root.lark`` it names (``color_name``), or, naming none, one alternative for each of its
options (``dock`` / ``undock``); a value slot is ``expr``; a text is ``STRING``. :class:`Built`
then tells :class:`rootlang.grammar.build.LineBuilder` how to make the node from what the rule
read, the same way for every form.

An event may be written as a condition is (``when bumper left pressed``, ``when docked``: the
sensor's alternative has the same symbols as the event's), so after ``when`` the grammar reads
both ways; ``form_event`` has the higher priority, so lark's parser takes the event when the
line ends there, and the condition when it goes on (``when bumper left pressed and x > 3``).
:func:`event_read_as` makes the same event of such a condition wherever one is made by other
means (brackets, a block).

The named colours and the built-in functions' tokens are written from
:data:`rootlang.colors.NAMED_COLORS` and :data:`rootlang.units.FUNCTIONS` (:func:`value_rules`),
and :func:`token_words` tells the error messages the words of each token written here.

So a new statement or event is a node and a form (and how it runs): no rule and no builder by
hand. The hand-written rules of ``root.lark`` stay for what the forms do not describe — the
headers ``when``, ``to``, ``if`` and ``else``, expressions, ``print``, ``set``/``change`` and
procedure calls — and for the mistakes the grammar reads on purpose (``set x = 5``, ``repeat``
alone). A word a form reads but does not print is optional (``times`` in ``repeat 4 times``),
and a form's ``also`` words may stand for its first part (``forever`` for ``repeat forever``).
"""

from __future__ import annotations

import functools
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from rootlang import ast, forms
from rootlang.colors import NAMED_COLORS
from rootlang.diagnostics import Span
from rootlang.forms import Body, Choice, Form, Slot, Text, Word
from rootlang.units import FUNCTIONS, OPERATORS, Written

__all__ = ["Built", "built", "canonical", "event_read_as", "grammar_text", "token_words"]

CHOICE_PRIORITY = 2  # above NAME: `turn left` is the direction, not a name
# above the sensors': `when docked` is the event, `when docked and x` the condition
EVENT_PRIORITY = 2
# Words read as a token of root.lark's: `colour` or `color`, as people spell it.
WORD_TOKENS = {"color": "_COLOR_WORD"}


@dataclass(frozen=True)
class Built:
    """How one generated alternative makes its node: the form, and the values of the choices
    this alternative spells out as keywords (``undock``: docking False)."""

    form: Form
    spelled: Mapping[str, Any]

    def node(self, span: Span, children: list[Any]) -> ast.Node:
        """The node, from the rule's children in order: a named token for each word with a
        token of its own and each choice with one, a value for each slot, a STRING for each
        text (keywords leave no child)."""
        fields: dict[str, Any] = {**self.form.fixed, **self.spelled}
        read = iter(children)
        for part in self.form.parts:
            if isinstance(part, Word):
                if part.terminal and not part.terminal.startswith("_"):
                    next(read)
            elif isinstance(part, Choice):
                if part.terminal:
                    fields[part.field] = part.value_of_words(canonical(next(read)))
            elif isinstance(part, Slot):
                fields[part.field] = next(read)
            elif isinstance(part, Text):
                fields[part.field] = str(next(read))[1:-1]
            elif isinstance(part, Body):  # a block header's: its lines are nested afterwards
                fields[part.field] = ()
        return self.form.node(span, **fields)

    def children(self, node: ast.Node) -> list[Any]:
        """What this alternative's rule reads for ``node``, as :meth:`node` takes it (the words
        of a choice's token, a slot's value, a text in quotes)."""
        read: list[Any] = []
        for part in self.form.parts:
            if isinstance(part, Word):
                if part.terminal and not part.terminal.startswith("_"):
                    read.append(part.text)
            elif isinstance(part, Choice):
                if part.terminal:
                    read.append(part.words(getattr(node, part.field)))
            elif isinstance(part, Slot):
                read.append(getattr(node, part.field))
            elif isinstance(part, Text):
                read.append(f'"{getattr(node, part.field)}"')
        return read


def canonical(token: object) -> str:
    """Words as read, in canonical form: lower case, single spaces (``Turn  LEFT``: ``turn
    left``)."""
    return " ".join(str(token).lower().split())


def _keywords(words: str) -> list[str]:
    return [WORD_TOKENS.get(word, f'"{word}"i') for word in words.split()]


def _alternatives(form: Form) -> list[tuple[list[str], dict[str, Any]]]:
    """The form's alternatives: their symbols, and the choice values each spells out."""
    found: list[tuple[list[str], dict[str, Any]]] = [([], {})]
    for index, part in enumerate(form.parts):
        if isinstance(part, Word):
            symbols = [part.terminal] if part.terminal else _keywords(part.text)
            if not part.printed:  # read if it is there
                symbols = [f"[{' '.join(symbols)}]"]
            starts = (
                [symbols, *(_keywords(word) for word in form.also)] if index == 0 else [symbols]
            )
            found = [(written + first, spelled) for written, spelled in found for first in starts]
        elif isinstance(part, Choice) and not part.terminal:
            found = [
                (written + _keywords(words), {**spelled, part.field: value})
                for written, spelled in found
                for value, words in part.options
            ]
        elif isinstance(part, Body):
            assert part is form.parts[-1], f"{form.block}: the body comes last"
        else:  # one symbol: the choice's token, a value, a text
            symbol = part.terminal if isinstance(part, Choice) else "expr"
            symbol = "STRING" if isinstance(part, Text) else symbol
            found = [([*written, symbol], spelled) for written, spelled in found]
    return found


def form_rules(
    statements: Sequence[Form], sensors: Sequence[Form], events: Sequence[Form]
) -> tuple[str, dict[str, Built]]:
    """The lark text of the ``form_statement``, ``form_header``, ``form_sensor`` and
    ``form_event`` rules and of the choices' tokens, and how each alternative (by its rule
    name) is built: a statement's form with a body is a block header's."""
    built: dict[str, Built] = {}
    rules = []
    written_as = (
        ("form_statement", _statement_forms(statements)),
        ("form_header", _header_forms(statements)),
        ("form_sensor", sensors),
        (f"form_event.{EVENT_PRIORITY}", events),
    )
    for rule, written in written_as:
        lines: list[str] = []
        for form in written:
            alternatives = _alternatives(form)
            for index, (symbols, spelled) in enumerate(alternatives):
                name = form.block if len(alternatives) == 1 else f"{form.block}__{index}"
                built[name] = Built(form, spelled)
                lines.append(f"{' '.join(symbols)} -> {name}")
        rules.append(f"?{rule}: " + "\n    | ".join(lines))
    tokens = _choice_tokens([*statements, *sensors, *events])
    return "\n\n".join(rules) + "\n\n" + "\n".join(tokens) + "\n", built


def token_words() -> dict[str, tuple[str, ...]]:
    """The words of each token written from the forms, as the error messages name them: a
    choice's options (``DIRECTION``: ``left``, ``right``), a word's own token (``AND_WAIT``)."""
    found: dict[str, list[str]] = {}
    for form in (*forms.STATEMENT_FORMS, *forms.EVENT_FORMS, *_sensor_forms()):
        for part in form.parts:
            if isinstance(part, Choice) and part.terminal.isupper():
                spelled = [words for _, words in part.options if words]
            elif isinstance(part, Word) and part.terminal.isupper():
                spelled = [part.text]
            else:
                continue
            known = found.setdefault(part.terminal, [])
            known += [words for words in spelled if words not in known]
    return {terminal: tuple(spelled) for terminal, spelled in found.items()}


def value_rules() -> str:
    """The rules of the values the grammar reads by name: ``color_name`` (every named colour,
    :data:`rootlang.colors.NAMED_COLORS`), the tokens of the built-in functions written
    ``round x`` (FUNCTION1) and ``min(a, b)`` (FUNCTION2), from :data:`rootlang.units.FUNCTIONS`,
    and the operators' tokens (COMPARE, ADD_OP, MINUS, MUL_OP), from
    :data:`rootlang.units.OPERATORS`."""
    colours = " | ".join(f'"{name}"i' for name in NAMED_COLORS)
    lines = [f"!color_name: {colours}"]
    for token, way in (("FUNCTION1", Written.ONE_VALUE), ("FUNCTION2", Written.BRACKETS)):
        names = "|".join(name for name, function in FUNCTIONS.items() if function.written is way)
        lines.append(f"{token}.{CHOICE_PRIORITY}: /({names})(?![\\w])/i")
    return "\n".join([*lines, *_operator_tokens()]) + "\n"


def _operator_tokens() -> list[str]:
    """``MUL_OP.2: "*" | "/" | "×" | "÷" | /mod(?![\\w])/i``: each operator token's spellings, a
    word as a whole word above NAME (`mod`), a sign as it is."""
    spellings: dict[str, list[str]] = {}
    for operator in OPERATORS.values():
        if operator.token:
            spellings.setdefault(operator.token, []).extend((operator.written, *operator.also))
    tokens = []
    for token, spelled in spellings.items():
        words = [spelling for spelling in spelled if spelling.isalpha()]
        priority = f".{CHOICE_PRIORITY}" if words else ""
        written = [f"/{s}(?![\\w])/i" if s in words else f'"{s}"' for s in spelled]
        tokens.append(f"{token}{priority}: {' | '.join(written)}")
    return tokens


def _choice_tokens(written: Iterable[Form]) -> list[str]:
    """``NAME.2: /(word|other words)(?![\\w])/i`` for each token a choice names: its words
    those of every choice naming it, longest first, a space written as any spaces."""
    spellings: dict[str, set[str]] = {}
    for form in written:
        for part in form.parts:
            if isinstance(part, Choice) and part.terminal.isupper():  # not a rule of root.lark
                words = {words for _, words in part.options if words} | set(part.also)
                spellings.setdefault(part.terminal, set()).update(words)
    tokens = []
    for terminal, words in spellings.items():
        ordered = sorted(words, key=lambda word: (-len(word), word))
        pattern = "|".join(r"[ \t]+".join(word.split()) for word in ordered)
        tokens.append(f"{terminal}.{CHOICE_PRIORITY}: /({pattern})(?![\\w])/i")
    return tokens


def _statement_forms(statements: Iterable[Form]) -> tuple[Form, ...]:
    """The statement forms of one line: those without a body."""
    return tuple(form for form in statements if not any(isinstance(p, Body) for p in form.parts))


def _header_forms(statements: Iterable[Form]) -> tuple[Form, ...]:
    """The statement forms of a block header (``repeat 4``, ``while x < 3``): with a body."""
    return tuple(form for form in statements if any(isinstance(p, Body) for p in form.parts))


def _sensor_forms() -> tuple[Form, ...]:
    """The sensors' forms (what the grammar reads as a sensor's value)."""
    return tuple(sensor.form for sensor in forms.SENSORS.values())


@dataclass(frozen=True)
class _Written:
    """What is written from the forms: the rules' lark text, how each alternative is built (by
    its rule name), and the event each condition's alternative also spells (by the sensor
    form's block and the choices its alternative spells out)."""

    rules: str
    built: dict[str, Built]
    as_event: dict[tuple[str, tuple[tuple[str, Any], ...]], Built]


@functools.cache
def _written() -> _Written:
    """Worked out once, for the grammar's text and for building the nodes alike."""
    statements, sensors, events = forms.STATEMENT_FORMS, _sensor_forms(), forms.EVENT_FORMS
    rules, made = form_rules(statements, sensors, events)
    event_by_symbols = {
        tuple(symbols): Built(form, spelled)
        for form in events
        for symbols, spelled in _alternatives(form)
    }
    as_event = {
        (form.block, tuple(spelled.items())): event_by_symbols[tuple(symbols)]
        for form in sensors
        for symbols, spelled in _alternatives(form)
        if tuple(symbols) in event_by_symbols
    }
    return _Written(rules, made, as_event)


def built() -> dict[str, Built]:
    """How each alternative written from the forms is built, by its rule name."""
    return _written().built


def event_read_as(span: Span, condition: ast.Expression) -> ast.Event:
    """The event a ``when`` line with this condition is read as: the event whose alternative
    has the same symbols as the condition's (``bumper left pressed``: the bumper's event, as
    the grammar reads it), else the condition becoming true."""
    try:
        form = forms.form_of(condition)
    except KeyError:
        form = None
    if form is not None:
        spelled = tuple(
            (part.field, getattr(condition, part.field))
            for part in form.parts
            if isinstance(part, Choice) and not part.terminal
        )
        event = _written().as_event.get((form.block, spelled))
        if event is not None:
            made = event.node(span, Built(form, dict(spelled)).children(condition))
            assert isinstance(made, ast.Event)
            return made
    return ast.ConditionBecomesTrue(span, condition)


def grammar_text(hand: str) -> str:
    """The whole grammar: the hand-written rules of ``root.lark`` and the forms' own."""
    written = "\n// ---- written from rootlang.forms (rootlang/grammar/rules.py) ----\n\n"
    return hand + written + _written().rules + "\n" + value_rules()
