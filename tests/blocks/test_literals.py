"""The literals a block may hold (a variable's name, a note, a hex colour) are read by the
grammar's own terminals (root.lark's NAME, NOTE, HEX_COLOR), not by copies of them."""

from __future__ import annotations

from rootlang.blocks import blocks_to_text
from rootlang.grammar import terminal


def test_the_literals_blocks_take_are_the_grammars_terminals() -> None:
    for pattern, name in ((blocks_to_text._NAME, "NAME"), (blocks_to_text._NOTE, "NOTE"),
                          (blocks_to_text._HEX, "HEX_COLOR")):  # fmt: skip
        assert pattern.pattern == terminal(name).pattern
        assert pattern.flags == terminal(name).flags


def test_a_terminal_is_read_as_the_grammar_writes_it() -> None:
    assert terminal("NOTE").fullmatch("C#4") and not terminal("NOTE").fullmatch("H4")
    assert terminal("HEX_COLOR").fullmatch("#FF00aa")
    assert terminal("NAME").fullmatch("speed_2") and not terminal("NAME").fullmatch("2x")
