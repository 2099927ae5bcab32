"""Values of a message that are kept as data until the message is shown: a suggestion, the
line to write, a kind of value in a unit, code, words the catalogue describes a thing with and a
value made of words and code. English is their ``str``; the catalogue
(:mod:`rootlang.wording.catalogue`) shows each in the message's language, with its code in the
program's language, from what it holds, so nothing reads a message, or code out of a value's
text, back. A value of any other type (a name the child gave, a path, a number, a reason) is
shown as it is: the catalogue never looks for English words inside it.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

__all__ = [
    "Code",
    "Described",
    "InUnit",
    "Phrase",
    "Suggestion",
    "Write",
    "suggestion",
    "unquoted",
    "write_line",
]


@dataclass(frozen=True)
class Code:
    """Code a value quotes (``found`` = "`foward`"): shown with its keywords in the program's
    language, between backticks unless ``quoted`` is False (a list of colours in a sentence)."""

    text: str
    quoted: bool = True

    def __str__(self) -> str:
        return f"`{self.text}`" if self.quoted else self.text


@dataclass(frozen=True)
class Described:
    """Words that describe ("a distance", "add", "other languages"): shown whole in the
    message's language, as the catalogue's ``_values`` translates them (in English where it
    has no translation)."""

    text: str

    def __str__(self) -> str:
        return self.text


@dataclass(frozen=True)
class Phrase:
    """A value made of words and code ("`left` or `right`", "use `round` on"): its words in the
    message's language (the whole phrase, if the catalogue knows it, else each part: a part in
    words as the catalogue's ``_phrases`` or ``_values`` translate it whole), its code in the
    program's."""

    parts: tuple[str | Code | Described | Phrase, ...]

    def __str__(self) -> str:
        return "".join(map(str, self.parts))

    @classmethod
    def listed(cls, items: Sequence[str | Code | Described | Phrase], last: str = " or ") -> Phrase:
        """ "a, b or c" (one item: just it)."""
        if len(items) == 1:
            return cls((items[0],))
        parts: list[str | Code | Described | Phrase] = []
        for number, item in enumerate(items):
            if number:
                parts.append(last if number == len(items) - 1 else ", ")
            parts.append(item)
        return cls(tuple(parts))


@dataclass(frozen=True)
class Write:
    """The line (or lines) a message says to write: " Write: `move 10 cm`"."""

    lines: tuple[str, ...]

    def __str__(self) -> str:
        if len(self.lines) == 1:
            return f" Write: `{self.lines[0]}`"
        return " Write these lines:" + "".join(f"\n    {line}" for line in self.lines)


@dataclass(frozen=True)
class Suggestion:
    """ " Did you mean "move"?", and the line to write with it, if any."""

    word: str
    write: Write | None = None

    def __str__(self) -> str:
        return f' Did you mean "{self.word}"?' + (str(self.write) if self.write else "")


@dataclass(frozen=True)
class InUnit:
    """A kind of value in a unit: "a distance in cm"."""

    kind: Described
    unit: str

    def __str__(self) -> str:
        return f"{self.kind} in {self.unit}"


def write_line(rewrite: str) -> Write | str:
    """How a message shows the line to write (several lines: under it); "" for none."""
    parts = [part.rstrip() for part in rewrite.split("\n") if part.strip()]
    if not parts:
        return ""
    if len(parts) == 1:
        return Write((parts[0].strip(),))
    return Write(tuple(parts))


def suggestion(word: str | None) -> Suggestion | str:
    """A " Did you mean ...?" for ``word``; "" for none."""
    return Suggestion(word) if word else ""


def unquoted(code: str) -> Code | str:
    """Code a message shows as it is, without backticks; "" for none."""
    return Code(code, quoted=False) if code else ""
