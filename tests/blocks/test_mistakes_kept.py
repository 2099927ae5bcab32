"""A program with mistakes is never cut short: a misspelt block header keeps its body (the
parser reads it as the header written right, with an error, and checks the body), and
`format`, the blocks and `translate` never drop a line of a program with mistakes."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rootlang import ast
from rootlang.blocks import to_text, to_workspace
from rootlang.checks import parse_and_check
from rootlang.cli.translate import translate
from rootlang.diagnostics import RootlangError
from rootlang.formatting import format_source
from rootlang.grammar import parse_lines

from .programs import random_program

TYPOS = {
    "forever": ["foorever", "forver", "forevr"],
    "while": ["whlie", "whle"],
    "repeat": ["repet", "repaet"],
    "if": ["iff"],
}


@pytest.mark.parametrize(
    ("header", "node"),
    [
        ("foorever", ast.Forever),
        ("forver", ast.Forever),
        ("whlie x < 3", ast.While),
        ("repet 4", ast.Repeat),
        ("repaet 4 times", ast.Repeat),
        ("iff x > 3", ast.If),
    ],
)
def test_a_misspelt_header_keeps_its_body_and_its_mistakes_are_reported(
    header: str, node: type[ast.Node]
) -> None:
    source = f'when started\n    set x to 1\n    {header}\n        move 10 cm\n        mvoe 5\n    say "end"\n'  # noqa: E501
    program, found = parse_and_check(source, "typo.root")
    assert program is not None
    codes = {(item.span.line, item.code) for item in found if item.severity == "error"}
    assert (3, "E023") in codes  # the header word, with the fix
    assert any(line == 5 for line, _ in codes)  # the body's own mistake (`mvoe`)
    recovered = program.scripts[0].body[1]
    assert isinstance(recovered, node)
    body = recovered.branches[0].body if isinstance(recovered, ast.If) else recovered.body  # type: ignore[attr-defined]
    assert [statement.span.line for statement in body] == [4, 5]
    message = next(item for item in found if item.code == "E023")
    assert message.span.column == 5 and message.span.end_column == 5 + len(header.split()[0])


def test_a_recovered_header_s_values_keep_their_columns() -> None:
    program, _ = parse_lines("when started\n    whlie x < 3\n        move 1 cm\n")
    loop = program.scripts[0].body[0]
    assert isinstance(loop, ast.While)
    assert (loop.condition.span.column, loop.condition.span.end_column) == (11, 16)


def test_format_and_blocks_leave_a_misspelt_header_s_file_as_it_is(tmp_path: Path) -> None:
    source = "when started\n    foorever\n        move 10 cm\n        turn right 90 degrees\n"
    path = tmp_path / "typo.root"
    path.write_text(source, encoding="utf-8")
    for command in (["format", str(path)], ["blocks", str(path)]):
        done = subprocess.run([sys.executable, "-m", "rootlang", *command],
                              capture_output=True, text=True, check=False)  # fmt: skip
        assert done.returncode == 1, command
        assert "Traceback" not in done.stderr
    assert path.read_text(encoding="utf-8") == source
    with pytest.raises(RootlangError):
        to_workspace(source)


@st.composite
def programs_with_mistakes(draw: st.DrawFn) -> str:
    lines = random_program(draw(st.integers(0, 10**6))).rstrip("\n").split("\n")
    for _ in range(draw(st.integers(1, 4))):
        at = draw(st.integers(0, len(lines) - 1))
        line = lines[at]
        roll = draw(st.integers(0, 4))
        if roll == 0:  # a header word misspelt
            for word, typos in TYPOS.items():
                if word in line.lower():
                    start = line.lower().index(word)
                    line = line[:start] + draw(st.sampled_from(typos)) + line[start + len(word) :]
                    break
        elif roll == 1:  # indented more or less
            line = " " * draw(st.sampled_from([0, 2, 4, 8, 12])) + line.lstrip()
        elif roll == 2 and line.strip():  # a letter left out
            cut = draw(st.integers(0, len(line) - 1))
            line = line[:cut] + line[cut + 1 :]
        elif roll == 3:  # a stray line
            stray = ["foorever", "whlie x < 3", "repet 4", "mvoe 10", ")(", '"open', "else"]
            lines.insert(at, " " * draw(st.sampled_from([0, 4, 8])) + draw(st.sampled_from(stray)))
            continue
        lines[at] = line
    return "\n".join(lines) + "\n"


def non_blank(text: str) -> int:
    return sum(1 for line in text.split("\n") if line.strip())


@given(programs_with_mistakes())
@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
def test_no_line_of_a_program_with_mistakes_is_ever_dropped(source: str) -> None:
    """format and the blocks either refuse (the file is left as it is) or keep every line;
    translate keeps every line whatever the mistakes (and adds its `# language:` line)."""
    try:
        formatted = format_source(source)
    except RootlangError:
        formatted = None
    if formatted is not None:
        assert non_blank(formatted) == non_blank(source)
    try:
        workspace = json.loads(json.dumps(to_workspace(source)))
    except RootlangError:
        workspace = None
    if workspace is not None:
        assert non_blank(to_text(workspace)) == non_blank(source)
    for language in ("nl", "de"):
        try:
            translated = translate(source, language)
        except RootlangError:
            continue
        added = translated.startswith("# language:") and not source.startswith("# language:")
        assert len(translated.split("\n")) - added == len(source.split("\n"))
