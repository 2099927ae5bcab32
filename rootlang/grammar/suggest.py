"""Find the word at fault on a line and what to write instead.

The suggestions come from the grammar, not from a list of known mistakes. Lark's interactive
parser tells, before each word of the line, which terminals could come there; the words those
terminals stand for (:func:`rootlang.grammar.words.terminal_words`) are the choices. A word the
language doesn't know is compared with the choices at its place, and each close choice is
tried by parsing the line again with it: a choice that makes the whole line read is the fix,
and the corrected line is shown. Two mistakes on one line are found the same way, one after
the other. When a close word alone doesn't make the line read, it is still named.

For the first word of a line (a command) any command whose line then reads is a fix, however
far its spelling: `walk forward 10 cm` reads only as `move forward 10 cm`.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Iterable
from dataclasses import dataclass, replace

from lark import Lark, Token, Tree
from lark.exceptions import LarkError, UnexpectedCharacters, UnexpectedInput, UnexpectedToken
from lark.parsers.lalr_interactive_parser import InteractiveParser

from rootlang.colors import NAMED_COLORS, SENSOR_COLORS
from rootlang.diagnostics import Diagnostic, Span, diagnostic, edit_distance
from rootlang.grammar.words import terminal_words
from rootlang.units import unit_named
from rootlang.wording.shown import Code, Described, Phrase, unquoted, write_line

# Tokens that are words the language doesn't know (a variable, a procedure, or a typo).
UNKNOWN_WORDS = frozenset({"NAME", "PROC", "PROC0"})
# Terminals and what a message calls their words.
WORD_KINDS = {"UNIT": "unit", "DIRECTION": "direction", "MOVE_DIRECTION": "direction",
              "NOTE": "note", "_COLOR_WORD": "word"}  # fmt: skip
COLOUR_WORDS = frozenset(NAMED_COLORS)
# Where one of these can come, a missing keyword is not the likely mistake (`say hi there`).
VALUE_STARTS = frozenset({"NAME", "NUMBER", "STRING"})
JOINING_WORDS = frozenset({"AND", "OR", "NOT", "MUL_OP", "AND_WAIT"})
_WORD = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
MOST_MENDED = 50  # lines of one file mended: a pasted page of garbage is still checked quickly
MOST_TRIES = 400  # parses one line's repair may take (a long line of typos stays quick)
DEPTH = 2  # mistakes mended on one line


@dataclass(frozen=True)
class Fix:
    """What to write instead of ``written`` (columns count from 1, end exclusive)."""

    column: int
    end_column: int
    written: str
    replacement: str
    what: str  # how a message calls the word: command, event, colour, unit, direction, word
    fixed_line: str | None = None  # the whole line written right, when it then reads
    inserted: bool = False  # `replacement` goes in before `written`, which stays
    terminal: str = ""  # the grammar's terminal for `replacement`
    # fixes as close as this one, to try in turn if this one's line proves wrong (units as
    # close as each other: `10 cms` is cm or cm/s, and only the checks know which kind fits)
    others: tuple[Fix, ...] = ()

    @property
    def distance(self) -> int:
        written, replacement = self.written.lower(), self.replacement.lower()
        return 0 if self.inserted else edit_distance(written, replacement)


@dataclass
class _Place:
    """One token of a line and the parser as it was before it."""

    token: Token
    before: InteractiveParser
    index: int
    after: str  # the type of the token before it ("" at the start of the line)

    @functools.cached_property
    def accepted(self) -> frozenset[str]:
        """The terminals that could have come in its place (asked only where needed: lark
        tries each terminal on a copy of the parser)."""
        return _accepted(self.before)


class Mender:
    """Repairs for one line, with a budget of parses."""

    def __init__(self, parser: Lark) -> None:
        self.parser = parser
        self.tries = 0
        self.words = terminal_words(parser)

    def reads(self, line: str) -> bool:
        return self.read(line) is not None

    def read(self, line: str) -> Tree[Token] | None:
        self.tries += 1
        try:
            return self.parser.parse(line + "\n")
        except (LarkError, RecursionError):
            return None

    def best_reading(self, line: str, fixes: list[Fix]) -> Fix | None:
        """Of the fixes that make ``line`` read, the one that leaves the fewest unknown words
        (`play noe A4` is `play note A4`, not `play not A4`), then the one whose word belongs to
        this command rather than to any value (`light spn` is `spin`, not `sin`)."""
        scored: list[tuple[tuple[int, int, int, int, int, str], Fix]] = []
        for fix in fixes:
            if self.tries >= MOST_TRIES:
                break
            mended = _apply(line, fix)
            tree = self.read(mended)
            if tree is None:
                continue
            names = len(list(tree.scan_values(_is_name)))
            generic = int(fix.terminal in self.value_terminals)
            lengths = abs(len(fix.written) - len(fix.replacement))
            score = (names, fix.distance, _not_dropped(fix), generic, lengths, fix.replacement)
            scored.append((score, replace(fix, fixed_line=mended.strip())))
        if not scored:
            return None
        scored.sort(key=lambda item: item[0])
        close = [fix for score, fix in scored if score[:2] == scored[0][0][:2]]
        if len(close) > 1 and all(fix.what == "unit" for fix in close):
            # units as close as each other: each is tried in place (rootlang.verify), in turn
            return replace(close[0], others=tuple(close[1:]))
        return scored[0][1]

    @functools.cached_property
    def value_terminals(self) -> frozenset[str]:
        """What can start any value (where `say` takes one)."""
        places = self.places("say x")
        return places[1].accepted if len(places) > 1 else frozenset()

    def places(self, line: str) -> list[_Place]:
        """Each token up to the first that doesn't fit, with what could have come there. A word
        the lexer can't take at its place (`turn rigt`) is a place too."""
        found: list[_Place] = []
        interactive = self.parser.parse_interactive(line + "\n")
        previous = ""
        try:
            for index, token in enumerate(interactive.iter_parse()):
                before = _snapshot(interactive)
                found.append(_Place(token, before, index, previous))
                previous = token.type
                if _glued(found):
                    break
        except UnexpectedInput as error:
            unlexed = _unlexed(error, line)
            if unlexed is not None and (
                not found or found[-1].token.start_pos != unlexed.start_pos
            ):
                before = _snapshot(interactive)
                found.append(_Place(unlexed, before, len(found), previous))
        except LarkError:
            pass
        if _glued(found):  # `seenn` lexed as `seen` `n`: one word, misspelt
            return [*found[:-2], _joined(found[-2], line)]
        return found

    def choices(self, place: _Place, line: str) -> dict[str, str]:
        """The words that fit at ``place``: word -> terminal (first word of a phrase)."""
        words: dict[str, str] = {}
        sensor_colours = "colo" in line[: place.token.start_pos or 0].lower()
        for terminal in sorted(place.accepted):
            for phrase in self.words.get(terminal, ()):
                word = phrase.split(" ")[0]
                if sensor_colours and word in COLOUR_WORDS and word not in SENSOR_COLORS:
                    continue  # the colour sensor tells only a few colours apart
                words.setdefault(word, terminal)
        return words

    def what(self, place: _Place, word: str, terminal: str) -> str:
        if place.after == "WHEN":
            return "event"
        if place.index == 0:
            return "command"
        if word in COLOUR_WORDS:
            return "colour"
        return WORD_KINDS.get(terminal, "word")

    def mend(self, line: str, depth: int = DEPTH) -> Fix | None:
        """The first fix of ``line``, with the whole line written right if it can be."""
        places = self.places(line)
        if not places:
            return None
        candidates = [
            fix
            for place in places
            if place.token.type in UNKNOWN_WORDS or (place is places[-1] and depth == DEPTH)
            for fix in self._substitutions(place, line)
        ]
        reading = self.best_reading(line, candidates)  # one word mended: the line reads
        if reading is not None:
            return reading
        if depth > 1:  # two words mended, one after the other
            for fix in candidates:
                if self.tries >= MOST_TRIES:
                    break
                further = self.mend(_apply(line, fix), depth - 1)
                if further is not None and further.fixed_line is not None:
                    return replace(fix, fixed_line=further.fixed_line)
        # Not reading even when mended, a word far off where any name could stand is a guess.
        guesses = {fix.column for place in places if "NAME" in place.accepted
                   for fix in self._substitutions(place, line)}  # fmt: skip
        best = next((fix for fix in candidates
                     if fix.distance == 1 or fix.column not in guesses), None)  # fmt: skip
        if depth < DEPTH:  # the second mistake of a line: only misspelt words
            return best
        return (
            self._insertion(places, line)
            or self._first_command(places, line)
            or best
            or self._deletion(places, line)
        )

    def _substitutions(self, place: _Place, line: str) -> list[Fix]:
        token = place.token
        written = str(token)
        if token.type not in UNKNOWN_WORDS and not written[:1].isalpha():
            return []
        start = token.column or 1
        sensor_colours = _SENSOR_COLOUR.search(line[: start - 1]) is not None
        fixes = []
        for terminal in sorted(place.accepted):
            for phrase in self.words.get(terminal, ()):
                if sensor_colours and phrase in COLOUR_WORDS and phrase not in SENSOR_COLORS:
                    continue  # the colour sensor tells only a few colours apart
                fix = _phrase_fix(line, start, phrase, terminal)
                if fix is not None:
                    fixes.append(replace(fix, what=self.what(place, fix.replacement, terminal)))
        return sorted(set(fixes), key=_closeness)

    def _insertion(self, places: list[_Place], line: str) -> Fix | None:
        """A missing keyword before the token that didn't fit: `set x 5` -> `set x to 5`."""
        place = places[-1]
        token = place.token
        takes_value = bool(place.accepted & VALUE_STARTS)
        if place.index == 0 or token.type in ("_NL", "$END") or takes_value:
            return None
        for terminal in sorted(place.accepted - JOINING_WORDS):
            words = self.words.get(terminal, ())
            if len(words) != 1:
                continue
            start = token.column or 1
            fix = Fix(start, start + len(str(token)), str(token), words[0], "word",
                      inserted=True)  # fmt: skip
            mended = _apply(line, fix)
            if self.reads(mended):
                return replace(fix, fixed_line=mended.strip())
        return None

    def _first_command(self, places: list[_Place], line: str) -> Fix | None:
        """An unknown first word followed by more words: the command whose line reads."""
        first = places[0]
        token = first.token
        if token.type != "NAME" or len(places) < 2:
            return None
        start = token.column or 1
        written = str(token)
        commands = [
            Fix(start, start + len(written), written, word, "command")
            for word in self.choices(first, line)
        ]
        for fix in sorted(commands, key=_closeness):
            mended = _apply(line, fix)
            if self.reads(mended):
                return replace(fix, fixed_line=mended.strip())
        return None

    def _deletion(self, places: list[_Place], line: str) -> Fix | None:
        """A word too many, where it doesn't fit: `turn right by 90 degrees`."""
        if len(places) < 2:
            return None
        failed, before = places[-1].token, places[-2].token
        known = {
            word for words in self.words.values() for phrase in words for word in phrase.split()
        }
        candidates = [before] if before.type in UNKNOWN_WORDS and str(before) in known else []
        a_word = failed.type not in UNKNOWN_WORDS or str(failed).lower() in known
        if a_word and failed.type not in ("_NL", "$END", "NUMBER", "STRING"):
            candidates.append(failed)
        for token in candidates:
            start = token.column or 1
            mended = line[: start - 1].rstrip() + " " + line[start - 1 + len(str(token)) :].lstrip()
            if self.reads(mended):
                fix = Fix(start, start + len(str(token)), str(token), "", "extra")
                return replace(fix, fixed_line=" ".join(mended.split()))
        return None


