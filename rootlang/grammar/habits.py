"""Habits children bring from other tools, as one table: the line as they write it, and the
rootlang line it means, with their own values.

Each :class:`Habit` is data: a pattern written the way the child writes the line, with slots
(``{v}`` any value, ``{name}`` a name, ``{args}`` what is between brackets, ``{rest}`` the rest
of the line), and what to write instead, with the same slots. A slot in the answer may say
how its value is written there: ``{v cm}`` adds the unit after a bare number (``fd 10`` ->
``move 10 cm``), ``{v!q}`` puts text in quotes, ``{v!neg}`` takes its negative, ``{args!sp}``
writes ``a, b`` as ``a b``, ``{v!note}`` writes a MIDI note number as a note name (60 ->
C4), ``{v!logo}`` writes a turtle Logo list of commands (``fd 10 rt 90``) as indented lines.
An answer with several lines uses ``\\n``; an empty answer deletes the line.

:data:`TIDY` holds the small habits that are part of a line (a `;` at its end, `await
robot.`, `&&`): each is a substitution, and the line tidied is looked up again, so `let x =
5;` needs no entry of its own.

The table is consulted only for lines that have a mistake (:func:`with_habits`); a line that
means something in rootlang is never rewritten (a procedure of the child's own called
`forward` is theirs). Every answer is still tried in place before it is shown
(:mod:`rootlang.verify`), so a habit that does not fit a line explains instead of misleading.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, replace

from rootlang.diagnostics import Diagnostic, Span, diagnostic


@dataclass(frozen=True)
class Habit:
    """One habit: where it comes from, the line as written there, and the rootlang line."""

    source: str  # the tool the habit comes from, as the message names it
    written: str
    rootlang: str
    why: str = "E031"  # the message: E031 (another tool's words), E032 (an end), E033 (import)


def _habits(source: str, pairs: Iterable[tuple[str, str]], why: str = "E031") -> list[Habit]:
    return [Habit(source, written, rootlang, why) for written, rootlang in pairs]


DELETE = ""

# fmt: off
HABITS: tuple[Habit, ...] = (
    *_habits("Scratch", [
        ("when green flag clicked", "when started"),
        ("when flag clicked", "when started"),
        ("when gf clicked", "when started"),
        ("when this sprite clicked", "when touched"),
        ("when i receive {v}", "when message {v!q} received"),
        ("broadcast {v} and wait", "send {v!q} and wait"),
        ("broadcast {v}", "send {v!q}"),
        ("move {v} steps", "move {v cm}"),
        ("move {v} step", "move {v cm}"),
        ("say {v} for {t} seconds", "say {v!q}\nwait {t} seconds"),
        ("say {v} for {t} secs", "say {v!q}\nwait {t} seconds"),
        ("say {v} for {t} second", "say {v!q}\nwait {t} seconds"),
        ("think {v} for {t} seconds", "say {v!q}\nwait {t} seconds"),
        ("think {v} for {t} secs", "say {v!q}\nwait {t} seconds"),
        ("think {v} for {t} second", "say {v!q}\nwait {t} seconds"),
        ("think {v}", "say {v!q}"),
        ("wait {v} secs", "wait {v} seconds"),
        ("wait {v} sec", "wait {v} seconds"),
        ("turn ↻ {v} degrees", "turn right {v} degrees"),
        ("turn ↺ {v} degrees", "turn left {v} degrees"),
        ("turn {v} degrees", "turn right {v} degrees"),
        ("turn cw {v} degrees", "turn right {v} degrees"),
        ("turn ccw {v} degrees", "turn left {v} degrees"),
        ("turn clockwise {v} degrees", "turn right {v} degrees"),
        ("turn anticlockwise {v} degrees", "turn left {v} degrees"),
        ("turn counterclockwise {v} degrees", "turn left {v} degrees"),
        ("point in direction {v}", "go to x position x y position y facing {v!heading}"),
        ("go to x: {x} y: {y}", "go to x {x cm} y {y cm}"),
        ("go to x {x} y {y}", "go to x {x cm} y {y cm}"),
        ("glide {t} secs to x: {x} y: {y}", "go to x {x cm} y {y cm}"),
        ("glide {t} seconds to x: {x} y: {y}", "go to x {x cm} y {y cm}"),
        ("play note {v} for {t} beats", "play note {v!note} for {t} seconds"),
        ("pen down", "marker down"),
        ("pen up", "marker up"),
        ("forever loop", "forever"),
        ("if touching edge", "if bumper any pressed"),
        ("if touching edge?", "if bumper any pressed"),
        ("if touching edge then", "if bumper any pressed"),
        ("if touching wall", "if bumper any pressed"),
        ("if on edge, bounce", "if bumper any pressed"),
        ("wait until touching edge", "wait until bumper any pressed"),
        ("repeat until touching edge", "repeat until bumper any pressed"),
        ("stop all sounds", "stop sound"),
    ]),
    *_habits("Scratch", [("end", DELETE)], why="E032"),
    *_habits("Python", [
        ("for {name} in range({v}):", "repeat {v}"),
        ("for {name} in range({v})", "repeat {v}"),
        ("for {name} in range(0, {v}):", "repeat {v}"),
        ("for {name} in range(0, {v})", "repeat {v}"),
        ("def {name}():", "to {name}"),
        ("def {name}()", "to {name}"),
        ("def {name}({args}):", "to {name} {args}"),
        ("def {name}({args})", "to {name} {args}"),
        ("def {name}:", "to {name}"),
        ("def {name}", "to {name}"),
        ("{name} += {v}", "change {name} by {v}"),
        ("{name} -= {v}", "change {name} by {v!neg}"),
        ("{name} = {name} + {v}", "change {name} by {v}"),
        ("{name} = {name} - {v}", "change {name} by {v!neg}"),
        ("elif {v}:", "else if {v}"),
        ("elif {v}", "else if {v}"),
        ("print({args})", "print {args}"),
        ("time.sleep({v})", "wait {v} seconds"),
        ("sleep({v})", "wait {v} seconds"),
        ("pass", DELETE),
    ]),
    *_habits("Python", [
        ("import {rest}", DELETE),
        ("from {rest} import {more}", DELETE),
    ], why="E033"),
    *_habits("JavaScript", [
        ("let {name} = {v}", "set {name} to {v}"),
        ("var {name} = {v}", "set {name} to {v}"),
        ("const {name} = {v}", "set {name} to {v}"),
        ("{name}++", "change {name} by 1"),
        ("{name}--", "change {name} by -1"),
        ("++{name}", "change {name} by 1"),
        ("function {name}()", "to {name}"),
        ("function {name}({args})", "to {name} {args}"),
        ("console.log({args})", "print {args}"),
        ("alert({v})", "say {v!q}"),
        ("} else if ({v})", "else if {v}"),
        ("} else if {v}", "else if {v}"),
        ("} else", "else"),
        ("else if ({v})", "else if {v}"),
        ("if ({v})", "if {v}"),
        ("while ({v})", "while {v}"),
        ("while (true)", "forever"),
        ("for (let {name} = 0; {name} < {v}; {name}++)", "repeat {v}"),
        ("for (var {name} = 0; {name} < {v}; {name}++)", "repeat {v}"),
    ]),
    *_habits("JavaScript", [("}", DELETE), ("};", DELETE)], why="E032"),
    *_habits("Logo", [
        ("forward {v}", "move {v cm}"),
        ("fd {v}", "move {v cm}"),
        ("back {v}", "move backward {v cm}"),
        ("backward {v}", "move backward {v cm}"),
        ("bk {v}", "move backward {v cm}"),
        ("right {v}", "turn right {v degrees}"),
        ("rt {v}", "turn right {v degrees}"),
        ("left {v}", "turn left {v degrees}"),
        ("lt {v}", "turn left {v degrees}"),
        ("pendown", "marker down"),
        ("pd", "marker down"),
        ("penup", "marker up"),
        ("pu", "marker up"),
        ("repeat {v} [{rest}]", "repeat {v}\n{rest!logo}"),
        ("setheading {v}", "go to x position x y position y facing {v!heading}"),
        ("seth {v}", "go to x position x y position y facing {v!heading}"),
        ("home", "go to x 0 cm y 0 cm"),
        ("make \"{name} {v}", "set {name} to {v}"),
        ("to {name} :{args}", "to {name} {args!logo_names}"),
    ]),
    *_habits("iRobot's Python SDK", [
        ("move({v})", "move {v cm}"),
        ("turn_left({v})", "turn left {v degrees}"),
        ("turn_right({v})", "turn right {v degrees}"),
        ("arc_left({v}, {r})", "arc left {v degrees} radius {r cm}"),
        ("arc_right({v}, {r})", "arc right {v degrees} radius {r cm}"),
        ("set_lights_rgb({r}, {g}, {b})", "light rgb {r} {g} {b}"),
        ("set_lights_on_rgb({r}, {g}, {b})", "light rgb {r} {g} {b}"),
        ("set_lights_blink_rgb({r}, {g}, {b})", "light blink rgb {r} {g} {b}"),
        ("set_lights_spin_rgb({r}, {g}, {b})", "light spin rgb {r} {g} {b}"),
        ("set_lights_off()", "light off"),
        ("set_wheel_speeds({l}, {r})", "set wheels left {l cm/s} right {r cm/s}"),
        ("navigate_to({x}, {y})", "go to x {x cm} y {y cm}"),
        ("set_marker(marker.down)", "marker down"),
        ("set_marker(marker.up)", "marker up"),
        ("set_marker({rest}down{more})", "marker down"),
        ("set_marker({rest}up{more})", "marker up"),
        ("play_note(note.{v}, {t})", "play note {v} for {t} seconds"),
        ("play_note({v}, {t})", "play {v} Hz for {t} seconds"),
        ("wait({v})", "wait {v} seconds"),
        ("stop()", "stop moving"),
        ("reset_navigation()", "reset position"),
        ("dock()", "dock"),
        ("undock()", "undock"),
        ("say({v})", "say {v}"),
        ("@event(robot.when_play)", "when started"),
        ("@event(robot.when_bumped{rest})", "when bumped"),
        ("@event(robot.when_touched{rest})", "when touched"),
        ("async def {name}({args}):", DELETE),
        ("robot = {rest}", DELETE),
        ("robot.play()", DELETE),
    ]),
    *_habits("other languages", [
        ("end {rest}", DELETE),
        ("endif", DELETE),
        ("endwhile", DELETE),
        ("done", DELETE),
        ("next", DELETE),
    ], why="E032"),
    *_habits("other languages", [
        ("repeat times {v}", "repeat {v}"),
        ("repeat {v} time", "repeat {v}"),
        ("{v} times", "repeat {v}"),
        ("do {v} times", "repeat {v}"),
        ("loop {v} times", "repeat {v}"),
        ("repeat {v} times do", "repeat {v}"),
        ("loop forever", "forever"),
        ("forever do", "forever"),
        ("do forever", "forever"),
        ("loop", "forever"),
        ("set {name} as {v}", "set {name} to {v}"),
        ("set {name} equal to {v}", "set {name} to {v}"),
        ("set {name} := {v}", "set {name} to {v}"),
        ("sleep {v}", "wait {v seconds}"),
        ("when program starts", "when started"),
        ("when the program starts", "when started"),
        ("when program begins", "when started"),
        ("when start", "when started"),
        ("when starts", "when started"),
        ("turn around", "turn right 180 degrees"),
        ("go forward {v}", "move {v cm}"),
        ("go back {v}", "move backward {v cm}"),
        ("go backward {v}", "move backward {v cm}"),
    ]),
)

# fmt: on

# Parts of a line written another way: (where from, pattern, replacement), applied in turn.
TIDY: tuple[tuple[str, str, str], ...] = (
    ("JavaScript", r"\s*;\s*$", ""),
    ("JavaScript", r"\s*\{\s*$", ""),
    ("JavaScript", r"^\s*\}\s*", ""),
    ("iRobot's Python SDK", r"^await\s+", ""),
    ("iRobot's Python SDK", r"^(?:robot|bot|root|create)\.", ""),
    ("JavaScript", r"\s*&&\s*", " and "),
    ("JavaScript", r"\s*\|\|\s*", " or "),
    ("Python", r"\s*:\s*$", ""),
    ("Python", r"(?<![\w\"])(True|False|None)(?![\w\"])", r"\1"),
    ("JavaScript", r"\s*//\s*", "  # "),
    ("Scratch", r"\b([0-9.]+)\s*(?:secs|sec)\b", r"\1 seconds"),
    ("Scratch", r"\b([0-9.]+)\s*steps?\b", r"\1 cm"),
    ("Scratch", r"<(?=[A-Za-z])([^<>]*[^\s<>])>", r"\1"),  # a condition in Scratch's <...>
    ("Scratch", r"\btouching (?:edge|wall)\??", "bumper any pressed"),
    ("Scratch", r"^(if\b.*\S)\s+then$", r"\1"),
    ("Logo", r"(?<=\s):([A-Za-z]\w*)", r"\1"),
)

_SLOT = re.compile(r"\{(\w+)\}")
_NUMBER = re.compile(r"-?[0-9]+(?:\.[0-9]+)?")
_QUOTED = re.compile(r'"[^"]*"|“[^”]*”')
_SINGLE_QUOTED = re.compile(r"'([^'\"]*)'")
_ANSWER_SLOT = re.compile(r"\{(\w+)(?: ([^}!]+))?(?:!(\w+))?\}")
_WORD = re.compile(r"[^\s\w]+|\w+")
_TOKEN = re.compile(r"[^\s\w]|\w+")
_LOGO_COMMAND = re.compile(r"([A-Za-z]+)((?:\s+-?[0-9.]+)*)")
_COMMENT = re.compile(r'\s+#(?!(?:[0-9a-f]{6})\b)[^"]*$', re.IGNORECASE)


@dataclass(frozen=True)
class Meaning:
    """What a line means in rootlang, found from a habit: the line(s) to write, the tool the
    habit comes from, the message, and the part of the line the caret goes under (columns
    from 1 on the line as written, end exclusive)."""

    rewrite: str
    source: str
    why: str
    column: int
    end_column: int
    written: str


@functools.cache
def _compiled(written: str) -> re.Pattern[str]:
    """A habit's pattern: its words case-insensitive, spaces optional around punctuation."""
    parts: list[str] = []
    seen: set[str] = set()
    position = 0
    for slot in _SLOT.finditer(written):
        parts.append(_literal(written[position : slot.start()]))
        name = slot.group(1)
        if name in seen:
            parts.append(rf"(?P={name})")
        elif name == "name":
            parts.append(rf"(?P<{name}>[A-Za-z_]\w*)")
        else:
            parts.append(rf"(?P<{name}>.+?)")
        seen.add(name)
        position = slot.end()
    parts.append(_literal(written[position:]))
    return re.compile(r"\s*" + "".join(parts) + r"\s*", re.IGNORECASE)


