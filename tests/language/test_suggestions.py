"""A beginner's typo gets the caret on the word at fault and a message naming the fix.

The suggestions come from the grammar (rootlang.grammar.suggest), so they are tested the way a
class would meet them: one-letter typos (a letter left out, one too many, two swapped, one
wrong) of every word of the language, in the lines of the gallery programs.
"""

from __future__ import annotations

import json
import random
import re
from pathlib import Path

import pytest

from rootlang.checks import diagnose
from rootlang.cli import main
from rootlang.grammar import lark_parser
from rootlang.grammar.suggest import mend_line
from rootlang.grammar.words import expand, terminal_words
from rootlang.robots import RobotModel

PROGRAMS = Path(__file__).resolve().parents[2] / "programs"
S = "when started\n"
LETTERS = "abcdefghijklmnopqrstuvwxyz"
LANGUAGE_WORDS = frozenset(
    word
    for phrases in terminal_words(lark_parser()).values()
    for phrase in phrases
    for word in phrase.split(" ")
)


def test_the_words_of_pattern_terminals_are_read_from_the_grammar() -> None:
    words = terminal_words(lark_parser())
    assert words["MOVE_DIRECTION"] == ("backward", "backwards", "forward", "forwards")
    assert "this script" in words["STOP_TARGET"]
    assert {"cm", "cm/s", "seconds", "hz"} <= set(words["UNIT"])
    assert words["_COLOR_WORD"] == ("color", "colour")
    assert "NAME" not in words and "NUMBER" not in words  # endless: no list
    assert expand(r"(front|back)[ \t]+(left|right)(?![\w])") == [
        "front left",
        "front right",
        "back left",
        "back right",
    ]


def one_letter_typos(word: str) -> dict[str, list[str]]:
    """Every typo of each kind that is not itself a word of the language."""
    kinds = {
        "left out": [word[:i] + word[i + 1 :] for i in range(len(word))],
        "swapped": [
            word[:i] + word[i + 1] + word[i] + word[i + 2 :]
            for i in range(len(word) - 1)
            if word[i] != word[i + 1]
        ],
        "wrong": [
            word[:i] + letter + word[i + 1 :]
            for i in range(len(word))
            for letter in LETTERS
            if letter != word[i]
        ],
        "one too many": [
            word[:i] + letter + word[i:] for i in range(len(word) + 1) for letter in LETTERS
        ],
    }
    return {
        kind: [typo for typo in typos if typo[:1].isalpha() and typo not in LANGUAGE_WORDS]
        for kind, typos in kinds.items()
    }


def gallery_words() -> list[tuple[str, int, int, str]]:
    """(program text, line index, column, word) for each language word of 3+ letters in the
    gallery, once per word and first word of its line."""
    found: dict[tuple[str, str], tuple[str, int, int, str]] = {}
    for program in sorted(PROGRAMS.glob("*.root")):
        text = program.read_text(encoding="utf-8")
        for index, line in enumerate(text.split("\n")):
            code = line.split("#", 1)[0]
            for word in re.finditer(r"[A-Za-z]+", code):
                inside_text = code[: word.start()].count('"') % 2 == 1
                if (
                    word.group().lower() in LANGUAGE_WORDS
                    and len(word.group()) > 2
                    and not inside_text
                ):
                    key = (word.group().lower(), code.split()[0].lower())
                    found.setdefault(key, (text, index, word.start(), word.group()))
    return list(found.values())


def names_the_fix(source: str, index: int, column: int, word: str) -> bool:
    """Some diagnostic on the line has its caret on the word and names ``word``."""
    wanted = word.lower()
    for found in diagnose(source):
        if found.span.line != index + 1:
            continue
        on_word = (
            found.span.column <= column + 1 < max(found.span.end_column, found.span.column + 1)
        )
        message = found.english.lower()
        if on_word and re.search(rf"[\"` ]{re.escape(wanted)}[\"` ]", message):
            return True
    return False


def test_one_letter_typos_of_every_word_in_the_gallery_point_at_it_and_name_it() -> None:
    chosen = random.Random(12)
    missed: list[str] = []
    tried = 0
    for number, (text, index, column, word) in enumerate(gallery_words()):
        lines = text.split("\n")
        kinds = list(one_letter_typos(word.lower()).items())
        for kind, typos in kinds[number % 2 :: 2]:  # two kinds a word, by turns: CPU is scarce
            typo = chosen.choice(typos)
            changed = lines[index][:column] + typo + lines[index][column + len(word) :]
            source = "\n".join([*lines[:index], changed, *lines[index + 1 :]])
            tried += 1
            if not names_the_fix(source, index, column, word):
                missed.append(f"{kind}: {changed.strip()!r} (meant {word})")
    assert tried > 300
    # `colokr` may be `colour` as well as `color`: a few typos are as close to another word
    assert len(missed) <= tried // 50, "\n".join(missed)


