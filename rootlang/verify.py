"""A suggestion is only shown if it is right.

A message that says what to write ("Did you mean ...?", "Write: `...`") carries the line as it
would then be (:attr:`Diagnostic.rewrite`). Before the message is shown, that line is tried in
place: the whole program is read and checked again with the line replaced, and the suggestion
stays only if the line then has no mistake. Otherwise the message explains without the fix
(:attr:`Diagnostic.plain`). A program in another language is tried in its own language. A
rewrite that leaves one mistake whose own message knows the rest (`mve 10` -> `move 10`,
which needs a unit) is followed one step further, so the line shown is the one that works
(`move 10 cm`).

Each try reads the whole program again (without suggestions of its own), so a file gets at
most :data:`MOST_TRIED` tries and a budget of lines read; past it, suggestions are left out
rather than shown untried.

The program's other lines that can't be read are left out of a try, so they hide nothing from
the checks: lines indented under one stay under a plain header (`when started` at the left
edge, `repeat 1` inside a script), which keeps them checked, and the names such a line may
give a value to (`x = 5 (((` sets `x`; a script's or procedure's header names its parameters)
count as set. Its other words do not: `fd hi` is not told `move hi cm` because `print hi (((`
is broken too.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import replace

from rootlang.diagnostics import Diagnostic, source_lines
from rootlang.grammar.habits import UNREADABLE, Above, indented_under, opens_lines, with_habits
from rootlang.wording.shown import write_line

MOST_TRIED = 60  # rewrites tried for one file
MOST_LINES_READ = 150_000  # lines read again for them, all tries together
FOLLOWED = 2  # a rewrite's own rewrite is followed this many steps

# Mistakes about the lines around a line, not its words: a rewrite that opens a block (`repeat
# 4`) where no lines are indented under it yet is right all the same.
ABOUT_OTHER_LINES = frozenset({"E009"})
# What reads a program and gives every diagnostic of it, without suggestions; the names that
# may have a value from lines left out.
Reader = Callable[[str, frozenset[str]], list[Diagnostic]]
# Words before a name that a line which can't be read may give a value: `set x`, `make "x`
# (rootlang's own, `set` and `change`, also in the program's language).
SETTING_WORDS = ("set", "make", "let", "var", "const", "int", "float", "change", "for", "global")
_NAME = re.compile(r"[^\W\d]\w*")


class Verifier:
    """The tries of one file's suggestions: ``text`` is the program as the parser reads it (in
    English), ``read`` gives its mistakes."""

    def __init__(
        self,
        text: str,
        read: Reader,
        in_language: Callable[[str], str],
        unreadable: frozenset[int] = frozenset(),
    ) -> None:
        self.lines = list(source_lines(text))
        self.unreadable = unreadable  # the numbers of the lines that can't be read
        ours = [in_language(f"{word} x to 1").split()[0] for word in ("set", "change")]
        words = "|".join(re.escape(word) for word in {*SETTING_WORDS, *ours})
        self.setting = re.compile(  # `x = 5`, `set [x v] to`, `x++`
            rf"(?<!\w)(?:{words})\s+[\"\[(:]?\s*([^\W\d]\w*)"
            r"|([^\W\d]\w*)\s*(?:[-+*/:]?=(?!=)|\+\+|--)",
            re.IGNORECASE,
        )
        self.read = read
        self.in_language = in_language
        self.tried: dict[tuple[int, str, int], str | None] = {}
        self.read_again: dict[tuple[int, str], tuple[Diagnostic, ...] | None] = {}
        self.lines_read = 0

    def verified(self, found: Diagnostic) -> Diagnostic:
        """``found`` if its rewrite holds (with the rewrite that does), else its plain form."""
        current: Diagnostic | None = found
        if _offers_nothing(found):  # a rewrite kept only for a suggestion that leads to it
            return found
        while current is not None and current.rewrite is not None:
            holding = self.holding(current.span.line, current.rewrite, FOLLOWED)
            if holding is not None:
                return current if holding == current.rewrite else rewritten(current, holding)
            current = current.plain
        return current if current is not None else found.without_suggestion()

    def holding(self, line: int, rewrite: str, follow: int) -> str | None:
        """``rewrite``, or a rewrite of it its own mistake proposes, if line ``line`` so
        written has no mistake; None if none does (or the budget is spent)."""
        key = (line, rewrite, follow)
        if key not in self.tried:
            self.tried[key] = self._try(line, rewrite, follow)
        return self.tried[key]

    def _try(self, line: int, rewrite: str, follow: int) -> str | None:
        mistakes = self.left(line, rewrite)
        if mistakes is None:
            return None
        if not mistakes:
            return rewrite
        if follow and "\n" not in rewrite and len(mistakes) == 1:
            further = mistakes[0].rewrite
            if further is not None and further != rewrite:
                return self.holding(line, further, follow - 1)
        return None

    def left(self, line: int, rewrite: str) -> tuple[Diagnostic, ...] | None:
        """The mistakes line ``line`` written as ``rewrite`` still has (lines it becomes: all
        of them); None when that can't be tried (no such line, or the budget is spent)."""
        key = (line, rewrite)
        if key not in self.read_again:
            self.read_again[key] = self._left(line, rewrite)
        return self.read_again[key]

    def _left(self, line: int, rewrite: str) -> tuple[Diagnostic, ...] | None:
        if not 0 < line <= len(self.lines) or not self._affordable():
            return None
        original = self.lines[line - 1]
        indent = original[: len(original) - len(original.lstrip())]
        parts = self.in_language(rewrite).split("\n")
        new = [indent + part.rstrip() if part.strip() else "" for part in parts]
        lines, unsure = self._others_left_out(line)
        deeper = len(new[-1]) - len(new[-1].lstrip()) - len(indent)
        if len(new) > 1 and deeper > 0 and opens_lines(self.lines, line):  # a header put in a
            lines = indented_under(lines, line, " " * deeper)  # script: its lines under its last
        text = "\n".join([*lines[: line - 1], *new, *lines[line:]])
        self.lines_read += len(self.lines) + len(new)
        last = line + len(new) - 1
        return tuple(
            item
            for item in self.read(text, unsure)
            if item.severity == "error"
            and line <= item.span.line <= last
            and item.code not in ABOUT_OTHER_LINES
        )

    def _others_left_out(self, line: int) -> tuple[list[str], frozenset[str]]:
        """The program's lines with the other lines that can't be read left out (a header in
        place of one with lines under it), and the names those may give a value to."""
        lines = list(self.lines)
        unsure: set[str] = set()
        for number in sorted(self.unreadable - {line}):
            text = self.lines[number - 1]
            indent = text[: len(text) - len(text.lstrip())]
            if opens_lines(self.lines, number):
                lines[number - 1] = indent + ("repeat 1" if indent else "when started")
            else:
                lines[number - 1] = ""
            words = _NAME.findall(text) if not indent else []  # a header's parameters
            found = [first or second for first, second in self.setting.findall(text)]
            unsure.update(word.lower() for word in [*words, *found])
        return lines, frozenset(unsure)

    def _affordable(self) -> bool:
        return len(self.read_again) < MOST_TRIED and self.lines_read < MOST_LINES_READ