def _phrase_fix(line: str, start: int, phrase: str, terminal: str) -> Fix | None:
    """``phrase`` (one or more words) in place of as many words written from ``start``: the
    fix of the one word that differs, if it is close (`stop this scirpt` -> `script`)."""
    wanted = phrase.split(" ")
    written = _WORD.findall(line[start - 1 :])[: len(wanted)]
    if len(written) < len(wanted):
        return None
    column = start
    differing: tuple[int, str, str] | None = None
    for typed, word in zip(written, wanted, strict=True):
        column = line.index(typed, column - 1) + 1
        if typed.lower() == word:
            column += len(typed)
            continue
        if differing is not None:  # two words off: not this phrase
            return None
        differing = (column, typed, word)
        column += len(typed)
    if differing is None:
        return None
    column, typed, word = differing
    limit = 1 if len(typed) <= 3 else 2
    distance = edit_distance(typed.lower(), word)
    if distance > limit or distance >= len(word) or len(word) < 2:
        return None
    if terminal == "UNIT":  # as units are written: Hz, not hz
        word = unit_named(word).name
    return Fix(column, column + len(typed), typed, word, "word", terminal=terminal)


def _is_name(value: object) -> bool:
    return isinstance(value, Token) and value.type in UNKNOWN_WORDS


