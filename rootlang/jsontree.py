"""JSON as deep as it comes, read and written without recursion.

A Blockly workspace nests one level deeper for every statement of a script (each block holds
the next one in ``next``), so a 500-line script is JSON 1,000 deep: Python's own ``json``
recurses in C once per level, which is a RecursionError at 1,000 and, on a 1 MB stack, a crash
before that on some Pythons (docs/runtime.md, "Depth"). ``loads`` and ``dumps`` keep their own
list of the containers they are inside instead, and give exactly what ``json`` gives. Shallow
text (most of it) still goes through ``json``'s C code, which is faster.
"""

from __future__ import annotations

import itertools
import json
import math
import re
import threading
from collections.abc import Callable
from typing import Any, cast

__all__ = ["dumps", "loads", "stack_has_room"]

FAST_DEPTH = 200
"""Text no deeper than this is read by ``json`` itself: a few hundred C frames are safe."""
_SPACE = re.compile(r"[ \t\n\r]*")
_NUMBER = re.compile(r"-?(?:0|[1-9][0-9]*)(\.[0-9]+)?([eE][-+]?[0-9]+)?")
_STRING = re.compile(r'"(?:[^"\\]|\\.)*"', re.DOTALL)
_NOT_BRACKET = re.compile(r"[^\[\]{}]+")
INDENTED_LEVELS = 32
"""``dumps`` with ``indent`` indents this many levels, and writes deeper ones on one line:
indenting every level of a long script's workspace would make it grow with its square."""
_CONSTANTS = {"true": True, "false": False, "null": None, "NaN": math.nan, "Infinity": math.inf,
              "-Infinity": -math.inf}  # fmt: skip
# json's own string reader (C): the text, the position after the opening quote -> (str, end)
scanstring = cast(Callable[[str, int], tuple[str, int]], json.decoder.scanstring)  # type: ignore[attr-defined]


def depth(text: str) -> int:
    """The most arrays and objects open at once in JSON ``text`` (strings left out)."""
    brackets = _NOT_BRACKET.sub("", _STRING.sub("", text))  # both in C: fast on large text
    return max(
        itertools.accumulate(1 if bracket in "[{" else -1 for bracket in brackets), default=0
    )


def loads(text: str) -> Any:
    """``json.loads(text)``, at any depth; ValueError (``json.JSONDecodeError``) as it gives."""
    if depth(text) <= FAST_DEPTH:
        return json.loads(text)
    return _Reader(text).read()


class _Reader:
    def __init__(self, text: str) -> None:
        self.text = text
        self.position = 0

    def _fail(self, what: str) -> json.JSONDecodeError:
        return json.JSONDecodeError(what, self.text, self.position)

    def _skip_space(self) -> str:
        """The next character after spaces ('' at the end)."""
        match = _SPACE.match(self.text, self.position)
        self.position = match.end() if match else self.position
        return self.text[self.position : self.position + 1]

    def _key(self) -> str:
        if self._skip_space() != '"':
            raise self._fail("Expecting property name enclosed in double quotes")
        key, self.position = scanstring(self.text, self.position + 1)
        if self._skip_space() != ":":
            raise self._fail("Expecting ':' delimiter")
        self.position += 1
        return key

    def _scalar(self, first: str) -> Any:
        if first == '"':
            value, self.position = scanstring(self.text, self.position + 1)
            return value
        for word, constant in _CONSTANTS.items():
            if self.text.startswith(word, self.position):
                self.position += len(word)
                return constant
        number = _NUMBER.match(self.text, self.position)
        if number is None:
            raise self._fail("Expecting value")
        self.position = number.end()
        if number.group(1) or number.group(2):
            return float(number.group())
        return int(number.group())

    def read(self) -> Any:
        open_containers: list[tuple[list[Any] | dict[str, Any], str]] = []  # (container, key)
        while True:
            first = self._skip_space()
            value: Any
            if first in ("[", "{"):  # a container: its first value comes next, if any
                self.position += 1
                value = [] if first == "[" else {}
                if self._skip_space() != ("]" if first == "[" else "}"):
                    open_containers.append((value, "" if first == "[" else self._key()))
                    continue
                self.position += 1
            else:
                value = self._scalar(first)
            while True:  # put the value in its container; close the containers it ends
                if not open_containers:
                    if self._skip_space():
                        raise self._fail("Extra data")
                    return value
                container, key = open_containers[-1]
                if isinstance(container, list):
                    container.append(value)
                else:
                    container[key] = value
                after = self._skip_space()
                self.position += 1
                if after == ",":
                    if isinstance(container, dict):
                        open_containers[-1] = (container, self._key())
                    break
                if after != ("]" if isinstance(container, list) else "}"):
                    self.position -= 1
                    raise self._fail("Expecting ',' delimiter")
                open_containers.pop()
                value = container


_this_thread = threading.local()


def stack_has_room() -> None:
    """This thread's stack has room for ``json``'s C code as deep as the recursion limit lets
    it go (a thread made with a big stack: the studio's conversion workers), so :func:`dumps`
    lets ``json`` write in one go (a 500-statement workspace: 15 ms -> 3 ms), and writes it
    itself only past the recursion limit."""
    _this_thread.has_room = True


def dumps(value: Any, *, indent: int | None = None, ensure_ascii: bool = True) -> str:
    """``json.dumps(value, indent=indent, ensure_ascii=ensure_ascii)``, at any depth (with
    ``indent``, levels past :data:`INDENTED_LEVELS` on one line)."""
    if indent is None and getattr(_this_thread, "has_room", False):
        try:
            return json.dumps(value, ensure_ascii=ensure_ascii)
        except RecursionError:
            pass
    written: list[str] = []
    todo: list[tuple[bool, Any, int]] = [(False, value, 0)]  # (text to write?, item, level)
    while todo:
        is_text, item, level = todo.pop()
        if is_text:
            written.append(item)
        elif (
            isinstance(item, dict | list)
            and (indent is None or level >= INDENTED_LEVELS)
            and not any(
                isinstance(inner, dict | list) and inner
                for inner in (item.values() if isinstance(item, dict) else item)
            )
        ):
            written.append(json.dumps(item, ensure_ascii=ensure_ascii))  # (flat: at once)
        elif isinstance(item, dict | list) and item:
            inner = outer = ""
            if indent is not None and level < INDENTED_LEVELS:
                inner, outer = "\n" + " " * indent * (level + 1), "\n" + " " * indent * level
            entries = list(item.items()) if isinstance(item, dict) else list(enumerate(item))
            todo.append((True, outer + ("}" if isinstance(item, dict) else "]"), 0))
            for index in range(len(entries) - 1, -1, -1):
                key, entry = entries[index]
                todo.append((False, entry, level + 1))
                separator = "," if indent is not None and level < INDENTED_LEVELS else ", "
                lead = inner if index == 0 else separator + inner
                if isinstance(item, dict):
                    lead += json.dumps(str(key), ensure_ascii=ensure_ascii) + ": "
                todo.append((True, lead, 0))
            todo.append((True, "{" if isinstance(item, dict) else "[", 0))
        else:
            written.append(json.dumps(item, ensure_ascii=ensure_ascii))
    return "".join(written)
