"""Shared message helpers: durations in words, "did you mean", rendering with a caret."""

from __future__ import annotations

from rootlang.diagnostics import Span, diagnostic, did_you_mean, render, seconds_text


def test_durations_read_as_words_with_the_right_plural() -> None:
    assert [seconds_text(s) for s in (1, 1.0, 2, 0.5, 10)] == [
        "1 second", "1 second", "2 seconds", "0.5 seconds", "10 seconds"
    ]


def test_did_you_mean_picks_the_closest_word_within_two_edits() -> None:
    assert did_you_mean("mve", ["move", "marker", "turn"]) == "move"
    assert did_you_mean("tunr", ["move", "turn"]) == "turn"  # a swap counts as one edit
    assert did_you_mean("xylophone", ["move", "turn"]) is None


def test_render_quotes_the_line_and_underlines_the_span() -> None:
    source = "when started\n    mve 10 cm\n"
    diag = diagnostic("E603", Span(2, 5, 2, 8)).in_file("square.root")
    lines = render(diag, source).splitlines()
    assert lines[0] == "square.root, line 2:"
    assert lines[1].endswith("mve 10 cm")
    assert lines[2].index("^") == lines[1].index("m") and lines[2].count("^") == 3
