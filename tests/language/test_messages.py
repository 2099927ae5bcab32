"""Every language message code, reached from a real program: (source, code, line, column)."""

from __future__ import annotations

import pytest

from rootlang.checks import diagnose, load_checked
from rootlang.messages import MESSAGES
from rootlang.robots import RobotModel
from rootlang.units import Quantity, UnitError, apply_function

S = "when started\n"  # most examples live in one script

CASES: list[tuple[str, str, int, int, RobotModel | None]] = [
    (S + "    move 10 cm at 5 cm/s\n", "E001", 2, 16, None),
    (S + '    say "hello\n', "E002", 2, 9, None),
    (S + "\tmove 1 cm\n    move 2 cm\n", "E003", 3, 1, None),
    ("move 10 cm\n" + S + "    move 1 cm\n", "E004", 1, 1, None),
    (S + "    set speed = 5 cm + 2 seconds\n", "E005", 2, 15, None),  # set ... to: no fix
    (S + "    repeat\n        move 1 cm\n", "E006", 2, 5, None),
    (S + "    else\n        move 1 cm\n", "E007", 2, 5, None),
    (S + "    move 1 cm\n        move 2 cm\n", "E008", 3, 9, None),
    (S + "    repeat 4\n    move 1 cm\n", "E009", 2, 5, None),
    (S + "    if true\n        move 1 cm\n      move 2 cm\n", "E010", 4, 7, None),
    ("when strated\n    move 1 cm\n", "E011", 1, 6, None),
    (S + "    move 1 cm @\n", "E012", 2, 15, None),
    (S + "    move\n", "E013", 2, 9, None),
    (S + "    move 10 km\n", "E014", 2, 13, None),
    (S + "    move 99999999999999999999 cm\n", "E015", 2, 10, None),
    (S + "    when bumped\n        move 1 cm\n", "E016", 2, 5, None),
    (S + "    move (1 cm, 2 cm)\n", "E017", 2, 10, None),
    (S + "    move " + "(1 cm + " * 101 + "1 cm" + ")" * 101 + "\n", "E018", 2, 5, None),
    (S + "    say 'hi' 5\n", "E019", 2, 9, None),
    (S + "    set größe to 5\n", "E020", 2, 11, None),
    ("when button pressed\n    move 1 cm\n", "E021", 1, 6, None),
    ("when bumped left\n    move 1 cm\n", "E022", 1, 6, None),
    ("when touched back  Right:\n    move 1 cm\n", "E022", 1, 6, None),
    (S + "    jump\n", "E101", 2, 5, None),
    (S + "    move lenght\n", "E102", 2, 10, None),
    ("to square size\n    move size\n" + S + "    square 1 cm, 2 cm\n", "E103", 4, 5, None),
    ("to a\n    stop moving\nto a\n    stop moving\n", "E104", 3, 1, None),
    ("to a x, x\n    stop moving\n", "E105", 1, 9, None),
    (S + "    return\n", "E106", 2, 5, None),
    ("to spin\n    turn left 1 degree\n" + S + "    move spin\n", "E107", 4, 10, None),
    (S + "    move 10\n", "E108", 2, 10, None),
    (S + "    turn right 10 cm\n", "E109", 2, 16, None),
    (S + "    move 10 cm + 3 seconds\n", "E110", 2, 10, None),
    (S + "    trun right 90 degrees\n", "E023", 2, 5, None),
    (S + "    set x 5\n", "E024", 2, 11, None),
    (S + "    turn right by 90 degrees\n", "E025", 2, 16, None),
    (S + "    side = 30 cm\n", "E026", 2, 10, None),  # the caret on `=`
    (S + "    move 1e308 cm\n", "E027", 2, 10, None),
    ("    move 10 cm\n    turn left 90 degrees\n", "E028", 1, 5, None),
    ("move 10 cm\nturn left 90 degrees\n", "E035", 1, 1, None),
    ("when started\n    fd 10\n", "E031", 2, 5, None),
    ("when started\n    end\n", "E032", 2, 5, None),
    ("import time\nwhen started\n    move 1 cm\n", "E033", 1, 1, None),
    ('when started\n    set x to 1\n    x += "a"\n', "E034", 3, 7, None),
    ("when started\n    for i in range(n):\n        move 1 cm\n", "E036", 2, 5, None),
    (S + "    t.speed(0)\n    move 1 cm\n", "E037", 2, 5, None),
    ("void loop()\n    move 1 cm\n", "E038", 1, 1, None),
    # a suggestion that, tried in place, leaves a mistake on the line: the message without it
    (S + "    move foward\n", "E029", 2, 10, None),
    (S + "    x = y + 1\n", "E030", 2, 7, None),
    (S + "    if bumped and zz\n        stop moving\n", "E124", 2, 8, None),
    (S + '    move "a" + 3\n', "E125", 2, 10, None),
    (
        "to square size\n    move size\n" + S + "    set n to 20\n    square n\n",
        "E126",
        5,
        12,
        None,
    ),
    (S + "    if bumped\n        stop moving\n", "E119", 2, 8, None),
    (S + "    wait until timer > 3\n", "E127", 2, 24, None),
    (S + "    light gold\n", "E120", 2, 11, None),
    (S + '    print "n is " + 3\n', "E121", 2, 11, None),
    ("to square size\n    move size\n" + S + "    square 20\n", "E122", 4, 12, None),
    (S + "    drive 30 cm/s\n", "E123", 2, 11, RobotModel.RT0),
    (S + "    if color on left = pink\n        stop moving\n", "E111", 2, 24, None),
    (S + "    if 3\n        stop moving\n", "E112", 2, 8, None),
    (S + "    print sqrt 4 cm\n", "E113", 2, 11, None),
    (S + "    set a to 2 cm\n    move a cm\n", "E114", 3, 10, None),
    ("to spin\n    stop moving\n" + S + "    set spin to 3\n", "E116", 4, 5, None),
    (S + "    set timer to 3\n", "E128", 2, 5, None),  # it would read the timer
    ("when stopped\n    move 1 cm\n", "E117", 2, 5, None),
    (S + "    say hello\n", "E118", 2, 9, None),
    (S + "    set score to 1\n    say scroe\n", "E102", 3, 9, None),  # a near miss: a variable
    ("when color red seen\n    stop moving\n", "W101", 1, 6, RobotModel.RT0),
    (S + "    dock\n", "W102", 2, 5, RobotModel.RT1),
    ("when stopped\n    wait 3 seconds\n", "W103", 2, 5, None),
    ("to square\n    move 1 cm\n", "W104", 1, 1, None),
    (S + "    drive 30 cm/s\n", "W105", 2, 11, None),  # defined, never called from a script
    (S + "    while True:\n        move 1 cm\n", "W106", 2, 5, None),  # runs: rootlang says forever
]


