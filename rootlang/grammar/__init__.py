"""Read a Root program: text in, :class:`rootlang.ast.Program` out, or a RootlangError that
lists every syntax mistake in the file.

The steps:

1. ``_prepare``: odd characters (E012) and mixed tabs and spaces (E003) are found on the raw
   text, line by line.
2. ``root.lark`` (LALR, lark's contextual lexer) parses the file as a list of lines. Procedure
   names from the file's ``to`` headers are found first, so their NAME tokens are retyped to
   PROC/PROC0 and ``double 3 cm`` reads as a call. If the whole file does not parse, each
   line is parsed on its own so that every broken line is reported, not just the first.
3. :mod:`rootlang.grammar.build` turns lines into AST statements and block headers;
   :mod:`rootlang.grammar.blocks` nests them by indentation.

A mistake's suggestion is only shown once tried in place, which takes the checks: reading a
program that must hold (:func:`rootlang.checks.parse`) stands above both.

The lark parser is built once per process and cached on disk (in the user's cache directory),
so ``rootlang check`` starts fast.
"""

from __future__ import annotations

import contextlib
import dataclasses
import functools
import gc
import itertools
import os
import re
import threading
from collections.abc import Callable, Iterator
from dataclasses import replace
from pathlib import Path

from lark import Lark, Token
from lark.exceptions import UnexpectedInput

from rootlang import ast
from rootlang.diagnostics import Diagnostic, RootlangError, Span, diagnostic
from rootlang.grammar.blocks import Broken, IndentedLine, Nester, indentation
from rootlang.grammar.build import Header, Line, LineBuilder, token_span, too_deep
from rootlang.grammar.rules import grammar_text
from rootlang.locale.translate import Translation, program_language, relocated, to_english

__all__ = ["odd_character", "parse_lines", "terminal"]

TAB_WIDTH = 4
# Read as a file beside this module (package data), as rootlang.sim.world finds its worlds:
# importlib.resources would cost `rootlang sim` and `check` a few milliseconds at start-up.
GRAMMAR_FILE = Path(__file__).with_name("root.lark")
_TERMINAL = re.compile(r"^([A-Z_]+)(?:\.\d+)?:[ \t]*/(.*)/([a-z]*)[ \t]*$", re.MULTILINE)


def terminal(name: str) -> re.Pattern[str]:
    """The pattern of the grammar's terminal ``name`` (``NAME``, ``NOTE``, ``HEX_COLOR``), as
    ``root.lark`` writes it, so what reads a literal outside the parser (the blocks) takes
    exactly what the grammar takes. Read from the file: no parser is built."""
    return _terminals()[name]


@functools.cache
def _terminals() -> dict[str, re.Pattern[str]]:
    """Every terminal ``root.lark`` writes as a regular expression, the file read once."""
    return {
        found.group(1): re.compile(found.group(2), re.IGNORECASE if "i" in found.group(3) else 0)
        for found in _TERMINAL.finditer(GRAMMAR_FILE.read_text(encoding="utf-8"))
    }


_PROCEDURE_HEADER = re.compile(rf"[ \t]*to[ \t]+({terminal('NAME').pattern})(.*)", re.IGNORECASE)
# Control characters, and the line breaks other than \n and \r (\r is read as a line end):
# VT, FF, NEL, U+2028, U+2029 break a line in editors and in Python's splitlines, so a text or
# a comment holding one would look like two lines (the blocks refuse them too).
_ODD_CHARACTER = re.compile(r"[\x00-\x08\x0b\x0c\x0e-\x1f\x7f\x85\u2028\u2029]")


def odd_character(text: str) -> bool:
    """Whether ``text`` holds a character no line of a program may hold (E012), or a line
    break (\n, \r)."""
    return "\n" in text or "\r" in text or _ODD_CHARACTER.search(text) is not None


