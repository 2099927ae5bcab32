# ruff: noqa: E501 - the keyword table is aligned in columns so each row reads across
"""The keyword tables: each English word (or phrase) of the language and how it is written in
Dutch, Spanish, French and German. docs/languages.md explains each table and its choices.

A row is ``(english, nl, es, fr, de)``; an empty cell means the English word is written in
that language too (it is a unit, a letter, or the same word). English keywords stay valid in
every language, so a class can mix both while it learns.

The words of the statements, events and sensors are written in their forms
(:class:`rootlang.forms.Said`: ``FORM_WORDS`` reads them), those of the built-in functions in
their entries (:data:`rootlang.units.FUNCTIONS`); the tables here hold only the words no form
has: block headers and ``print``/``change``, operators and values, colours and units.

Rules that keep translation exact (tests/languages check every one):

- within a language, each written word or phrase means one English word or phrase, so a
  program translated to English and back is unchanged;
- a phrase keeps the slots of its English phrase in the same order (``set left wheel`` is
  ``fija rueda izquierda``): only words inside a phrase may change order, so the grammar does
  not change;
- ``to`` at the start of a line defines a procedure and ``to`` after ``set NAME`` gives a value:
  each has its own word (``PROCEDURE_TO``, ``ASSIGNMENT_TO``); words shared by two meanings in
  one language are told apart by those two places alone (see :mod:`rootlang.locale`).
"""

from __future__ import annotations

from rootlang import forms
from rootlang.units import FUNCTIONS
from rootlang.wording.language import LANGUAGE_NAMES as LANGUAGE_NAMES
from rootlang.wording.language import LANGUAGES as LANGUAGES

Row = tuple[str, str, str, str, str]
"""``(english, nl, es, fr, de)``."""

# fmt: off
CONTROL: tuple[Row, ...] = (  # the words of block headers no form has, `print` and `change`
    # english            nl                   es                        fr                        de
    ("when",             "wanneer",           "cuando",                 "quand",                  "wenn"),
    ("until",            "totdat",            "hasta que",              "jusqu'à",                ""),
    ("if",               "als",               "si",                     "si",                     "falls"),
    ("then",             "dan",               "entonces",               "alors",                  "dann"),
    ("else",             "anders",            "sino",                   "sinon",                  "sonst"),
    ("print",            "schrijf",           "escribe",                "écris",                  "schreibe"),
    ("change",           "verander",          "cambia",                 "change",                 "ändere"),
    ("by",               "met",               "por",                    "par",                    "um"),
)
VALUES: tuple[Row, ...] = (  # operators and values
    ("and",              "en",                "y",                      "et",                     "und"),
    ("or",               "of",                "o",                      "ou",                     "oder"),
    ("not",              "niet",              "no",                     "non",                    "nicht"),
    ("true",             "waar",              "verdadero",              "vrai",                   "wahr"),
    ("false",            "onwaar",            "falso",                  "faux",                   "falsch"),
    ("note",             "noot",              "nota",                   "",                       ""),
)
COLOURS: tuple[Row, ...] = (  # colours
    ("red",              "rood",              "rojo",                   "rouge",                  "rot"),
    ("orange",           "oranje",            "naranja",                "",                       ""),
    ("yellow",           "geel",              "amarillo",               "jaune",                  "gelb"),
    ("green",            "groen",             "verde",                  "vert",                   "grün"),
    ("cyan",             "cyaan",             "cian",                   "",                       ""),
    ("blue",             "blauw",             "azul",                   "bleu",                   "blau"),
    ("purple",           "paars",             "morado",                 "violet",                 "lila"),
    ("pink",             "roze",              "rosa",                   "rose",                   "rosa"),
    ("white",            "wit",               "blanco",                 "blanc",                  "weiß"),
    ("black",            "zwart",             "negro",                  "noir",                   "schwarz"),
)
UNIT_WORDS: tuple[Row, ...] = (  # units' words (cm, mm, m, Hz, %, ° are written the same everywhere)
    ("degrees",          "graden",            "grados",                 "degrés",                 "grad"),
    ("degree",           "graad",             "grado",                  "degré",                  ""),
    ("seconds",          "seconden",          "segundos",               "secondes",               "sekunden"),
    ("second",           "seconde",           "segundo",                "seconde",                "sekunde"),
)
# fmt: on
FORM_WORDS: tuple[Row, ...] = tuple(  # the statements', events' and sensors' (rootlang.forms)
    {said.english: said.row for form in forms.every_form() for said in form.said()}.values()
)
FUNCTION_WORDS: tuple[Row, ...] = tuple(  # the built-in functions' names (rootlang.units)
    (function.name, *function.words) for function in FUNCTIONS.values() if any(function.words)
)

KEYWORDS: tuple[Row, ...] = (
    *CONTROL,
    *FORM_WORDS,
    *VALUES,
    *COLOURS,
    *UNIT_WORDS,
    *FUNCTION_WORDS,
)
"""Every keyword table's rows, in one."""

PROCEDURE_TO: dict[str, str] = {"nl": "leer", "es": "para", "fr": "pour", "de": "lerne"}
"""``to`` at the start of a line, defining a procedure (as in Logo: ``pour carré``)."""

ASSIGNMENT_TO: dict[str, str] = {"nl": "op", "es": "en", "fr": "à", "de": "auf"}
"""``to`` right after ``set NAME``: ``zet snelheid op 5``, ``fija velocidad en 5``."""

NOTE_NAMES: dict[str, dict[str, str]] = {
    "es": {"c": "do", "d": "re", "e": "mi", "f": "fa", "g": "sol", "a": "la", "b": "si"},
    "fr": {"c": "do", "d": "ré", "e": "mi", "f": "fa", "g": "sol", "a": "la", "b": "si"},
    "de": {"b": "h"},
}
"""Note names that differ from English (the letter before ``#``/``b`` and the octave): solfège
in Spanish and French; in German B is H (and English Bb is German B)."""

TABLE_START = "<!-- keyword table: generated by `python -m rootlang.locale`; do not edit -->"
TABLE_END = "<!-- end of the keyword table -->"


def markdown_table() -> str:
    """The keyword tables as docs/languages.md shows them, between TABLE_START and TABLE_END."""
    other = LANGUAGES[1:]
    lines = [
        TABLE_START,
        "| " + " | ".join(LANGUAGE_NAMES[language] for language in LANGUAGES) + " |",
        "|---|---|---|---|---|",
        "| `to` (a procedure, first word of a line) | "
        + " | ".join(f"`{PROCEDURE_TO[language]}`" for language in other)
        + " |",
        "| `to` (after `set NAME`) | "
        + " | ".join(f"`{ASSIGNMENT_TO[language]}`" for language in other)
        + " |",
        *("| " + " | ".join(f"`{cell or row[0]}`" for cell in row) + " |" for row in KEYWORDS),
        TABLE_END,
    ]
    return "\n".join(lines)


def with_table(document: str) -> str:
    """``document`` (docs/languages.md) with its keyword table as the tables are now."""
    before, _, rest = document.partition(TABLE_START)
    _, _, after = rest.partition(TABLE_END)
    return before + markdown_table() + after
