"""The one description of the language: every statement, event and sensor, once.

Each :class:`Form` says how one construct is written — a sequence of parts: fixed words, a
choice among a few words, a value slot of a known kind, an indented body — and which Blockly
block shows it. Everything else reads this table instead of keeping its own:

- the grammar's rule for each statement, and how the node is built from what it read, are
  written from the parts when the grammar loads (:mod:`rootlang.grammar.rules`);
- ``rootlang format`` prints statements and events from the parts (:mod:`rootlang.formatting`);
- the block definitions and the toolbox are generated from them, and blocks are read back into
  syntax-tree nodes by them (:mod:`rootlang.blocks`);
- the checks and the runtime take each argument's kind and how its message names it
  (``ARGUMENT_RULES``), how a condition's message names its line (``CONDITIONS``), which
  statements move the robot (``MOTION``, from each form's ``moves``), the feature a
  statement needs (``NEEDS``, from each form's ``needs``), the robot feature and packet
  behind every event and sensor (``EVENTS``, ``SENSORS``) and the packet behind every
  feature (``FEATURES``: which robot has what is the packet table's);
- a form's words say how Dutch, Spanish, French and German write them (:class:`Said`): the
  keyword tables (:mod:`rootlang.locale.keywords`) are read from the forms, with the few words
  no form has (``when``, ``if``, ``print``, the colours and units).

The operators and the built-in functions are described once too, a step below the forms, in
:mod:`rootlang.units` (``OPERATORS``, ``FUNCTIONS``), whose unit rules need them: the grammar,
the printer, the blocks, the checks and the runtime read them there.

A syntax-tree type may have several forms (``set wheels left .. right ..``, ``set left wheel
..``): the first form that matches a node is how it is written. A test walks :mod:`rootlang.ast`
and fails for any node type that has no form here (or no special case in the printers).
"""

from __future__ import annotations

import dataclasses
import enum
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any, Generic, NamedTuple, TypeVar, cast

from rootlang import ast
from rootlang.colors import NAMED_COLORS, SENSOR_COLORS
from rootlang.units import Kind

__all__ = [
    "ARGUMENT_RULES",
    "CONDITIONS",
    "EVENTS",
    "EVENT_FORMS",
    "EVENT_WORDS",
    "FEATURES",
    "MOTION",
    "NEEDS",
    "SENSORS",
    "SPECIAL_NODES",
    "STATEMENT_FORMS",
    "STATEMENT_WORDS",
    "ArgumentRule",
    "Body",
    "Category",
    "Choice",
    "Form",
    "Said",
    "Sensor",
    "Slot",
    "Text",
    "Word",
    "body_of",
    "every_form",
    "form_of",
    "words",
]


class Category(enum.Enum):
    """A toolbox category: its name and colour (each category its own hue, as in Scratch, in a
    darker shade: the blocks' white words are at least 4.5:1 on it, WCAG 2.1 AA)."""

    EVENTS = ("Events", "#a16207")
    MOTION = ("Motion", "#2563eb")
    DRAWING = ("Drawing", "#047857")
    LIGHTS = ("Lights", "#7c3aed")
    SOUND = ("Sound", "#a21caf")
    CONTROL = ("Control", "#b45309")
    SENSORS = ("Sensors", "#0e7490")
    OPERATORS = ("Operators", "#15803d")
    VARIABLES = ("Variables", "#c2410c")
    PROCEDURES = ("Procedures", "#e11d48")
    MESSAGES = ("Messages", "#be185d")

    @property
    def label(self) -> str:
        return self.value[0]

    @property
    def colour(self) -> str:
        return self.value[1]


# ---- parts of a form ---------------------------------------------------------------------


@dataclass(frozen=True)
class Said:
    """A word or phrase of the language, and how Dutch, Spanish, French and German write it
    (``""``: as English does): a row of the keyword tables, where docs/languages.md gives the
    rules a translation keeps (:mod:`rootlang.locale.keywords` checks them)."""

    english: str
    nl: str = ""
    es: str = ""
    fr: str = ""
    de: str = ""

    @property
    def row(self) -> tuple[str, str, str, str, str]:
        """``(english, nl, es, fr, de)``."""
        return (self.english, self.nl, self.es, self.fr, self.de)


Phrase = str | Said
"""A word or phrase a form is written with: with its translations, or one written in every
language as in English (``x``, ``auto``), or one whose translations a table of
:mod:`rootlang.locale.keywords` gives (``and``)."""


def _text(*phrases: Phrase) -> str:
    return " ".join(phrase.english if isinstance(phrase, Said) else phrase for phrase in phrases)


def _translated(*phrases: Phrase | tuple[Phrase, ...]) -> tuple[Said, ...]:
    flat = [item for p in phrases for item in (p if isinstance(p, tuple) else (p,))]
    return tuple(phrase for phrase in flat if isinstance(phrase, Said))


@dataclass(frozen=True)
class Word:
    """Words written as they are: ``move``, ``radius``, ``play sweep from``. ``terminal``: the
    grammar reads them as that one token of its own (``and wait``, which `and` would otherwise
    begin a condition with). ``said``: the phrases of ``text`` other languages write their own
    way (made by :func:`words`). ``printed`` False: words the grammar also reads there but
    the printers and the blocks leave out (``times`` in ``repeat 4 times``)."""

    text: str
    terminal: str = ""
    said: tuple[Said, ...] = ()
    printed: bool = True