def _literal(text: str) -> str:
    """Fixed words of a pattern: spaces, `_` or nothing between two words, spaces optional
    around punctuation."""
    words = _TOKEN.findall(text)
    if not words:
        return r"\s+" if text else ""
    pattern = ""
    if text[0].isspace():
        pattern = r"\s+" if words[0][0].isalnum() else r"\s*"
    for index, word in enumerate(words):
        if index:  # two words: also run together or joined by `_` (`pen_down`, `penDown`)
            together = word[0].isalnum() and words[index - 1][-1].isalnum()
            pattern += r"[\s_]*" if together else r"\s*"
        pattern += re.escape(word)
    if text[-1].isspace():
        pattern += r"\s+" if words[-1][-1].isalnum() else r"\s*"
    elif not words[-1][-1].isalnum():
        pattern += r"\s*"
    return pattern


def meanings(line: str) -> list[Meaning]:
    """What a line written with habits may mean, the likeliest first: a habit of the whole
    line, the line with its small habits tidied away, a habit of the line tidied."""
    code = _COMMENT.sub("", line).strip()
    if not code:
        return []
    tidied, sources = _tidied(code)
    found = [_whole(code)]
    if tidied != code:
        found += [_whole(tidied), (Habit(sources[0], code, tidied), {})]
    found.append(_logo_sequence(code))
    result: list[Meaning] = []
    for item in found:
        if item is None:
            continue
        habit, values = item
        rewrite = _answer(habit.rootlang, values)
        if rewrite is None or any(known.rewrite == rewrite for known in result):
            continue
        if rewrite.split() == code.split():  # the line as written: no habit on it
            continue
        column, end = _caret(line, rewrite)
        written = line[column - 1 : end - 1]
        result.append(Meaning(rewrite, habit.source, habit.why, column, end, written))
    return result


