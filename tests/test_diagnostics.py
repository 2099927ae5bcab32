"""Shared message helpers: durations in words, "did you mean", rendering with a caret."""

from __future__ import annotations

from rootlang.diagnostics import (
    LINE_SHOWN,
    Span,
    diagnostic,
    did_you_mean,
    render,
    seconds_text,
)
from rootlang.wording.language import ENGLISH


def test_durations_read_as_words_with_the_right_plural() -> None:
    assert [seconds_text(s) for s in (1, 1.0, 2, 0.5, 10)] == [
        "1 second",
        "1 second",
        "2 seconds",
        "0.5 seconds",
        "10 seconds",
    ]


def test_did_you_mean_picks_the_closest_word_within_two_edits() -> None:
    assert did_you_mean("mve", ["move", "marker", "turn"]) == "move"
    assert did_you_mean("tunr", ["move", "turn"]) == "turn"  # a swap counts as one edit
    assert did_you_mean("xylophone", ["move", "turn"]) is None


def test_render_quotes_the_line_and_underlines_the_span() -> None:
    source = "when started\n    mve 10 cm\n"
    diag = diagnostic("E603", Span(2, 5, 2, 8)).in_file("square.root")
    lines = render(diag, source, ENGLISH).splitlines()
    assert lines[0] == "square.root, line 2:"
    assert lines[1].endswith("mve 10 cm")
    assert lines[2].index("^") == lines[1].index("m") and lines[2].count("^") == 3


def test_a_long_line_is_shown_around_its_caret() -> None:
    from rootlang.checks import diagnose

    for before, after in ((0, 4000), (2000, 2000), (4000, 0), (30, 60)):
        line = "    print " + "(" * before + "mve" + ")" * after
        source = f"when started\n{line}\n"
        mistake = next(d for d in diagnose(source, "long.root") if d.severity == "error")
        quoted, caret = (shown[8:] for shown in render(mistake, source, ENGLISH).splitlines()[1:3])
        assert len(quoted) <= LINE_SHOWN + 2 and len(caret) <= len(quoted) + 1
        # under the caret: what is there in the whole line (or its end)
        at, whole_at = caret.index("^"), mistake.span.column - 1
        assert quoted[at : at + 1] == line[whole_at : whole_at + 1], (before, after)
        assert quoted.startswith("…") == (len(line) > LINE_SHOWN and whole_at > LINE_SHOWN // 4)


def test_a_line_separator_inside_a_text_does_not_shift_the_quoted_line() -> None:
    from rootlang.checks import parse_and_check

    for separator in ("\u2028", "\u0085", "\u2029", "\x0c"):
        source = f'when started\n    say "a{separator}b"\n    mve 1 cm\n'
        _, found = parse_and_check(source, "odd.root")
        mistake = next(item for item in found if item.code == "E101")
        assert mistake.span.line == 3
        shown = render(mistake, source, ENGLISH)
        assert shown.splitlines()[1].strip() == "mve 1 cm", separator


def test_many_diagnostics_of_one_source_split_it_once() -> None:
    from rootlang.diagnostics import render_all, source_lines

    source = "when started\n" + "    mve 1 cm\n" * 2000
    source_lines.cache_clear()
    render_all([diagnostic("E101", Span(line, 5, line, 8), name="mve", suggestion="")
                for line in range(2, 2002)], source, ENGLISH)  # fmt: skip
    assert source_lines.cache_info().misses == 1
