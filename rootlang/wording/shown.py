"""Values of a message that are kept as data until the message is shown: a suggestion, the
line to write, a kind of value in a unit, code quoted in a value and a value made of words and
code. English is their ``str``; the catalogue (:mod:`rootlang.wording.catalogue`) shows each in
the message's language, with its code in the program's language, from what it holds, so
nothing reads a message, or code out of a value's text, back.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["Code", "InUnit", "Phrase", "Suggestion", "Write", "suggestion", "write_line"]


@dataclass(frozen=True)
class Code:
    """Code a value quotes (``found`` = "`foward`"): shown with its keywords in the program's
    language, between backticks unless ``quoted`` is False (a list of colours in a sentence)."""

    text: str
    quoted: bool = True

    def __str__(self) -> str:
        return f"`{self.text}`" if self.quoted else self.text


@dataclass(frozen=True)
class Phrase:
    """A value made of words and code ("`left` or `right`", "use `round` on"): its words in the
    message's language (a whole phrase the catalogue knows, else word by word), its code in
    the program's."""

    parts: tuple[str | Code | Phrase, ...]

    def __str__(self) -> str:
        return "".join(map(str, self.parts))

    @classmethod
    def listed(cls, items: list[str | Code | Phrase], last: str = " or ") -> Phrase:
        """ "a, b or c" (one item: just it)."""
        if len(items) == 1:
            return cls((items[0],))
        parts: list[str | Code | Phrase] = []
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
    """A kind of value in a unit: "a distance in cm" (``kind`` as the catalogue names it)."""

    kind: str
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
