"""Messages in five languages: every code translated with the same placeholders, chosen by the
command line, the program's language, a studio page's or the system locale; suggestions in the
child's words."""

from __future__ import annotations

import asyncio
import re
from pathlib import Path

import pytest

from rootlang.checks import diagnose
from rootlang.cli import main
from rootlang.diagnostics import diagnostic
from rootlang.locale.translate import about
from rootlang.messages import MESSAGES
from rootlang.runtime.stops import Connected, RunEnded, StoppedBy, StopReason
from rootlang.wording.catalogue import translations
from rootlang.wording.language import ENGLISH, Languages
from rootlang.wording.shown import Code, Described, InUnit, Phrase, Suggestion, Write

TRANSLATED = ("nl", "es", "fr", "de")
PLACEHOLDER = re.compile(r"(?<!\{)\{([a-z_]+)\}(?!\})")


@pytest.fixture(autouse=True)
def no_system_locale(monkeypatch: pytest.MonkeyPatch) -> None:
    for variable in ("LC_ALL", "LC_MESSAGES", "LANG"):
        monkeypatch.delenv(variable, raising=False)


@pytest.mark.parametrize("language", TRANSLATED)
def test_every_code_is_translated_with_the_same_placeholders(language: str) -> None:
    table = translations(language)
    missing = sorted(set(MESSAGES) - set(table))
    print(f"{language}: {len(set(MESSAGES) & set(table))} of {len(MESSAGES)} codes translated")
    assert missing == []
    for code, english in MESSAGES.items():
        assert set(PLACEHOLDER.findall(table[code])) == set(PLACEHOLDER.findall(english)), code
    extras = {"_did_you_mean", "_values", "_phrases"}
    assert {key for key in table if key.startswith("_")} == extras
    assert not set(table) - set(MESSAGES) - extras


def told(source: str, language: str) -> list[str]:
    """The diagnostics of ``source`` as a command given ``--language`` says them."""
    languages = Languages(chosen=language)
    return [item.shown(languages) for item in diagnose(source, language=language)]


