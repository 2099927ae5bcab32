"""The grammar's rules for what the forms describe, written from them when the grammar loads.

Each statement form (:data:`rootlang.forms.STATEMENT_FORMS`, those without a body) becomes one
alternative of the ``form_statement`` rule, each sensor's form (:data:`rootlang.forms.SENSORS`)
one of ``form_sensor``, named after its block (``root_turn``): a word is
written as the grammar's keywords (``"go"i "to"i "x"i``) or as the token it names
(``AND_WAIT``); a choice is the token it names, whose pattern is made here from the words of
every choice that names it (``DIRECTION.2: /(left|right)(?![\\w])/i``), or, naming none, one
alternative for each of its options (``dock`` / ``undock``); a value slot is ``expr``; a text
is ``STRING``. :class:`Built` then tells :class:`rootlang.grammar.build.LineBuilder` how to
make the node from what the rule read, the same way for every form.

So a new statement is a node and a form (and how it runs): no rule and no builder by hand. The
hand-written rules of ``root.lark`` stay for what the forms do not describe — block headers,
events and expressions, ``print``, ``set``/``change`` and procedure calls — and for
the mistakes the grammar reads on purpose (``set x = 5``, ``repeat`` alone).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from rootlang import forms
from rootlang.forms import Body, Choice, Form, Slot, Text, Word

__all__ = ["Built", "form_rules", "grammar_text"]

CHOICE_PRIORITY = 2  # above NAME: `turn left` is the direction, not a name
# Words read as a token of root.lark's: `colour` or `color`, as people spell it.
WORD_TOKENS = {"color": "_COLOR_WORD"}


@dataclass(frozen=True)
class Built:
    """How one generated alternative makes its node: the form, and the values of the choices
    this alternative spells out as keywords (``undock``: docking False)."""

    form: Form
    spelled: Mapping[str, Any]

    def node(self, span: Any, children: list[Any]) -> Any:
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
                    fields[part.field] = part.value_of_words(_words(next(read)))
            elif isinstance(part, Slot):
                fields[part.field] = next(read)
            elif isinstance(part, Text):
                fields[part.field] = str(next(read))[1:-1]
        return self.form.node(span, **fields)


def _words(token: object) -> str:
    return " ".join(str(token).lower().split())


def _keywords(words: str) -> list[str]:
    return [WORD_TOKENS.get(word, f'"{word}"i') for word in words.split()]


def _alternatives(form: Form) -> list[tuple[list[str], dict[str, Any]]]:
    """The form's alternatives: their symbols, and the choice values each spells out."""
    found: list[tuple[list[str], dict[str, Any]]] = [([], {})]
    for part in form.parts:
        if isinstance(part, Word):
            symbols = [part.terminal] if part.terminal else _keywords(part.text)
            found = [(written + symbols, spelled) for written, spelled in found]
        elif isinstance(part, Choice) and not part.terminal:
            found = [
                (written + _keywords(words), {**spelled, part.field: value})
                for written, spelled in found
                for value, words in part.options
            ]
        elif isinstance(part, Body):
            raise ValueError(f"{form.block}: a block header is a rule of root.lark")
        else:  # one symbol: the choice's token, a value, a text
            symbol = part.terminal if isinstance(part, Choice) else "expr"
            symbol = "STRING" if isinstance(part, Text) else symbol
            found = [([*written, symbol], spelled) for written, spelled in found]
    return found


def form_rules(statements: Sequence[Form], sensors: Sequence[Form]) -> tuple[str, dict[str, Built]]:
    """The lark text of the ``form_statement`` and ``form_sensor`` rules and of the choices'
    tokens, and how each alternative (by its rule name) is built."""
    built: dict[str, Built] = {}
    rules = []
    for rule, written in (("form_statement", statements), ("form_sensor", sensors)):
        lines: list[str] = []
        for form in written:
            alternatives = _alternatives(form)
            for index, (symbols, spelled) in enumerate(alternatives):
                name = form.block if len(alternatives) == 1 else f"{form.block}__{index}"
                built[name] = Built(form, spelled)
                lines.append(f"{' '.join(symbols)} -> {name}")
        rules.append(f"?{rule}: " + "\n    | ".join(lines))
    tokens = _choice_tokens([*statements, *sensors])
    return "\n\n".join(rules) + "\n\n" + "\n".join(tokens) + "\n", built


def _choice_tokens(statements: Iterable[Form]) -> list[str]:
    """``NAME.2: /(word|other words)(?![\\w])/i`` for each token a choice names: its words
    those of every choice naming it, longest first, a space written as any spaces."""
    spellings: dict[str, set[str]] = {}
    for form in statements:
        for part in form.parts:
            if isinstance(part, Choice) and part.terminal:
                words = {words for _, words in part.options if words} | set(part.also)
                spellings.setdefault(part.terminal, set()).update(words)
    tokens = []
    for terminal, words in spellings.items():
        ordered = sorted(words, key=lambda word: (-len(word), word))
        pattern = "|".join(r"[ \t]+".join(word.split()) for word in ordered)
        tokens.append(f"{terminal}.{CHOICE_PRIORITY}: /({pattern})(?![\\w])/i")
    return tokens


def statement_forms(statements: Iterable[Form]) -> tuple[Form, ...]:
    """The statement forms the grammar is written from: those without a body."""
    return tuple(form for form in statements if not any(isinstance(p, Body) for p in form.parts))


def sensor_forms() -> tuple[Form, ...]:
    return tuple(sensor.form for sensor in forms.SENSORS.values())


def built() -> dict[str, Built]:
    """How each alternative written from the forms is built, by its rule name (worked out
    once for the forms in force: forms hold dicts, so they key no cache themselves)."""
    statements = forms.STATEMENT_FORMS
    kept = _BUILT.get(id(statements))
    if kept is None or kept[0] is not statements:
        made = form_rules(statement_forms(statements), sensor_forms())[1]
        kept = _BUILT[id(statements)] = (statements, made)
    return kept[1]


_BUILT: dict[int, tuple[tuple[Form, ...], dict[str, Built]]] = {}


def grammar_text(hand: str, statements: tuple[Form, ...]) -> tuple[str, dict[str, Built]]:
    """The whole grammar: the hand-written rules of ``root.lark`` and the forms' own."""
    rules, made = form_rules(statement_forms(statements), sensor_forms())
    return (
        hand + "\n// ---- written from rootlang.forms (rootlang/grammar/rules.py) ----\n\n" + rules,
        made,
    )