@pytest.mark.parametrize(("source", "code", "line", "column", "robot"), CASES)
def test_each_message_is_reported_where_the_mistake_is(
    source: str, code: str, line: int, column: int, robot: RobotModel | None
) -> None:
    found = [(d.code, d.span.line, d.span.column) for d in diagnose(source, "t.root", robot)]
    assert (code, line, column) in found, found
    assert "{" not in next(d.english for d in diagnose(source, "t.root", robot) if d.code == code)


def test_square_root_below_zero_is_a_run_time_unit_error() -> None:
    with pytest.raises(UnitError) as caught:
        apply_function("sqrt", [Quantity.number(-4)])
    assert caught.value.code == "E115"


def test_every_language_code_has_a_case() -> None:
    ours = {code for code in MESSAGES if code[:2] in ("E0", "E1", "W1")}
    covered = {case[1] for case in CASES} | {"E115"}
    assert ours == covered


def test_a_clean_program_has_no_diagnostics() -> None:
    assert diagnose(S + "    move 10 cm\n    turn left 90 degrees\n") == []


def test_all_mistakes_of_a_file_come_in_one_go() -> None:
    source = S + '    mve 10 cm\n    turn left 90\n    say "oops\n    repeat\n        move 1\n'
    codes = [d.code for d in diagnose(source)]
    assert codes == ["E023", "E108", "E002", "E006", "E108"]