def meaning(line: str) -> Meaning | None:
    """The likeliest rootlang line a line written with a habit means, or None."""
    found = meanings(line)
    return found[0] if found else None


def _whole(code: str) -> tuple[Habit, dict[str, str]] | None:
    for habit in HABITS:
        match = _compiled(habit.written).fullmatch(code)
        if match:
            return habit, {name: value.strip() for name, value in match.groupdict().items()}
    return None


def _tidied(code: str) -> tuple[str, list[str]]:
    sources: list[str] = []
    for source, pattern, replacement in TIDY:
        tidied = re.sub(pattern, replacement, code, flags=re.IGNORECASE)
        if tidied != code:
            sources.append(source)
            code = tidied
    return code.strip(), sources


def _answer(template: str, values: dict[str, str]) -> str | None:
    """The rootlang line with the child's values in their slots; None when a value can't be
    written that way (`{v!note}` of a word)."""
    failed = False

    def fill(slot: re.Match[str]) -> str:
        nonlocal failed
        name, unit, how = slot.group(1), slot.group(2), slot.group(3)
        value = _SINGLE_QUOTED.sub(r'"\1"', values.get(name, ""))  # Python's 'text'
        written = _written(value, unit, how)
        if written is None:
            failed = True
            return ""
        return written

    answer = _ANSWER_SLOT.sub(fill, template)
    return None if failed else answer


