"""Values of a message that are kept as data until the message is shown: a suggestion, the
line to write, a kind of value in a unit. English is their ``str``; the catalogue
(:mod:`rootlang.locale.catalogue`) shows each in the message's language, with its code in the
program's language, from what it holds, so nothing reads a message back.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["InUnit", "Suggestion", "Write", "suggestion", "write_line"]


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
