"""Random valid programs, generated from the language description, for round-trip tests.

Every statement, event and sensor form of ``rootlang.forms`` can appear (a new form is covered
without touching this file), with values of every kind, brackets, words in odd case and spacing,
the language's alternative spellings, comments (own-line and end-of-line) and blank lines.
"""

from __future__ import annotations

import random
from dataclasses import dataclass, field

from rootlang import ast, forms
from rootlang.colors import NAMED_COLORS
from rootlang.forms import Body, Choice, Form, Slot, Text, Word
from rootlang.units import UNITS, Kind

VARIABLES = ("a", "count", "size", "speed_2")
SPELLINGS = {"repeat forever": ("forever", "repeat forever"), "color": ("color", "colour")}
COMMENTS = ("draw it", "", "  two spaces", "# heading", "why: the robot turns", "TODO fix")


@dataclass
class Generator:
    seed: int
    rng: random.Random = field(init=False)
    procedures: dict[str, int] = field(default_factory=dict)

    def __post_init__(self) -> None:
        self.rng = random.Random(self.seed)

    # ---- words ---------------------------------------------------------------------------

    def word(self, text: str) -> str:
        text = self.rng.choice(SPELLINGS.get(text, (text,)))
        if self.rng.random() < 0.15:
            text = text.upper() if self.rng.random() < 0.5 else text.title()
        return text

    def join(self, words: list[str]) -> str:
        gap = "  " if self.rng.random() < 0.1 else " "
        return gap.join(word for word in words if word)

    # ---- values ----------------------------------------------------------------------------

    def number(self) -> str:
        return self.rng.choice(["0", "1", "4", "10", "2.5", ".5", "360", "007", "1.250"])

    def literal(self, kind: Kind | None) -> str:
        kind = kind or self.rng.choice(list(Kind))
        if kind is Kind.NUMBER:
            return self.number()
        if kind.is_quantity:
            if kind is Kind.FREQUENCY and self.rng.random() < 0.5:
                note = self.rng.choice(["C4", "c#5", "Bb3", "a4", "G2"])
                return f"{self.word('note')} {note}"
            unit = self.rng.choice([u.name for u in UNITS.values() if u.kind is kind])
            space = "" if self.rng.random() < 0.3 else " "
            sign = "-" if self.rng.random() < 0.15 else ""
            return f"{sign}{self.number()}{space}{self.word(unit)}"
        if kind is Kind.TEXT:
            return self.rng.choice(['"hello"', '"go"', '""', '"a, b"', '“say "hi"”'])
        if kind is Kind.BOOLEAN:
            return self.word(self.rng.choice(["true", "false"]))
        return self.rng.choice([
            self.word(self.rng.choice(list(NAMED_COLORS))), "#FF8000", "#00ff7f",
            f"rgb {self.number()} 128 {self.number()}",
        ])  # fmt: skip

    def expression(self, kind: Kind | None = None, depth: int = 0) -> str:
        roll = self.rng.random()
        if depth >= 2 or roll < 0.35:
            return self.literal(kind)
        if roll < 0.45:
            return self.rng.choice(VARIABLES)
        if roll < 0.55:
            sensor = self.rng.choice(list(forms.SENSORS.values()))
            return self.form_text(sensor.form)
        inner = self.bracket(self.expression(kind, depth + 1))
        other = self.bracket(self.expression(kind, depth + 1))
        if roll < 0.75:
            op = self.rng.choice(["+", "-", "*", "/", self.word("mod"), "×", "÷"])
            return f"{inner} {op} {other}"
        if roll < 0.82:
            op = self.rng.choice(["=", "==", "!=", "<>", "<", ">=", "≤", "≠"])
            logic = self.rng.choice(["", f" {self.word('and')} true", f" {self.word('or')} x2"])
            return f"{inner} {op} {other}{logic}"
        if roll < 0.86:
            return f"{self.word('not')} {inner}"
        if roll < 0.89:
            return f"-{inner}"
        if roll < 0.93:
            function = self.rng.choice(["round", "abs", "sqrt", "sin", "cos"])
            return f"{self.word(function)} {inner}"
        if roll < 0.96:
            return f"{self.word('random')} {inner} {self.word('to')} {other}"
        if roll < 0.98:
            function = self.rng.choice(["min", "max", "join"])
            return f"{self.word(function)}({inner}, {other})"
        unit = self.rng.choice([unit.name for unit in UNITS.values()])
        return f"{self.rng.choice(VARIABLES)} {self.word(unit)}"

    def bracket(self, text: str) -> str:
        simple = text.replace("_", "").replace(".", "").isalnum()
        return text if simple and self.rng.random() < 0.7 else f"({text})"

    # ---- lines -----------------------------------------------------------------------------

    def form_text(self, form: Form) -> str:
        words: list[str] = []
        for part in form.parts:
            if isinstance(part, Word):
                words.append(" ".join(self.word(w) for w in part.text.split()))
            elif isinstance(part, Choice):
                written = part.words(self.rng.choice([value for value, _ in part.options]))
                words.append(self.word(written) if written else "")
            elif isinstance(part, Slot):
                words.append(self.expression(part.kind))
            elif isinstance(part, Text):
                words.append('"ready"')
        return self.join(words)

    def comment(self) -> str:
        return "#" + self.rng.choice(COMMENTS)

    def end(self) -> str:
        return f"  {self.comment()}" if self.rng.random() < 0.15 else ""

    def colon(self) -> str:
        return ":" if self.rng.random() < 0.2 else ""

    def block(self, depth: int, lines: list[str], size: int) -> None:
        indent = "    " * depth
        for _ in range(size):
            if self.rng.random() < 0.1:
                lines.append("")
            if self.rng.random() < 0.1:
                lines.append("    " * self.rng.randint(0, depth) + self.comment())
            self.statement(depth, indent, lines)

    def statement(self, depth: int, indent: str, lines: list[str]) -> None:
        roll = self.rng.random()
        nested = depth < 3
        if roll < 0.08 and nested:
            lines.append(f"{indent}{self.word('if')} {self.expression(Kind.BOOLEAN)}"
                         f"{self.colon()}{self.end()}")  # fmt: skip
            self.block(depth + 1, lines, self.rng.randint(1, 2))
            for _ in range(self.rng.randint(0, 2)):
                lines.append(f"{indent}else if {self.expression(Kind.BOOLEAN)}{self.end()}")
                self.block(depth + 1, lines, 1)
            if self.rng.random() < 0.5:
                lines.append(f"{indent}{self.word('else')}{self.colon()}{self.end()}")
                self.block(depth + 1, lines, self.rng.randint(1, 2))
            return
        if roll < 0.14:
            values = ", ".join(self.expression() for _ in range(self.rng.randint(0, 3)))
            lines.append(f"{indent}{self.word('print')} {values}".rstrip() + self.end())
            return
        if roll < 0.2:
            name = self.rng.choice(VARIABLES)
            lines.append(f"{indent}set {name} to {self.expression()}{self.end()}")
            return
        if roll < 0.23:
            lines.append(f"{indent}change {self.rng.choice(VARIABLES)} by {self.expression()}")
            return
        if roll < 0.27 and self.procedures:
            name, count = self.rng.choice(sorted(self.procedures.items()))
            values = ", ".join(self.expression() for _ in range(count))
            lines.append(f"{indent}{name} {values}".rstrip())
            return
        form = self.rng.choice(forms.STATEMENT_FORMS)
        has_body = any(isinstance(part, Body) for part in form.parts)
        if (has_body and not nested) or form.node is ast.Return:
            form, has_body = forms.STATEMENT_FORMS[0], False
        header = self.form_text(form)
        lines.append(f"{indent}{header}{self.colon() if has_body else ''}{self.end()}")
        if has_body:
            self.block(depth + 1, lines, self.rng.randint(1, 3))

    def program(self) -> str:
        lines: list[str] = []
        if self.rng.random() < 0.5:
            lines.append(self.comment())
        for index in range(self.rng.randint(0, 2)):
            name = f"shape{index}"
            parameters = ["size", "n"][: self.rng.randint(0, 2)]
            self.procedures[name] = len(parameters)
        for name, count in self.procedures.items():
            lines.append(f"to {name} {', '.join(['size', 'n'][:count])}".rstrip() + self.colon())
            self.block(1, lines, self.rng.randint(1, 3))
            lines.append("")
        for _ in range(self.rng.randint(1, 3)):
            event = self.rng.choice(forms.EVENT_FORMS)
            lines.append(f"{self.word('when')} {self.form_text(event)}{self.colon()}{self.end()}")
            self.block(1, lines, self.rng.randint(1, 4))
            if self.rng.random() < 0.7:
                lines.append("")
        if self.rng.random() < 0.3:
            lines.append("    " * self.rng.randint(0, 1) + self.comment())
        return "\n".join(lines) + "\n"


def random_program(seed: int) -> str:
    return Generator(seed).program()