def _written(value: str, unit: str | None, how: str | None) -> str | None:
    if unit and _NUMBER.fullmatch(value):
        return f"{value} {unit}"
    if how == "q":
        return value if _QUOTED.fullmatch(value) or _NUMBER.fullmatch(value) else f'"{value}"'
    if how == "neg":
        if _NUMBER.fullmatch(value):
            return value[1:] if value.startswith("-") else f"-{value}"
        return f"-{value}" if re.fullmatch(r"\w+", value) else f"-({value})"
    if how == "note":
        return _note_name(value)
    if how == "heading":  # Scratch: 0 is up, 90 is right; rootlang's heading: 90 is where it
        if not _NUMBER.fullmatch(value):  # started facing, counted anticlockwise
            return None
        return f"{(90 - float(value)) % 360:g} degrees"
    if how == "logo":
        return _logo_lines(value)
    if how == "logo_names":
        return ", ".join(name.lstrip(":") for name in value.split())
    if how == "sp":
        return " ".join(part.strip() for part in value.split(","))
    return value


NOTE_NAMES = ("C", "C#", "D", "D#", "E", "F", "F#", "G", "G#", "A", "A#", "B")


def _note_name(value: str) -> str | None:
    """A MIDI note number as a note name: 60 is C4 (Scratch's music notes)."""
    if not re.fullmatch(r"[0-9]+", value) or not 12 <= int(value) <= 127:
        return None if not re.fullmatch(r"[A-Ga-g][#b]?[0-9]", value) else value.upper()
    number = int(value)
    return f"{NOTE_NAMES[number % 12]}{number // 12 - 1}"