class _LexerState:
    """What the lexer needs and finds in the file being parsed: the procedures it defines
    (name -> has parameters), and the comments it skips (kept for ``format`` and the blocks)."""

    def __init__(self) -> None:
        self.names: dict[str, bool] = {}
        self.comments: list[Token] = []
        self.lock = threading.RLock()

    @contextlib.contextmanager
    def using(self, names: dict[str, bool]) -> Iterator[None]:
        """Parse with ``names`` as the procedures; a parse inside it (a suggestion checking a
        mended line) gets its own names and comments and gives these back."""
        with self.lock:
            saved = self.names, self.comments
            self.names, self.comments = names, []
            try:
                yield
            finally:
                self.names, self.comments = saved

    def retype(self, token: Token) -> Token:
        takes_values = self.names.get(token.value.lower())
        if takes_values is not None:
            token.type = "PROC" if takes_values else "PROC0"
        return token

    def comment(self, token: Token) -> Token:
        self.comments.append(token)
        return token


_LEXER = _LexerState()


def _cache_file() -> str | bool:
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(Path.home(), ".cache")
    folder = os.path.join(base, "rootlang")
    try:
        os.makedirs(folder, exist_ok=True)
    except OSError:
        return False
    return os.path.join(folder, "root-grammar.lark-cache")


@functools.cache
def lark_parser() -> Lark:
    grammar = grammar_text(GRAMMAR_FILE.read_text(encoding="utf-8"))
    with without_cycle_collector():  # loading makes thousands of lasting objects, no garbage
        return Lark(
            grammar,
            parser="lalr",
            propagate_positions=True,
            maybe_placeholders=True,
            # NAME must come last: lark 1.3's lexer chains a callback onto its own keyword check
            # with a closure over its loop variable, so only the last key's chain works.
            lexer_callbacks={"COMMENT": _LEXER.comment, "NAME": _LEXER.retype},
            cache=_cache_file(),
        )


class LinesRead:
    """The lines of one program already read, each as the parser read it (the lines it became,
    what it said of them, the comments in it), by where the line stands, its text and the
    procedures the program defines. A program read again and again with one line changed
    (:mod:`rootlang.verify` tries each suggestion in place) reads only that line again: a
    line stands alone (indentation is measured after parsing), so the rest read the same."""

    def __init__(self) -> None:
        self.lines: dict[
            tuple[int, str, frozenset[tuple[str, bool]]],
            tuple[list[Line], list[Diagnostic], list[ast.Comment], Diagnostic | None],
        ] = {}
        self._deep: dict[int, bool] = {}  # by the id of a line kept in ``lines``

    def deep(self, line: Line) -> bool:
        """:func:`too_deep`, asked once of each line read."""
        found = self._deep.get(id(line))
        if found is None:
            found = self._deep[id(line)] = too_deep(line)
        return found


def parse_lines(
    source: str, file: str = "", language: str | None = None, *, suggest: bool = True,
    lines_read: LinesRead | None = None,
) -> tuple[ast.Program, list[Diagnostic]]:  # fmt: skip
    """The program (with broken lines left out) and every syntax diagnostic, for callers that
    go on to check what did parse (``rootlang check`` reports both in one go). ``suggest``:
    look for the fix of each broken line (off when only where the mistakes are matters).
    ``lines_read``: lines read before, kept to read them only once (their fixes not looked for).

    A program in another language (``language``, or as :func:`program_language` decides) is
    translated to English first and its spans moved back onto its own text."""
    text, diagnostics = _prepare(source)
    try:
        language = program_language(source, language)
    except RootlangError as unknown:  # `# language: xx`: say so, and read it as English
        diagnostics.extend(unknown.diagnostics)
        language = "en"
    if language == "en":
        program, found = _parse_text(text, file, suggest, lines_read)
        return program, sorted([*diagnostics, *found], key=_order)
    translation = to_english(text, language)
    program, found = _parse_text(translation.text, file, suggest, lines_read)
    moved = [_moved(item, translation) for item in found]
    read = dataclasses.replace(relocated(program, translation), language=language)
    return read, sorted([*diagnostics, *moved], key=_order)


