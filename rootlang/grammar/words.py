"""The words of the language, read from the grammar itself: what each terminal can be.

A keyword terminal (``"turn"i``) is one word. A pattern terminal such as
``/(forward|forwards|backward|backwards)(?![\\w])/i`` is a short, finite list of words, found by
expanding the small part of regular expressions the grammar uses for them (groups, ``|``,
``?``, ``[xyz]``, a space class, a look-ahead). Terminals that stand for endless words (NAME,
NUMBER, STRING) have no list. So "did you mean" suggestions follow the grammar as it changes,
with no second list of words to keep up to date.
"""

from __future__ import annotations

import functools

from lark import Lark
from lark.lexer import PatternStr

MOST_WORDS = 60  # a terminal with more spellings than this (notes: C4, F#5 ...) is not a list
_SPACES = frozenset(" \t")


class _Endless(Exception):
    """The pattern matches more than a short list of words."""


@functools.cache
def terminal_words(parser: Lark) -> dict[str, tuple[str, ...]]:
    """Terminal name -> the words it can be (lower case), for every terminal that is a word
    or a short list of words."""
    words: dict[str, tuple[str, ...]] = {}
    for terminal in parser.terminals:
        pattern = terminal.pattern
        if isinstance(pattern, PatternStr):
            spelled: tuple[str, ...] = (pattern.value.lower(),)
        else:
            try:
                spelled = tuple(sorted(set(expand(pattern.value))))
            except _Endless:
                continue
        spelled = tuple(word for word in spelled if word[:1].isalpha())
        if spelled and len(spelled) <= MOST_WORDS:
            words[terminal.name] = spelled
    return words


def expand(pattern: str) -> list[str]:
    """Every string a simple regular expression matches; raises _Endless for anything else."""
    reader = _Reader(pattern)
    found = reader.alternatives()
    if reader.position != len(pattern):
        raise _Endless(pattern)
    return [" ".join(word.lower().split()) for word in found]


class _Reader:
    def __init__(self, pattern: str) -> None:
        self.pattern = pattern
        self.position = 0

    def peek(self) -> str:
        return self.pattern[self.position : self.position + 1]

    def take(self) -> str:
        character = self.peek()
        self.position += 1
        return character

    def alternatives(self) -> list[str]:
        found = self.sequence()
        while self.peek() == "|":
            self.take()
            found += self.sequence()
        return found

    def sequence(self) -> list[str]:
        found = [""]
        while self.peek() not in ("", "|", ")"):
            piece = self.quantified(self.atom())
            found = [start + end for start in found for end in piece]
            if len(found) > MOST_WORDS:
                raise _Endless(self.pattern)
        return found

    def atom(self) -> list[str]:
        character = self.take()
        if character == "(":
            if self.pattern.startswith(("?!", "?="), self.position):
                self.skip_group()  # a look-ahead matches no characters
                return [""]
            if self.pattern.startswith("?:", self.position):
                self.position += 2
            inner = self.alternatives()
            if self.take() != ")":
                raise _Endless(self.pattern)
            return inner
        if character == "[":
            return self.character_class()
        if character == "\\":
            escaped = self.take()
            if escaped.isalnum():  # \w, \d ...: a class, not one character
                raise _Endless(self.pattern)
            return [escaped]
        if character in ".*+?{}^$":
            raise _Endless(self.pattern)
        return [character]

    def skip_group(self) -> None:
        depth = 1
        while depth:
            character = self.take()
            if not character:
                raise _Endless(self.pattern)
            if character == "\\":
                self.take()
            depth += {"(": 1, ")": -1}.get(character, 0)

    def character_class(self) -> list[str]:
        end = self.pattern.find("]", self.position)
        if end < 0:
            raise _Endless(self.pattern)
        inside = self.pattern[self.position : end].replace("\\t", "\t")
        self.position = end + 1
        if "-" in inside or inside.startswith("^") or "\\" in inside:
            raise _Endless(self.pattern)
        if set(inside) <= _SPACES:  # any space: a space is how people write it
            return [" "]
        return list(inside)

    def quantified(self, piece: list[str]) -> list[str]:
        mark = self.peek()
        if mark == "?":
            self.take()
            return ["", *piece]
        if mark in ("*", "+"):
            self.take()
            if piece != [" "]:
                raise _Endless(self.pattern)
            return [""] if mark == "*" else [" "]
        return piece