def test_a_code_not_yet_translated_is_shown_in_english(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delitem(translations("nl"), "E204")
    assert diagnostic("E204").shown(Languages(chosen="nl")) == MESSAGES["E204"]


def test_the_system_locale_chooses_when_nothing_else_does(monkeypatch: pytest.MonkeyPatch) -> None:
    assert Languages.of_command().messages == "en"
    monkeypatch.setenv("LANG", "fr_FR.UTF-8")
    command = Languages.of_command()  # (read once, when the command starts)
    assert command.messages == "fr"
    assert diagnostic("E204").shown(command) == "Je ne peux pas diviser par zéro."
    program = command.for_program("de")
    assert diagnostic("E204").shown(program) == "Ich kann nicht durch null teilen."
    chosen = Languages.of_command("es").for_program("de")
    assert diagnostic("E204").shown(chosen) == "No puedo dividir entre cero."
    assert Languages.of_command(environment={"LC_ALL": "de_DE", "LANG": "fr_FR"}).messages == "de"


def test_values_and_code_in_messages_speak_the_language() -> None:
    assert told("cuando empieza\n    gira izquierda 10 segundos\n", "es") == [
        "gira necesita un ángulo, como `gira derecha 90 grados`, pero esto es un tiempo."
    ]


def test_what_the_parser_expected_is_said_in_the_language() -> None:
    assert told("cuando empieza\n    gira 90 grados\n    repite 3 veces veces\n", "es") == [
        "No esperaba `90` aquí. Esperaba `izquierda` o `derecha`.",
        "`veces` no va aquí. Escribe: `repite 3 veces`",
    ]


def test_did_you_mean_searches_the_childs_language() -> None:
    assert told("wanneer gestart\n    beweg 10 cm\n    mvoe 1 cm\n", "nl") == [
        'Ik ken de opdracht "beweg" niet. Bedoel je "beweeg"?',
        'Ik ken de opdracht "mvoe" niet. Bedoel je "beweeg"? Schrijf: `beweeg 1 cm`',
    ]


def test_a_misspelt_unit_is_suggested_in_the_language_with_its_line() -> None:
    # the suggestion is data (a word, the line to write): said in the language, its word and
    # line in the program's, its caret on the child's word; units as close as each other
    # (cms: cm or cm/s) are tried in place, and the one whose kind fits is said
    dutch = Languages(chosen="nl")
    found = diagnose("wanneer gestart\n    beweeg 10 cms\n    wacht 500 ma\n", language="nl")
    assert [(item.span.column, item.shown(dutch).split(" Eenheden")[0]) for item in found] == [
        (15, 'Ik ken de eenheid `cms` niet. Bedoel je "cm"? Schrijf: `beweeg 10 cm`'),
        (15, 'Ik ken de eenheid `ma` niet. Bedoel je "ms"? Schrijf: `wacht 500 ms`'),
    ]
    suggestion = dict(found[0].values)["suggestion"]
    assert suggestion == Suggestion("cm", Write(("move 10 cm",)))  # worked out in English
    assert str(suggestion) == ' Did you mean "cm"? Write: `move 10 cm`'


def test_a_kind_in_a_unit_is_data_said_in_the_language() -> None:
    (found,) = diagnose("quand démarré\n    dis 10 cm + 5 degrés\n", language="fr")
    assert InUnit(Described("une distance"), "cm") not in dict(found.values).values()
    assert InUnit(Described("a distance"), "cm") in dict(found.values).values()
    assert "une distance en cm" in found.shown(Languages(chosen="fr"))


def test_a_program_declaring_its_language_gets_messages_in_it(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    program = tmp_path / "p.root"
    program.write_text("# language: de\nwenn gestartet\n    bewege 10 cm / 0\n", encoding="utf-8")
    assert main(["sim", str(program)]) == 1
    assert "Ich kann nicht durch null teilen." in capsys.readouterr().err


def test_a_pages_language_wins_for_messages_and_code_stays_the_programs() -> None:
    studio = Languages(chosen="de", program="fr")
    assert diagnostic("E204").shown(studio.for_page("nl")) == "Ik kan niet delen door nul."
    assert diagnostic("E204").shown(studio) == "Ich kann nicht durch null teilen."
    dutch_page = ENGLISH.for_page("nl")  # an English program on a Dutch page: its code stays
    assert [item.shown(dutch_page) for item in diagnose("when started\n    move 10\n")] == [
        "move heeft een afstand nodig, zoals `move 10 cm`. Schrijf: `move 10 cm`"
    ]  # (the suggestion's words are the page's, its code the program's)


def test_a_page_language_nobody_knows_is_passed_over() -> None:
    assert ENGLISH.for_page("xx").messages == "en"
    assert Languages(chosen="nl").for_page("xx").messages == "nl"


def test_two_pages_speaking_at_once_each_keep_their_own_language() -> None:
    """The studio's server answers two pages in one event loop: each request's task has its
    own languages, however their steps interleave."""

    async def page(language: str) -> list[str]:
        said = []
        languages = ENGLISH.for_page(language)  # (the request's, handed down)
        for _ in range(3):
            await asyncio.sleep(0)  # the other page goes on meanwhile
            said.append(diagnostic("E204").shown(languages))
        return said

    async def both() -> list[list[str]]:
        return list(await asyncio.gather(page("nl"), page("fr"), page("de")))

    assert asyncio.run(both()) == [
        ["Ik kan niet delen door nul."] * 3,
        ["Je ne peux pas diviser par zéro."] * 3,
        ["Ich kann nicht durch null teilen."] * 3,
    ]


VIEW_CODES = sorted(code for code in MESSAGES if code.startswith("V"))  # the child's view's words


@pytest.mark.parametrize("language", TRANSLATED)
def test_the_words_of_a_runs_view_are_in_every_language(language: str) -> None:
    table = translations(language)
    assert VIEW_CODES and [code for code in VIEW_CODES if code not in table] == []
    assert table["V001"] != MESSAGES["V001"]


def test_a_runs_view_speaks_the_command_lines_language(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    program = tmp_path / "p.root"
    text = 'when started\n    repeat 3\n        say "hoi"\n    print "klaar"\n    stop all\n'
    program.write_text(text, encoding="utf-8")
    assert main(["sim", "--language", "nl", str(program)]) == 0
    assert capsys.readouterr().out.splitlines() == [
        "   0.0 s  regel 1    wanneer gestart",
        '   0.0 s  regel 3        zeg "hoi"',
        "   0.7 s                 ... nog 2 keer, tot 0.7 s",
        '   1.1 s  regel 4        schrijf "klaar"',
        "   1.1 s             gestopt door stop alles",
    ]
    assert main(["sim", str(program)]) == 0  # (the command line leaves no choice behind it)
    assert capsys.readouterr().out.splitlines()[-3:] == [
        "   0.7 s                ... 2 more times, until 0.7 s",
        '   1.1 s  line 4        print "klaar"',
        "   1.1 s            stopped by stop all",
    ]


def test_a_runs_view_speaks_the_programs_declared_language(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    program = tmp_path / "p.root"
    program.write_text("# language: de\nwenn gestartet\n    bewege 10 cm\n", encoding="utf-8")
    assert main(["sim", str(program)]) == 0
    assert capsys.readouterr().out.splitlines() == [
        "   0.0 s  Zeile 2    wenn gestartet",
        "   0.0 s  Zeile 3        bewege 10 cm",
        "   1.2 s             das Ende: jedes Skript ist fertig",
    ]


def test_why_a_run_stopped_is_recorded_in_english_and_said_in_the_language() -> None:
    limit = StoppedBy(StopReason.TIME_LIMIT, seconds=30)
    ended = RunEnded("time_limit", limit)
    connected = Connected("Root RT1", "1.3")
    french = ENGLISH.for_page("fr")
    assert limit.english() == "the time limit of 30 s"  # what the trace keeps
    assert ended.english() == "ended: time_limit (the time limit of 30 s)"
    assert connected.english() == "connected to Root RT1 (protocol 1.3)"
    assert limit.shown(french) == "la limite de temps de 30 s"
    assert ended.shown(french) == "arrêté par la limite de temps de 30 s"
    assert StoppedBy.link("the link dropped").shown(french) == "the link dropped"  # its own words
    assert connected.shown(french) == "connecté à Root RT1 (protocole 1.3)"
    assert ended.shown(ENGLISH) == "stopped by the time limit of 30 s"


def test_why_a_run_stopped_goes_to_json_and_back() -> None:
    for reason in StopReason:
        stopped = StoppedBy(reason, seconds=2.5 if reason is StopReason.TIME_LIMIT else None)
        assert StoppedBy.from_json(stopped.to_json()) == stopped
    assert StoppedBy.link("gone").to_json() == {"reason": "link", "words": "gone"}
    assert StoppedBy.from_json({"reason": "no such reason"}) is None
    assert StoppedBy.from_json({"reason": "time_limit", "seconds": "soon"}) is None
    # the studio hands its own reason for ending a page's link on as data: no words read back
    dropped = StoppedBy(StopReason.PAGE_LINK_DROPPED)
    assert StoppedBy.link(dropped) is dropped
    assert StoppedBy.link(dropped.english()).reason is StopReason.LINK  # words stay words


def test_code_in_a_value_is_data_its_words_in_the_pages_language_its_code_the_programs() -> None:
    """What the parser expected is words and code (nothing reads code back out of a value's
    text): on a Dutch page, a French program's code stays French."""
    source = "# language: fr\nquand démarré\n    tourne 90 degrés\n    dis 1 +\n"
    turn, say = diagnose(source)
    expected = dict(turn.values)["expected"]
    assert isinstance(expected, Phrase) and Code("left") in expected.parts
    assert str(expected) == "`left` or `right`" and dict(turn.values)["found"] == Code("90")
    dutch_page = about(ENGLISH.for_page("nl"), source)
    assert turn.shown(dutch_page).endswith("Ik verwachtte `gauche` of `droite`.")
    assert say.shown(dutch_page).endswith("een waarde, zoals `10 cm`, een naam of `vrai`.")
    assert say.shown(about(ENGLISH, source)).endswith(
        "une valeur, comme `10 cm`, un nom ou `vrai`."
    )


def test_a_value_is_shown_as_its_type_says_never_by_its_name() -> None:
    """Words that describe are translated whole whatever their name; a name the child gave is
    shown as it is, even where it holds the catalogue's English words."""
    dutch_page = ENGLISH.for_page("nl")
    # a robot the child named "Root or Create": its name is no phrase to translate
    robot = diagnostic("E401", wanted="Root or Create", seconds="5 s", robots="none")
    assert '"Root or Create"' in robot.shown(dutch_page)
    (text,) = diagnose('when started\n    if 3 cm < "a name or text"\n        print 1\n')
    assert text.code == "E110" and text.shown(dutch_page) == (
        "Ik kan een afstand in cm en tekst niet vergelijken."
    )  # "text", the kind, is described: said in Dutch whatever the value's name
    assert dict(text.values)["right"] == Described("text")


@pytest.mark.parametrize("language", ["nl", "es", "fr", "de"])
def test_the_catalogue_holds_words_whole_not_phrases_to_swap_inside_text(language: str) -> None:
    """Every word the catalogue translates is looked up whole: a value's text is never
    searched for English phrases (a child's "a name or b" keeps its words in every language)."""
    page = ENGLISH.for_page(language)
    found = diagnostic("E705", block="say", id="q", what="the text 'a name or b'", fix="")
    assert "'a name or b'" in found.shown(page)
    assert "`a name or b`" in diagnostic("E013", expected=Phrase((Code("a name or b"),))).shown(
        page
    )
    listed = Phrase.listed([Described("a distance"), Code("left"), "x or y"])
    said = diagnostic("E013", expected=listed).shown(page)
    words = translations(language)["_values"]
    assert f"{words['a distance']}, `" in said and " x or y" in said