def _snapshot(interactive: InteractiveParser) -> InteractiveParser:
    copied: InteractiveParser = interactive.copy(deepcopy_values=False)  # type: ignore[no-untyped-call]
    return copied


def _accepted(interactive: InteractiveParser) -> frozenset[str]:
    terminals: set[str] = interactive.accepts()  # type: ignore[no-untyped-call]
    return frozenset(terminals)


def _glued(found: list[_Place]) -> bool:
    if len(found) < 2:
        return False
    before, token = found[-2].token, found[-1].token
    touching = before.end_pos == token.start_pos
    return touching and str(before)[-1:].isalpha() and str(token)[:1].isalpha()


def _joined(place: _Place, line: str) -> _Place:
    start = place.token.start_pos or 0
    word = _WORD.match(line, start)
    text = word.group() if word else str(place.token)
    token = Token("NAME", text, start, 1, start + 1)
    return _Place(token, place.before, place.index, place.after)


def _unlexed(error: UnexpectedInput, line: str) -> Token | None:
    """The word the lexer stopped at (it is not fed to the parser, so not a place yet)."""
    if isinstance(error, UnexpectedToken):
        token: Token = error.token
        return token
    word = _WORD.match(line, getattr(error, "pos_in_stream", 0) or 0)
    if isinstance(error, UnexpectedCharacters) and word:
        return Token("NAME", word.group(), word.start(), 1, word.start() + 1)
    return None