def _logo_sequence(code: str) -> tuple[Habit, dict[str, str]] | None:
    """Several turtle Logo commands on one line (`fd 10 rt 90`): the lines they mean."""
    commands = [match.group().strip() for match in _LOGO_COMMAND.finditer(code)]
    if len(commands) < 2 or "".join(commands).replace(" ", "") != code.replace(" ", ""):
        return None
    lines = _logo_lines(code)
    if lines is None:
        return None
    return Habit("Logo", code, "\n".join(line.strip() for line in lines.split("\n"))), {}


def _logo_lines(body: str) -> str | None:
    """`fd 10 rt 90` as the rootlang lines it means, indented one step."""
    lines = []
    for command in _LOGO_COMMAND.finditer(body):
        found = meaning(command.group().strip())
        if found is None or "\n" in found.rewrite:
            return None
        lines.append("    " + found.rewrite)
    return "\n".join(lines) if lines else None


def _caret(line: str, rewrite: str) -> tuple[int, int]:
    """Where the habit shows on the line: the first word of it that the rootlang line does not
    have, through the words after it that it does not have either; if it has them all, the
    first word where the two differ."""
    kept = {word.lower() for word in _WORD.findall(rewrite)} | set(_TOKEN.findall(rewrite))
    words = list(_WORD.finditer(line))
    start = next(
        (index for index, word in enumerate(words) if word.group().lower() not in kept), None
    )
    if start is None:
        wanted = [word.lower() for word in _WORD.findall(rewrite)]
        start = next(
            (
                index
                for index, word in enumerate(words)
                if index >= len(wanted) or word.group().lower() != wanted[index]
            ),
            None,
        )
        if start is None:
            indent = len(line) - len(line.lstrip())
            return indent + 1, len(line.rstrip()) + 1
        return words[start].start() + 1, words[start].end() + 1
    end = start
    while end + 1 < len(words) and words[end + 1].group().lower() not in kept:
        end += 1
    if not words[start].group()[0].isalnum() and start != end:
        end = start  # punctuation: just it (`;`, `+=`)
    return words[start].start() + 1, words[end].end() + 1


