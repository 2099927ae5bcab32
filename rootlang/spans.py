"""Where a piece of a program is: the one small value type the syntax tree and the diagnostics
share. It stands below both, so the forms (:mod:`rootlang.forms`), and the keyword tables that
read their words, need nothing of the diagnostics."""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["Span"]


@dataclass(frozen=True, order=True)
class Span:
    """A stretch of source text; lines and columns count from 1, the end is exclusive."""

    line: int
    column: int
    end_line: int
    end_column: int

    @classmethod
    def point(cls, line: int, column: int, width: int = 1) -> Span:
        return cls(line, column, line, column + max(width, 1))