@pytest.mark.parametrize(
    ("source", "line", "word", "fix"),
    [
        (S + "    trun right 90 degrees\n", 2, "trun", "`turn right 90 degrees`"),
        (S + "    move foward 10 cm\n", 2, "foward", "`move forward 10 cm`"),
        (S + "    play noet C4 for 1 second\n", 2, "noet", "`play note C4 for 1 second`"),
        (S + "    light gren\n", 2, "gren", "`light green`"),
        (S + "    light grey\n", 2, "grey", "red, orange, yellow"),
        (S + "    if bumped\n        stop moving\n", 2, "bumped", "`bumper any pressed`"),
        (S + "    wait until bumped\n", 2, "bumped", "`bumper any pressed`"),
        (S + "    wait until touched\n", 2, "touched", "`touch any pressed`"),
        ("    move 10 cm\n    turn left 90 degrees\n", 1, "move", "`when started`"),
        (S + '    set n to 2\n    print "n is " + n\n', 3, '"n is "', '`join("n is ", n)`'),
        (S + "    set x 5\n", 2, "5", "`set x to 5`"),
        (S + "    side = 30 cm\n", 2, "=", "`set side to 30 cm`"),
        ("to square size\n    move size\n" + S + "    square 20\n", 4, "20", "`square 20 cm`"),
        (S + "    move 1e308 cm\n", 2, "1e308", "without `e`"),
        (S + "    walk forward 10 cm\n", 2, "walk", "`move forward 10 cm`"),
        (S + "    trun rigth 90 degrees\n", 2, "trun", "`turn right 90 degrees`"),
        (S + "    turn right by 90 degrees\n", 2, "by", "`turn right 90 degrees`"),
        (S + "    stop ths script\n", 2, "ths", "`stop this script`"),
        (S + '    send "go" and wiat\n', 2, "wiat", '`send "go" and wait`'),
        (S + "    move 10 cms\n", 2, "cms", "`move 10 cm`"),
        (S + "    wait 500 ma\n", 2, "ma", "`wait 500 ms`"),
        (S + "    stopp moving\n", 2, "stopp", "`stop moving`"),
        ("whn started\n    move 1 cm\n", 1, "whn", "`when started`"),
        ("when obstacle seenn\n    move 1 cm\n", 1, "seenn", "`when obstacle seen`"),
        ("when colour gren seen\n    move 1 cm\n", 1, "gren", "`when colour green seen`"),
        ("when udocked\n    move 1 cm\n", 1, "udocked", '"undocked"'),
        (S + "    if colour on left = yelow\n        stop moving\n", 2, "yelow", "white, black"),
        (S + "    play noot C4 for 1 second\n", 2, "noot", "`play note C4 for 1 second`"),
        (S + "    if bumed\n        stop moving\n", 2, "bumed", "`bumper any pressed`"),
        (S + "    set gravity compensation on 50 perent\n", 2, "perent", '"%"'),
        ("when ndocked\n    move 1 cm\n", 1, "ndocked", '"undocked"'),
    ],
)
def test_the_issues_mistakes_point_at_the_word_and_name_the_fix(
    source: str, line: int, word: str, fix: str
) -> None:
    column = source.split("\n")[line - 1].index(word) + 1
    found = [d for d in diagnose(source) if d.span.line == line]
    assert found, source
    first = found[0]
    assert first.span.column <= column < max(first.span.end_column, first.span.column + 1)
    assert fix in first.english, first.english


def test_a_literal_speed_too_fast_for_the_robot_is_said_in_the_childs_unit() -> None:
    (found,) = diagnose(S + "    drive 30 cm/s\n", robot=RobotModel.RT1)
    assert found.english == "The Root RT1 can drive at most 10 cm/s, not 30 cm/s."
    assert diagnose(S + "    drive 30 cm/s\n", robot=RobotModel.CREATE3) == []
    (warning,) = diagnose(S + "    drive 30 cm/s\n")  # no robot named: those it is too fast for
    assert warning.severity == "warning"
    assert warning.english.startswith(
        "Root RT0 and Root RT1 can drive at most 10 cm/s, not 30 cm/s"
    )


def test_when_docked_on_a_root_is_a_warning_naming_the_robot() -> None:
    (found,) = diagnose("when docked\n    say 1\n", robot=RobotModel.RT0)
    assert (found.code, found.severity) == ("W101", "warning")
    assert "Root RT0" in found.english and "never run" in found.english


def test_check_json_gives_the_column_inside_the_word_and_the_fix(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = tmp_path / "typo.root"
    path.write_text(S + "    move 10 cm\n    trun left 90 degrees\n", encoding="utf-8")
    assert main(["check", "--json", str(path)]) == 1
    (found,) = json.loads(capsys.readouterr().out)
    assert (found["line"], found["column"], found["end_column"]) == (3, 5, 9)
    assert '"turn"' in found["message"] and "`turn left 90 degrees`" in found["message"]


def test_a_line_with_no_nearby_word_gets_no_guess() -> None:
    parser = lark_parser()
    assert mend_line(parser, "say hello there everyone") is None
    assert mend_line(parser, "move 10 cm") is None  # nothing to mend
    (found,) = diagnose(S + "    say hello\n")
    assert found.code == "E118"  # words that lost their quotes, not a colour called `yellow`