def habit_diagnostics(line: str, number: int) -> list[Diagnostic]:
    """What to say of a line written with habits, the likeliest meaning first (each still to be
    tried in place, rootlang.verify)."""
    said = []
    for item in meanings(line):
        span = Span(number, item.column, number, item.end_column)
        found = diagnostic(item.why, span, written=item.written, source=item.source)
        if item.why == "E031":
            found = found.with_values(write=_write(item.rewrite))
        said.append(replace(found, rewrite=item.rewrite))
    return said


def header_habits(
    line: str, number: int
) -> list[tuple[str, list[tuple[int, int, int, int]], Diagnostic]]:
    """The one-line meanings of a line with lines indented under it, for the parser to read as
    a block header (so the lines under it stay its body): each as the line with its
    indentation, where its words are on the child's line (the child's values keep their
    places, for the carets of their own mistakes), and the diagnostic."""
    indent = line[: len(line) - len(line.lstrip())]
    found = []
    for said in habit_diagnostics(line, number):
        rewrite = said.rewrite or ""
        if not rewrite or "\n" in rewrite:
            continue
        fixed = indent + rewrite
        found.append((fixed, _anchors(fixed, line), said))
    return found


def _anchors(fixed: str, line: str) -> list[tuple[int, int, int, int]]:
    """For each word of ``fixed`` also on ``line`` (in order): its column in each (0-based)."""
    anchors = []
    position = 0
    for word in _WORD.finditer(fixed):
        at = line.lower().find(word.group().lower(), position)
        if at < 0:
            continue
        anchors.append((word.start(), at, len(word.group()), len(word.group())))
        position = at + len(word.group())
    return anchors


def _write(rewrite: str) -> str:
    from rootlang.verify import write_line

    return write_line(rewrite)