def words(*phrases: Phrase, terminal: str = "", printed: bool = True) -> Word:
    """The words of these phrases in turn: ``words(SET, WHEELS, LEFT)`` is ``set wheels left``,
    with the translations of each."""
    return Word(_text(*phrases), terminal, _translated(*phrases), printed)


Meaning = TypeVar("Meaning")


@dataclass(frozen=True)
class Choice(Generic[Meaning]):
    """One of a few words, stored in the node's ``field``: ``(node value, words written)``.
    Words may be empty (``anywhere`` in ``when color red seen`` is not written); ``labels``
    override what the block's menu shows for such a choice. ``meanings``: what each value
    stands for on the robot (the colour sensors a zone covers, the light state ...), read by
    the runtime with :meth:`meaning`. ``terminal``: the grammar reads the words as one token
    of that name (its words those of every choice that names it), else each option is a line
    of its own (``dock`` / ``undock``); ``also``: other spellings it reads, and their value
    (``forwards``, ``pen``); ``said``: how other languages write the options' phrases."""

    field: str
    options: tuple[tuple[Any, str], ...]
    labels: Mapping[Any, str] = dataclasses.field(default_factory=dict)
    meanings: Mapping[Any, Meaning] = dataclasses.field(default_factory=dict)
    terminal: str = ""
    also: Mapping[str, Any] = dataclasses.field(default_factory=dict)
    said: tuple[Said, ...] = ()

    def meaning(self, value: Any) -> Meaning:
        return self.meanings[value]

    def value_of_words(self, written: str) -> Any:
        """The value the words read stand for (lower case, single spaces); KeyError if none."""
        for value, words in self.options:
            if words == written:
                return value
        return self.also[written]

    def words(self, value: Any) -> str:
        return next(words for option, words in self.options if option == value)

    def label(self, value: Any) -> str:
        return self.labels.get(value) or self.words(value)

    def value_of_label(self, label: str) -> Any:
        """The node value a block's menu item stands for; KeyError if none."""
        for value, _ in self.options:
            if self.label(value) == label:
                return value
        raise KeyError(label)


@dataclass(frozen=True)
class Slot:
    """A value: the node's expression ``field``, of ``kind`` (None: any value). ``default`` is
    the text of the value a block from the toolbox starts with. ``label`` and ``example`` are
    how a message about a wrong kind names the command and shows it right."""

    field: str
    kind: Kind | None
    default: str
    label: str = ""
    example: str = ""


@dataclass(frozen=True)
class Text:
    """A word or text the child types, stored as a plain string (a message's name)."""

    field: str
    default: str


@dataclass(frozen=True)
class Body:
    """The indented block under a header line."""

    field: str = "body"


Part = Word | Choice[Any] | Slot | Text | Body


@dataclass(frozen=True)
class Needs:
    """The robot feature a statement needs (a key of ``FEATURES``) and how a message says what
    it does (``use the eraser``): the checks warn on a robot without it (W102), the runtime
    stops with E201. With ``follows``, both are ``by_value[the value of that field]``."""

    feature: str = ""
    action: str = ""
    follows: str = ""
    by_value: Mapping[Any, tuple[str, str]] = dataclasses.field(default_factory=dict)

    def of(self, node: ast.Node) -> tuple[str, str]:
        if self.follows:
            return self.by_value[getattr(node, self.follows)]
        return self.feature, self.action


@dataclass(frozen=True)
class Form:
    """One way a construct is written, and the block that shows it.

    ``fixed`` gives the node fields this form does not show (``set left wheel`` has
    ``right=None``); a node *matches* when its fixed fields are equal, its choices are among
    the options and its slots are filled. A statement's form says the robot feature it
    ``needs`` (if not every robot has it) and whether it ``moves`` the robot (not in ``when
    stopped``)."""

    block: str
    node: type[ast.Node]
    category: Category
    parts: tuple[Part, ...]
    fixed: Mapping[str, Any] = dataclasses.field(default_factory=dict)
    tooltip: str = ""
    also: tuple[str, ...] = ()  # other words the line may start with, for its first part
    needs: Needs | None = None
    moves: bool = False

    def matches(self, node: ast.Node) -> bool:
        if type(node) is not self.node:
            return False
        if any(getattr(node, name) != value for name, value in self.fixed.items()):
            return False
        for part in self.parts:
            if isinstance(part, Choice) and getattr(node, part.field) not in dict(part.options):
                return False
            if isinstance(part, Slot) and getattr(node, part.field) is None:
                return False
        return True

    @property
    def slots(self) -> tuple[Slot, ...]:
        return tuple(part for part in self.parts if isinstance(part, Slot))

    def first_words(self) -> tuple[str, ...]:
        """The words a line in this form can start with (none when it starts with a value)."""
        first = self.parts[0]
        if isinstance(first, Word):
            return (first.text.split()[0], *self.also)
        if isinstance(first, Choice):
            return (*(words.split()[0] for _, words in first.options if words), *self.also)
        return self.also

    def said(self) -> tuple[Said, ...]:
        """The phrases of this form other languages write their own way, in order."""
        return tuple(
            said for part in self.parts if isinstance(part, Word | Choice) for said in part.said
        )


Option = Phrase | tuple[Phrase, ...]  # a choice's option: its phrase, or phrases in turn


def _option(option: Option) -> str:
    return _text(*option) if isinstance(option, tuple) else _text(option)