def _moved(item: Diagnostic, translation: Translation) -> Diagnostic:
    """``item`` with its span on the child's text, and so the message it falls back to."""
    plain = None if item.plain is None else _moved(item.plain, translation)
    return replace(item, span=translation.source_span(item.span), plain=plain)


def prepared_text(source: str) -> str:
    """The program's text as the parser numbers its lines (line ends made one)."""
    return _prepare(source)[0]


def _parse_text(
    text: str, file: str, suggest: bool = True, lines_read: LinesRead | None = None
) -> tuple[ast.Program, list[Diagnostic]]:
    """Parse prepared English text."""
    raw_lines = text.split("\n")
    procedures = _procedure_names(raw_lines)
    parser = lark_parser()
    with _LEXER.using(procedures), without_cycle_collector():
        if lines_read is None:
            lines, broken, diagnostics, comments = _parse(parser, text, raw_lines, suggest)
        else:
            lines, broken, diagnostics, comments = _parse_each(
                parser, raw_lines, lines_read, frozenset(procedures.items())
            )
    deep = [line for line in lines if (too_deep if lines_read is None else lines_read.deep)(line)]
    if deep:  # E018 at the line; the rest read on
        lines = [line for line in lines if line not in deep]
        broken += [Broken(line.span) for line in deep]
        diagnostics += [diagnostic("E018", line.span, limit=ast.NESTING_LIMIT) for line in deep]
    indented = _indent_lines(lines, broken, raw_lines)
    if any(_opens_nothing(line, after) for line, after in itertools.pairwise(indented)):
        with _LEXER.using(procedures):
            indented = _misspelt_headers(parser, indented, raw_lines, diagnostics)
    nester = Nester(indented)
    program = nester.program(file, comments)
    if nester.diagnostics:  # only a program with mistakes loads the suggestions (start-up)
        from rootlang.grammar.suggest import misspelt_header

        with _LEXER.using(procedures):
            diagnostics.extend(
                misspelt_header(parser, found, raw_lines) for found in nester.diagnostics
            )
    return program, diagnostics


def _opens_nothing(line: IndentedLine, after: IndentedLine) -> bool:
    """A line that is no block header, with lines indented under it (a mistake)."""
    return after.indent > line.indent and not isinstance(line.item, Header)


def _misspelt_headers(
    parser: Lark, lines: list[IndentedLine], raw_lines: list[str], diagnostics: list[Diagnostic]
) -> list[IndentedLine]:
    """Recovery: a misspelt block header with lines indented under it (`foorever`, `whlie x <
    3`, `repet 4`) is read as the header written right, with an error on the word (E023), so
    its body stays in the program: it is checked (its own mistakes are reported too), and as
    the program has an error, ``format`` and the blocks leave it as it is."""
    recovered = list(lines)
    for index, (line, after) in enumerate(itertools.pairwise(lines)):
        if not _opens_nothing(line, after):
            continue
        text = raw_lines[line.number - 1]
        for fixed_line, anchors, said in _header_readings(parser, text, line.number):
            builder = LineBuilder(line_offset=line.number - 1)
            _LEXER.comments = []
            try:
                header = builder.transform(parser.parse(fixed_line + "\n"))[0]
            except UnexpectedInput:
                continue
            if not isinstance(header, Header):
                continue
            if header.kind == "when" and said.code not in HABIT_CODES:
                continue
            # the spans of the line written right, moved onto the child's
            moved = Translation("", [[] for _ in range(line.number - 1)] + [anchors])
            value = header.value
            value = relocated(value, moved) if isinstance(value, ast.Node) else value
            header = Header(header.kind, moved.source_span(header.span), value)
            recovered[index] = replace(line, item=header)
            if not isinstance(line.item, Broken):  # a broken line has its syntax error already
                diagnostics.append(said)
            break
    return recovered