def _offers_nothing(found: Diagnostic) -> bool:
    plain = found.plain
    return plain is not None and (plain.code, plain.values) == (found.code, found.values)


def rewritten(found: Diagnostic, rewrite: str) -> Diagnostic:
    """``found`` showing ``rewrite`` as the line to write."""
    values = dict(found.values)
    if "write" in values:
        return replace(found.with_values(write=write_line(rewrite)), rewrite=rewrite)
    if found.plain is not None:  # a message with no place for the line: the one without a fix
        return found.plain
    return found.without_suggestion()


def verify_all(
    found: list[Diagnostic],
    text: str,
    read: Reader,
    in_language: Callable[[str], str],
    above: Above,
) -> list[Diagnostic]:
    """Every diagnostic of a file with its suggestion tried: kept, followed or left out; a
    line written with a habit from another tool gets the rootlang line it means
    (:mod:`rootlang.grammar.habits`, asking ``above`` what the checks say of a line).
    ``in_language`` puts a rewrite (written in English) in the program's language."""
    if not any(item.severity == "error" for item in found):
        return found
    unreadable = frozenset(
        item.span.line
        for item in found
        if item.severity == "error" and item.code.startswith("E0") and item.code in UNREADABLE
    )
    verifier = Verifier(text, read, in_language, unreadable)
    found = with_habits(found, verifier.lines, verifier.left, above)
    if not any(item.rewrite is not None for item in found):
        return found
    return [verifier.verified(item) for item in found]
