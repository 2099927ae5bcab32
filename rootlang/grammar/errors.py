"""Turn lark's parse errors into diagnostics in plain words: never a token name.

Each lark error says where it stopped and which terminals it could have taken there. This
module names those terminals the way a student thinks of them ("a value, like `10 cm`",
"`left` or `right`", "the end of the line") and picks a dedicated message for the common
mistakes: an unclosed string (E002), an unknown unit (E014), a misspelt word (E001 with
"did you mean").
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import replace

from lark import Lark, Token
from lark.exceptions import UnexpectedCharacters, UnexpectedInput, UnexpectedToken
from lark.lexer import PatternStr

from rootlang.colors import NAMED_COLORS
from rootlang.diagnostics import Diagnostic, Span, diagnostic, did_you_mean
from rootlang.forms import SENSORS
from rootlang.grammar.rules import token_words
from rootlang.grammar.suggest import Fix, fix_diagnostic, mend_line
from rootlang.units import UNITS
from rootlang.wording.shown import (
    Code,
    Phrase,
    Suggestion,
    Write,
    suggestion,
    unquoted,
    write_line,
)

# Terminals and words that can start a value; when lark expects a number there, all of them
# together read as "a value".
VALUE_TERMINALS = frozenset(
    {"NUMBER", "STRING", "BOOLEAN", "HEX_COLOR", "NAME", "PROC", "PROC0", "FUNCTION1",
     "FUNCTION2", "LPAR", "_COLOR_WORD", "MINUS"}
)  # fmt: skip
VALUE_WORDS = frozenset(
    {"note", "rgb", "random", "not", *NAMED_COLORS,
     *(word for sensor in SENSORS.values() for word in sensor.form.first_words())}
)  # fmt: skip
EVENT_TERMINALS = frozenset({"STARTED", "BUMPED"})
# (its example's text, "go", is words of the message: the catalogue translates this one whole)
EVENT_PHRASE = Phrase(
    (
        "an event, like ",
        Code("started"),
        ", ",
        Code("bumped"),
        " or ",
        Code('message "go" received'),
    )
)
VALUE_PHRASE = Phrase(("a value, like ", Code("10 cm"), ", a name or ", Code("true")))

# How to name the terminals that are patterns rather than fixed words: the words of the
# tokens written from the forms (a choice's options, in order; rootlang.grammar.rules).
PATTERN_WORDS: dict[str, tuple[str, ...]] = token_words()
PHRASES = {
    "_NL": "the end of the line",
    "UNIT": "a unit, like cm or seconds",
    "NAME": "a name",
    "NOTE": "a note name, like C4 or F#5",
    "STRING": 'some text in quotes, like "go"',
    "COMPARE": "a comparison like = or <",
    "ADD_OP": "+ or -",
    "MINUS": "+ or -",
    "MUL_OP": "* or /",
}
# Words that can come right after a value somewhere in the language.
FOLLOW_A_VALUE = ("times", "for", "to", "radius", "facing", "volume", "then", "and", "or", "mod")
IGNORED = frozenset({"_COLON", "COMMENT", "$END", "THEN", "TIMES"})
MOST_SHOWN = 6


def describe_expected(parser: Lark, expected: Iterable[str]) -> tuple[Phrase, list[str]]:
    """The expected terminals in words (their code as :class:`Code`, shown in the program's
    language), and the plain words among them (for "did you mean")."""
    names = set(expected) - IGNORED
    phrases: list[str | Code | Phrase] = []
    choices: list[str] = []
    if names >= EVENT_TERMINALS:
        return EVENT_PHRASE, choices
    if "NUMBER" in names:
        phrases.append(VALUE_PHRASE)
        names = {name for name in names if not _starts_value(parser, name)}
    for name in sorted(names):
        if name in PATTERN_WORDS:
            choices.extend(PATTERN_WORDS[name])
            phrases.extend(Code(word) for word in PATTERN_WORDS[name])
        elif name in PHRASES:
            phrases.append(PHRASES[name])
        else:
            word = _fixed_word(parser, name)
            if word is not None:
                choices.append(word)
                phrases.append(Code(word))
    # (in the order of their English: the end of the line last)
    phrases = sorted(
        set(phrases), key=lambda phrase: (str(phrase).startswith("the end"), str(phrase))
    )
    if not phrases:
        return Phrase(("something else",)), choices
    if len(phrases) > MOST_SHOWN:
        phrases = [*phrases[: MOST_SHOWN - 1], "something else"]
    return Phrase.listed(phrases), choices


def _starts_value(parser: Lark, name: str) -> bool:
    word = _fixed_word(parser, name)
    return name in VALUE_TERMINALS or (word is not None and word.lower() in VALUE_WORDS)


def _fixed_word(parser: Lark, name: str) -> str | None:
    """The word a keyword terminal stands for; None for patterns and declared terminals."""
    try:
        pattern = parser.get_terminal(name).pattern
    except KeyError:  # PROC and PROC0 are declared, not defined
        return None
    return pattern.value if isinstance(pattern, PatternStr) else None


def syntax_diagnostic(
    parser: Lark, error: UnexpectedInput, line_text: str, line_offset: int, *, mend: bool = True
) -> Diagnostic:
    """One diagnostic for lark's error on a line whose text is ``line_text``; ``mend``: look for
    the fix of a misspelt, missing or extra word too."""
    line = (error.line if error.line and error.line > 0 else 1) + line_offset
    column = error.column if error.column and error.column > 0 else 1
    if isinstance(error, UnexpectedCharacters):
        character = line_text[column - 1 : column] or " "
        if character in ('"', "“"):
            return diagnostic("E002", Span(line, column, line, len(line_text) + 1))
        if character in ("'", "‘", "’"):  # a habit from other languages, or a word processor
            return diagnostic("E019", Span.point(line, column))
        if character.isalpha():  # ö, é, ß: a name in the child's own language
            return diagnostic("E020", Span.point(line, column), character=character)
        return diagnostic("E012", Span.point(line, column), character=repr(character))
    assert isinstance(error, UnexpectedToken)
    token: Token = error.token
    expected = error.accepts or error.expected
    described, choices = describe_expected(parser, expected)
    header = _WHEN_HEADER.fullmatch(line_text)
    one_side = _one_side_event(header.group(1)) if header else None
    if header and one_side is not None:
        start = header.start(1) + 1
        span = Span(line, start, line, start + len(header.group(1)))
        plain = diagnostic("E021", span, words=header.group(1))
        return diagnostic("E022", span, event=unquoted(one_side)).offering(one_side, plain)
    word = str(token)
    found = _written_differently(parser, line_text, line, column, word, mend=mend)
    if found is not None and found.code in ("E024", "E025") and found.rewrite is not None:
        # if the word put in or left out proves wrong, what the parser expected says more
        unmended = syntax_diagnostic(parser, error, line_text, line_offset, mend=False)
        return replace(found, plain=unmended)
    if found is not None:
        return found
    if token.type in ("_NL", "$END"):
        end = len(line_text.rstrip()) + 1
        return diagnostic("E013", Span.point(line, end), expected=described)
    if header and "COMPARE" in expected:  # `when button pressed`: read as a condition `button`
        start = header.start(1) + 1
        words = header.group(1)
        return diagnostic("E021", Span(line, start, line, start + len(words)), words=words)
    span = Span(line, column, line, column + max(len(str(token)), 1))
    after_number = re.search(r"[0-9][ \t]*$", line_text[: column - 1]) is not None
    if after_number:  # lark has already left the number's state: offer what may follow one
        choices = [*choices, *FOLLOW_A_VALUE]
    close_to_choice = len(word) > 2 and did_you_mean(word, choices) is not None
    if after_number and token.type in ("NAME", "PROC", "PROC0") and not close_to_choice:
        spelled_out = did_you_mean(word, SPELLED_OUT_UNITS)  # `perent`: percent, so %
        unit = SPELLED_OUT_UNITS.get(spelled_out or "") or _close(
            word, [u.name for u in UNITS.values()]
        )
        plain = diagnostic("E014", span, unit=word, suggestion="", known=KNOWN_UNITS)
        if not unit:
            return plain
        fixed = replaced(line_text, span, unit)  # `move 10 centimeters`: the line with `cm`
        written = write_line(fixed)
        with_line = Suggestion(unit, written if isinstance(written, Write) else None)
        found = diagnostic("E014", span, unit=word, suggestion=with_line, known=KNOWN_UNITS)
        return found.offering(fixed, plain)
    close = _close(word, choices)
    found = diagnostic("E001", span, found=Code(word), expected=described,
                       suggestion=suggestion(close))  # fmt: skip
    return found.offering(replaced(line_text, span, close)) if close else found


def _written_differently(
    parser: Lark, line_text: str, line: int, column: int, word: str, *, mend: bool
) -> Diagnostic | None:
    """A mistake with a known fix: a number with `e`, `x = 5`, or a misspelt, missing or extra
    word (:mod:`rootlang.grammar.suggest`)."""
    number = _NUMBER_BEFORE.search(line_text[: column - 1])
    if number and _EXPONENT.fullmatch(word):
        start = number.start() + 1
        written = number.group() + word
        span = Span(line, start, line, column + len(word))
        example = unquoted(_digits(written))
        return diagnostic("E027", span, written=unquoted(written), example=example)
    assignment = _ASSIGNMENT.fullmatch(line_text)
    if assignment and parses(parser, f"set {assignment.group(2)} to {assignment.group(3)}"):
        sign = line_text.index("=", assignment.end(2)) + 1  # the caret on `=`, the habit
        span = Span(line, sign, line, sign + 1)
        name, value = assignment.group(2), assignment.group(3)
        plain = diagnostic("E030", span, name=name)
        fixed = f"set {name} to {value}"
        found = diagnostic("E026", span, name=name, write=write_line(fixed))
        return found.offering(fixed, plain)
    fix = mend_line(parser, line_text) if mend else None
    if fix is None:
        return None
    if fix.what == "unit":
        return _unit_fix(fix, line, line_text)
    return fix_diagnostic(fix, line, line_text)


def _unit_fix(fix: Fix, line: int, line_text: str) -> Diagnostic:
    """E014 for a misspelt unit, with the line written right; as close units are tried in
    turn (rootlang.verify), the next is what to say if this one's line proves wrong."""
    written = write_line(fix.fixed_line or "")
    suggestion = Suggestion(fix.replacement, written if isinstance(written, Write) else None)
    span = Span(line, fix.column, line, fix.end_column)
    found = diagnostic("E014", span, unit=fix.written, suggestion=suggestion, known=KNOWN_UNITS)
    others = fix.others
    plain = _unit_fix(replace(others[0], others=others[1:]), line, line_text) if others else None
    return found.offering(fix.fixed_line or replaced(line_text, span, fix.replacement), plain)