def _choice(name: str, *options: Option, terminal: str = "", **also: Any) -> Choice[Any]:
    """A choice of ``options``, each stored as the words written."""
    written = tuple((_option(option), _option(option)) for option in options)
    return Choice(name, written, terminal=terminal, also=also, said=_translated(*options))


def _flag(name: str, yes: Phrase, no: Phrase, terminal: str = "") -> Choice[Any]:
    return Choice(name, ((True, _text(yes)), (False, _text(no))), terminal=terminal,
                  said=_translated(yes, no))  # fmt: skip


def _meant(
    name: str, meanings: Mapping[str, Meaning], *options: Option, terminal: str = ""
) -> Choice[Meaning]:
    """A choice of ``options`` (each stored as the words written), with what each stands for."""
    return dataclasses.replace(_choice(name, *options, terminal=terminal), meanings=meanings)


# ---- the forms' words in Dutch, Spanish, French and German --------------------------------
# Those of more than one form, once (a form's own are written in it). A word with no Said is
# written as in English in every language (x, auto), or is translated by a table of
# rootlang.locale.keywords (and).
# fmt: off
LEFT = Said("left", "links", "izquierda", "gauche", "links")
RIGHT = Said("right", "rechts", "derecha", "droite", "rechts")
FRONT = Said("front", "voor", "delante", "devant", "vorne")
BACK = Said("back", "achter", "detrás", "derrière", "hinten")
BOTH = Said("both", "beide", "ambos", "les deux", "beide")
ANY = Said("any", "elke", "cualquiera", "n'importe", "jede")
MIDDLE = Said("middle", "midden", "centro", "milieu", "mitte")
EVERYWHERE = Said("everywhere", "overal", "todas partes", "partout", "überall")
ON = Said("on", "aan", "en", "sur", "auf")
OFF = Said("off", "uit", "apagado", "éteint", "aus")
SET = Said("set", "zet", "fija", "mets", "setze")
TO = Said("to", "tot", "hasta", "à", "bis")
FOR = Said("for", "gedurende", "durante", "pendant", "für")
STOP = Said("stop", "stop", "detén", "arrête", "stopp")
REPEAT = Said("repeat", "herhaal", "repite", "répète", "wiederhole")
WAIT = Said("wait", "wacht", "espera", "attends", "warte")
PLAY = Said("play", "speel", "toca", "joue", "spiele")
LIGHT = Said("light", "licht", "luz", "lumière", "licht")
BUMPER = Said("bumper", "", "parachoques", "pare-chocs", "stoßstange")
TOUCH = Said("touch", "aanraking", "toque", "toucher", "berührung")
PRESSED = Said("pressed", "ingedrukt", "pulsado", "appuyé", "gedrückt")
COLOR = Said("color", "kleur", "", "couleur", "farbe")
SEEN = Said("seen", "gezien", "visto", "vu", "gesehen")
CLIFF = Said("cliff", "afgrond", "precipicio", "vide", "abgrund")
BATTERY = Said("battery", "batterij", "batería", "batterie", "batterie")
OBSTACLE = Said("obstacle", "obstakel", "obstáculo", "", "hindernis")
DOCKED = Said("docked", "geparkeerd", "atracado", "accosté", "angedockt")
# fmt: on

_DIRECTION = _choice("direction", LEFT, RIGHT, terminal="DIRECTION")

# ---- statements --------------------------------------------------------------------------

_DISTANCE = Slot("distance", Kind.LENGTH, "10 cm", "move", "move 10 cm")
_GO_X = Slot("x", Kind.LENGTH, "20 cm", "go to x", "go to x 20 cm y 10 cm")
_GO_Y = Slot("y", Kind.LENGTH, "10 cm", "go to ... y", "go to x 20 cm y 10 cm")
_LEFT_WHEEL = Slot("left", Kind.SPEED, "5 cm/s", "set wheels", "set left wheel 5 cm/s")
_RIGHT_WHEEL = Slot("right", Kind.SPEED, "5 cm/s", "set wheels", "set right wheel 5 cm/s")
_GRAVITY = words(SET, Said("gravity compensation", "zwaartekrachtcompensatie",
                           "compensación de gravedad", "compensation de gravité",
                           "schwerkraftausgleich"))  # fmt: skip
_GRAVITY_MODE = _choice("mode", ON, OFF, "auto", terminal="GRAVITY_MODE")
_GRAVITY_AMOUNT = Slot(
    "amount", Kind.PERCENT, "50 %", "set gravity compensation", "set gravity compensation on 50 %"
)
_LIGHT_COLOR = Slot("color", Kind.COLOR, "green", "light", "light red")
_SWEEP = (
    words(PLAY, Said("sweep", "glissando", "barrido", "glissando", "glissando"),
          Said("from", "van", "de", "de", "von")),
    Slot("start", Kind.FREQUENCY, "200 Hz", "play sweep from", "from 200 Hz"),
    words(TO),
    Slot("end", Kind.FREQUENCY, "800 Hz", "play sweep ... to", "to 800 Hz"),
    words(FOR),
    Slot("duration", Kind.TIME, "2 seconds", "play sweep ... for", "for 2 seconds"),
)  # fmt: skip


def _condition(command: str) -> Slot:
    """A condition: a value true or false, which a message (E112) names by its ``command``."""
    return Slot("condition", Kind.BOOLEAN, "bumper any pressed", command)