# Mistakes that say a line's words can't be read (not where the line stands, nor a value's
# kind): only a line with one of them may be written with a habit.
UNREADABLE = frozenset({
    "E001", "E004", "E002", "E011", "E012", "E013", "E014", "E019", "E021", "E023", "E024", "E025",
    "E026", "E029", "E030", "E101", "E102", "E118", "E120",
})  # fmt: skip
# Messages in the parser's own terms: worse than saying where the habit comes from.
PARSER_WORDS = frozenset({"E001", "E012", "E013"})


def with_habits(
    found: list[Diagnostic],
    lines: Sequence[str],
    left: Callable[[int, str], Sequence[Diagnostic] | None],
) -> list[Diagnostic]:
    """``found`` with the mistakes of each line written with a habit replaced by the one
    message that says what it means in rootlang, the first whose line holds (``left``, the
    mistakes it has when tried in place, is empty). A line whose only mistake left is a name
    of the child's own that has no value yet (`total += 5`, `total` never set) gets its line
    all the same, and is told to set the name first (the missing line is another one). When
    none holds, a line's own messages stay, unless they only speak of what the parser
    expected: then the message names where the habit is from."""
    errors: dict[int, list[Diagnostic]] = {}
    for item in found:
        if item.severity == "error":
            errors.setdefault(item.span.line, []).append(item)
    meant: dict[int, Diagnostic] = {}
    for number, mistakes in errors.items():
        if not 0 < number <= len(lines) or not any(m.code in UNREADABLE for m in mistakes):
            continue
        line = lines[number - 1]
        said = habit_diagnostics(line, number)
        holding, unset = None, None
        for item in said:
            wrong = left(number, item.rewrite or "")
            if wrong == ():
                holding = item
                break
            name = _unset_name(wrong, line)
            if unset is None and name is not None:
                unset = item, name
        if holding is not None:
            unread = next(m for m in mistakes if m.code in UNREADABLE)
            meant[number] = _narrowed(holding, unread.span, line)
        elif unset is not None and unset[0].code == "E031":
            item, name = unset
            values = dict(item.values)
            meant[number] = diagnostic("E036", item.span, written=values["written"], name=name,
                                       source=values["source"], write=values["write"])  # fmt: skip
        elif said and all(mistake.code in PARSER_WORDS for mistake in mistakes):
            first = said[0]
            values = dict(first.values)
            meant[number] = diagnostic("E034", first.span, written=values["written"],
                                       source=values["source"])  # fmt: skip
    if not meant:
        return found
    kept = [item for item in found if item.span.line not in meant or item.severity != "error"]
    return sorted([*kept, *meant.values()], key=lambda item: (item.span, item.code))


def _unset_name(mistakes: Sequence[Diagnostic] | None, line: str) -> str | None:
    """The name of the child's own line that has no value yet, when that is the only mistake
    ``mistakes`` (of the line rewritten) has."""
    if not mistakes or any(item.code != "E102" for item in mistakes):
        return None
    names = {str(dict(item.values)["name"]) for item in mistakes}
    words = {word.lower() for word in re.findall(r"\w+", line)}
    return min(names) if len(names) == 1 and min(names).lower() in words else None


# Punctuation as other languages write it: their two-character operators, else one character.
_PUNCTUATION = re.compile(r"[-+*/%=<>!:]=|\+\+|--|&&|\|\||[^\s\w]")


def _narrowed(said: Diagnostic, unread: Span, line: str) -> Diagnostic:
    """``said`` with its caret on the sign where rootlang could not read the line, when that
    is a later sign of the run of punctuation the caret starts on (`print('hi')`: the `'`, not
    the `(` rootlang reads too; `x -= 2` keeps `-=`)."""
    span = said.span
    if span.line != unread.line or not span.column < unread.column < span.end_column:
        return said
    run = re.match(r"[^\s\w]+", line[span.column - 1 :])
    for sign in _PUNCTUATION.finditer(run.group() if run else ""):
        start, end = span.column + sign.start(), span.column + sign.end()
        if start != unread.column:
            continue
        narrowed = replace(span, column=start, end_column=end)
        return replace(said, span=narrowed).with_values(written=sign.group())
    return said
