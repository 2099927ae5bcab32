"""The replay page's list, without the child's view (``html_text(recording)`` from Python):
colours and notes by name, what was said once, in the words of the program."""

from __future__ import annotations

from rootlang.app.session import simulate
from rootlang.checks import load_checked
from rootlang.colors import color_name
from rootlang.sim.render.compose import replay_of
from rootlang.sim.world import default_world
from rootlang.units import note_frequency, note_name

PROGRAM = """when started
    light green
    play note C4 for 0.2 seconds
    play note F#5 for 0.2 seconds
    say "hello"
    light rgb 1 2 3
"""


def test_the_list_names_colours_and_notes_and_says_each_thing_once() -> None:
    checked = load_checked(PROGRAM, "p.root")
    _, recording = simulate(checked.program, default_world(), source=PROGRAM)
    texts = [happening.text for happening in replay_of(recording).events]
    assert "light on green" in texts
    assert "♪ C4 for 0.2 seconds" in texts and "♪ F#5 for 0.2 seconds" in texts
    assert texts.count("say “hello”") == 1 and not any("says" in text for text in texts)
    assert "light on #010203" in texts  # a colour without a name keeps its digits


def test_note_names_round_trip_and_odd_frequencies_stay_in_hertz() -> None:
    for name in ("C4", "A4", "F#5", "B3", "C#2"):
        assert note_name(note_frequency(name)) == name
    assert note_name(300) == "300 Hz"
    assert color_name((255, 105, 180)) == "pink"