# `when bumper any pressed` would read as the event `when bumped`: a condition of its own
_WHEN_CONDITION = Slot("condition", Kind.BOOLEAN, "timer > 5 seconds", "when")
_MESSAGE = Slot("message", Kind.TEXT, '"go"', "send", 'send "go"')
_MOVE = words(Said("move", "beweeg", "mueve", "bouge", "bewege"))
_GO_TO = words(Said("go to", "ga naar", "ve a", "va à", "gehe zu"), "x")
_SEND = words(Said("send", "stuur", "envía", "envoie", "sende"))
_RETURN = words(Said("return", "geef", "devuelve", "renvoie", "gib"))
_RETURN_VALUE = Slot("value", None, "0")
_M, _D, _L, _S, _C, _MSG = (
    Category.MOTION,
    Category.DRAWING,
    Category.LIGHTS,
    Category.SOUND,
    Category.CONTROL,
    Category.MESSAGES,
)

_GRAVITY_NEEDS = Needs("gravity compensation", "set gravity compensation")

STATEMENT_FORMS: tuple[Form, ...] = (
    Form("root_move", ast.Move, _M,
         (_MOVE, _DISTANCE), {"direction": ""},
         "Drive straight; a negative distance goes backwards.", moves=True),
    Form("root_move_direction", ast.Move, _M,
         (_MOVE, _choice("direction",
                                 Said("forward", "vooruit", "adelante", "avant", "vorwärts"),
                                 Said("backward", "achteruit", "atrás", "arrière", "rückwärts"),
                                 terminal="MOVE_DIRECTION",
                                 forwards="forward", backwards="backward"), _DISTANCE),
         moves=True),
    Form("root_turn", ast.Turn, _M, (words(Said("turn", "draai", "gira", "tourne", "drehe")),
         _DIRECTION, Slot("angle", Kind.ANGLE, "90 degrees", "turn", "turn right 90 degrees")),
         moves=True),
    Form("root_arc", ast.Arc, _M, (
        words(Said("arc", "boog", "arco", "", "bogen")), _DIRECTION,
        Slot("angle", Kind.ANGLE, "90 degrees", "arc", "arc right 90 degrees radius 10 cm"),
        words(Said("radius", "straal", "radio", "rayon", "")),
        Slot("radius", Kind.LENGTH, "10 cm", "arc ... radius", "arc right 90 degrees radius 10 cm"),
    ), moves=True),
    Form("root_go_to", ast.GoTo, _M,
         (_GO_TO, _GO_X, words("y"), _GO_Y), {"facing": None}, moves=True),
    Form("root_go_to_facing", ast.GoTo, _M, (
        _GO_TO, _GO_X, words("y"), _GO_Y,
        words(Said("facing", "richting", "mirando", "orienté", "ausrichtung")),
        Slot("facing", Kind.ANGLE, "90 degrees", "facing", "facing 90 degrees"),
    ), moves=True),
    Form("root_set_wheels", ast.SetWheels, _M,
         (words(SET, Said("wheels", "wielen", "ruedas", "roues", "räder"), LEFT), _LEFT_WHEEL,
          words(RIGHT), _RIGHT_WHEEL), moves=True),
    Form("root_set_left_wheel", ast.SetWheels, _M,
         (words(SET, Said("left wheel", "linkerwiel", "rueda izquierda", "roue gauche",
                          "linkes rad")), _LEFT_WHEEL), {"right": None}, moves=True),
    Form("root_set_right_wheel", ast.SetWheels, _M,
         (words(SET, Said("right wheel", "rechterwiel", "rueda derecha", "roue droite",
                          "rechtes rad")), _RIGHT_WHEEL), {"left": None}, moves=True),
    Form("root_drive", ast.Drive, _M,
         (words(Said("drive", "rijd", "conduce", "roule", "fahre")),
          Slot("speed", Kind.SPEED, "5 cm/s", "drive", "drive 5 cm/s")), moves=True),
    Form("root_stop_moving", ast.StopMoving, _M,
         (words(Said("stop moving", "stop met rijden", "detente", "arrête de bouger",
                     "halte an")),)),
    Form("root_reset_position", ast.ResetPosition, _M,
         (words(Said("reset position", "herstel positie", "reinicia posición",
                     "réinitialise position", "setze position zurück")),)),
    Form("root_dock", ast.Dock, _M,
         (_flag("docking", Said("dock", "parkeer", "atraca", "accoste", "andocken"),
                Said("undock", "vertrek", "desatraca", "largue", "abdocken")),),
         tooltip="Create 3: drive onto the dock, or off it.", moves=True,
         needs=Needs(follows="docking", by_value={True: ("dock", "dock"),
                                                  False: ("dock", "undock")})),
    Form("root_gravity", ast.SetGravityCompensation, _M,
         (_GRAVITY, _GRAVITY_MODE), {"amount": None}, needs=_GRAVITY_NEEDS),
    Form("root_gravity_amount", ast.SetGravityCompensation, _M,
         (_GRAVITY, _GRAVITY_MODE, _GRAVITY_AMOUNT), needs=_GRAVITY_NEEDS),
    Form("root_tool", ast.Tool, _D,
         (_choice("tool", Said("marker", "stift", "rotulador", "feutre", "stift"),
                  Said("eraser", "gum", "borrador", "gomme", "radierer"), terminal="TOOL",
                  pen="marker"),
          _flag("down", Said("down", "omlaag", "abajo", "bas", "runter"),
                Said("up", "omhoog", "arriba", "haut", "hoch"), terminal="TOOL_POSITION")),
         needs=Needs(follows="tool", by_value={tool: (tool, f"use the {tool}")
                                               for tool in ("marker", "eraser")})),
    Form("root_light", ast.Light, _L, (words(LIGHT), _LIGHT_COLOR), {"mode": "on"}),
    Form("root_light_mode", ast.Light, _L,
         (words(LIGHT), _choice("mode", Said("blink", "knipper", "parpadea", "clignote", "blinke"),
                                Said("spin", "rond", "remolino", "tourbillon", "kreise"),
                                terminal="LIGHT_MODE", on="on"),
          _LIGHT_COLOR)),
    Form("root_light_off", ast.Light, _L, (words(LIGHT, OFF),), {"mode": "off", "color": None}),
    Form("root_play", ast.PlayNote, _S, (
        words(PLAY),
        Slot("frequency", Kind.FREQUENCY, "note C4", "play", "play note C4 for 1 second"),
        words(FOR),
        Slot("duration", Kind.TIME, "0.5 seconds", "play ... for", "play 440 Hz for 1 second"),
    )),
    Form("root_play_sweep", ast.PlaySweep, _S, _SWEEP, {"volume": None}),
    Form("root_play_sweep_volume", ast.PlaySweep, _S, (
        *_SWEEP, words(Said("volume", "", "volumen", "", "lautstärke")),
        Slot("volume", Kind.PERCENT, "50 %", "volume", "volume 50 %"),
    )),
    Form("root_say", ast.Say, _S, (words(Said("say", "zeg", "di", "dis", "sage")),
                                   Slot("text", None, '"hello"'))),
    Form("root_stop_sound", ast.StopSound, _S,
         (words(STOP, Said("sound", "geluid", "sonido", "son", "ton")),)),
    Form("root_wait", ast.Wait, _C,
         (words(WAIT), Slot("duration", Kind.TIME, "1 second", "wait", "wait 2 seconds"))),
    Form("root_wait_until", ast.WaitUntil, _C,
         (words(Said("wait until", "wacht totdat", "espera hasta que", "attends jusqu'à",
                     "warte bis")), _condition("wait until"))),
    Form("root_repeat", ast.Repeat, _C,
         (words(REPEAT), Slot("count", Kind.NUMBER, "4", "repeat", "repeat 4"),
          words(Said("times", "keer", "veces", "fois", "mal"), printed=False), Body())),
    Form("root_forever", ast.Forever, _C,
         (words(REPEAT, Said("forever", "altijd", "siempre", "toujours", "immer")), Body()),
         also=("forever",)),
    Form("root_repeat_until", ast.RepeatUntil, _C,
         (words(Said("repeat until", "herhaal totdat", "repite hasta que", "répète jusqu'à",
                     "wiederhole bis")), _condition("repeat until"), Body())),
    Form("root_while", ast.While, _C,
         (words(Said("while", "zolang", "mientras", "tant que", "solange")), _condition("while"),
          Body())),
    Form("root_stop", ast.Stop, _C,
         (words(STOP), _choice("target",
                               Said("this script", "dit script", "este guion", "ce script",
                                    "dieses skript"),
                               Said("other scripts", "andere scripts", "otros guiones",
                                    "autres scripts", "andere skripte"),
                               Said("all", "alles", "todo", "tout", "alles"),
                               terminal="STOP_TARGET"))),
    Form("root_send", ast.Send, _MSG, (_SEND, _MESSAGE), {"wait": False}),
    Form("root_send_and_wait", ast.Send, _MSG,
         (_SEND, _MESSAGE, words("and", WAIT, terminal="AND_WAIT")), {"wait": True}),
    Form("root_return", ast.Return, Category.PROCEDURES, (_RETURN,), {"value": None}),
    Form("root_return_value", ast.Return, Category.PROCEDURES, (_RETURN, _RETURN_VALUE)),
)  # fmt: skip
"""Every statement but the few the printers handle themselves (see ``SPECIAL_NODES``)."""