def parses(parser: Lark, line_text: str) -> bool:
    try:
        parser.parse(line_text + "\n")
    except UnexpectedInput:
        return False
    return True


def _digits(number: str) -> str:
    """`1e3` written out (`1000`); a number too long to write out gets a plain example."""
    value = float(number)
    return f"{value:.0f}" if value < 1e7 else "1000"


_NUMBER_BEFORE = re.compile(r"[0-9]+(\.[0-9]+)?$")
_EXPONENT = re.compile(r"e[0-9]+", re.IGNORECASE)
_ASSIGNMENT = re.compile(r"(\s*)([a-z][a-z0-9_]*)\s*=\s*(.*?)\s*", re.IGNORECASE)


def _close(typed: str, choices: Iterable[str]) -> str | None:
    """Suggestions for or from one- and two-letter words (`at` -> `and`) would be guesses."""
    word = did_you_mean(typed, choices) if len(typed) > 2 else None
    return word if word and len(word) > 2 else None


def replaced(line_text: str, span: Span, word: str) -> str:
    """The line with the text under ``span`` (on it) replaced by ``word``."""
    return (line_text[: span.column - 1] + word + line_text[span.end_column - 1 :]).strip()


_WHEN_HEADER = re.compile(r"\s*when\s+(.*?)\s*:?\s*(?:#.*)?", re.IGNORECASE)

# `when bumped left`, `when touched back right`: the one-side events are written another way
_ONE_SIDE = (
    (re.compile(r"bumped\s+(left|right|both)", re.IGNORECASE), "when bumper {side} pressed"),
    (
        re.compile(r"touched\s+((?:front|back)\s+(?:left|right))", re.IGNORECASE),
        "when touch {side} pressed",
    ),
)


def _one_side_event(words: str) -> str | None:
    for pattern, event in _ONE_SIDE:
        found = pattern.fullmatch(words)
        if found:
            return event.format(side=" ".join(found.group(1).lower().split()))
    return None


KNOWN_UNITS = "mm, cm, m, inches, degrees, seconds, ms, cm/s, mm/s, Hz, %"

# units written out in full, as children often do: too far from the short name for did_you_mean
SPELLED_OUT_UNITS = {
    f"{prefix}{spelling}{plural}": short
    for prefix, short in (("milli", "mm"), ("centi", "cm"), ("", "m"))
    for spelling in ("meter", "metre")
    for plural in ("", "s")
} | {"millisecond": "ms", "milliseconds": "ms", "hertz": "Hz", "percent": "%"}