def _closeness(fix: Fix) -> tuple[int, int, int, str]:
    """Fewest edits first; then a letter left out (`degres` is `degrees`), then the same length
    (`noet` is `note` swapped, not `not`)."""
    lengths = abs(len(fix.written) - len(fix.replacement))
    return (fix.distance, _not_dropped(fix), lengths, fix.replacement)


def _not_dropped(fix: Fix) -> int:
    """0 when ``written`` is ``replacement`` with letters left out, the commonest slip."""
    letters = iter(fix.replacement.lower())
    return 0 if all(letter in letters for letter in fix.written.lower()) else 1


def mend_line(parser: Lark, line: str) -> Fix | None:
    """The fix for a line that doesn't read, or None when no word nearby explains it."""
    return Mender(parser).mend(line)


def word_fix(parser: Lark, line: str, column: int, written: str) -> Fix | None:
    """A word that read as a name (`light gren`): the closest word the grammar takes in its
    place, with the line written right if it then reads."""
    mender = Mender(parser)
    places = mender.places(line)
    at = [index for index, place in enumerate(places) if place.token.column == column]
    if not at:
        return None
    fixes = [  # its own place, or a phrase begun before it (`send "go" and wiat`)
        fix
        for place in places[max(at[0] - 1, 0) : at[0] + 1]
        for fix in mender._substitutions(place, line)
        if fix.column == column
    ]
    reading = mender.best_reading(line, fixes)
    if reading is not None:
        return reading
    # one letter off, though the line needs more (`move foward`)
    return next((fix for fix in sorted(fixes, key=_closeness) if fix.distance == 1), None)