SPECIAL_NODES: dict[type[ast.Node], tuple[str, ...]] = {
    ast.If: ("if", "else"),  # if / else if / else: Blockly's own `controls_if` block
    ast.Print: ("print",),  # any number of values
    ast.SetVariable: ("set",),  # Blockly's variable blocks
    ast.ChangeVariable: ("change",),
    ast.CallProcedure: (),  # one block per procedure, any number of values
    ast.Branch: (),  # part of If
    ast.Script: (),
    ast.Procedure: (),
    ast.Parameter: (),
    ast.Program: (),
    ast.Comment: (),
}
"""Node types written by code rather than by a form (each named where it is handled), with
the words a statement of that type starts with."""

# ---- events ------------------------------------------------------------------------------

# What the choices of events and sensors stand for on the robot: the protocol's names for the
# touch sensors and light states (the protocol's enums load only with the runtime), the colour
# sensor's 32 sensors (left to right) and the 7 IR sensors (left to right) each side covers.
_BUMPER_SIDES: dict[str, tuple[tuple[str, ...], ...]] = {  # pressed: all of one group
    "left": (("LEFT",),),
    "right": (("RIGHT",),),
    "both": (("LEFT", "RIGHT"),),
    "any": (("LEFT",), ("RIGHT",)),
}
_TOUCH_SENSORS: dict[str, tuple[str, ...]] = {
    "front left": ("FRONT_LEFT",),
    "front right": ("FRONT_RIGHT",),
    "back left": ("REAR_LEFT",),
    "back right": ("REAR_RIGHT",),
    "any": ("FRONT_LEFT", "FRONT_RIGHT", "REAR_LEFT", "REAR_RIGHT"),
}
_COLOR_ZONES = {
    "anywhere": range(0, 32),
    "left": range(0, 10),
    "middle": range(10, 22),
    "right": range(22, 32),
    "everywhere": range(0, 32),
}
_OBSTACLE_SIDES = {"any": range(0, 7), "left": range(0, 2), "front": range(2, 5),
                   "right": range(5, 7)}  # fmt: skip