@pytest.mark.parametrize(
    "header",
    [
        "    repeat 4 (((",
        "    if x > ((",
        "    forever )",
        "    print hi (((",
        "to square size (((",
    ],
)
def test_the_lines_under_a_broken_line_are_checked_each_mistake_said_once(header: str) -> None:
    under = "    " * (header.startswith(" ") + 1)
    source = (
        f"when started\n    set x to 1\n{header}\n"
        f"{under}say scroe\n{under}mvoe 5 cm\n{under}move 10\n{under}turn left 90 degrees\n"
    )
    found = [(d.span.line, d.code) for d in diagnose(source)]
    assert found == sorted(set(found)), found  # no message twice
    assert [code for line, code in found if line > 3] == ["E118", "E023", "E108"], found
    if header.startswith(" "):  # no line but the broken one is told anything once it reads
        mended = source.replace(header, "    repeat 4")
        fixed = [(d.span.line, d.code) for d in diagnose(mended)]
        assert [item for item in fixed if item[0] > 3] == [item for item in found if item[0] > 3]


def test_syntax_errors_never_name_tokens() -> None:
    for source in (
        S + "    move\n",
        S + "    turn 90\n",
        S + "    set\n",
        "when\n",
        S + "    if\n",
    ):
        for found in diagnose(source):
            assert not any(word in found.english for word in ("_NL", "NAME", "$END", "__ANON"))


def test_a_misspelt_word_after_a_number_is_not_called_a_unit() -> None:
    (found,) = diagnose(S + "    repeat 4 tims\n        move 1 cm\n")
    assert found.code == "E023" and 'Did you mean "times"?' in found.english
    assert "Write: `repeat 4 times`" in found.english


def test_a_file_indented_with_tabs_only_is_fine() -> None:
    assert diagnose("when started\n\trepeat 2\n\t\tmove 1 cm\n\tturn left 1 degree\n") == []


def test_run_time_argument_checks_give_the_check_time_message() -> None:
    from rootlang.checks import expect_argument
    from rootlang.units import Kind

    (move,) = load_checked(S + "    move 1 cm\n").scripts[0].body
    with pytest.raises(UnitError) as caught:
        expect_argument(move, "distance", Kind.NUMBER)
    assert (caught.value.code, str(caught.value.values["example"])) == ("E108", "move 10 cm")
    assert expect_argument(move, "distance", Kind.LENGTH) is Kind.LENGTH


def test_a_two_letter_word_gets_no_guessed_suggestion() -> None:
    # `at` is two edits from `and`: suggesting it would send a child the wrong way
    (found,) = diagnose(S + "    move 10 cm at 5 cm/s\n")
    assert found.code == "E001" and "Did you mean" not in found.english


@pytest.mark.parametrize(
    ("line", "short"),
    [("move 10 centimeters", "cm"), ("move 10 Metres", "m"), ("wait 10 milliseconds", "ms")],
)
def test_a_unit_written_out_in_full_suggests_its_short_name(line: str, short: str) -> None:
    (found,) = diagnose(S + f"    {line}\n")
    assert found.code == "E014" and f'Did you mean "{short}"?' in found.english


def test_a_unit_that_would_not_fit_the_command_is_not_suggested() -> None:
    (found,) = diagnose(S + "    move 10 milliseconds\n")  # `move 10 ms` is no better
    assert found.code == "E014" and "Did you mean" not in found.english


@pytest.mark.parametrize(
    ("line", "written"),
    [
        ("play C4 for 1 second", "play note C4 for 1 second"),
        ("set tune to Bb3", "set tune to note Bb3"),
        ("play g5 for 0.5 seconds", "play note g5 for 0.5 seconds"),
    ],
)
def test_a_note_written_without_note_gets_its_word(line: str, written: str) -> None:
    (found,) = diagnose(S + f"    {line}\n")
    assert found.code == "E024" and found.english.endswith(f"Write: `{written}`")
    note = written.split("note ")[1].split()[0]
    assert found.span.column == len("    ") + line.index(note) + 1  # the caret on the note


def test_a_variable_named_like_a_note_stays_a_variable() -> None:
    assert diagnose(S + "    set c4 to 262 Hz\n    play c4 for 1 second\n") == []