def _apply(line: str, fix: Fix) -> str:
    before, after = line[: fix.column - 1], line[fix.end_column - 1 :]
    if fix.inserted:
        return f"{before}{fix.replacement} {line[fix.column - 1 :]}"
    return f"{before}{fix.replacement}{after}"


def closest(written: str, words: Iterable[str], limit: int = 0) -> list[str]:
    """Words within reach of ``written`` (by default 1 edit for short words, else 2), the
    closest first."""
    limit = limit or (1 if len(written) <= 3 else 2)
    scored = sorted((edit_distance(written.lower(), word.lower()), word) for word in set(words))
    return [word for distance, word in scored if distance <= limit]


# Event words written as conditions (`if bumped`): what asks the same question of a sensor.
EVENT_AS_CONDITION = {
    "bumped": ("the bumpers", "bumper any pressed"),
    "pressed": ("the bumpers", "bumper any pressed"),
    "touched": ("the touch sensors", "touch any pressed"),
    "undocked": ("the dock", "not docked"),
}


def colours_known(line: str, before: str = " ") -> Phrase:
    """The colours that fit on ``line``: the colour sensor's few, or every named colour (the
    colours as code: in the program's language)."""
    if _SENSOR_COLOUR.search(line):
        return Phrase((before, "The colour sensor can see ", _listed(SENSOR_COLORS), "."))
    return Phrase((before, "Colours I know: ", _listed(NAMED_COLORS), "."))


def _listed(words: Iterable[str]) -> Code:
    listed = list(words)
    return Code(", ".join(listed[:-1]) + " and " + listed[-1], quoted=False)


_SENSOR_COLOUR = re.compile(r"\bcolou?r\b", re.IGNORECASE)


def unknown_word(
    parser: Lark, line: str, span: Span, name: str, names: Iterable[str], *, colour: bool = False
) -> Diagnostic | None:
    """A diagnostic for a word read as a name no one set, when the grammar explains it better
    than a variable could: an event word as a condition (E119), a word the grammar takes at
    that place (E023: `light gren`, `move foward`), or an unknown colour (E120). None leaves
    it to the name checks."""
    variable = closest(name, names) if len(name) > 2 else []
    event_word = closest(name, EVENT_AS_CONDITION) if len(name) > 3 else []
    if event_word and not variable:  # `if bumped`, `if bumed`
        sensor, read = EVENT_AS_CONDITION[event_word[0]]
        rewrite = (line[: span.column - 1] + read + line[span.end_column - 1 :]).strip()
        found = diagnostic("E119", span, word=event_word[0], sensor=sensor, read=read,
                           write=write_line(rewrite))  # fmt: skip
        plain = diagnostic("E124", span, word=event_word[0])
        return found.offering(rewrite, plain)
    marked = _unmarked_value(parser, line, span, name)
    if marked is not None and not variable:  # `play C4`: `play note C4`
        return fix_diagnostic(marked, span.line, line)
    fix = word_fix(parser, line, span.column, name)
    if fix is not None and (not variable or fix.distance < edit_distance(name, variable[0])):
        return fix_diagnostic(fix, span.line, line)
    sensor_colour = _SENSOR_COLOUR.search(line) and closest(name, COLOUR_WORDS, limit=2)
    if (colour or sensor_colour) and not variable:
        return diagnostic("E120", span, word=name, colours=colours_known(line, before=""))
    return None