_LIGHT_STATES = {
    "dark": "BOTH_DARK",
    "bright": "BOTH_BRIGHT",
    "brighter on left": "LEFT_BRIGHTER",
    "brighter on right": "RIGHT_BRIGHTER",
}

BUMPER_SIDE: Choice[tuple[tuple[str, ...], ...]] = _meant(
    "side", _BUMPER_SIDES, LEFT, RIGHT, BOTH, ANY, terminal="BUMPER_SIDE"
)
"""Which bumper: its meaning, the ``BumperState`` bits (by name) that are pressed together,
any one group of them (``any``: the left one, or the right one)."""
TOUCH_SENSOR: Choice[tuple[str, ...]] = _meant(
    "sensor", _TOUCH_SENSORS, (FRONT, LEFT), (FRONT, RIGHT), (BACK, LEFT), (BACK, RIGHT), ANY,
    terminal="TOUCH_SENSOR",
)  # fmt: skip
"""Which touch sensor: its meaning, the ``TouchSensors`` bits it stands for (by name)."""
TOUCH_SENSOR_NAMES: tuple[str, ...] = tuple(
    value for value, _ in TOUCH_SENSOR.options if len(TOUCH_SENSOR.meaning(value)) == 1
)
"""The touch sensors one by one, as programs name them (``front left`` ... ``back right``)."""
BUMPER_SIDE_NAMES: tuple[str, ...] = tuple(
    value for value, _ in BUMPER_SIDE.options if len(BUMPER_SIDE.meaning(value)) == 1
    and len(BUMPER_SIDE.meaning(value)[0]) == 1
)  # fmt: skip
"""The bumpers one by one, as programs name them (``left``, ``right``)."""
COLOR_ZONE: Choice[range] = Choice(
    "zone", tuple((zone, f"on {zone}" if zone != "anywhere" else "") for zone in _COLOR_ZONES),
    {"anywhere": "anywhere"}, _COLOR_ZONES, said=(ON, LEFT, MIDDLE, RIGHT, EVERYWHERE),
)  # fmt: skip
"""Where ``when color ... seen`` looks: its meaning, the colour sensors it covers."""
OBSTACLE_SIDE: Choice[range] = Choice(
    "side", tuple((side, f"on {side}" if side != "any" else "") for side in _OBSTACLE_SIDES),
    {"any": "anywhere"}, _OBSTACLE_SIDES, said=(ON, LEFT, FRONT, RIGHT),
)  # fmt: skip
"""Where ``when obstacle seen`` looks: its meaning, the IR sensors it covers."""
_BRIGHTER = Said("brighter", "helderder", "más brillante", "plus clair", "heller")
LIGHT_STATE: Choice[str] = _meant(
    "state", _LIGHT_STATES, Said("dark", "donker", "oscuro", "sombre", "dunkel"),
    Said("bright", "helder", "brillante", "clair", "hell"), (_BRIGHTER, ON, LEFT),
    (_BRIGHTER, ON, RIGHT), terminal="LIGHT_STATE",
)  # fmt: skip
"""``when light ...``: its meaning, the ``LightState`` it stands for (by name)."""

_PRESSED = _flag("pressed", PRESSED, Said("released", "losgelaten", "soltado", "relâché",
                                            "losgelassen"))  # fmt: skip
_ANY_COLOR = tuple((name, name) for name in dict.fromkeys((*SENSOR_COLORS, *NAMED_COLORS)))
_E = Category.EVENTS

