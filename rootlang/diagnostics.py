"""Diagnostics: every error or warning rootlang shows a person.

A diagnostic has a code (looked up in :mod:`rootlang.messages`), a source span and the
named values its message needs. Rendering quotes the source line with a caret under the span,
in the shape LANGUAGE.md §7 asks for::

    square.root, line 4:
            mve 10 cm
            ^^^
    I don't know the command "mve". Did you mean "move"?

A diagnostic holds no words until it is shown, and the languages to show it in are an argument
(:class:`~rootlang.wording.language.Languages`): :attr:`Diagnostic.english` for what a record
or a log keeps, :meth:`Diagnostic.shown` and :func:`render` for a person.
"""

from __future__ import annotations

import errno
import functools
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field, replace
from typing import Literal

from rootlang.messages import MESSAGES
from rootlang.spans import Span as Span  # (its home: below the syntax tree; shown here too)
from rootlang.wording.catalogue import message
from rootlang.wording.language import ENGLISH, Languages

Severity = Literal["error", "warning"]
# The values of a message that hold its suggestion: " Did you mean ...?", " Write: `...`".
SUGGESTING = frozenset({"suggestion", "write"})


NO_SPAN = Span(0, 0, 0, 0)


@dataclass(frozen=True)
class Diagnostic:
    """One error or warning: its catalogue ``code``, where it is, and its message's values."""

    code: str
    span: Span
    values: tuple[tuple[str, object], ...] = ()
    severity: Severity = "error"
    file: str = ""
    # The line as the message says to write it ("" deletes it; several lines are separated by
    # "\n", each put at the line's indentation), and the message to show instead when that
    # rewrite, tried in place, still leaves a mistake on the line (rootlang.verify).
    rewrite: str | None = field(default=None, compare=False)
    plain: Diagnostic | None = field(default=None, compare=False, repr=False)

    @property
    def english(self) -> str:
        """The message in the catalogue's English (what a record or a log keeps)."""
        return message(self.code, dict(self.values), ENGLISH)

    def shown(self, languages: Languages) -> str:
        """The message as ``languages`` show it."""
        return message(self.code, dict(self.values), languages)

    def in_file(self, file: str) -> Diagnostic:
        return replace(self, file=file)

    def offering(self, rewrite: str, plain: Diagnostic | None = None) -> Diagnostic:
        """This diagnostic proposing ``rewrite`` for its line; ``plain`` (by default the same
        message with its suggestion and "Write:" left out) if the rewrite proves wrong."""
        return replace(self, rewrite=rewrite, plain=plain or self.without_suggestion())

    def without_suggestion(self) -> Diagnostic:
        values = {name: "" if name in SUGGESTING else value for name, value in self.values}
        return Diagnostic(self.code, self.span, tuple(sorted(values.items())), self.severity,
                          self.file)  # fmt: skip

    def with_values(self, **values: object) -> Diagnostic:
        return replace(self, values=tuple(sorted({**dict(self.values), **values}.items())))

    def to_json(self, languages: Languages) -> dict[str, object]:
        return {
            "file": self.file,
            "line": self.span.line,
            "column": self.span.column,
            "end_line": self.span.end_line,
            "end_column": self.span.end_column,
            "code": self.code,
            "severity": self.severity,
            "message": self.shown(languages),
        }


def diagnostic(
    code: str, span: Span = NO_SPAN, *, severity: Severity = "error", **values: object
) -> Diagnostic:
    """Make a diagnostic; fails loudly (at development time) for a code not in the catalogue."""
    return _catalogued(code, span, values, severity)


_FILE_PROBLEMS = {
    errno.ENOENT: "V064", errno.EISDIR: "V065", errno.EACCES: "V066", errno.EPERM: "V066",
    errno.ENOSPC: "V067", errno.EDQUOT: "V067", errno.EROFS: "V068",
}  # fmt: skip


def file_problem(error: OSError | UnicodeDecodeError) -> Diagnostic | str:
    """Why a file could not be read or written, as a message's ``reason`` says it: in the
    message's language for what a person meets (not text, no such folder, a folder, no
    permission, a full or read-only disk), else the system's own words; never Python's
    ``[Errno 2] ...: 'path'``."""
    if isinstance(error, UnicodeDecodeError):
        return diagnostic("V063")
    code = _FILE_PROBLEMS.get(error.errno or 0)
    if code is None and isinstance(error, IsADirectoryError):  # Windows: a folder is EACCES
        code = "V065"
    return diagnostic(code) if code else error.strerror or str(error)


def _catalogued(
    code: str, span: Span, values: dict[str, object], severity: Severity = "error"
) -> Diagnostic:
    if code not in MESSAGES:
        raise KeyError(f"no message {code!r} in rootlang.messages")
    return Diagnostic(code, span, tuple(sorted(values.items())), severity)


