"""Habits from Scratch, Python, JavaScript, turtle Logo and iRobot's Python SDK: the caret on the
habit and the rootlang line it means, with the child's own values (rootlang.grammar.habits)."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest

from rootlang.checks import diagnose
from rootlang.forms import STATEMENT_WORDS
from rootlang.grammar.habits import (
    HABITS,
    LAST,
    SHARED_WORDS,
    SYNONYMS,
    WRITTEN_HABITS,
    WRITTEN_SYNONYMS,
    claimed_word,
    meaning,
    of_other_tools,
    synonyms_of_other_tools,
)
from rootlang.locale.translate import about
from rootlang.wording.language import ENGLISH

S = "when started\n    set x to 1\n"
ROOT = Path(__file__).resolve().parents[2]

CASES = [  # (line inside `when started`, the caret's text, the line(s) to write)
    ("move 10 steps", "steps", "Write: `move 10 cm`"),
    ('broadcast "go"', "broadcast", 'Write: `send "go"`'),
    ('say "hi" for 2 seconds', "for", 'Write these lines:\n    say "hi"\n    wait 2 seconds'),
    ("point in direction 180", "point in direction 180", "facing 270 degrees`"),
    ("x += 1", "+=", "Write: `change x by 1`"),
    ("x = x + 1", "=", "Write: `change x by 1`"),
    ("time.sleep(1)", "time.sleep(", "Write: `wait 1 seconds`"),
    ("move 10 cm;", ";", "Write: `move 10 cm`"),
    ("let y = 5", "let", "Write: `set y to 5`"),
    ("var y = 5", "var", "Write: `set y to 5`"),
    ("forward 10", "forward", "Write: `move 10 cm`"),
    ("fd 10", "fd", "Write: `move 10 cm`"),
    ("right 90", "right", "Write: `turn right 90 degrees`"),
    ("lt 45", "lt", "Write: `turn left 45 degrees`"),
    ("pd", "pd", "Write: `marker down`"),
    ("pu", "pu", "Write: `marker up`"),
    ("repeat 4 [ fd 10 rt 90 ]", "[",
     "Write these lines:\n    repeat 4\n        move 10 cm\n        turn right 90 degrees"),
    ("await robot.move(10)", "await robot.", "Write: `move 10 cm`"),
    ("robot.set_lights_rgb(255, 0, 0)", "robot.set_lights_rgb(", "Write: `light rgb 255 0 0`"),
    ("end", "end", "Delete this line."),
    ("import time", "import time", "Delete this line."),
    ("repeat times 4", "times", "Write: `repeat 4`"),
    ("if touching edge", "touching edge", "Write: `if bumper any pressed`"),
    ("if x == 3 {", "{", "Write: `if x == 3`"),
    ("turn right 45", "45", "Write: `turn right 45 degrees`"),
    ("pen_down", "pen_down", "Write: `marker down`"),
    ("print('hi')", "'", 'Write: `print "hi"`'),
    ("turn ↻ 15 degrees", "↻", "Write: `turn right 15 degrees`"),
    ("fd 10 rt 90", "fd", "Write these lines:\n    move 10 cm\n    turn right 90 degrees"),
    ("if <touching edge?> then", "<", "Write: `if bumper any pressed`"),
    # the caret on the first part that must change; the child's values, counted or unboxed
    ("if (x > 3) {", "{", "Write: `if x > 3`"),
    ("move (10) steps", "steps", "Write: `move 10 cm`"),
    ("say Hello!", "Hello!", 'Write: `say "Hello!"`'),
    ("set [score] to (0)", "[", "Write: `set score to 0`"),
    ("go to x: 10 y: 20", "x:", "Write: `go to x 10 cm y 20 cm`"),
    ("for i in range(2, 10, 2):", "for i in range(2, 10, 2):", "Write: `repeat 4`"),
    ("for (let i = 1; i <= 3; i++) {", "for (let i = 1; i <=", "Write: `repeat 3`"),
    ("x = 5", "=", "Write: `set x to 5`"),
    ("x *= 2", "*=", "Write: `set x to x * 2`"),
    ('print(f"x is {x}")', "f", 'Write: `print join("x is ", x)`'),
    ("if (x === 3 && x < 9) {", "===", "Write: `if x = 3 and x < 9`"),
    ("setxy 10 20", "setxy", "Write: `go to x 10 cm y 20 cm`"),
    ("await robot.move(distance=15)", "await robot.", "Write: `move 15 cm`"),
    ("await robot.play_note(Note.C5_SHARP, Note.QUARTER)", "await robot",
     "Write: `play note C#5 for 0.25 seconds`"),
    ("await robot.set_lights(Robot.LIGHT_ON, Color(255, 0, 0))",
     "await robot.set_lights(Robot.LIGHT_ON, Color(", "Write: `light rgb 255 0 0`"),
    ("set x = 5", "=", "Write: `set x to 5`"),
    ("if x is bigger than 3", "is bigger than", "Write: `if x > 3`"),
    # words in another order: the caret on the word out of place
    ("turn 90 degrees right", "right", "Write: `turn right 90 degrees`"),
    ("turn 90 degrees left", "left", "Write: `turn left 90 degrees`"),
    ("move 10 cm forward", "forward", "Write: `move forward 10 cm`"),
    ("move 5 backwards", "backwards", "Write: `move backward 5 cm`"),
    # a word a child uses for a command, or a command word with an ending
    ("roll 30 cm", "roll", "Write: `move 30 cm`"),
    ("shine red", "shine", "Write: `light red`"),
    ("start drawing", "start drawing", "Write: `marker down`"),
    ("hum note C5 for 1 second", "hum", "Write: `play note C5 for 1 second`"),
    ("delay 2 seconds", "delay", "Write: `wait 2 seconds`"),
    ("waited 1 second", "waited", "Write: `wait 1 second`"),
    ("quit", "quit", "Write: `stop all`"),
    ("turtle.forward(50)", "turtle.forward(", "Write: `move 50 cm`"),
    ("move 10 centimeters", "centimeters", "Write: `move 10 cm`"),
    ("/* turn now */", "/*", "Write: `# turn now`"),
    ("set x to sqrt of x", "of", "Write: `set x to sqrt x`"),
    ("marker off", "off", "Write: `marker up`"),
    ("var total;", "var", "Write: `set total to 0`"),
    ("move 10 cm!", "!", "Write: `move 10 cm`"),
    # milliseconds where the tool counts them (MakeCode's pause, Arduino's delay, JavaScript)
    ("delay 500", "delay", "Write: `wait 500 ms`"),
    ("await sleep(1000);", "await sleep(", "Write: `wait 1000 ms`"),
    ("pause 2 seconds", "pause", "Write: `wait 2 seconds`"),
    # two commands said as one sentence; a command with how many times
    ("move 10 cm and turn left 45 degrees", "and",
     "Write these lines:\n    move 10 cm\n    turn left 45 degrees"),
    ("move 3 cm 5 times", "5 times", "Write these lines:\n    repeat 5\n        move 3 cm"),
    # Scratch as scratchblocks writes it: drop-down arrows, round and hexagonal slots, reporters
    ("change [x v] by (3)", "[", "Write: `change x by 3`"),
    ("if <<(x) > (1)> and <(x) < (9)>> then", "<<(", "Write: `if x > 1 and x < 9`"),
    ("stop [other scripts in stage v]", "[", "Write: `stop other scripts`"),
    ("say (join [score: ] (x))", "[", 'Write: `say join("score: ", x)`'),
    ("say (x position) for (1) seconds", "for", "    say position x\n    wait 1 seconds"),
    ("wait until <(timer) > (4)>", "<(", "Write: `wait until timer > 4 seconds`"),
    # Python's turtle called on a turtle of any name
    ("bob.circle(-15, 90)", "bob.circle(-", "Write: `arc right 90 degrees radius 15 cm`"),
    ("pen.pencolor('purple')", "pen.pencolor('", "Write: `light purple`"),
    ("turtle.setheading(45)", "turtle.setheading(", "facing 45 degrees`"),
    ("t.speed(0)", "t.speed(0)", "Delete this line."),
    ("screen = turtle.Screen()", "screen = turtle.Screen()", "Delete this line."),
    # C-style loops and declarations (JavaScript, Arduino, MakeCode)
    ("for (;;) {", "for (;;) {", "Write: `forever`"),
    ("for (int k = 6; k >= 1; --k) {", "for (int k =", "Write: `repeat 6`"),
    ("float y = 2.5;", "float", "Write: `set y to 2.5`"),
    ("delay(100);", "delay(", "Write: `wait 100 ms`"),
    ("basic.pause(20)", "basic.pause(", "Write: `wait 20 ms`"),
    ("Serial.println(x);", "Serial.println(", "Write: `print x`"),
    ("tone(8, 440, 200);", "tone(8,", "Write: `play 440 Hz for 200 ms`"),
    # Logo's lists of commands: ifelse, nested repeats, prefix arithmetic
    ("ifelse :x > 2 [pd] [pu]", "ifelse :",
     "    if x > 2\n        marker down\n    else\n        marker up"),
    ("repeat 2 [repeat 3 [fd 5] rt 90]", "[",
     "    repeat 2\n        repeat 3\n            move 5 cm\n        turn right 90 degrees"),
    ("print product :x 3", "product :", "Write: `print x * 3`"),
    # a time in a unit rootlang has not; arithmetic said in words
    ("wait 3 minutes", "minutes", "Write: `wait 180 seconds`"),
    ("set x to x minus 2", "minus", "Write: `set x to x - 2`"),
    ("set x to x divided by 4", "divided by", "Write: `set x to x / 4`"),
    # numbers in words; a command for a time, or said with how many times; calls of words
    ("turn left forty five degrees", "forty five", "Write: `turn left 45 degrees`"),
    ("move a hundred mm", "a hundred", "Write: `move 100 mm`"),
    ("light blue for 3 seconds", "for", "    light blue\n    wait 3 seconds"),
    ("say yay 2 times", "2 times", '    repeat 2\n        say "yay"'),
    ("document.write(x);", "document.write(", "Write: `print x`"),
    ("exit()", "exit()", "Write: `stop all`"),
    ("broadcast go and wait", "broadcast go", 'Write: `send "go" and wait`'),
    # an event word as a condition; a bare number compared with a time
    ("if touched", "touched", "Write: `if touch"),
]  # fmt: skip


@pytest.mark.parametrize(("line", "caret", "write"), CASES)
def test_a_habit_gets_the_line_it_means(line: str, caret: str, write: str) -> None:
    body = "\n        move 1 cm\n" if line.startswith(("repeat", "if")) else "\n"
    found = [d for d in diagnose(S + "    " + line + body) if d.severity == "error"]
    assert len(found) == 1, [d.english for d in found]
    (mistake,) = found
    written = line[mistake.span.column - 5 : mistake.span.end_column - 5]
    assert (mistake.span.line, written) == (3, caret)
    assert write in mistake.english


@pytest.mark.parametrize(
    ("program", "write"),
    [
        ("when green flag clicked\n    move 1 cm\n", "Write: `when started`"),
        ("def square(size):\n    move size\n", "Write: `to square size`"),
        ("when started\n    set x to 0\n    if x > 1\n        move 1 cm\n    elif x < 1:\n"
         "        move 2 cm\n", "Write: `else if x < 1`"),
    ],
)  # fmt: skip
def test_a_header_habit_gets_its_header(program: str, write: str) -> None:
    (found,) = [d for d in diagnose(program) if d.severity == "error"]
    assert write in found.english


def test_what_rootlang_already_accepts_stays_accepted() -> None:
    program = S + "    if x == 1 then\n        pen down\n    while x < 3:\n        change x by 1\n"
    assert diagnose(program) == []


def test_a_procedure_of_the_childs_own_is_never_a_habit() -> None:
    program = "to forward steps\n    move steps\n" + S + "    forward 10 cm\n"
    assert diagnose(program) == []


def test_a_habit_whose_line_would_still_be_wrong_explains_without_a_fix() -> None:
    (found,) = diagnose(S + '    x += "abc"\n')  # `change x by "abc"`: a number changed by text
    assert found.code == "E034" and "Write" not in found.english
    assert "Python" in found.english


@pytest.mark.parametrize(
    ("line", "name", "write"),
    [("total += 5", "total", "change total by 5"),
     ("for i in range(n):\n        move 1 cm", "n", "repeat n")],
)  # fmt: skip
def test_a_name_never_set_gets_its_line_and_is_told_to_set_it_first(
    line: str, name: str, write: str
) -> None:
    (found,) = diagnose(S + f"    {line}\n")
    habit, then = found.english.split("\n")[-2:]  # the habit's line first, then the other step
    assert found.code == "E036" and habit.endswith(f"Write: `{write}`"), found.english
    assert then == f"Then give `{name}` a value on a line before this one, like `set {name} to 0`."


def test_a_logo_name_never_set_says_the_logo_habit_first_then_to_set_it() -> None:
    (found,) = diagnose("when started\n    print :count\n")
    assert (found.code, found.span.column, found.span.end_column) == ("E036", 11, 12)
    assert found.english == (
        "`:` is written that way in Logo. Write: `print count`\n"
        "Then give `count` a value on a line before this one, like `set count to 0`."
    )


@pytest.mark.parametrize(
    ("line", "caret"),
    [("repeat 4x", "4x"), ("repeat x4", "x4"), ("repeat 4 x", "x"), ("4 times repeat", "times"),
     ("repeat 4×", "×")],
)  # fmt: skip
def test_a_count_written_with_a_times_sign_is_repeat_and_the_count(line: str, caret: str) -> None:
    (found,) = diagnose(f"when started\n    {line}\n        move 1 cm\n")
    line_text = f"    {line}"
    assert line_text[found.span.column - 1 : found.span.end_column - 1] == caret
    assert found.english.endswith("Write: `repeat 4`"), found.english


def test_a_command_with_a_times_sign_is_a_loop_over_it() -> None:
    (found,) = diagnose("when started\n    move 10 cm 3x\n")
    assert found.english.endswith("Write these lines:\n    repeat 3\n        move 10 cm")
    assert (found.span.column, found.span.end_column) == (16, 18)  # `3x`


def test_the_sdks_script_on_its_own_is_when_started_and_keeps_its_lines() -> None:
    (found,) = diagnose("async def play(robot):\n    move 10 cm\n")
    assert (found.code, found.span.line) == ("E031", 1), found.english
    assert found.english.endswith("Write: `when started`")


def test_the_sdks_script_under_its_event_line_is_deleted_not_a_second_header() -> None:
    program = "@event(robot.when_bumped, [True, False])\nasync def bumped(robot):\n    move 10 cm\n"
    found = [(d.code, d.span.line, d.english.split(". ")[-1]) for d in diagnose(program)]
    assert found == [
        ("E031", 1, "Write: `when bumper left pressed`"),
        ("E033", 2, "Delete this line."),
    ]


def test_a_habit_is_written_in_the_childs_language() -> None:
    source = "# language: nl\nwanneer gestart\n    fd 10\n"
    (found,) = diagnose(source)
    told = found.shown(about(ENGLISH, source))
    assert found.code == "E031" and "Schrijf: `beweeg 10 cm`" in told, told


def test_the_habit_table_is_data_every_entry_from_a_tool() -> None:
    assert len(HABITS) > 100
    assert {habit.source for habit in HABITS} >= {"Scratch", "Python", "JavaScript", "Logo"}
    found = meaning("fd 25")
    assert found is not None and found.rewrite == "move 25 cm" and found.source == "Logo"


def test_the_held_out_habits_score_at_least_90_percent() -> None:
    spec = importlib.util.spec_from_file_location("habits_bench", ROOT / "benchmarks/habits.py")
    assert spec is not None and spec.loader is not None
    bench = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(bench)
    scores = [bench.score(*case)[0] for case in bench.HELD_OUT]
    assert sum(scores) / len(scores) >= 0.9


def test_the_lines_under_a_habit_header_stay_its_body_and_are_checked() -> None:
    program = (
        "when green flag clicked\n"
        "    set n to 3\n"
        "    for i in range(n):\n"
        "        fd 10\n"
        "        mve 5 cm\n"
    )
    found = [(d.code, d.span.line, d.span.column) for d in diagnose(program)]
    assert found == [("E031", 1, 6), ("E031", 3, 5), ("E031", 4, 9), ("E023", 5, 9)]
    (loop,) = [d for d in diagnose(program) if d.span.line == 3]
    assert "Write: `repeat n`" in loop.english


def test_a_value_under_a_habit_header_is_underlined_where_the_child_wrote_it() -> None:
    program = "when started\n    for i in range(count):\n        move 1 cm\n"
    (found,) = diagnose(program)  # `count` was never set: `repeat count`, once it is
    assert found.code == "E036" and (found.span.line, found.span.column) == (2, 5)


@pytest.mark.parametrize(
    "header", ["def square(size):", "def square(size)", "function square(size) {"]
)
def test_the_lines_under_a_procedure_written_as_in_python_are_checked(header: str) -> None:
    program = f"{header}\n    mve size\n    turn right 45\n\nwhen started\n    square 10 cm\n"
    found = [(d.code, d.span.line, d.span.column) for d in diagnose(program)]
    assert found == [("E031", 1, 1), ("E023", 2, 5), ("E108", 3, 16)]  # `size` is known
    assert "Write: `to square size`" in diagnose(program)[0].english


def test_a_line_rootlang_reads_but_another_tool_wrote_gets_a_warning_with_its_word() -> None:
    (found,) = diagnose(S + "    while True:\n        move 1 cm\n")
    assert (found.code, found.severity, found.span.column) == ("W106", "warning", 5)
    assert found.english.endswith("Write: `forever`")
    assert diagnose(S + "    while x < 3:\n        change x by 1\n") == []


def test_a_misspelt_name_of_the_childs_own_beats_a_habit() -> None:
    (found,) = diagnose(S + "    set score to 1\n    say scroe\n")
    assert found.code == "E102" and '"score"' in found.english


def test_words_the_child_wrote_unquoted_keep_their_case() -> None:
    (found,) = diagnose(S + "    say Hello\n")
    assert found.code == "E118" and found.english.endswith('Write: `say "Hello"`')


def test_a_suggestion_in_the_programs_own_language_is_tried_in_place() -> None:
    source = "# language: fr\nquand démarré\n    avance 10\n    avanc 10 cm\n"
    found = diagnose(source)
    languages = about(ENGLISH, source)
    assert [d.code for d in found] == ["E031", "E101"]
    assert "Écris : `bouge 10 cm`" in found[0].shown(languages)  # French Logo's avance
    assert "avant" not in found[1].shown(languages)  # `avant 10 cm` is no command: not offered


def test_arduinos_loop_at_the_left_edge_is_one_message_a_script_and_forever() -> None:
    program = "void loop() {\n    move size\n}\n"
    found = [(d.code, d.span.line) for d in diagnose(program)]
    assert found == [("E038", 1), ("E102", 2), ("E032", 3)]  # its lines are checked too
    (loop,) = [d for d in diagnose(program) if d.span.line == 1]
    assert loop.english == (
        "`void loop() {` is written that way in Arduino. Write these lines:\n"
        "    when started\n"
        "        forever\n"
        "Then move the lines under it one step to the right, under `forever`."
    )


@pytest.mark.parametrize(
    ("program", "write"),
    [("void setup() {\n    move 1 cm\n}\n", "Write: `when started`"),
     ("when started\n    move 1 cm\nfd 10\n",
      "Write these lines:\n    when started\n        move 10 cm"),
     ("when started\n    void loop() {\n        move 1 cm\n    }\n", "Write: `forever`")],
)  # fmt: skip
def test_a_habit_at_the_left_edge_goes_in_a_script_of_its_own(program: str, write: str) -> None:
    found = [d for d in diagnose(program) if d.english.endswith(write)]
    assert [d.code for d in found] == ["E031"], [d.english for d in diagnose(program)]


def test_no_habit_or_synonym_calls_a_word_of_rootlang_another_tools() -> None:
    # a habit is another tool's only while rootlang doesn't say it (but for the few words of
    # rootlang's that other tools use other ways: `go right 90`, `change x to 5`)
    own = STATEMENT_WORDS - SHARED_WORDS
    assert SHARED_WORDS <= STATEMENT_WORDS  # none of them is stale
    claimed = {claimed_word(habit.written, habit.rootlang) for habit in (*HABITS, *LAST)}
    claimed |= {claimed_word(w, ours) for words, ours in SYNONYMS for w in words.split("|")}
    assert claimed & own == set()


def test_a_word_rootlang_takes_up_stops_being_another_tools_at_once() -> None:
    # `spin 3 turns` in the language: `spin` lines are no longer Scratch's or a synonym of turn
    # (from the tables as written, so this holds the day rootlang says `spin` itself)
    own = STATEMENT_WORDS | {"spin"}
    assert any(habit.written.startswith("spin") for habit in WRITTEN_HABITS)
    assert not any(
        habit.written.startswith("spin") for habit in of_other_tools(WRITTEN_HABITS, own)
    )
    kept = synonyms_of_other_tools(WRITTEN_SYNONYMS, own)
    assert "spin" not in {word for words, _ in kept for word in words.split("|")}
    assert dict((ours, words) for words, ours in kept)["turn"].startswith("rotate|twist")