EVENT_FORMS: tuple[Form, ...] = (
    Form("root_when_started", ast.Started, _E,
         (words(Said("started", "gestart", "empieza", "démarré", "gestartet")),)),
    Form("root_when_stopped", ast.Stopped, _E,
         (words(Said("stopped", "gestopt", "detenido", "arrêté", "gestoppt")),),
         tooltip="Runs when the program is stopped; may light and sound, not move (2 seconds)."),
    Form("root_when_bumped", ast.BumperEvent, _E,
         (words(Said("bumped", "gebotst", "choca", "heurté", "gestoßen")),),
         {"side": "any", "pressed": True}),
    Form("root_when_bumper", ast.BumperEvent, _E,
         (words(BUMPER), BUMPER_SIDE, _PRESSED)),
    Form("root_when_touched", ast.TouchEvent, _E,
         (words(Said("touched", "aangeraakt", "tocado", "touché", "berührt")),),
         {"sensor": "any", "pressed": True}),
    Form("root_when_touch", ast.TouchEvent, _E, (words(TOUCH), TOUCH_SENSOR, _PRESSED)),
    Form("root_when_color", ast.ColorSeen, _E, (
        words(COLOR), Choice("color", _ANY_COLOR, terminal="color_name"),
        words(SEEN), COLOR_ZONE,
    )),
    Form("root_when_light", ast.LightEvent, _E, (words(LIGHT), LIGHT_STATE)),
    Form("root_when_cliff", ast.CliffEvent, _E,
         (words(CLIFF), _flag("detected", Said("detected", "ontdekt", "detectado", "détecté",
                                               "erkannt"),
                              Said("cleared", "verdwenen", "despejado", "dégagé", "frei")))),
    Form("root_when_stalled", ast.StalledEvent, _E,
         (words(Said("stalled", "vast", "atascado", "bloqué", "blockiert")),)),
    Form("root_when_battery_low", ast.BatteryLowEvent, _E,
         (words(BATTERY, Said("low", "laag", "baja", "faible", "schwach")),)),
    Form("root_when_obstacle", ast.ObstacleSeen, _E, (words(OBSTACLE, SEEN), OBSTACLE_SIDE)),
    Form("root_when_docked", ast.DockEvent, _E,
         (_flag("docked", DOCKED, Said("undocked", "vertrokken", "desatracado", "largué",
                                       "abgedockt")),)),
    Form("root_when_message", ast.MessageReceived, Category.MESSAGES,
         (words(Said("message", "bericht", "mensaje", "", "nachricht")), Text("message", "go"),
          words(Said("received", "ontvangen", "recibido", "reçu", "empfangen")))),
    Form("root_when_condition", ast.ConditionBecomesTrue, _E, (_WHEN_CONDITION,),
         tooltip="Runs each time the condition turns from false to true."),
)  # fmt: skip
"""How each event is written after ``when``; each is a hat block."""


@dataclass(frozen=True)
class EventSource:
    """Where a robot event comes from: the robot ``feature`` it needs (as the checks name it,
    see ``FEATURES``) and the ``packet`` that carries it."""

    feature: str
    packet: str


EVENTS: dict[type[ast.RobotEvent], EventSource] = {
    ast.BumperEvent: EventSource("bumpers", "bumper_event"),
    ast.TouchEvent: EventSource("touch sensors", "touch_sensor_event"),
    ast.ColorSeen: EventSource("colour sensor", "color_sensor_event"),
    ast.LightEvent: EventSource("light sensors", "light_event"),
    ast.CliffEvent: EventSource("cliff sensor", "cliff_event"),
    ast.StalledEvent: EventSource("stall sensing", "motor_stall_event"),
    ast.BatteryLowEvent: EventSource("battery sensor", "battery_level_event"),
    ast.ObstacleSeen: EventSource("obstacle sensors", "ir_proximity_event"),
    ast.DockEvent: EventSource("dock", "docking_sensor_event"),
}
"""The events the robot sends; the others (started, stopped, message, condition) are the
program's own."""

# ---- sensors -----------------------------------------------------------------------------


@dataclass(frozen=True)
class Sensor:
    """A sensor reading: the kind of value it gives, how it is written (``where`` is its
    choice of side), the robot ``feature`` it needs and the ``packet`` that tells it (None:
    every robot has it, or the host keeps it)."""

    sensor: ast.SensorKind
    kind: Kind
    form: Form
    feature: str | None = None
    packet: str | None = None


def _sensor(
    sensor: ast.SensorKind,
    kind: Kind,
    parts: tuple[Part, ...],
    feature: str | None = None,
    packet: str | None = None,
) -> Sensor:
    form = Form(f"root_sensor_{sensor.value}", ast.SensorRead, Category.SENSORS, parts,
                {"sensor": sensor} if any(isinstance(p, Choice) for p in parts)
                else {"sensor": sensor, "where": None})  # fmt: skip
    return Sensor(sensor, kind, form, feature, packet)


def _where(choice: Choice[Meaning]) -> Choice[Meaning]:
    """An event's choice as a sensor reads it: the same words and meanings, in ``where``."""
    return dataclasses.replace(choice, field="where")


_K = ast.SensorKind
_AXIS = ("x", "y")
SENSORS: dict[ast.SensorKind, Sensor] = {
    sensor.sensor: sensor
    for sensor in (
        _sensor(_K.BUMPER, Kind.BOOLEAN, (words(BUMPER), _where(BUMPER_SIDE), words(PRESSED)),
                "bumpers", "bumper_event"),
        _sensor(_K.TOUCH, Kind.BOOLEAN, (words(TOUCH), _where(TOUCH_SENSOR), words(PRESSED)),
                "touch sensors", "touch_sensor_event"),
        _sensor(_K.COLOR, Kind.COLOR, (words(COLOR, ON),
                _meant("where", _COLOR_ZONES, LEFT, MIDDLE, RIGHT, EVERYWHERE,
                       terminal="COLOR_ZONE")),
                "colour sensor", "color_sensor_event"),
        _sensor(_K.LIGHT, Kind.PERCENT, (words(LIGHT), _choice("where", LEFT, RIGHT,
                terminal="DIRECTION")), "light sensors",
                "get_light_values"),
        _sensor(_K.BATTERY, Kind.PERCENT, (words(BATTERY),), "battery sensor",
                "get_battery_level"),
        _sensor(_K.POSITION, Kind.LENGTH, (words(Said("position", "positie", "posición", "", "")),
                _choice("where", *_AXIS, terminal="AXIS"))),
        _sensor(_K.HEADING, Kind.ANGLE, (words(Said("heading", "koers", "rumbo", "cap", "kurs")),)),
        _sensor(_K.TILT, Kind.NUMBER, (words(Said("tilt", "kanteling", "inclinación",
                "inclinaison", "neigung")), _choice("where", *_AXIS, "z", terminal="AXIS")),
                "accelerometer", "get_accelerometer"),
        _sensor(_K.CLIFF, Kind.BOOLEAN, (words(CLIFF),), "cliff sensor", "cliff_event"),
        _sensor(_K.OBSTACLE, Kind.PERCENT, (words(OBSTACLE),
                _meant("where", _OBSTACLE_SIDES, LEFT, FRONT, RIGHT,
                       terminal="OBSTACLE_SIDE")),
                "obstacle sensors", "get_packed_ir_proximity"),
        _sensor(_K.TIMER, Kind.TIME, (words(Said("timer", "", "cronómetro", "chrono",
                                                 "stoppuhr")),)),
        _sensor(_K.DOCKED, Kind.BOOLEAN, (words(DOCKED),), "dock", "docking_sensor_event"),
    )
}  # fmt: skip