HABIT_CODES = frozenset({"E031", "E032", "E033"})  # a `when` line written as in Scratch


def _header_readings(
    parser: Lark, text: str, number: int
) -> list[tuple[str, list[tuple[int, int, int, int]], Diagnostic]]:
    """What a line that opens nothing may be as a block header: a misspelt header word
    (`foorever`), or a habit from another tool (`for i in range(4):`, rootlang.grammar.habits),
    each as the line, its words' places on the child's line, and what to say of it."""
    from rootlang.grammar.habits import header_habits
    from rootlang.grammar.suggest import fix_diagnostic, header_fix

    found = header_fix(parser, text)
    if found is None:
        return header_habits(text, number)
    fix, fixed_line = found
    start = fix.column - 1
    anchor = (
        (start, start, len(fix.replacement) + 1, 0)
        if fix.inserted
        else (start, start, len(fix.replacement), fix.end_column - fix.column)
    )
    return [(fixed_line, [anchor], fix_diagnostic(fix, number, text))]


@contextlib.contextmanager
def without_cycle_collector() -> Iterator[None]:
    """Parsing makes many short-lived objects and no reference cycles, so Python's cycle
    collector only gets in the way (it halves the speed on a 10,000-line program)."""
    was_enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was_enabled:
            gc.enable()


def _order(item: Diagnostic) -> tuple[Span, str]:
    return (item.span, item.code)


def _prepare(source: str) -> tuple[str, list[Diagnostic]]:
    """Normalise line ends, blank out odd characters (E012) and find mixed indentation (E003)."""
    diagnostics: list[Diagnostic] = []
    text = source.lstrip("\ufeff").replace("\r\n", "\n").replace("\r", "\n")
    lines = text.split("\n")
    indent_style = ""
    for number, line in enumerate(lines, 1):
        for match in _ODD_CHARACTER.finditer(line):
            span = Span.point(number, match.start() + 1)
            diagnostics.append(diagnostic("E012", span, character=repr(match.group())))
        if _ODD_CHARACTER.search(line):
            lines[number - 1] = _ODD_CHARACTER.sub(" ", line)
        lead = indentation(line)
        if not lead or not line.strip() or line.lstrip().startswith("#"):
            continue
        style = "tabs" if "\t" in lead else "spaces"
        if ("\t" in lead and " " in lead) or (indent_style and style != indent_style):
            diagnostics.append(diagnostic("E003", Span(number, 1, number, len(lead) + 1)))
        indent_style = indent_style or style
    return "\n".join(lines), diagnostics


def _procedure_names(lines: list[str]) -> dict[str, bool]:
    names: dict[str, bool] = {}
    for line in lines:
        match = _PROCEDURE_HEADER.fullmatch(line)
        if match:
            rest = match.group(2).split("#", 1)[0].strip().rstrip(":").strip()
            names[match.group(1).lower()] = bool(rest)
    return names


def _parse(
    parser: Lark, text: str, raw_lines: list[str], suggest: bool = True
) -> tuple[list[Line], list[Broken], list[Diagnostic], list[ast.Comment]]:
    """Parse the whole text at once; if that fails, parse line by line to find every error."""
    try:
        _LEXER.comments = []
        builder = LineBuilder()
        lines = builder.transform(parser.parse(text + "\n"))
        return lines, [], builder.diagnostics, _comments(_LEXER.comments, raw_lines)
    except UnexpectedInput:
        pass
    # Only a program with mistakes gets here, and only then load the messages (start-up).
    from rootlang.grammar.suggest import MOST_MENDED

    def read(number: int, line_text: str, broken_before: int) -> _Read:
        # Mending tries every word with the parser's state copied, which is as long as the
        # brackets are deep: a line deeper than any program may be isn't mended (linear time).
        mend = (
            suggest
            and broken_before < MOST_MENDED
            and _bracket_depth(line_text) <= ast.NESTING_LIMIT
        )
        return _read_line(parser, line_text, number, raw_lines, mend=mend)

    return _line_by_line(raw_lines, read)


