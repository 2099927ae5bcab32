"""Programs in Dutch, Spanish, French and German: every gallery program translated to each
language and back is byte-identical, and each translation runs with the original's trace."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from rootlang.app.files import world_for
from rootlang.app.session import simulate
from rootlang.checks import diagnose, parse_and_check
from rootlang.cli import main
from rootlang.cli.translate import translate
from rootlang.diagnostics import RootlangError, Span, render
from rootlang.formatting import format_source
from rootlang.locale import lines
from rootlang.locale import translate as translate_module
from rootlang.locale.translate import (
    Translation,
    declared_language,
    from_english,
    lines_in_english,
    to_english,
)
from rootlang.wording.language import ENGLISH

PROGRAMS = Path(__file__).resolve().parents[2] / "programs"
GALLERY = sorted(PROGRAMS.glob("*.root"))
MISTAKES = [  # those written in English (habit_french_logo.root is French already)
    path
    for path in sorted((PROGRAMS / "mistakes").glob("*.root"))
    if declared_language(path.read_text(encoding="utf-8")) is None
]
OTHER_LANGUAGES = ("nl", "es", "fr", "de")


@pytest.mark.parametrize("language", OTHER_LANGUAGES)
@pytest.mark.parametrize("program", GALLERY + MISTAKES, ids=lambda path: path.name)
def test_every_program_translated_and_back_is_byte_identical(program: Path, language: str) -> None:
    """A mistake may be a word of the other language (`light gruen` is German `grün` spelt
    with ue): then translate refuses (E902) rather than change the program."""
    source = program.read_text(encoding="utf-8")
    try:
        translated = translate(source, language, written_in="en")
    except RootlangError as error:
        assert program in MISTAKES
        assert [item.code for item in error.diagnostics] == ["E902"]
        return
    assert translated.startswith(f"# language: {language}\n")  # so it runs as it is
    back = translate(translated, "en", written_in=language)
    assert back == f"# language: en\n{source}"  # the same program, saying it is English


@pytest.mark.parametrize("language", OTHER_LANGUAGES)
def test_each_translation_runs_with_the_same_trace(language: str) -> None:
    """The translation declares its language on its first line, in place of the program's
    opening comment, so every line keeps its number (messages stay in English)."""
    for program in GALLERY:
        source = program.read_text(encoding="utf-8")
        world = world_for(program, source)
        original = _trace(source, program.name, world)
        first, rest = from_english(source, language).split("\n", 1)
        assert first.startswith("#")
        translated = _trace(f"# language: {language}\n{rest}", program.name, world)
        assert translated == original, program.name


def _trace(source: str, file: str, world: object) -> list[str]:
    checked, found = parse_and_check(source, file, world.robot.model)  # type: ignore[attr-defined]
    if checked is None or any(item.severity == "error" for item in found):
        return [f"{item.code} line {item.span.line}" for item in found]
    result, _ = simulate(checked, world, source=source)  # type: ignore[arg-type]
    # (as data: an error's record keeps its own place in the child's text, a column apart)
    return [repr(entry.to_json()) for entry in result.trace.entries] + [result.end]


@pytest.mark.parametrize("language", OTHER_LANGUAGES)
def test_mistakes_are_found_on_the_same_lines_in_every_language(language: str) -> None:
    """The same lines are wrong (a few codes differ: a misspelt word's whole-line fix, E023,
    is worked out on English text, so the other languages get the plainer E120)."""
    for program in MISTAKES:
        source = program.read_text(encoding="utf-8")
        try:
            translated = translate(source, language, written_in="en")
        except RootlangError:  # the mistake is a word of that language (see above)
            continue
        original = [(d.span.line, d.severity) for d in diagnose(source, program.name)]
        added = 1  # the `# language:` line translate puts first, so the result runs as it is
        read = diagnose(translated, program.name, language=language)
        found = [(d.span.line - added, d.severity) for d in read]
        assert found == original, program.name


def test_a_program_declares_its_language_on_an_opening_line() -> None:
    source = (
        "# my robot\n# language: es\ncuando empieza\n    mueve 10 cm\n    gira derecha 90 grados\n"
    )
    assert diagnose(source) == []
    assert format_source(source) == source


def test_english_keywords_stay_valid_in_every_language() -> None:
    source = "# language: nl\nwanneer gestart\n    move 10 cm\n    draai links 90 degrees\n"
    assert diagnose(source) == []


def test_carets_point_at_the_childs_own_words() -> None:
    source = "# language: es\ncuando empieza\n    gira izquierda 10 segundos\n    muevee 3 cm\n"
    shown = [render(item, source, ENGLISH).splitlines()[1:3] for item in diagnose(source, "p.root")]
    assert shown == [
        ["            gira izquierda 10 segundos", "                           ^^^^^^^^^^^"],
        ["            muevee 3 cm", "            ^^^^^^"],
    ]


def test_an_unknown_language_is_named_on_its_line_and_english_is_read() -> None:
    found = diagnose("# language: xx\nwhen started\n    move 1 cm\n")
    assert [(item.code, item.span.line, item.span.column) for item in found] == [("E901", 1, 13)]


@pytest.mark.parametrize(
    ("english", "language", "local"),
    [
        ("    play note C4 for 1 second", "es", "    toca nota Do4 durante 1 segundo"),
        ("    play note Bb3 for 1 second", "fr", "    joue note Sib3 pendant 1 seconde"),
        ("    play note B4 for 1 second", "de", "    spiele note H4 für 1 sekunde"),
        ("    play note Bb3 for 1 second", "de", "    spiele note B3 für 1 sekunde"),
        ("    play note C#4 for 1 second", "fr", "    joue note Do#4 pendant 1 seconde"),
        ("To square size", "fr", "Pour square size"),
        ("    set speed to random 1 to 6", "nl", "    zet speed op willekeurig 1 tot 6"),
        ("    go to x 10 cm y 5 cm", "es", "    ve a x 10 cm y 5 cm"),
        ("    print position y and true", "es", "    escribe posición y y verdadero"),
        ("WHEN STARTED", "de", "WENN GESTARTET"),
        ('    say "when left"  # turn left', "nl", '    zeg "when left"  # turn left'),
        ("when touch front left pressed", "fr", "quand toucher devant gauche appuyé"),
        ("    set left wheel 5 cm/s", "es", "    fija rueda izquierda 5 cm/s"),
    ],
)
def test_words_notes_and_the_places_that_decide_a_meaning(
    english: str, language: str, local: str
) -> None:
    assert from_english(english, language) == local
    assert to_english(local, language).text == english


def test_script_headers_are_put_into_english_alone(monkeypatch: pytest.MonkeyPatch) -> None:
    # the trace names scripts by their header lines: only those are translated for it
    source = "# language: nl\nwanneer gestart\n    beweeg 10 cm\n\nwanneer gebotst\n    piep\n"
    translated: list[str] = []
    translate_line = lines.translate_line

    def counted(line: str, table: Any, *, to_english: bool) -> tuple[str, list[Any]]:
        translated.append(line)
        return translate_line(line, table, to_english=to_english)

    monkeypatch.setattr(translate_module, "translate_line", counted)
    assert lines_in_english(source, [2, 5, 99]) == {2: "when started", 5: "when bumped"}
    assert translated == ["wanneer gestart", "wanneer gebotst"]
    assert lines_in_english("# language: xx\nwanneer gestart\n", [2]) == {2: "wanneer gestart"}


def test_english_is_not_translated_and_its_spans_stay() -> None:
    english = "when started\n    move 10 cm  # forward\n"
    assert to_english(english, "en") == Translation(english)  # (no anchors worked out)
    span = Span(2, 5, 2, 15)
    assert to_english(english, "en").source_span(span) == span


def test_a_child_may_leave_out_accents_and_write_ss_for_sharp_s() -> None:
    assert to_english("    escribe posicion x", "es").text == "    print position x"
    assert to_english("wenn stossstange links gedrueckt", "de").text == ("when bumper left pressed")


def test_translate_refuses_a_name_that_is_a_word_of_the_new_language(tmp_path: Path) -> None:
    program = tmp_path / "p.root"
    program.write_text("when started\n    set als to 3\n    move als cm\n", encoding="utf-8")
    with pytest.raises(RootlangError) as raised:
        translate(program.read_text(encoding="utf-8"), "nl")
    assert raised.value.diagnostics[0].code == "E902"
    assert "als" in raised.value.diagnostics[0].english


def test_the_translate_command_writes_the_program_and_renames_its_language(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    program = tmp_path / "p.root"
    program.write_text("# language: nl\nwanneer gestart\n    beweeg 10 cm\n", encoding="utf-8")
    assert main(["translate", str(program), "--to", "fr"]) == 0
    assert capsys.readouterr().out == "# language: fr\nquand démarré\n    bouge 10 cm\n"
    out = tmp_path / "en.root"
    assert main(["translate", str(program), "--to", "en", "-o", str(out)]) == 0
    assert out.read_text(encoding="utf-8") == "# language: en\nwhen started\n    move 10 cm\n"


def test_the_language_option_reads_a_program_without_a_declaration(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    program = tmp_path / "p.root"
    program.write_text("cuando empieza\n    mueve 10 cm\n", encoding="utf-8")
    assert main(["check", str(program), "--language", "es"]) == 0
    assert main(["check", str(program)]) == 1
    capsys.readouterr()


def test_a_new_program_in_a_language_says_so_and_runs(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["new", str(tmp_path / "hallo"), "--language", "nl"]) == 0
    written = (tmp_path / "hallo.root").read_text(encoding="utf-8")
    assert written.splitlines()[1:4] == ["# language: nl", "wanneer gestart", "    licht groen"]
    assert main(["check", str(tmp_path / "hallo.root")]) == 0
    capsys.readouterr()


@pytest.mark.parametrize("language", OTHER_LANGUAGES)
def test_a_program_saved_with_a_byte_order_mark_translates_to_one_that_runs(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], language: str
) -> None:
    """Windows Notepad starts a UTF-8 file with U+FEFF: the `# language:` line goes after it,
    not before (a mark in the middle of the program is a character the parser can't read)."""
    program = tmp_path / "p.root"
    program.write_bytes(b"\xef\xbb\xbfwhen started\r\n    move 10 cm\r\n")
    translated = tmp_path / "t.root"
    assert main(["translate", str(program), "--to", language, "-o", str(translated)]) == 0
    assert translated.read_text(encoding="utf-8").startswith(f"\ufeff# language: {language}\n")
    assert main(["check", str(translated)]) == 0
    back = tmp_path / "back.root"
    assert main(["translate", str(translated), "--to", "en", "-o", str(back)]) == 0
    assert (
        back.read_text(encoding="utf-8") == "\ufeff# language: en\nwhen started\n    move 10 cm\n"
    )
    capsys.readouterr()