# ---- what the checks and the runtime read ------------------------------------------------


class ArgumentRule(NamedTuple):
    """The kind of value a command's argument needs, and how a message about a value of
    another kind names the command and shows it right (``move``, ``move 10 cm``)."""

    kind: Kind
    command: str
    example: str


ARGUMENT_RULES: dict[tuple[type[ast.Node], str], ArgumentRule] = {
    (form.node, slot.field): ArgumentRule(slot.kind, slot.label, slot.example)
    for form in STATEMENT_FORMS
    for slot in form.slots
    if slot.kind is not None and slot.kind is not Kind.BOOLEAN
}
"""(statement type, field) -> its rule: what a wrong kind of value is told, at check time and
at run time alike."""

CONDITIONS: dict[type[ast.Node], str] = {
    form.node: slot.label
    for form in (*STATEMENT_FORMS, *EVENT_FORMS)
    for slot in form.slots
    if slot.kind is Kind.BOOLEAN
}
"""Statement or event type -> how a message names the line whose value must be true or false
(``wait until``, ``while``, ``when`` ...): at check time and at run time alike (E112)."""

MOTION: tuple[type[ast.Node], ...] = tuple(
    dict.fromkeys(form.node for form in STATEMENT_FORMS if form.moves)
)
"""Statements that move the robot (their forms say so; not allowed in ``when stopped``)."""

NEEDS: dict[type[ast.Node], Needs] = {
    form.node: form.needs for form in STATEMENT_FORMS if form.needs is not None
}
"""Statement type -> the robot feature it needs (its forms say it)."""

ERASER = "eraser"
FEATURES: dict[str, str] = {
    "colour sensor": "color_sensor_event",
    "light sensors": "light_event",
    "cliff sensor": "cliff_event",
    "obstacle sensors": "ir_proximity_event",
    "dock": "dock",
    "marker": "set_marker_position",
    ERASER: "set_marker_position",
    "gravity compensation": "set_gravity_compensation",
    "bumpers": "bumper_event",
    "touch sensors": "touch_sensor_event",
    "stall sensing": "motor_stall_event",
    "battery sensor": "battery_level_event",
    "accelerometer": "get_accelerometer",
}
"""Each robot feature (as messages name it: "Root RT0 has no colour sensor") -> the packet it
needs: the robots that have the feature are those the packet table gives that packet (and, for
the eraser, those whose marker actuator holds one: ``protocol.table.ERASERS``)."""


STATEMENT_WORDS: frozenset[str] = frozenset(
    word
    for words in (*(form.first_words() for form in STATEMENT_FORMS), *SPECIAL_NODES.values())
    for word in words
)
"""Every word a statement can start with (what an unknown command may have meant)."""
EVENT_WORDS: frozenset[str] = frozenset(word for form in EVENT_FORMS for word in form.first_words())
"""Every word an event can start with, after ``when``."""


def form_of(node: ast.Node) -> Form:
    """The form a node is written in (the first that matches); KeyError if it has none."""
    for form in _FORMS_BY_NODE.get(type(node), ()):
        if form.matches(node):
            return form
    raise KeyError(type(node).__name__)


def body_of(statement: ast.Statement) -> ast.Block | None:
    """The block under a statement whose form has a body (a loop's), else None (``if`` holds
    its blocks in its branches)."""
    field = _BODY_FIELDS.get(type(statement))
    return None if field is None else cast("ast.Block", getattr(statement, field))


def every_form() -> tuple[Form, ...]:
    """The statements', the events' and the sensors' forms, in that order."""
    return (*STATEMENT_FORMS, *EVENT_FORMS, *(sensor.form for sensor in SENSORS.values()))


def _forms_by_node() -> dict[type[ast.Node], tuple[Form, ...]]:
    table: dict[type[ast.Node], list[Form]] = {}
    for form in every_form():
        table.setdefault(form.node, []).append(form)
    return {node: tuple(forms) for node, forms in table.items()}


_FORMS_BY_NODE = _forms_by_node()
_BODY_FIELDS: dict[type[ast.Node], str] = {
    form.node: part.field
    for form in STATEMENT_FORMS
    for part in form.parts
    if isinstance(part, Body)
}
