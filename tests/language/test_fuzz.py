"""No input — random text, broken programs, deep nesting, huge numbers, 10,000 lines — gives
anything but a program or RootlangError."""

from __future__ import annotations

import random
import re
from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st

from rootlang.checks import load_checked
from rootlang.diagnostics import RootlangError

PROGRAMS = sorted((Path(__file__).parents[2] / "programs").rglob("*.root"))
ALPHABET = st.sampled_from(
    [*list('abcdefmorstuvwxyz0123456789 \t\n"#%:(),.+-*/=<>°≤'), "when ", "move ", "cm", "\n    "]
)


def outcome(source: str) -> str:
    try:
        load_checked(source, "fuzz.root")
    except RootlangError as error:
        assert error.diagnostics, "an error must say what is wrong"
        for found in error.diagnostics:
            assert not re.search(r"\{[a-z_]+\}", found.english) and found.span.line >= 0
        return "errors"
    return "program"


@settings(max_examples=150, deadline=None)
@given(st.lists(ALPHABET, max_size=60))
def test_random_text(pieces: list[str]) -> None:
    outcome("".join(pieces))


@settings(max_examples=60, deadline=None)
@given(st.binary(max_size=200))
def test_random_bytes(data: bytes) -> None:
    outcome(data.decode("utf-8", errors="replace"))


def test_mutations_of_the_gallery() -> None:
    """Delete, duplicate or swap characters of real programs, a few hundred times."""
    chooser = random.Random(3)
    results = set()
    for _ in range(300):
        text = chooser.choice(PROGRAMS).read_text(encoding="utf-8")
        position = chooser.randrange(len(text))
        edit = chooser.choice(("delete", "duplicate", "swap", "tab"))
        if edit == "delete":
            text = text[:position] + text[position + 1 :]
        elif edit == "duplicate":
            text = text[:position] + text[position] * 2 + text[position + 1 :]
        elif edit == "swap" and position + 1 < len(text):
            text = text[:position] + text[position + 1] + text[position] + text[position + 2 :]
        else:
            text = text[:position] + "\t" + text[position:]
        results.add(outcome(text))
    assert results == {"program", "errors"}


def test_every_kind_of_unfinished_line() -> None:
    """Lines of real programs cut short, or with a word dropped, anywhere."""
    chooser = random.Random(5)
    lines = [
        line
        for path in PROGRAMS
        for line in path.read_text(encoding="utf-8").splitlines()
        if line.strip() and not line.lstrip().startswith("#")
    ]
    for _ in range(400):
        line = chooser.choice(lines).strip()
        words = line.split()
        cut = line[: chooser.randrange(1, len(line) + 1)]
        dropped = (
            " ".join(words[:i] + words[i + 1 :]) if (i := chooser.randrange(len(words))) else cut
        )
        for variant in (cut, dropped):
            outcome("when started\n    " + variant + "\n")
            outcome(variant + "\n    stop moving\n")


def _nested_repeats(blocks: int) -> str:
    lines = ["when started"] + [" " * (4 * depth) + "repeat 2" for depth in range(1, blocks + 1)]
    return "\n".join([*lines, " " * (4 * blocks + 4) + "move 1 cm"])


def test_deep_nesting() -> None:  # up to NESTING_LIMIT (100) blocks inside each other
    assert outcome(_nested_repeats(100)) == "program"
    assert outcome(_nested_repeats(101)) == "errors"
    assert outcome(_nested_repeats(300)) == "errors"


def test_deep_parentheses() -> None:
    assert outcome("when started\n    move " + "(" * 300 + "1 cm" + ")" * 300) == "program"
    assert outcome("when started\n    move " + "(" * 300 + "1 cm") == "errors"
    # brackets that change nothing aren't calculations: only calculations count
    assert outcome("when started\n    move " + "(" * 5000 + "1 cm" + ")" * 5000) == "program"
    for inside, read in ((100, "program"), (101, "errors"), (245, "errors")):
        move = "when started\n    move " + "(1 cm + " * inside + "1 cm" + ")" * inside
        assert outcome(move) == read


def test_very_deep_blocks() -> None:
    lines = ["when started"] + [" " * depth + "repeat 2" for depth in range(1, 3000)]
    assert outcome("\n".join([*lines, " " * 3000 + "move 1 cm"])) in ("errors", "program")


def test_huge_numbers() -> None:
    assert outcome("when started\n    move " + "9" * 400 + " cm\n") == "errors"
    assert outcome("when started\n    wait 0." + "0" * 400 + "1 seconds\n") == "program"


def test_ten_thousand_lines() -> None:
    body = "".join(
        f"    move {n % 7 + 1} cm\n    turn left {n % 90} degrees\n" for n in range(5000)
    )
    assert outcome("when started\n" + body) == "program"
    assert outcome("when started\n" + body + "    mve 1 cm\n") == "errors"
