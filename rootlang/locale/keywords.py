# ruff: noqa: E501 - the keyword table is aligned in columns so each row reads across
"""The keyword tables: each English word (or phrase) of the language and how it is written in
Dutch, Spanish, French and German. docs/languages.md explains each table and its choices.

A row is ``(english, nl, es, fr, de)``; an empty cell means the English word is written in
that language too (it is a unit, a letter, or the same word). English keywords stay valid in
every language, so a class can mix both while it learns.

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

from rootlang.units import FUNCTIONS

LANGUAGES: tuple[str, ...] = ("en", "nl", "es", "fr", "de")
"""English, Dutch, Spanish, French and German: the languages a program may be written in."""

LANGUAGE_NAMES: dict[str, str] = {
    "en": "English",
    "nl": "Nederlands",
    "es": "Español",
    "fr": "Français",
    "de": "Deutsch",
}

Row = tuple[str, str, str, str, str]
"""``(english, nl, es, fr, de)``."""

# fmt: off
CONTROL: tuple[Row, ...] = (  # the words of scripts, loops, choices and stops
    # english            nl                   es                        fr                        de
    ("when",             "wanneer",           "cuando",                 "quand",                  "wenn"),
    ("repeat until",     "herhaal totdat",    "repite hasta que",       "répète jusqu'à",         "wiederhole bis"),
    ("wait until",       "wacht totdat",      "espera hasta que",       "attends jusqu'à",        "warte bis"),
    ("repeat",           "herhaal",           "repite",                 "répète",                 "wiederhole"),
    ("times",            "keer",              "veces",                  "fois",                   "mal"),
    ("forever",          "altijd",            "siempre",                "toujours",               "immer"),
    ("until",            "totdat",            "hasta que",              "jusqu'à",                ""),
    ("while",            "zolang",            "mientras",               "tant que",               "solange"),
    ("if",               "als",               "si",                     "si",                     "falls"),
    ("then",             "dan",               "entonces",               "alors",                  "dann"),
    ("else",             "anders",            "sino",                   "sinon",                  "sonst"),
    ("to",               "tot",               "hasta",                  "à",                      "bis"),
    ("wait",             "wacht",             "espera",                 "attends",                "warte"),
    ("stop moving",      "stop met rijden",   "detente",                "arrête de bouger",       "halte an"),
    ("this script",      "dit script",        "este guion",             "ce script",              "dieses skript"),
    ("other scripts",    "andere scripts",    "otros guiones",          "autres scripts",         "andere skripte"),
    ("all",              "alles",             "todo",                   "tout",                   "alles"),
    ("stop",             "stop",              "detén",                  "arrête",                 "stopp"),
    ("send",             "stuur",             "envía",                  "envoie",                 "sende"),
    ("print",            "schrijf",           "escribe",                "écris",                  "schreibe"),
    ("set",              "zet",               "fija",                   "mets",                   "setze"),
    ("change",           "verander",          "cambia",                 "change",                 "ändere"),
    ("by",               "met",               "por",                    "par",                    "um"),
    ("return",           "geef",              "devuelve",               "renvoie",                "gib"),
)
EVENTS: tuple[Row, ...] = (  # what a `when` waits for
    ("started",          "gestart",           "empieza",                "démarré",                "gestartet"),
    ("stopped",          "gestopt",           "detenido",               "arrêté",                 "gestoppt"),
    ("bumped",           "gebotst",           "choca",                  "heurté",                 "gestoßen"),
    ("bumper",           "",                  "parachoques",            "pare-chocs",             "stoßstange"),
    ("released",         "losgelaten",        "soltado",                "relâché",                "losgelassen"),
    ("pressed",          "ingedrukt",         "pulsado",                "appuyé",                 "gedrückt"),
    ("touched",          "aangeraakt",        "tocado",                 "touché",                 "berührt"),
    ("touch",            "aanraking",         "toque",                  "toucher",                "berührung"),
    ("color",            "kleur",             "",                       "couleur",                "farbe"),
    ("seen",             "gezien",            "visto",                  "vu",                     "gesehen"),
    ("on",               "aan",               "en",                     "sur",                    "auf"),
    ("cliff",            "afgrond",           "precipicio",             "vide",                   "abgrund"),
    ("stalled",          "vast",              "atascado",               "bloqué",                 "blockiert"),
    ("battery",          "batterij",          "batería",                "batterie",               "batterie"),
    ("low",              "laag",              "baja",                   "faible",                 "schwach"),
    ("obstacle",         "obstakel",          "obstáculo",              "",                       "hindernis"),
    ("undocked",         "vertrokken",        "desatracado",            "largué",                 "abgedockt"),
    ("docked",           "geparkeerd",        "atracado",               "accosté",                "angedockt"),
    ("message",          "bericht",           "mensaje",                "",                       "nachricht"),
    ("received",         "ontvangen",         "recibido",               "reçu",                   "empfangen"),
    ("front",            "voor",              "delante",                "devant",                 "vorne"),
    ("back",             "achter",            "detrás",                 "derrière",               "hinten"),
    ("both",             "beide",             "ambos",                  "les deux",               "beide"),
    ("any",              "elke",              "cualquiera",             "n'importe",              "jede"),
    ("middle",           "midden",            "centro",                 "milieu",                 "mitte"),
    ("everywhere",       "overal",            "todas partes",           "partout",                "überall"),
    ("dark",             "donker",            "oscuro",                 "sombre",                 "dunkel"),
    ("brighter",         "helderder",         "más brillante",          "plus clair",             "heller"),
    ("bright",           "helder",            "brillante",              "clair",                  "hell"),
    ("detected",         "ontdekt",           "detectado",              "détecté",                "erkannt"),
    ("cleared",          "verdwenen",         "despejado",              "dégagé",                 "frei"),
)
MOTION: tuple[Row, ...] = (  # moving and drawing
    ("move",             "beweeg",            "mueve",                  "bouge",                  "bewege"),
    ("forward",          "vooruit",           "adelante",               "avant",                  "vorwärts"),
    ("backward",         "achteruit",         "atrás",                  "arrière",                "rückwärts"),
    ("turn",             "draai",             "gira",                   "tourne",                 "drehe"),
    ("left wheel",       "linkerwiel",        "rueda izquierda",        "roue gauche",            "linkes rad"),
    ("right wheel",      "rechterwiel",       "rueda derecha",          "roue droite",            "rechtes rad"),
    ("left",             "links",             "izquierda",              "gauche",                 "links"),
    ("right",            "rechts",            "derecha",                "droite",                 "rechts"),
    ("arc",              "boog",              "arco",                   "",                       "bogen"),
    ("radius",           "straal",            "radio",                  "rayon",                  ""),
    ("go to",            "ga naar",           "ve a",                   "va à",                   "gehe zu"),
    ("facing",           "richting",          "mirando",                "orienté",                "ausrichtung"),
    ("wheels",           "wielen",            "ruedas",                 "roues",                  "räder"),
    ("drive",            "rijd",              "conduce",                "roule",                  "fahre"),
    ("reset position",   "herstel positie",   "reinicia posición",      "réinitialise position",  "setze position zurück"),
    ("gravity compensation", "zwaartekrachtcompensatie", "compensación de gravedad",
                         "compensation de gravité",                     "schwerkraftausgleich"),
    ("off",              "uit",               "apagado",                "éteint",                 "aus"),
    ("undock",           "vertrek",           "desatraca",              "largue",                 "abdocken"),
    ("dock",             "parkeer",           "atraca",                 "accoste",                "andocken"),
    ("marker",           "stift",             "rotulador",              "feutre",                 "stift"),
    ("eraser",           "gum",               "borrador",               "gomme",                  "radierer"),
    ("up",               "omhoog",            "arriba",                 "haut",                   "hoch"),
    ("down",             "omlaag",            "abajo",                  "bas",                    "runter"),
)
LIGHTS_AND_SOUND: tuple[Row, ...] = (  # lights and sound
    ("light",            "licht",             "luz",                    "lumière",                "licht"),
    ("blink",            "knipper",           "parpadea",               "clignote",               "blinke"),
    ("spin",             "rond",              "remolino",               "tourbillon",             "kreise"),
    ("play",             "speel",             "toca",                   "joue",                   "spiele"),
    ("sweep",            "glissando",         "barrido",                "glissando",              "glissando"),
    ("from",             "van",               "de",                     "de",                     "von"),
    ("for",              "gedurende",         "durante",                "pendant",                "für"),
    ("volume",           "",                  "volumen",                "",                       "lautstärke"),
    ("say",              "zeg",               "di",                     "dis",                    "sage"),
    ("sound",            "geluid",            "sonido",                 "son",                    "ton"),
    ("note",             "noot",              "nota",                   "",                       ""),
)
VALUES: tuple[Row, ...] = (  # values and sensors
    ("and",              "en",                "y",                      "et",                     "und"),
    ("or",               "of",                "o",                      "ou",                     "oder"),
    ("not",              "niet",              "no",                     "non",                    "nicht"),
    ("true",             "waar",              "verdadero",              "vrai",                   "wahr"),
    ("false",            "onwaar",            "falso",                  "faux",                   "falsch"),
    ("position",         "positie",           "posición",               "",                       ""),
    ("heading",          "koers",             "rumbo",                  "cap",                    "kurs"),
    ("tilt",             "kanteling",         "inclinación",            "inclinaison",            "neigung"),
    ("timer",            "",                  "cronómetro",             "chrono",                 "stoppuhr"),
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
FUNCTION_WORDS: tuple[Row, ...] = tuple(  # the built-in functions' names (rootlang.units)
    (function.name, *function.words) for function in FUNCTIONS.values() if any(function.words)
)

KEYWORDS: tuple[Row, ...] = (
    *CONTROL,
    *EVENTS,
    *MOTION,
    *LIGHTS_AND_SOUND,
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