@dataclass
class RootlangError(Exception):
    """Raised with one or more diagnostics; the CLI renders them and never shows a traceback."""

    diagnostics: Sequence[Diagnostic]
    source: str = field(default="", repr=False)

    def __post_init__(self) -> None:
        super().__init__("; ".join(f"{d.code}: {d.english}" for d in self.diagnostics))

    @classmethod
    def of(cls, code: str, span: Span = NO_SPAN, **values: object) -> RootlangError:
        return cls([_catalogued(code, span, values)])

    def render(self, languages: Languages) -> str:
        return render_all(self.diagnostics, self.source, languages)


@functools.lru_cache(maxsize=4)
def source_lines(source: str) -> tuple[str, ...]:
    """The program's lines as the parser numbers them: split at line ends (\\n, \\r\\n, \\r)
    only, so a U+2028 or U+0085 inside a text is not a line of its own. Cached: every
    diagnostic of one program quotes the same source (splitting it again for each made
    rendering 20,000 diagnostics take seconds)."""
    return tuple(source.lstrip("\ufeff").replace("\r\n", "\n").replace("\r", "\n").split("\n"))


def render(diag: Diagnostic, source: str, languages: Languages) -> str:
    """The human form: where, the line with a caret under the span, then the message, as
    ``languages`` show it."""
    lines = source_lines(source)
    parts: list[str] = []
    where = diag.file or "<program>"
    label = message("V091", {}, languages) + " " if diag.severity == "warning" else ""
    if diag.span.line >= 1:  # the header in the child's language too ("regel 4")
        parts.append(f"{where}, {message('V007', {'line': diag.span.line}, languages)}:")
        if diag.span.line <= len(lines):
            text = lines[diag.span.line - 1].expandtabs(4).rstrip()
            start = max(diag.span.column, 1)
            end = diag.span.end_column if diag.span.end_line == diag.span.line else len(text) + 1
            text, start, width = _around(text, start, max(end - start, 1))
            parts.append("        " + text)
            parts.append("        " + " " * (start - 1) + "^" * width)
    elif diag.file:
        parts.append(f"{where}:")
    parts.append(label + diag.shown(languages))
    return "\n".join(parts)


LINE_SHOWN = 100  # characters of a longer line shown, around the caret


def _around(text: str, start: int, width: int) -> tuple[str, int, int]:
    """A line too long to read on a screen, cut to :data:`LINE_SHOWN` characters around the
    caret (``…`` where it is cut), with the caret's new column and width."""
    if len(text) <= LINE_SHOWN:
        return text, start, width
    first = max(0, min(start - 1 - LINE_SHOWN // 4, len(text) - LINE_SHOWN))
    before = "…" if first else ""
    after = "…" if first + LINE_SHOWN < len(text) else ""
    start = start - first + len(before)
    width = max(1, min(width, LINE_SHOWN + len(before) - start + 1))
    return before + text[first : first + LINE_SHOWN] + after, start, width


def render_all(diags: Iterable[Diagnostic], source: str, languages: Languages) -> str:
    return "\n\n".join(render(d, source, languages) for d in diags)


def seconds_text(seconds: float) -> str:
    """A duration as words for a message: "1 second", "2.5 seconds"."""
    return f"{seconds:g} second" + ("" if seconds == 1 else "s")


def did_you_mean(word: str, candidates: Iterable[str], max_distance: int = 2) -> str | None:
    """The closest candidate within ``max_distance`` edits (ties: alphabetical), or None."""
    return _closest(word.lower(), tuple(sorted(set(candidates))), max_distance)


@functools.lru_cache(maxsize=1024)
def _closest(lowered: str, candidates: tuple[str, ...], max_distance: int) -> str | None:
    """Cached: a program with one typo on 20,000 lines asks the same question 20,000 times."""
    best: tuple[int, str] | None = None
    for candidate in candidates:
        distance = edit_distance(lowered, candidate.lower())
        if distance <= max_distance and (best is None or distance < best[0]):
            best = (distance, candidate)
    return best[1] if best else None


def edit_distance(a: str, b: str) -> int:
    """Levenshtein distance, with a swap of neighbours counting as one edit."""
    previous_previous: list[int] = []
    previous = list(range(len(b) + 1))
    for i, ca in enumerate(a, 1):
        current = [i]
        for j, cb in enumerate(b, 1):
            cost = min(previous[j] + 1, current[j - 1] + 1, previous[j - 1] + (ca != cb))
            if i > 1 and j > 1 and ca == b[j - 2] and a[i - 2] == cb:
                cost = min(cost, previous_previous[j - 2] + 1)
            current.append(cost)
        previous_previous, previous = previous, current
    return previous[-1]