# Values the grammar takes only after the word that marks them (`note C4`): the terminal, and
# the word. Written without it, the value reads as a name no one set.
MARKED_VALUES = (("NOTE", "note"),)


def _unmarked_value(parser: Lark, line: str, span: Span, name: str) -> Fix | None:
    """``name`` is a value written without its word (`play C4`), and the line reads with it."""
    for terminal, word in MARKED_VALUES:
        pattern = parser.get_terminal(terminal).pattern
        flags = re.IGNORECASE if "i" in pattern.flags else 0
        if re.fullmatch(pattern.to_regexp(), name, flags) is None:
            continue
        written = line[span.column - 1 : span.end_column - 1]  # (as written: `C4`, not `c4`)
        fix = Fix(span.column, span.end_column, written, word, "word", inserted=True)
        mended = _apply(line, fix)
        if Mender(parser).reads(mended):
            return replace(fix, fixed_line=mended.strip())
    return None


def header_fix(parser: Lark, line: str) -> tuple[Fix, str] | None:
    """The fix for a line whose first word is a misspelt block header (`foorever`, `whlie x <
    3`, `repet 4`, `iff x > 3`) when the line written right is a header, and that line with
    its indentation (the parser then keeps the lines indented under it as its body)."""
    word = _WORD.search(line)
    fix = word_fix(parser, line, word.start() + 1, word.group()) if word else None
    if fix is None or fix.fixed_line is None:
        return None
    tree = Mender(parser).read(fix.fixed_line)
    found = tree.children[0] if tree is not None and tree.children else None
    header = isinstance(found, Tree) and str(found.data).endswith("_header")
    return (fix, _apply(line, fix)) if header else None


def misspelt_header(parser: Lark, found: Diagnostic, lines: list[str]) -> Diagnostic:
    """A command at the left edge (E004) that is a misspelt `when` or `to` line (`whn
    started`): say so, with the line written right."""
    if found.code != "E004" or not 0 < found.span.line <= len(lines):
        return found
    line = lines[found.span.line - 1]
    word = _WORD.match(line, found.span.column - 1)
    fix = word_fix(parser, line, found.span.column, word.group()) if word else None
    if fix is None or fix.fixed_line is None:
        return found
    return fix_diagnostic(fix, found.span.line, line)


def fix_diagnostic(fix: Fix, line_number: int, line: str) -> Diagnostic:
    """E023 (a word misspelt), E024 (a word missing), E025 (a word too many) for ``fix``."""
    span = Span(line_number, fix.column, line_number, fix.end_column)
    write = write_line(fix.fixed_line or "")
    if fix.inserted:
        found = diagnostic("E024", span, written=unquoted(fix.written),
                           replacement=unquoted(fix.replacement), write=write)  # fmt: skip
        return found.offering(fix.fixed_line) if fix.fixed_line else found
    if not fix.replacement:  # the caret on the whole word as the child wrote it: `4x`
        glued = re.search(r"\w+$", line[: fix.column - 1]) if fix.written[:1].isalnum() else None
        if glued is not None:
            span = replace(span, column=glued.start() + 1)
        written = line[span.column - 1 : span.end_column - 1] if glued else fix.written
        found = diagnostic("E025", span, written=unquoted(written), write=write)
        return found.offering(fix.fixed_line) if fix.fixed_line else found
    more = colours_known(line) if fix.what == "colour" else ""
    what, misspelt = Described(fix.what), unquoted(fix.written)
    found = diagnostic("E023", span, what=what, written=misspelt,
                       replacement=unquoted(fix.replacement), write=write, more=more)  # fmt: skip
    plain = diagnostic("E029", span, what=what, written=misspelt, more=more)
    if fix.others:  # the next as close, if this one's line proves wrong
        plain = fix_diagnostic(replace(fix.others[0], others=fix.others[1:]), line_number, line)
    return found.offering(fix.fixed_line or _apply(line, fix).strip(), plain)