def _parse_each(
    parser: Lark,
    raw_lines: list[str],
    lines_read: LinesRead,
    procedures: frozenset[tuple[str, bool]],
) -> tuple[list[Line], list[Broken], list[Diagnostic], list[ast.Comment]]:
    """:func:`_parse`'s reading line by line, without looking for fixes, each line read once
    (``lines_read``): what a line that can't be read says is the same every time."""

    def read(number: int, line_text: str, broken_before: int) -> _Read:
        key = (number, line_text, procedures)
        found = lines_read.lines.get(key)
        if found is None:
            found = _read_line(parser, line_text, number, raw_lines, mend=False)
            lines_read.lines[key] = found
        return found

    return _line_by_line(raw_lines, read)


# One line read: its lines, what was said of them, its comments, and its syntax error if any.
_Read = tuple[list[Line], list[Diagnostic], list[ast.Comment], Diagnostic | None]


def _read_line(
    parser: Lark, line_text: str, number: int, raw_lines: list[str], *, mend: bool
) -> _Read:
    builder = LineBuilder(line_offset=number - 1)
    _LEXER.comments = []
    try:
        items = builder.transform(parser.parse(line_text + "\n"))
    except UnexpectedInput as error:
        from rootlang.grammar.errors import syntax_diagnostic  # (a program with mistakes only)

        return [], [], [], syntax_diagnostic(parser, error, line_text, number - 1, mend=mend)
    return items, builder.diagnostics, _comments(_LEXER.comments, raw_lines, number - 1), None


def _line_by_line(
    raw_lines: list[str], read: Callable[[int, str, int], _Read]
) -> tuple[list[Line], list[Broken], list[Diagnostic], list[ast.Comment]]:
    """Every line read on its own (``read`` is given its number, its text and how many lines
    before it were broken), a line that can't be read marked broken."""
    lines: list[Line] = []
    broken: list[Broken] = []
    diagnostics: list[Diagnostic] = []
    comments: list[ast.Comment] = []
    for number, line_text in enumerate(raw_lines, 1):
        if not line_text.strip():
            continue
        items, said_of_it, its_comments, syntax_error = read(number, line_text, len(broken))
        if syntax_error is not None:
            diagnostics.append(syntax_error)
            start = len(indentation(line_text)) + 1
            broken.append(Broken(Span(number, start, number, len(line_text) + 1)))
            continue
        lines.extend(items)
        diagnostics.extend(said_of_it)
        comments.extend(its_comments)
    return lines, broken, diagnostics, comments


def _bracket_depth(line: str) -> int:
    """The most round brackets open at once in ``line``, text in quotes left out."""
    deepest = depth = 0
    for match in _BRACKET_OR_TEXT.finditer(line):
        depth += {"(": 1, ")": -1}.get(match.group(), 0)
        deepest = max(deepest, depth)
    return deepest


_BRACKET_OR_TEXT = re.compile(r'"[^"]*"?|[()]')


def _comments(tokens: list[Token], raw_lines: list[str], line_offset: int = 0) -> list[ast.Comment]:
    comments = []
    for token in tokens:
        span = token_span(token, line_offset)
        own_line = not raw_lines[span.line - 1][: span.column - 1].strip()
        comments.append(ast.Comment(span, str(token)[1:].rstrip(), own_line))
    return comments


def _indent_lines(
    lines: list[Line], broken: list[Broken], raw_lines: list[str]
) -> list[IndentedLine]:
    result: list[IndentedLine] = []
    items: list[Line | Broken] = [*lines, *broken]
    for item in sorted(items, key=lambda entry: entry.span):
        text = raw_lines[item.span.line - 1]
        lead = indentation(text)
        width = len(lead.expandtabs(TAB_WIDTH))
        first_word = text.strip().split(" ")[0] if text.strip() else ""
        result.append(IndentedLine(item.span.line, width, item, first_word))
    return result
