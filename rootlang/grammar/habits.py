"""Habits children bring from other tools, as one table: the line as they write it, and the
rootlang line it means, with their own values.

Each :class:`Habit` is data: a pattern written the way the child writes the line, with slots
(``{v}`` any value, ``{name}`` a name, ``{count}`` a whole number, ``{args}`` what is between
brackets, ``{rest}`` the rest of the line, ``{any}`` anything or nothing, ``{o}`` what a method
is called on: ``t.circle(20)``), and what to write instead, with the same slots.
A slot in the answer may say how its value is written there: ``{v cm}`` adds the unit after
a bare number (``fd 10`` -> ``move 10 cm``), ``{v!q}`` puts text in quotes, ``{v!neg}`` takes
its negative, ``{args!sp}`` writes ``a, b`` as ``a b``, ``{v!note}`` writes a MIDI note number
as a note name (60 -> C4), ``{v!logo}`` writes a turtle Logo list of commands (``fd 10 rt
90``) as indented lines.
An answer with several lines uses ``\\n``; an empty answer deletes the line.

:data:`TIDY` holds the small habits that are part of a line (a `;` at its end, `await
robot.`, `&&`): each is a substitution, and the line tidied is looked up again, so `let x =
5;` needs no entry of its own.

The table is consulted only for lines that have a mistake (:func:`with_habits`); a line that
means something in rootlang is never rewritten (a procedure of the child's own called
`forward` is theirs). Every answer is still tried in place before it is shown
(:mod:`rootlang.verify`), so a habit that does not fit a line explains instead of misleading.
"""

from __future__ import annotations

import functools
import math
import re
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass, replace

from rootlang.diagnostics import Diagnostic, Span, diagnostic
from rootlang.forms import STATEMENT_WORDS
from rootlang.wording.shown import Code, Described, unquoted, write_line


@dataclass(frozen=True)
class Habit:
    """One habit: where it comes from, the line as written there, and the rootlang line."""

    source: str  # the tool the habit comes from, as the message names it
    written: str
    rootlang: str
    why: str = "E031"  # the message: E031 (another tool's words), E032 (an end), E033 (import)
    caret: str = ""  # the slot the caret starts on, to the line's end (else: the first change)


def _habits(source: str, pairs: Iterable[tuple[str, str]], why: str = "E031") -> list[Habit]:
    return [  # a line to delete is one that isn't needed (E033), not one to write another way
        Habit(source, written, rootlang, "E033" if rootlang == DELETE and why == "E031" else why)
        for written, rootlang in pairs
    ]


DELETE = ""
TIMES = ("{a} {count} times", "repeat {count}\n    {a!line}")  # a command said with how many
# Shapes of many tools (Python's, JavaScript's, C's): a line that fits one only once tidied
# (`int x = 4;`) is from the tool whose habit the tidying took away.
GENERAL = (
    ("{name} = {v}", "set {name} to {v}"),
    ("{name}()", "{name}"),
    ("{name}({args})", "{name} {args}"),
)

# rootlang's own words that other tools use other ways (`go right 90`, `change x to 5`, `stop
# drawing`): a habit or synonym may start with one of these, never with another word of
# rootlang's (see of_other_tools).
SHARED_WORDS = frozenset(("go", "set", "change", "repeat", "while", "stop"))


def _word(text: str) -> str:
    found = re.match(r"[^\W\d]\w*", text.strip())
    return found.group(0).lower() if found else ""


def claimed_word(written: str, rootlang: str) -> str:
    """The word a habit (or a synonym) says belongs to another tool: the first word of the
    line as written, when rootlang's line does not use it ("" when it does, or starts with
    no word: ``turn {v} right`` only puts rootlang's words in another order)."""
    word = _word(written)
    return "" if word in re.findall(r"\w+", rootlang.lower()) else word


def of_other_tools(
    habits: Iterable[Habit], own: frozenset[str] = STATEMENT_WORDS
) -> tuple[Habit, ...]:
    """The habits that are another tool's while rootlang says none of ``own`` (the words a
    rootlang statement starts with) their way: a word rootlang takes up (a new statement,
    ``spin 3 turns``) stops being another tool's at once, and its line is read as rootlang's."""
    return tuple(
        habit
        for habit in habits
        if claimed_word(habit.written, habit.rootlang) not in own - SHARED_WORDS
    )


def synonyms_of_other_tools(
    synonyms: Iterable[tuple[str, str]], own: frozenset[str] = STATEMENT_WORDS
) -> tuple[tuple[str, str], ...]:
    """The synonyms (``words|...``, rootlang's word) without any word rootlang says itself."""
    kept = []
    for words, ours in synonyms:
        theirs = [w for w in words.split("|") if claimed_word(w, ours) not in own - SHARED_WORDS]
        if theirs:
            kept.append(("|".join(theirs), ours))
    return tuple(kept)


# fmt: off
HABITS: tuple[Habit, ...] = (
    # a command said with how many times (say hi 3 times): before any tool's way of the command
    *(
        replace(habit, caret="count")  # the caret on `4 times`
        for habit in _habits("other languages", [TIMES])
    ),
    *_habits("Scratch", [
        ("when green flag clicked", "when started"),
        ("when flag clicked", "when started"),
        ("when gf clicked", "when started"),
        ("when this sprite clicked", "when touched"),
        ("when i receive {v}", "when message {v!q} received"),
        ("broadcast {v} and wait", "send {v!q} and wait"),
        ("broadcast {v}", "send {v!q}"),
        ("move {v} steps", "move {v cm}"),
        ("move {v} step", "move {v cm}"),
        ("turn right {v} degrees", "turn right {v degrees}"),
        ("turn left {v} degrees", "turn left {v degrees}"),
        ("rest for {t} beats", "wait {t seconds}"),
        ("set pen color to {c}", "light {c}"),
        ("set pen colour to {c}", "light {c}"),
        ("say {v} for {t} seconds", "say {v!q}\nwait {t} seconds"),
        ("say {v} for {t} secs", "say {v!q}\nwait {t} seconds"),
        ("say {v} for {t} second", "say {v!q}\nwait {t} seconds"),
        ("think {v} for {t} seconds", "say {v!q}\nwait {t} seconds"),
        ("think {v} for {t} secs", "say {v!q}\nwait {t} seconds"),
        ("think {v} for {t} second", "say {v!q}\nwait {t} seconds"),
        ("think {v}", "say {v!q}"),
        ("say {v}", "say {v!q}"),
        ("wait {v} secs", "wait {v} seconds"),
        ("wait {v} sec", "wait {v} seconds"),
        ("turn ↻ {v} degrees", "turn right {v} degrees"),
        ("turn ↺ {v} degrees", "turn left {v} degrees"),
        ("turn {v} degrees", "turn right {v} degrees"),
        ("turn cw {v} degrees", "turn right {v} degrees"),
        ("turn ccw {v} degrees", "turn left {v} degrees"),
        ("turn clockwise {v} degrees", "turn right {v} degrees"),
        ("turn anticlockwise {v} degrees", "turn left {v} degrees"),
        ("turn counterclockwise {v} degrees", "turn left {v} degrees"),
        ("point in direction {v}", "go to x position x y position y facing {v!heading}"),
        ("go to x: {x} y: {y}", "go to x {x cm} y {y cm}"),
        ("go to x {x} y {y}", "go to x {x cm} y {y cm}"),
        ("glide {t} secs to x: {x} y: {y}", "go to x {x cm} y {y cm}"),
        ("glide {t} seconds to x: {x} y: {y}", "go to x {x cm} y {y cm}"),
        ("play note {v} for {t} beats", "play note {v!note} for {t} seconds"),
        ("pen down", "marker down"),
        ("pen up", "marker up"),
        ("forever loop", "forever"),
        ("if touching edge", "if bumper any pressed"),
        ("if touching edge?", "if bumper any pressed"),
        ("if touching edge then", "if bumper any pressed"),
        ("if touching wall", "if bumper any pressed"),
        ("if on edge, bounce", "if bumper any pressed"),
        ("wait until touching edge", "wait until bumper any pressed"),
        ("repeat until touching edge", "repeat until bumper any pressed"),
        ("stop all sounds", "stop sound"),
        ("stop other scripts in {rest}", "stop other scripts"),  # in sprite, in stage
        ("turn {v}", "turn right {v degrees}"),
        ("set {n} to {v}", "set {n!name} to {v}"),
        ("change {n} by {v}", "change {n!name} by {v}"),
    ]),
    *_habits("Scratch", [("end", DELETE)], why="E032"),
    *_habits("Python", [
        ("for {name} in range({v}):", "repeat {v}"),
        ("for {name} in range({v})", "repeat {v}"),
        ("for {name} in range({a}, {v}, {s})", "repeat {v!count}"),
        ("for {name} in range({a}, {v})", "repeat {v!count}"),
        ("def {name}():", "to {name}"),
        ("def {name}()", "to {name}"),
        ("def {name}({args}):", "to {name} {args}"),
        ("def {name}({args})", "to {name} {args}"),
        ("def {name}:", "to {name}"),
        ("def {name}", "to {name}"),
        ("{name} += {v}", "change {name} by {v}"),
        ("{name} -= {v}", "change {name} by {v!neg}"),
        ("{name} = {name} + {v}", "change {name} by {v}"),
        ("{name} = {name} - {v}", "change {name} by {v!neg}"),
        ("{name} *= {v}", "set {name} to {name} * {v}"),
        ("{name} /= {v}", "set {name} to {name} / {v}"),
        ("elif {v}:", "else if {v}"),
        ("elif {v}", "else if {v}"),
        ("print({args})", "print {args}"),
        ("if {c}: {s}", "if {c}\n    {s}"),
        ("while {c}: {s}", "while {c}\n    {s}"),
        ("else: {s}", "else\n    {s}"),
        ("time.sleep({v})", "wait {v} seconds"),
        ("sleep({v})", "wait {v seconds}"),
        ("pass", DELETE),
    ]),
    *_habits("Python", [
        ("import {rest}", DELETE),
        ("global {rest}", DELETE),  # every name a procedure uses is shared already
        ("nonlocal {rest}", DELETE),
        ("from {rest} import {more}", DELETE),
    ], why="E033"),
    # Python's turtle, called on a turtle of any name (`t.circle(20)`, `turtle.goto(0, 0)`):
    # its heading counts anticlockwise from the x axis, as rootlang's does (Logo's does not)
    *_habits("Python's turtle", [
        ("{o}.circle(-{r})", "arc right 360 degrees radius {r cm}"),
        ("{o}.circle({r})", "arc left 360 degrees radius {r cm}"),
        ("{o}.circle(-{r}, {a})", "arc right {a degrees} radius {r cm}"),
        ("{o}.circle({r}, {a})", "arc left {a degrees} radius {r cm}"),
        ("{o}.pencolor({r}, {g}, {b})", "light rgb {r} {g} {b}"),
        ("{o}.pencolor({c})", "light {c!word}"),
        ("{o}.color({c}, {f})", "light {c!word}"),
        ("{o}.color({c})", "light {c!word}"),
        ("{o}.setheading({v})", "go to x position x y position y facing {v degrees}"),
        ("{o}.seth({v})", "go to x position x y position y facing {v degrees}"),
        ("{o}.goto({x}, {y})", "go to x {x cm} y {y cm}"),
        ("{o}.setpos({x}, {y})", "go to x {x cm} y {y cm}"),
        ("{o}.setposition({x}, {y})", "go to x {x cm} y {y cm}"),
        ("{o}.home()", "go to x 0 cm y 0 cm"),
    ]),
    *_habits("Python's turtle", [  # setting the turtle up, and ending
        ("{name} = {o}.Turtle()", DELETE), ("{name} = Turtle()", DELETE),
        ("{name} = {o}.Screen()", DELETE), ("{name} = Screen()", DELETE),
        ("{o}.done()", DELETE), ("{o}.mainloop()", DELETE), ("{o}.exitonclick()", DELETE),
        ("{o}.bye()", DELETE),
    ], why="E033"),
    *_habits("Python's turtle", [  # how the screen looks: a robot has nothing like it
        *((f"{{o}}.{call}({{any}})", DELETE) for call in (
            "speed", "shape", "shapesize", "hideturtle", "showturtle", "ht", "st", "bgcolor",
            "title", "setup", "tracer", "pensize", "width", "fillcolor", "begin_fill",
            "end_fill", "stamp", "clear", "screensize", "bgpic", "colormode", "update",
        )),
    ], why="E037"),
    *_habits("JavaScript", [
        *(
            (f"{word} {{name}} = {function}", f"to {{name}}{parameters}")
            for word in ("const", "let", "var")
            for function, parameters in (
                ("() =>", ""), ("({args}) =>", " {args!sp}"), ("{args} =>", " {args!sp}"),
                ("function()", ""), ("function({args})", " {args!sp}"),
            )
        ),
        ("let {name} = {v}", "set {name} to {v}"),
        ("var {name} = {v}", "set {name} to {v}"),
        ("const {name} = {v}", "set {name} to {v}"),
        ("let {name}", "set {name} to 0"),
        ("var {name}", "set {name} to 0"),
        ("{name}++", "change {name} by 1"),
        ("{name}--", "change {name} by -1"),
        ("++{name}", "change {name} by 1"),
        ("function {name}()", "to {name}"),
        ("function {name}({args})", "to {name} {args}"),
        ("console.log({args})", "print {args}"),
        ("console.{name}({args})", "print {args}"),  # console.info, console.error
        ("document.write({args})", "print {args}"),
        ("document.writeln({args})", "print {args}"),
        ("alert({v})", "say {v!q}"),
        ("await sleep({v});", "wait {v ms}"),  # a sleep of the child's own: ms, as setTimeout's
        ("} else if ({v})", "else if {v}"),
        ("} else if {v}", "else if {v}"),
        ("} else", "else"),
        ("else if ({v})", "else if {v}"),
        ("if ({v})", "if {v}"),
        ("while (true)", "forever"),
        ("while (1)", "forever"),  # C and Arduino: 1 is true
        ("for (;;)", "forever"),
        ("while ({v})", "while {v}"),
        ("for ({name} = {a}; {name} < {v}; {name}++)", "repeat {v!count}"),
        ("for ({name} = {a}; {name} <= {v}; {name}++)", "repeat {v!count_to}"),
        ("for ({name} = {a}; {name} < {v}; {name} += {s})", "repeat {v!count}"),
        ("for ({name} = {a}; {name} <= {v}; {name} += {s})", "repeat {v!count_to}"),
        # counting down: from {v} to {a}
        ("for ({name} = {v}; {name} > {a}; {name}--)", "repeat {v!count}"),
        ("for ({name} = {v}; {name} >= {a}; {name}--)", "repeat {v!count_to}"),
        ("for ({name} = {v}; {name} > {a}; {name} -= {s})", "repeat {v!count}"),
        ("for ({name} = {v}; {name} >= {a}; {name} -= {s})", "repeat {v!count_to}"),
    ]),
    *_habits("MakeCode", [  # its blocks written in JavaScript: basic.pause(100)
        ("{o}.forever({rest}", "forever"),  # basic.forever(function () {
        ("{o}.pause({v})", "wait {v ms}"),
        ("{o}.showString({v})", "say {v!q}"),
        ("{o}.showNumber({v})", "say {v}"),
        ("{o}.playTone({v}, {t})", "play {v Hz} for {t ms}"),
        ("{o}.sendString({v})", "send {v!q}"),
        ("{o}.sendNumber({v})", "send {v!q}"),
    ]),
    *_habits("Arduino", [
        ("void setup()", "when started"),
        ("void loop()", "forever"),
        ("tone({p}, {v}, {t})", "play {v Hz} for {t ms}"),
        ("noTone({p})", "stop sound"),
        ("{o}.println({args})", "print {args}"),
        ("{o}.print({args})", "print {args}"),
    ]),
    *_habits("Arduino", [("{o}.begin({rest})", DELETE)], why="E033"),  # Serial.begin(9600)
    *_habits("JavaScript", [  # the end of a block (passed to a function: `});`)
        ("}", DELETE), ("};", DELETE), ("})", DELETE), ("});", DELETE),
    ], why="E032"),
    *_habits("Logo", [("]", DELETE)], why="E032"),
    *_habits("Logo", [
        ("hideturtle", DELETE), ("showturtle", DELETE), ("ht", DELETE), ("st", DELETE),
    ], why="E033"),
    # other tools' comments: a comment in rootlang starts with #
    *_habits("JavaScript", [("/* {rest} */", "# {rest}"), ("/** {rest} */", "# {rest}")]),
    *_habits("Python", [('"""{rest}"""', "# {rest}"), ("'''{rest}'''", "# {rest}")]),
    *_habits("Logo", [("; {rest}", "# {rest}")]),
    *_habits("Logo", [
        ("forward {v}", "move {v cm}"),
        ("fd {v}", "move {v cm}"),
        ("back {v}", "move backward {v cm}"),
        ("backward {v}", "move backward {v cm}"),
        ("bk {v}", "move backward {v cm}"),
        ("right {v}", "turn right {v degrees}"),
        ("rt {v}", "turn right {v degrees}"),
        ("left {v}", "turn left {v degrees}"),
        ("lt {v}", "turn left {v degrees}"),
        ("pendown", "marker down"),
        ("pd", "marker down"),
        ("penup", "marker up"),
        ("pu", "marker up"),
        ("repeat {v} [{rest}]", "repeat {v}\n{rest!logo}"),
        ("setheading {v}", "go to x position x y position y facing {v!heading}"),
        ("seth {v}", "go to x position x y position y facing {v!heading}"),
        ("home", "go to x 0 cm y 0 cm"),
        ("setxy {x} {y}", "go to x {x cm} y {y cm}"),
        ("setpos [{x} {y}]", "go to x {x cm} y {y cm}"),
        ("setx {x}", "go to x {x cm} y position y"),
        ("sety {y}", "go to x position x y {y cm}"),
        ("setpencolor {c}", "light {c}"),
        ("setpencolour {c}", "light {c}"),
        ("setpc {c}", "light {c}"),
        ("penerase", "eraser down"),
        ("pe", "eraser down"),
        ("penpaint", "marker down"),
        ("ppt", "marker down"),
        ("clearscreen", "reset position"),
        ("cs", "reset position"),
        # Logo in the other languages rootlang reads (French, Spanish, German, Dutch Logos)
        ("avance {v}", "move {v cm}"), ("av {v}", "move {v cm}"),
        ("recule {v}", "move backward {v cm}"),
        ("tournedroite {v}", "turn right {v degrees}"), ("td {v}", "turn right {v degrees}"),
        ("tournegauche {v}", "turn left {v degrees}"), ("tg {v}", "turn left {v degrees}"),
        ("droite {v}", "turn right {v degrees}"), ("gauche {v}", "turn left {v degrees}"),
        ("lève crayon", "marker up"), ("leve crayon", "marker up"), ("lc", "marker up"),
        ("baisse crayon", "marker down"), ("bc", "marker down"),
        ("origine", "go to x 0 cm y 0 cm"),
        ("répète {v} [{rest}]", "repeat {v}\n{rest!logo}"),
        ("repete {v} [{rest}]", "repeat {v}\n{rest!logo}"),
        ("avanza {v}", "move {v cm}"), ("retrocede {v}", "move backward {v cm}"),
        ("giraderecha {v}", "turn right {v degrees}"), ("gd {v}", "turn right {v degrees}"),
        ("giraizquierda {v}", "turn left {v degrees}"), ("gi {v}", "turn left {v degrees}"),
        ("subelapiz", "marker up"), ("sl", "marker up"),
        ("bajalapiz", "marker down"), ("bl", "marker down"),
        ("vorwärts {v}", "move {v cm}"), ("vw {v}", "move {v cm}"),
        ("rückwärts {v}", "move backward {v cm}"), ("rw {v}", "move backward {v cm}"),
        ("stifthoch", "marker up"), ("stiftab", "marker down"),
        ("vooruit {v}", "move {v cm}"), ("achteruit {v}", "move backward {v cm}"),
        ("penop", "marker up"), ("penneer", "marker down"),
        ("make \"{name} {v}", "set {name} to {v}"),
        ("to {name} :{args}", "to {name} {args!logo_names}"),
        ("ifelse {c} [{rest}] [{more}]", "if {c}\n{rest!logo}\nelse\n{more!logo}"),
        ("if {c} [{rest}] [{more}]", "if {c}\n{rest!logo}\nelse\n{more!logo}"),
        ("if {c} [{rest}]", "if {c}\n{rest!logo}"),
        ("while [{c}] [{rest}]", "while {c}\n{rest!logo}"),
        ("until [{c}] [{rest}]", "repeat until {c}\n{rest!logo}"),
        ("forever [{rest}]", "forever\n{rest!logo}"),
        ("output {v}", "return {v}"),
        ("op {v}", "return {v}"),
        ("label {v}", "say {v!q}"),
        ("print [{v}]", "print {v!q}"),
        ("show [{v}]", "print {v!q}"),
        ("show {v}", "print {v}"),
    ]),
    *_habits("iRobot's Python SDK", [
        ("move({v})", "move {v cm}"),
        ("turn_left({v})", "turn left {v degrees}"),
        ("turn_right({v})", "turn right {v degrees}"),
        ("arc_left({v}, {r})", "arc left {v degrees} radius {r cm}"),
        ("arc_right({v}, {r})", "arc right {v degrees} radius {r cm}"),
        ("set_lights_rgb({r}, {g}, {b})", "light rgb {r} {g} {b}"),
        ("set_lights_on_rgb({r}, {g}, {b})", "light rgb {r} {g} {b}"),
        ("set_lights_blink_rgb({r}, {g}, {b})", "light blink rgb {r} {g} {b}"),
        ("set_lights_spin_rgb({r}, {g}, {b})", "light spin rgb {r} {g} {b}"),
        ("set_lights_off()", "light off"),
        ("set_lights({p}on, {c})", "light {c}"),
        ("set_lights({p}blink, {c})", "light blink {c}"),
        ("set_lights({p}spin, {c})", "light spin {c}"),
        ("set_lights({p}off{more})", "light off"),
        ("set_wheel_speeds({l}, {r})", "set wheels left {l cm/s} right {r cm/s}"),
        ("set_left_speed({v})", "set left wheel {v cm/s}"),
        ("set_right_speed({v})", "set right wheel {v cm/s}"),
        ("navigate_to({x}, {y}, {h})", "go to x {x cm} y {y cm} facing {h degrees}"),
        ("navigate_to({x}, {y})", "go to x {x cm} y {y cm}"),
        ("set_marker_down()", "marker down"),
        ("set_marker_up()", "marker up"),
        ("set_eraser_down()", "eraser down"),
        ("set_eraser_up()", "eraser up"),
        ("set_marker_and_eraser_up()", "marker up"),
        ("set_marker(erase)", "eraser down"),
        ("set_marker(marker.down)", "marker down"),
        ("set_marker(marker.up)", "marker up"),
        ("set_marker({rest}down{more})", "marker down"),
        ("set_marker({rest}up{more})", "marker up"),
        ("set_marker({rest}down)", "marker down"),
        ("set_marker({rest}up)", "marker up"),
        ("set_marker({rest}erase)", "eraser down"),
        ("set_gravity_compensation({p}on, {v})", "set gravity compensation on {v %}"),
        ("play_note({v}, {t})", "play {v!pitch} for {t seconds}"),
        ("play_tone({v}, {t})", "play {v!pitch} for {t seconds}"),
        ("wait({v})", "wait {v seconds}"),
        ("stop()", "stop moving"),
        ("stop_sound()", "stop sound"),
        ("arc({p}left, {v}, {r})", "arc left {v degrees} radius {r cm}"),
        ("arc({p}right, {v}, {r})", "arc right {v degrees} radius {r cm}"),
        ("turn({p}left, {v})", "turn left {v degrees}"),
        ("turn({p}right, {v})", "turn right {v degrees}"),
        ("reset_navigation()", "reset position"),
        ("dock()", "dock"),
        ("undock()", "undock"),
        ("say({v})", "say {v}"),
        ("@event(robot.when_play)", "when started"),
        ("@event(robot.when_bumped, [true, false])", "when bumper left pressed"),
        ("@event(robot.when_bumped, [false, true])", "when bumper right pressed"),
        ("@event(robot.when_bumped{rest})", "when bumped"),
        ("@event(robot.when_touched, [true, false, false, false])",
         "when touch front left pressed"),
        ("@event(robot.when_touched, [false, true, false, false])",
         "when touch front right pressed"),
        ("@event(robot.when_touched, [false, false, true, false])",
         "when touch back left pressed"),
        ("@event(robot.when_touched, [false, false, false, true])",
         "when touch back right pressed"),
        ("@event(robot.when_touched{rest})", "when touched"),
        ("@event(robot.when_cliff_sensor{rest})", "when cliff detected"),
        ("@event(robot.when_stop{rest})", "when stopped"),
        # the SDK's script: under its @event line, or on its own (then it is `when started`)
        ("async def {name}({args}):", "when started"),
        ("async def {name}({args}):", DELETE),
        ("robot = {rest}", DELETE),
        ("robot.play()", DELETE),
        ("hand_over()", DELETE),
    ]),
    *_habits("other languages", [
        ("end {rest}", DELETE),
        ("endif", DELETE),
        ("endwhile", DELETE),
        ("done", DELETE),
        ("next", DELETE),
    ], why="E032"),
    *_habits("other languages", [
        ("repeat times {v}", "repeat {v}"),
        ("repeat {count} times", "repeat {count}"),  # (once its times sign is a word: 4x)
        ("{count} times repeat", "repeat {count}"),  # the words the other way round
        ("repeat {v} time", "repeat {v}"),
        ("{v} times", "repeat {v}"),
        ("do {v} times", "repeat {v}"),
        ("loop {v} times", "repeat {v}"),
        ("repeat {v} times do", "repeat {v}"),
        ("loop forever", "forever"),
        ("forever do", "forever"),
        ("do forever", "forever"),
        ("loop", "forever"),
        ("set {name} as {v}", "set {name} to {v}"),
        ("set {name} equal to {v}", "set {name} to {v}"),
        ("set {name} := {v}", "set {name} to {v}"),
        ("set {name} = {v}", "set {name} to {v}"),
        ("make {name} = {v}", "set {name} to {v}"),
        ("make {name} {v}", "set {name} to {v}"),
        ("let {name} be {v}", "set {name} to {v}"),
        ("change {name} to {v}", "set {name} to {v}"),
        ("set {name} by {v}", "change {name} by {v}"),
        ("increase {name} by {v}", "change {name} by {v}"),
        ("decrease {name} by {v}", "change {name} by {v!neg}"),
        ("add {v} to {name}", "change {name} by {v}"),
        ("subtract {v} from {name}", "change {name} by {v!neg}"),
        ("turn {v} degrees right", "turn right {v} degrees"),
        ("turn {v} degrees left", "turn left {v} degrees"),
        ("turn {v} right", "turn right {v degrees}"),
        ("turn {v} left", "turn left {v degrees}"),
        ("move {v} forward", "move forward {v cm}"),
        ("move {v} forwards", "move forward {v cm}"),
        ("move {v} backward", "move backward {v cm}"),
        ("move {v} backwards", "move backward {v cm}"),
        ("move {v} back", "move backward {v cm}"),
        ("go right {v}", "turn right {v degrees}"),
        ("go left {v}", "turn left {v degrees}"),
        ("spin around", "turn right 360 degrees"),
        ("spin right {v}", "turn right {v degrees}"),
        ("spin left {v}", "turn left {v degrees}"),
        ("spin {v}", "turn right {v degrees}"),
        ("spin", "turn right 360 degrees"),
        ("stop", "stop moving"),
        ("loop {v}", "repeat {v}"),
        ("pause {v}", "wait {v seconds}"),
        ("move back {v}", "move backward {v cm}"),
        ("{name} := {v}", "set {name} to {v}"),
        ("when play", "when started"),
        ("when run", "when started"),
        ("when flag", "when started"),
        ("until {v}", "repeat until {v}"),
        ("loop until {v}", "repeat until {v}"),
        ("repeat while {v}", "while {v}"),
        ("walk {v}", "move {v cm}"),
        ("go {v}", "move {v cm}"),
        ("step {v}", "move {v cm}"),
        ("when clicked", "when touched"),
        ("when tapped", "when touched"),
        ("sleep {v}", "wait {v seconds}"),
        # a bare number after pause/delay is milliseconds (MakeCode's pause, Arduino's delay)
        ("pause({v})", "wait {v ms}"), ("pause {v}", "wait {v ms}"),
        ("delay({v})", "wait {v ms}"), ("delay {v}", "wait {v ms}"),
        ("when program starts", "when started"),
        ("when the program starts", "when started"),
        ("when program begins", "when started"),
        ("when start", "when started"),
        ("when starts", "when started"),
        ("turn around", "turn right 180 degrees"),
        ("go forward {v}", "move {v cm}"),
        ("go back {v}", "move backward {v cm}"),
        ("go backward {v}", "move backward {v cm}"),
    ]),
    *_habits("other languages", [  # two commands said as one sentence
        ("{a} and then {b}", "{a!line}\n{b!line}"),
        ("{a} then {b}", "{a!line}\n{b!line}"),
        ("{a} and {b}", "{a!line}\n{b!line}"),
    ]),
    # the most general shapes last: a line is tried with every habit it fits, in this order
    *_habits("Python", GENERAL),
)

# fmt: on
WRITTEN_HABITS = HABITS  # as written here, before rootlang's own words are taken out
HABITS = of_other_tools(WRITTEN_HABITS)

# Habits a line is tried with last, its other habits tidied away first (`say (join [a] (b))
# for 1 seconds` is Scratch's say-for, before it is a command for a time).
LAST: tuple[Habit, ...] = tuple(_habits("other languages", [
    (f"{{a}} for {{t}} {unit}", "{a!line}\nwait {t} seconds")  # light red for 2 seconds
    for unit in ("seconds", "second", "secs", "sec")
]))  # fmt: skip

# Lines rootlang reads as they are, written the way another tool says them, where rootlang has
# a word of its own: a warning shows that word (W106); the line still runs as written.
ACCEPTED: tuple[Habit, ...] = (
    *_habits("Python", [("while true", "forever"), ("while true:", "forever")]),
    *_habits("JavaScript", [("while (true)", "forever"), ("while (true):", "forever")]),
    *_habits(
        "other languages", [("set light to {c}", "light {c}"), ("set lights to {c}", "light {c}")]
    ),
)


def accepted_habits(lines: Sequence[str], english: Sequence[str] | None = None) -> list[Diagnostic]:
    """W106 for each line rootlang reads that is another tool's way of saying one of its own
    words (`while True:` is `forever`). ``english``: the lines with their keywords in English,
    for a program in another language (the caret then spans the child's whole line)."""
    found = []
    for number, line in enumerate(english or lines, start=1):
        code = _COMMENT.sub("", line.strip()).strip()
        fits = ((h, _compiled(h.written).fullmatch(code)) for h in ACCEPTED)
        habit, match = next(((h, m) for h, m in fits if m), (None, None))
        if habit is None or match is None:
            continue
        answers = _answers(habit.rootlang, {k: v.strip() for k, v in match.groupdict().items()})
        if not answers:
            continue
        column, end = _caret(line, answers[0])
        if english:
            line = lines[number - 1]
            column, end = len(line) - len(line.lstrip()) + 1, len(line.rstrip()) + 1
        span = Span(number, column, number, end)
        found.append(diagnostic("W106", span, severity="warning", source=Described(habit.source),
                                written=unquoted(line[column - 1 : end - 1]),
                                write=write_line(answers[0])))  # fmt: skip
    return found


C_TYPES = r"int|long|short|unsigned(?:\s+int)?|byte|float|double|bool|boolean|char|String|auto"
# A Scratch slot as join's value: a box [text] (text, in quotes) or a round one (a value).
_SLOT_BOX = r"\[[^\[\]]*\]|\([^()]*\)"


def _scratch_join(found: re.Match[str]) -> str:
    """Scratch's join [x is ] (x): join("x is ", x), the text's spaces kept."""
    values = [
        f'"{slot[1:-1]}"' if slot.startswith("[") else slot[1:-1].strip()
        for slot in (found.group(1), found.group(2))
    ]
    return f"join({', '.join(values)})"


_SCRATCH_JOIN = re.compile(rf"\bjoin\s*({_SLOT_BOX})\s*({_SLOT_BOX})", re.IGNORECASE)
_ATOM = r"-?[0-9.]+|[A-Za-z_]\w*"
NUMBER_WORDS = {
    word: value
    for value, word in enumerate(
        re.split(
            " ",
            "zero one two three four five six seven eight nine ten eleven twelve thirteen "
            "fourteen fifteen sixteen seventeen eighteen nineteen twenty",
        )
    )
} | {"thirty": 30, "forty": 40, "fifty": 50, "sixty": 60, "seventy": 70, "eighty": 80,
     "ninety": 90, "hundred": 100}  # fmt: skip
_NUMBER_WORD = "|".join(sorted(NUMBER_WORDS, key=len, reverse=True))


def _number_words(found: re.Match[str]) -> str:
    """`ninety` as 90, `forty five` as 45, `a hundred` as 100, `three hundred and ten` as 310;
    words that don't make one number that way (`one eighty`) stay as they are."""
    words = [word for word in re.split(r"[\s-]+", found.group().lower()) if word != "and"]
    hundreds = 0
    if "hundred" in words:
        at = words.index("hundred")
        before = words[:at]
        if len(before) > 1 or (
            before and before[0] != "a" and not 0 < NUMBER_WORDS[before[0]] < 10
        ):
            return found.group()
        hundreds = 100 * (NUMBER_WORDS[before[0]] if before and before[0] != "a" else 1)
        words = words[at + 1 :]
    values = [NUMBER_WORDS.get(word, -1) for word in words]
    if not values:
        return str(hundreds)
    if len(values) == 1 and values[0] >= 0:
        return str(hundreds + values[0])
    if len(values) == 2 and values[0] % 10 == 0 and values[0] >= 20 and 0 < values[1] < 10:
        return str(hundreds + values[0] + values[1])  # forty five
    return found.group()


_IN_SECONDS = {"minutes": 60, "minute": 60, "mins": 60, "min": 60, "hours": 3600, "hour": 3600}


def _in_seconds(found: re.Match[str]) -> str:
    """`2 minutes` as `120 seconds` (a number that isn't one: as it is)."""
    number = _number(found.group(1))
    if number is None:
        return found.group()
    return f"{number * _IN_SECONDS[found.group(2).lower()]:g} seconds"


# Parts of a line written another way: (where from, pattern, replacement), applied in turn to
# the line outside its text in quotes. Python's f-strings come first (their text is the code).
TIDY: tuple[tuple[str, str, str | Callable[[re.Match[str]], str]], ...] = (
    # a C type before a name being declared (Arduino's `int speed = 10;`, `for (int i = 0; …`)
    ("Arduino", rf"^(?:{C_TYPES})\s+(?=[A-Za-z_]\w*\s*(?:=|;|$))", ""),
    ("Arduino", rf"\bfor\s*\(\s*(?:{C_TYPES})\s+", "for ("),
    ("JavaScript", r"\s*;\s*$", ""),
    ("other languages", r"(?<=[\w\")])[.!]+$", ""),  # a sentence's full stop (or !)
    ("JavaScript", r"\s*\{\s*$", ""),
    ("JavaScript", r"^\s*\}\s*", ""),
    ("iRobot's Python SDK", r"^await\s+", ""),
    ("iRobot's Python SDK", r"^(?:robot|bot|root|create)\.", ""),
    ("iRobot's Python SDK", r"(?<=\w\()\s*[A-Za-z_]\w*\s*=(?!=)\s*", ""),  # move(distance=10)
    ("iRobot's Python SDK", r"(?<=,)\s*[A-Za-z_]\w*\s*=(?!=)\s*", " "),
    ("iRobot's Python SDK", r"\bColor\(\s*(\w+)\s*,\s*(\w+)\s*,\s*(\w+)\s*\)", r"rgb \1 \2 \3"),
    ("iRobot's Python SDK", r"\bNote\.([A-G])([0-9])_SHARP\b", r"\1#\2"),
    ("iRobot's Python SDK", r"\bNote\.([A-G])([0-9])_FLAT\b", r"\1b\2"),
    ("iRobot's Python SDK", r"\bNote\.([A-G][0-9])\b", r"\1"),
    ("iRobot's Python SDK", r"\bNote\.WHOLE\b", "1"),
    ("iRobot's Python SDK", r"\bNote\.HALF\b", "0.5"),
    ("iRobot's Python SDK", r"\bNote\.QUARTER\b", "0.25"),
    ("iRobot's Python SDK", r"\bNote\.EIGHTH\b", "0.125"),
    ("iRobot's Python SDK", r"\bNote\.SIXTEENTH\b", "0.0625"),
    ("Python", r"\b(?:asyncio|time)\.sleep\(", "sleep("),
    ("JavaScript", r"\bfor\s*\(\s*(?:let|var|const)\s+", "for ("),
    # a counting loop's step written another way: i += 1, ++i, i = i + 1 are all i++
    (
        "JavaScript",
        r";\s*(?:(\w+)\s*\+=\s*1|\+\+\s*(\w+)|(\w+)\s*=\s*\3\s*\+\s*1)\s*\)",
        r"; \1\2\3++)",
    ),
    (
        "JavaScript",
        r";\s*(?:(\w+)\s*-=\s*1|--\s*(\w+)|(\w+)\s*=\s*\3\s*-\s*1)\s*\)",
        r"; \1\2\3--)",
    ),
    ("JavaScript", r"\s*===\s*", " = "),
    ("JavaScript", r"\s*!==\s*", " != "),
    ("JavaScript", r"\s*&&\s*", " and "),
    ("JavaScript", r"\s*\|\|\s*", " or "),
    ("JavaScript", r"!(?=[\w(])", "not "),
    ("JavaScript", r"\b(?:Math|math)\.(round|abs|min|max|sqrt|sin|cos)\b", r"\1"),
    ("Python", r"\brandom\.randint\(\s*([^,()]+?)\s*,\s*([^,()]+?)\s*\)", r"random \1 to \2"),
    ("Python", r"\b(?:str|float)\(([^()]*)\)", r"\1"),
    ("Python", r"\s*%\s*(?=[\w(])", " mod "),
    ("Python", r"\s*:\s*$", ""),
    ("Python", r"(?<![\w\"])(True|False|None)(?![\w\"])", r"\1"),
    ("JavaScript", r"\s*//\s*", "  # "),
    ("Scratch", r"\b([0-9.]+\)?)\s*(?:secs|sec)\b", r"\1 seconds"),
    ("Scratch", r"\b([0-9.]+\)?)\s*steps?\b", r"\1 cm"),
    (
        "Scratch",
        r"^((?:if|else if|while|repeat until|wait until|until)\s+)<\s*(.*?)\s*>"
        r"(\s*(?:then)?)$",
        r"\1\2\3",
    ),  # a condition in Scratch's <...>
    ("Scratch", r"<(?=[A-Za-z])([^<>]*[^\s<>])>", r"\1"),
    ("Scratch", r"\s+[v▾](?=\s*[\])])", ""),  # a drop-down's arrow: [score v], (Meow v)
    ("Scratch", r"\[(abs|sqrt|sin|cos|round)\]\s+of\s+", r"\1 "),
    ("Scratch", r"\[(?!\s*[A-Za-z]+\s+-?[0-9:])\s*([^\[\]]*?)\s*\]", r"\1"),  # a box: [go]
    ("Scratch", r"\bpick random\b", "random"),
    # Scratch's reporters of where the sprite is: (x position), (direction)
    ("Scratch", r"\(\s*([xy])\s+position\s*\)|(?<![\w.])([xy])\s+position\b", r"position \1\2"),
    ("Scratch", r"\(\s*direction\s*\)", "heading"),
    ("Scratch", r"\?(?=\s*(?:then)?\s*$)", ""),  # a question's sign: touching edge?
    ("Scratch", r"\b(abs|sqrt|round|sin|cos)\s+of\s+", r"\1 "),  # [abs] of (x)
    ("Scratch", r"\btouching (?:edge|wall)\??", "bumper any pressed"),
    ("Scratch", r"^((?:if|else if|while)\b.*\S)\s+then$", r"\1"),
    ("other languages", r"^((?:if|else if|while|repeat)\b.*\S)\s+do$", r"\1"),
    ("other languages", r"\s+(?:is\s+)?equals?(?:\s+to)?\s+", " = "),
    ("other languages", r"\s+(?:is\s+)?(?:bigger|greater|more|larger|higher)\s+than\s+", " > "),
    ("other languages", r"\s+(?:is\s+)?(?:smaller|less|fewer|lower)\s+than\s+", " < "),
    ("other languages", r"\s+is\s+not\s+", " != "),
    # a count with a times sign at the end of a line: repeat 4x, move 10 cm 3x, repeat x4
    ("other languages", r"(?<![\w.])(?:([0-9]+)\s*[x×]|(?:x|×\s*)([0-9]+))\s*$", r" \1\2 times"),
    # arithmetic said in words: x plus 1, x times 2 (`4 times` at the end is a loop's)
    ("other languages", r"\s+plus\s+(?=[\w(\"-])", " + "),
    ("other languages", r"\s+minus\s+(?=[\w(\"-])", " - "),
    ("other languages", r"\s+(?:times|multiplied\s+by)\s+(?=[\w(-])", " * "),
    ("other languages", r"\s+divided\s+by\s+(?=[\w(-])", " / "),
    (
        "other languages",
        rf"\b(?:{_NUMBER_WORD}|a(?=\s+hundred\b))(?:[\s-]+(?:and\s+)?(?:{_NUMBER_WORD}))*\b",
        _number_words,
    ),  # turn right ninety degrees, repeat four times
    # a time in a unit rootlang has not: in seconds (1 minute is 60 seconds)
    ("other languages", rf"(?<![\w.])(-?[0-9.]+)\s*({'|'.join(_IN_SECONDS)})\b", _in_seconds),
    ("other languages", r"\s+is\s+", " = "),
    ("other languages", r"^(?:on|whenever)\s+(?=\w)", "when "),
    ("Logo", r"(?<=\s):([A-Za-z]\w*)", r"\1"),
    *(  # Logo's arithmetic before its values: sum :x 1 is x + 1
        ("Logo", rf"\b{word}\s+({_ATOM})\s+({_ATOM})(?=\s|\]|$)", rf"(\1 {sign} \2)")
        for word, sign in (
            ("sum", "+"),
            ("difference", "-"),
            ("product", "*"),
            ("quotient", "/"),
            ("remainder", "mod"),
            ("modulo", "mod"),
        )
    ),
    ("Logo", r'^((?:print|show|type|label)\s+)"([A-Za-z_]\w*)$', r'\1"\2"'),  # print "hi
    ("Logo", r'^((?:setpc|setpencolou?r)\s+)"([A-Za-z_]\w*)$', r"\1\2"),  # setpc "red
)

# Words children use for a command, their own or another tool's: the line is read again with
# rootlang's words in their place, and then as any line (its habits, its units, tried in place).
SYNONYMS: tuple[tuple[str, str], ...] = (
    ("zoom|roll|travel|run|advance|ride|dash|race|scoot|hop|jump|walk|step|head", "move"),
    ("rotate|spin|twist|pivot|swivel|steer", "turn"),
    ("pause|sleep|delay|rest|hold|stay|wait for", "wait"),
    ("glow|shine|lights|led|leds|lamp|light up|colou?r|set light|set lights|set colou?r", "light"),
    ("sing|sound|tone|hum|toot|beep", "play"),
    ("speak|talk|tell|shout|yell|announce|think", "say"),
    ("show|display|log|echo|output|write|puts", "print"),
    ("draw|draw on|pen on|start drawing|pen down|pendown|marker on", "marker down"),
    ("draw off|pen off|stop drawing|pen up|penup|marker off", "marker up"),
    ("exit|quit|halt|end program|stop program|stop everything|terminate", "stop all"),
    ("brake|freeze|stand still", "stop moving"),
    ("always|keep going|again and again|repeat forever", "forever"),
)
WRITTEN_SYNONYMS = SYNONYMS  # as written here, before rootlang's own words are taken out
SYNONYMS = synonyms_of_other_tools(WRITTEN_SYNONYMS)
_SYNONYM = [  # (the longest words first: `draw on` before `draw`)
    (
        re.compile(
            rf"(?:{'|'.join(sorted(words.split('|'), key=len, reverse=True))})(?=\s|$)", re.I
        ),
        ours,
    )
    for words, ours in SYNONYMS
]
_CALL = re.compile(r"(?:[A-Za-z_]\w*\.)*([A-Za-z_]\w*)\(\s*([^()]*?)\s*\)")
# a command word with an ending (moves, turning, waited): the word itself
_ENDING = re.compile(r"([a-z]+?)(?:e?s|ing|ed)(?=\s|$)", re.IGNORECASE)

# Python's f-string: f"x is {x}" is join("x is ", x).
_F_STRING = re.compile(r'\bf"([^"]*)"')

_SLOT = re.compile(r"\{(\w+)\}")
_NUMBER = re.compile(r"-?[0-9]+(?:\.[0-9]+)?")
_QUOTED = re.compile(r'"[^"]*"|“[^”]*”')
_SINGLE_QUOTED = re.compile(r"'([^'\"]*)'")
_ANSWER_SLOT = re.compile(r"\{(\w+)(?: ([^}!]+))?(?:!(\w+))?\}")
_WORD = re.compile(r"[^\s\w]+|\w+")
_TOKEN = re.compile(r"[^\s\w]|\w+")
_PUNCTUATION_OR_WORD = re.compile(r"===|!==|[-+*/%=<>!:]=|\+\+|--|&&|\|\||//|[^\s\w]|\w+")
_LOGO_COMMAND = re.compile(r"([A-Za-z]+)((?:\s+(?:-?[0-9.]+|:[A-Za-z_]\w*))*)")
_COMMENT = re.compile(r'\s+#(?!(?:[0-9a-f]{6})\b)[^"]*$', re.IGNORECASE)


@dataclass(frozen=True)
class Meaning:
    """What a line means in rootlang, found from a habit: the line(s) to write, the tool the
    habit comes from, the message, and the part of the line the caret goes under (columns
    from 1 on the line as written, end exclusive)."""

    rewrite: str
    source: str
    why: str
    column: int
    end_column: int
    written: str
    line: str = ""  # the line as the child wrote it
    tidied: str | None = None  # the line with only its small habits tidied away
    tidied_at: tuple[int, int, str] | None = None  # where that changes the line first, and what


@functools.cache
def _compiled(written: str) -> re.Pattern[str]:
    """A habit's pattern: its words case-insensitive, spaces optional around punctuation."""
    parts: list[str] = []
    seen: set[str] = set()
    position = 0
    for slot in _SLOT.finditer(written):
        parts.append(_literal(written[position : slot.start()]))
        name = slot.group(1)
        if name in seen:
            parts.append(rf"(?P={name})")
        elif name == "name":
            parts.append(rf"(?P<{name}>[A-Za-z_]\w*)")
        elif name == "count":
            parts.append(rf"(?P<{name}>[0-9]+)")
        elif name == "o":  # what a method is called on: `t`, `turtle`, `basic`, `Serial`
            parts.append(rf"(?P<{name}>[A-Za-z_]\w*(?:\.[A-Za-z_]\w*)*)")
        elif name == "any":  # anything, or nothing: `t.hideturtle()`, `t.speed(0)`
            parts.append(rf"(?P<{name}>.*?)")
        else:
            parts.append(rf"(?P<{name}>(?![=<>])..*?)")  # a value: not the rest of a `<=`
        seen.add(name)
        position = slot.end()
    parts.append(_literal(written[position:]))
    return re.compile(r"\s*" + "".join(parts) + r"\s*", re.IGNORECASE)


def _literal(text: str) -> str:
    """Fixed words of a pattern: spaces, `_` or nothing between two words, spaces optional
    around punctuation."""
    words = _TOKEN.findall(text)
    if not words:
        return r"\s+" if text else ""
    pattern = ""
    if text[0].isspace():
        pattern = r"\s+" if words[0][0].isalnum() else r"\s*"
    for index, word in enumerate(words):
        if index:  # two words: also run together or joined by `_` (`pen_down`, `penDown`)
            together = word[0].isalnum() and words[index - 1][-1].isalnum()
            pattern += r"[\s_]*" if together else r"\s*"
        pattern += re.escape(word)
    if text[-1].isspace():
        pattern += r"\s+" if words[-1][-1].isalnum() else r"\s*"
    elif not words[-1][-1].isalnum():
        pattern += r"\s*"
    return pattern


def meanings(line: str) -> list[Meaning]:
    """What a line written with habits may mean, the likeliest first: each habit of the whole
    line, then each habit of the line with its small habits tidied away, then the line tidied
    (and several Logo commands on one line)."""
    code = _COMMENT.sub("", line.strip()).strip()
    if not code:
        return []
    tidied, sources = _tidied(code)
    found = list(_wholes(code))
    if tidied != code:
        unboxed = _ROUND_BOX.sub(r"\1", tidied)  # Scratch's (0) is 0
        general = {written for written, _ in GENERAL}
        found += [
            (replace(habit, source=sources[0]) if habit.written in general else habit, values)
            for habit, values in _wholes(tidied)
        ]
        found.append((Habit(sources[0], code, unboxed), {}))
        found.append((Habit(sources[0], code, tidied), {}))
    logo = _logo_sequence(code)
    if logo is not None:
        found.append(logo)
    for renamed in _renamed(tidied):
        found += [*_wholes(renamed), (Habit("other languages", code, renamed), {})]
    call = _CALL.fullmatch(tidied)
    if call:  # Python's turtle: t.forward(50) is Logo's forward 50
        turtle = f"{call.group(1)} {call.group(2).replace(',', ' ')}".strip()
        found += [
            (replace(habit, source="Python's turtle"), values) for habit, values in _wholes(turtle)
        ]
        for renamed in _renamed(turtle):  # a word children use, called: exit(), beep()
            found += [*_wholes(renamed), (Habit("Python", code, renamed), {})]
    found += _wholes(tidied, LAST)
    offset = line.index(code)
    minimal = _changed(code, tidied, offset) if tidied != code and tidied else None
    result: list[Meaning] = []
    for habit, values in found:
        for rewrite in _answers(habit.rootlang, values):
            if any(known.rewrite == rewrite for known in result):
                continue
            if rewrite.split() == code.split():  # the line as written: no habit on it
                continue
            column, end = _caret_of(habit, code, offset) or _caret(line, rewrite)
            written = line[column - 1 : end - 1]
            result.append(Meaning(rewrite, habit.source, habit.why, column, end, written,
                                  line, tidied, minimal))  # fmt: skip
            if len(result) == MOST_MEANINGS:
                break
        if len(result) == MOST_MEANINGS:
            break
    return result + _in_a_script(result) if offset == 0 else result


def _in_a_script(found: Sequence[Meaning]) -> list[Meaning]:
    """A line at the left edge whose meaning is a command or a block (Arduino's `void loop()
    {`: `forever`): each such meaning in a script of its own, which is what the other tool
    means by a line there (`when started`, and the lines indented under it)."""
    return [
        replace(item, rewrite=IN_A_SCRIPT + "".join(f"\n    {part}" for part in parts))
        for item in found
        if (parts := item.rewrite.split("\n")) != [""] and not _opens_script_line(parts[0])
    ]


IN_A_SCRIPT = "when started"  # the script a line at the left edge goes in


MOST_MEANINGS = 8  # meanings of one line to try in place, the likeliest first


def meaning(line: str) -> Meaning | None:
    """The likeliest rootlang line a line written with a habit means, or None."""
    found = meanings(line)
    return found[0] if found else None


def _caret_of(habit: Habit, code: str, offset: int) -> tuple[int, int] | None:
    """Where a habit whose caret starts on one of its slots puts it on the line (``code`` is
    ``offset`` characters into it), when the line as written fits the habit."""
    match = _compiled(habit.written).fullmatch(code) if habit.caret else None
    if match is None:
        return None
    return offset + match.start(habit.caret) + 1, offset + len(code.rstrip()) + 1


def _wholes(code: str, table: Sequence[Habit] = HABITS) -> Iterator[tuple[Habit, dict[str, str]]]:
    """Every habit the whole line fits, in the table's order, with the child's values."""
    for habit in table:
        match = _compiled(habit.written).fullmatch(code)
        if match:
            yield habit, {name: value.strip() for name, value in match.groupdict().items()}


def _tidied(code: str) -> tuple[str, list[str]]:
    """The line with its small habits tidied away (TIDY), and the tools they come from. Text
    in quotes is left as it is; Python's f-strings become `join(...)` first."""
    sources: list[str] = []
    joined = _F_STRING.sub(_joined, code)
    if joined != code:
        sources.append("Python")
    scratch = _SCRATCH_JOIN.sub(_scratch_join, joined)  # its text is the child's, as written
    if scratch != joined:
        sources.append("Scratch")
        joined = scratch
    texts: list[str] = []

    def hide(found: re.Match[str]) -> str:
        texts.append(found.group())
        return f"\ue000{len(texts) - 1}\ue001"

    code = _QUOTED.sub(hide, joined)
    unboxed = _scratch_conditions(code)
    if unboxed != code:
        sources.append("Scratch")
        code = unboxed
    for source, pattern, replacement in TIDY:
        tidied = re.sub(pattern, replacement, code, flags=re.IGNORECASE)
        if tidied != code:
            sources.append(source)
            code = tidied
    code = re.sub("\ue000([0-9]+)\ue001", lambda found: texts[int(found.group(1))], code)
    return code.strip(), sources


def _scratch_conditions(code: str) -> str:
    """The line without Scratch's hexagonal slots, `<` and `>` around a condition (`if <(x) >
    (3)> then`, `<<a> and <b>>`): a `<` that opens one has no space after it, a `>` that
    closes one none before it, and only the pairs are taken away (`x < 3` stays)."""
    opened: list[int] = []
    dropped: list[int] = []
    for index, sign in enumerate(code):
        before = code[index - 1] if index else " "
        after = code[index + 1] if index + 1 < len(code) else " "
        if sign == "<" and before in " <([" and (after.isalpha() or after in "(<["):
            opened.append(index)
        elif sign == ">" and opened and (before.isalnum() or before in ")>]?") and after in " >)]":
            dropped += [opened.pop(), index]
    return "".join(sign for index, sign in enumerate(code) if index not in dropped)


def _renamed(code: str) -> list[str]:
    """The line with a word a child uses for a command (:data:`SYNONYMS`), or a command word
    with an ending (``moves``, ``turning``), replaced by rootlang's words."""
    found = []
    for pattern, ours in _SYNONYM:
        match = pattern.match(code)
        if match:
            found.append(ours + code[match.end() :])
    ending = _ENDING.match(code)
    if ending and code.split(maxsplit=1)[0].lower() not in STATEMENT_WORDS:
        stem = ending.group(1).lower()
        for word in (stem, stem + "e", stem[:-1]):  # turns, moving -> mov+e, stopped -> stopp
            if word in STATEMENT_WORDS:
                found.append(word + code[ending.end() :])
                break
    return found


def _joined(found: re.Match[str]) -> str:
    """f"x is {x}" as join("x is ", x)."""
    parts = [part for part in re.split(r"(\{[^{}]*\})", found.group(1)) if part]
    values = [part[1:-1].strip() if part.startswith("{") else f'"{part}"' for part in parts]
    if len(values) == 1:
        return values[0]
    return f"join({', '.join(values)})" if values else '""'


def _changed(line: str, tidied: str, offset: int) -> tuple[int, int, str] | None:
    """The first part of the line its tidied form changes (columns from 1 on the line
    ``offset`` characters further right, end exclusive), or None when the change is only an
    addition at the end (the caret then stays where it is)."""
    same = 0
    while same < min(len(line), len(tidied)) and line[same] == tidied[same]:
        same += 1
    while same < len(line) and line[same].isspace():
        same += 1
    if same >= len(line.rstrip()):
        return None
    tokens = [token for token in _PUNCTUATION_OR_WORD.finditer(line) if token.end() > same]
    first = tokens[0]
    return offset + first.start() + 1, offset + first.end() + 1, first.group()


def _answers(template: str, values: dict[str, str]) -> list[str]:
    """The rootlang line(s) with the child's values in their slots, each way a value may be
    written there (`say Hello` is `say "Hello"`, `say x` may be `say x`); none when a value
    can't be written that way (`{v!note}` of a word)."""
    answers = [""]
    position = 0
    for slot in _ANSWER_SLOT.finditer(template):
        name, unit, how = slot.group(1), slot.group(2), slot.group(3)
        value = _SINGLE_QUOTED.sub(r'"\1"', values.get(name, ""))  # Python's 'text'
        ways = _written(value, unit, how, values)
        fixed = template[position : slot.start()]
        answers = [answer + fixed + way for answer in answers for way in ways]
        position = slot.end()
    return [answer + template[position:] for answer in answers]


def _number(value: str) -> float | None:
    return float(value) if _NUMBER.fullmatch(value) else None


def _written(value: str, unit: str | None, how: str | None, values: dict[str, str]) -> list[str]:
    """The ways a value may be written in its slot of the answer, the likeliest first."""
    boxed = _BOX.fullmatch(value)  # Scratch's boxes: (10), [go]
    if boxed and boxed.group(1) is not None and how == "q" and re.search(r"\w\s+\w", value):
        return []  # a round slot holds a value, not text: (y position)
    if boxed:
        value = (boxed.group(1) if boxed.group(1) is not None else boxed.group(2)).strip()
        value = re.sub(r"\s+[v▾]$", "", value)  # a drop-down's arrow: [score v]
    if how != "logo":
        value = _LOGO_NAME.sub(r"\1", value)  # Logo's :size is the value of size
    if unit:
        if _NUMBER.fullmatch(value):
            return [f"{value} {unit}"]
        if re.fullmatch(r"[A-Za-z_]\w*", value):  # a name holding a plain number, or a length
            return [f"{value} {unit}", value]
        return [value]
    if how == "q":
        if _QUOTED.fullmatch(value) or _NUMBER.fullmatch(value):
            return [value]
        if value.startswith("(") and _closing_bracket(value) == len(value) - 1:
            return [value[1:-1].strip()]  # a Scratch reporter in its round slot: a value
        if '"' in value or "“" in value or re.search(r"[\[\]()]", value):
            return []  # a Scratch block inside (`(join [a] (b))`): not text to quote
        quoted = f'"{value}"'
        # words may be a value of rootlang's (`position y`): tried first, as written
        expression = re.fullmatch(r"[\w\s+\-*/()<>=.]*", value)
        return [value, quoted] if expression else [quoted]
    if how == "neg":
        if _NUMBER.fullmatch(value):
            return [value[1:] if value.startswith("-") else f"-{value}"]
        return [f"-{value}" if re.fullmatch(r"\w+", value) else f"-({value})"]
    if how in ("count", "count_to"):
        return _count(value, values.get("a", "0"), values.get("s", "1"), how == "count_to")
    if how == "pitch":  # the SDK's notes are frequencies: Note.A4 is 440 (Hz)
        if _NUMBER.fullmatch(value):
            return [f"{value} Hz"]
        name = _note_name(value)
        return [f"note {name}"] if name else []
    if how == "note":
        name = _note_name(value)
        return [name] if name else []
    if how == "heading":  # Scratch: 0 is up, 90 is right; rootlang's heading: 90 is where it
        if not _NUMBER.fullmatch(value):  # started facing, counted anticlockwise
            return []
        return [f"{(90 - float(value)) % 360:g} degrees"]
    if how == "logo":
        lines = _logo_lines(value)
        return [lines] if lines else []
    if how == "logo_names":
        return [", ".join(name.lstrip(":") for name in value.split())]
    if how == "name":  # Scratch's names may have spaces: my score is my_score
        words = value.split()
        return ["_".join(words)] if len(words) > 1 and all(w.isidentifier() for w in words) else []
    if how == "word":  # a colour written as text: pencolor("red") is red
        unquoted = re.fullmatch(r'"([^"\s]+)"', value)
        return [unquoted.group(1)] if unquoted else [value]
    if how == "line":  # a line of its own inside the answer: as written, or what it means
        return [value, *(m.rewrite for m in meanings(value) if "\n" not in m.rewrite)]
    if how == "sp":
        return [" ".join(part.strip() for part in value.split(","))]
    return [value]


_LOGO_NAME = re.compile(r"(?:^|(?<=[\s(\[])):([A-Za-z_]\w*)")
_ROUND_BOX = re.compile(r"(?<=\s)\((-?[0-9.]+|[A-Za-z_]\w*)\)")
_BOX = re.compile(r"\(([^()]*)\)|\[([^\[\]]*)\]")


def _count(stop: str, start: str, step: str, through: bool) -> list[str]:
    """How many times a counting loop goes round: Python's range(start, stop, step), or
    JavaScript's `i < stop` (``through``: `i <= stop`)."""
    low, high, by = _number(start), _number(stop), _number(step)
    if low is not None and high is not None and by:
        times = max(0, math.ceil((high - low + (1 if through else 0)) / by))
        return [f"{times:g}"]
    if by != 1:
        return []
    extra = " + 1" if through else ""
    if low == 0:
        return [f"{stop}{extra}"]
    return [f"{stop} - {start}{extra}"]


NOTE_NAMES = ("C", "C#", "D", "D#", "E", "F", "F#", "G", "G#", "A", "A#", "B")


_NOTE = re.compile(r"[A-Ga-g][#b]?[0-9]")  # a note's name, as the grammar's NOTE reads it


def _note_name(value: str) -> str | None:
    """A MIDI note number as a note name: 60 is C4 (Scratch's music notes)."""
    if not re.fullmatch(r"[0-9]+", value) or not 12 <= int(value) <= 127:
        return None if not _NOTE.fullmatch(value) else value.upper()
    number = int(value)
    return f"{NOTE_NAMES[number % 12]}{number // 12 - 1}"


def _logo_sequence(code: str) -> tuple[Habit, dict[str, str]] | None:
    """Several turtle Logo commands on one line (`fd 10 rt 90`): the lines they mean."""
    commands = [match.group().strip() for match in _LOGO_COMMAND.finditer(code)]
    if len(commands) < 2 or "".join(commands).replace(" ", "") != code.replace(" ", ""):
        return None
    lines = _logo_lines(code)
    if lines is None:
        return None
    return Habit("Logo", code, "\n".join(line.strip() for line in lines.split("\n"))), {}


def _logo_lines(body: str, indent: str = "    ") -> str | None:
    """`fd 10 rt 90` as the rootlang lines it means, indented one step (a `repeat 4 [...]`
    inside it: its lines one step further)."""
    lines = []
    position = 0
    while position < len(body):
        if body[position].isspace():
            position += 1
            continue
        nested = _LOGO_REPEAT.match(body, position)
        end = _closing(body, nested.end()) if nested else None
        if nested and end is not None:
            inner = _logo_lines(body[nested.end() : end], indent + "    ")
            if inner is None:
                return None
            count = _LOGO_NAME.sub(r"\1", nested.group(1))
            lines += [f"{indent}repeat {count}", inner]
            position = end + 1
            continue
        command = _LOGO_COMMAND.match(body, position)
        found = meaning(command.group().strip()) if command and command.group() else None
        if command is None or found is None or "\n" in found.rewrite:
            return None
        lines.append(indent + found.rewrite)
        position = command.end()
    return "\n".join(lines) if lines else None


_LOGO_REPEAT = re.compile(r"(?:repeat|répète|repete)\s+(-?[0-9]+|:?[A-Za-z_]\w*)\s*\[", re.I)


def _closing_bracket(text: str) -> int | None:
    """Where the `)` that closes the `(` text starts with is."""
    depth = 0
    for index, sign in enumerate(text):
        depth += {"(": 1, ")": -1}.get(sign, 0)
        if depth == 0:
            return index
    return None


def _closing(text: str, start: int) -> int | None:
    """Where the `]` that closes the `[` just before ``start`` is."""
    depth = 1
    for index in range(start, len(text)):
        depth += {"[": 1, "]": -1}.get(text[index], 0)
        if depth == 0:
            return index
    return None


def _caret(line: str, rewrite: str) -> tuple[int, int]:
    """Where the habit shows on the line: the first word of it that the rootlang line does not
    have (outside text in quotes: a word the answer puts in quotes is one the child must
    change), through the words after it that it does not have either; if it has them all, the
    first word where the two differ. Scratch's labels (`x:`) are one word."""
    outside = _QUOTED.sub(" ", rewrite)
    kept = {word.lower() for word in _WORD.findall(outside)} | set(_TOKEN.findall(outside))
    texts = [(found.start(), found.end()) for found in _QUOTED.finditer(line)]
    boxes = {  # Scratch's round slot: (10) is 10, when what is in it stays
        at
        for box in _ROUND_SLOT.finditer(line)
        if all(word.lower() in kept for word in _WORD.findall(box.group(1)))
        for at in (box.start(), box.end() - 1)
    }
    words = [
        word
        for word in _LABEL_OR_WORD.finditer(line)
        if not any(start <= word.start() < end for start, end in texts)
        and not (word.group() in "()" and word.start() in boxes)
    ]
    start = next(
        (index for index, word in enumerate(words) if word.group().lower() not in kept), None
    )
    if start is None:
        words = [word for word in _WORD.finditer(line) if word.start() not in boxes]
        wanted = [word.lower() for word in _WORD.findall(rewrite)]
        start = _out_of_place([word.group().lower() for word in words], wanted)
        if start is None:
            indent = len(line) - len(line.lstrip())
            return indent + 1, len(line.rstrip()) + 1
        return words[start].start() + 1, words[start].end() + 1
    after = words[start + 1].group() if start + 1 < len(words) else ""
    if _NUMBER.fullmatch(words[start].group()) and after.isalpha() and after.lower() not in kept:
        start += 1  # `1 minute` is `60 seconds`: the unit is what was written another way
    end = start
    while end + 1 < len(words) and words[end + 1].group().lower() not in kept:
        end += 1
    if not words[start].group()[0].isalnum() and start != end:
        end = start  # punctuation: just it (`;`, `+=`)
    return words[start].start() + 1, words[end].end() + 1


MOST_WORDS_COMPARED = 2_500  # words x words of a line put in order (a line of 50 words)


def _out_of_place(words: Sequence[str], wanted: Sequence[str]) -> int | None:
    """Which of ``words`` (all of them also in ``wanted``) is out of place: the first one left
    out of the longest run of them that ``wanted`` has in the same order, when that is the
    same run whichever words it keeps first (`move 10 cm forward` as `move forward 10 cm`:
    `forward`); else the first place where the two differ (`y position` as `position y`: `y`).
    None: the same words."""
    out = _left_out(words, wanted) if len(words) * len(wanted) <= MOST_WORDS_COMPARED else set()
    if out and out == {len(words) - 1 - index for index in _left_out(words[::-1], wanted[::-1])}:
        return min(out)
    return next(
        (
            index
            for index, word in enumerate(words)
            if index >= len(wanted) or word != wanted[index]
        ),
        None,
    )


def _left_out(words: Sequence[str], wanted: Sequence[str]) -> set[int]:
    """The places of ``words`` left out of the longest run of them that ``wanted`` has in the
    same order, the earlier words kept where they can be."""
    longest = [[0] * (len(wanted) + 1) for _ in range(len(words) + 1)]  # of words[i:], wanted[j:]
    for i in reversed(range(len(words))):
        for j in reversed(range(len(wanted))):
            same = words[i] == wanted[j]
            longest[i][j] = (
                longest[i + 1][j + 1] + 1 if same else max(longest[i + 1][j], longest[i][j + 1])
            )
    out: set[int] = set()
    i = j = 0
    while i < len(words):
        if j < len(wanted) and words[i] == wanted[j] and longest[i][j] == longest[i + 1][j + 1] + 1:
            i, j = i + 1, j + 1
        elif j < len(wanted) and longest[i][j + 1] == longest[i][j]:
            j += 1  # a word the line doesn't have here: this word may still be in its place
        else:
            out.add(i)
            i += 1
    return out


_LABEL_OR_WORD = re.compile(r"[A-Za-z_]\w*:(?=\s)|[^\s\w]+|\w+")
_ROUND_SLOT = re.compile(r"(?<=\s)\(([\w\s.-]+)\)")


def habit_diagnostics(line: str, number: int) -> list[Diagnostic]:
    """What to say of a line written with habits, the likeliest meaning first (each still to be
    tried in place, rootlang.verify)."""
    return [_said(item, number) for item in meanings(line)]


def _said(item: Meaning, number: int) -> Diagnostic:
    span = Span(number, item.column, number, item.end_column)
    written, source = unquoted(item.written), Described(item.source)
    found = diagnostic(item.why, span, written=written, source=source)
    if item.why == "E031":
        found = found.with_values(write=write_line(item.rewrite))
    return replace(found, rewrite=item.rewrite)


def header_habits(
    line: str, number: int
) -> list[tuple[str, list[tuple[int, int, int, int]], Diagnostic]]:
    """The one-line meanings of a line with lines indented under it, for the parser to read as
    a block header (so the lines under it stay its body): each as the line with its
    indentation, where its words are on the child's line (the child's values keep their
    places, for the carets of their own mistakes), and the diagnostic."""
    indent = line[: len(line) - len(line.lstrip())]
    found = []
    for said in habit_diagnostics(line, number):
        rewrite = said.rewrite or ""
        if not indent:  # at the left edge only a script's header opens lines (_in_a_script)
            rewrite = rewrite.split("\n")[0] if _opens_script_line(rewrite) else ""
        if not rewrite or "\n" in rewrite:
            continue
        fixed = indent + rewrite
        found.append((fixed, _anchors(fixed, line), said))
    return found


def _anchors(fixed: str, line: str) -> list[tuple[int, int, int, int]]:
    """For each word of ``fixed`` also on ``line`` (in order): its column in each (0-based)."""
    anchors = []
    position = 0
    for word in _WORD.finditer(fixed):
        at = line.lower().find(word.group().lower(), position)
        if at < 0:
            continue
        anchors.append((word.start(), at, len(word.group()), len(word.group())))
        position = at + len(word.group())
    return anchors


# Mistakes that say a line's words can't be read (not where the line stands, nor a value's
# kind): only a line with one of them may be written with a habit.
UNREADABLE = frozenset({
    "E001", "E004", "E002", "E011", "E012", "E013", "E014", "E019", "E021", "E023", "E024", "E025",
    "E026", "E029", "E030", "E101", "E102", "E120", "E005", "E017", "E108",
})  # fmt: skip
# Messages in the parser's own terms: worse than saying where the habit comes from.
PARSER_WORDS = frozenset({"E001", "E012", "E013"})


@dataclass(frozen=True)
class Above:
    """What the habits ask of the checks, which stand above the grammar (rootlang.checks gives
    it, so the grammar imports no checks): the words of the language (a word of them is no
    name to set), and whether a line reads and checks in a script of its own, its names aside
    (tried in place in a program whose other lines can't be read either, the checks may not
    have run)."""

    keywords: Callable[[], frozenset[str]]
    alone: Callable[[str], bool]


def with_habits(
    found: list[Diagnostic],
    lines: Sequence[str],
    left: Callable[[int, str], Sequence[Diagnostic] | None],
    above: Above,
) -> list[Diagnostic]:
    """``found`` with the mistakes of each line written with a habit replaced by the one
    message that says what it means in rootlang, the first whose line holds (``left``, the
    mistakes it has when tried in place, is empty). A line whose only mistake left is a name
    of the child's own that has no value yet (`total += 5`, `total` never set) gets its line
    all the same, and is told to set the name first (the missing line is another one). When
    none holds, a line's own messages stay, unless they only speak of what the parser
    expected: then the message names where the habit is from. ``above``: what the checks say
    of lines (:class:`Above`)."""
    errors: dict[int, list[Diagnostic]] = {}
    for item in found:
        if item.severity == "error":
            errors.setdefault(item.span.line, []).append(item)
    meant: dict[int, Diagnostic] = {}
    for number, mistakes in sorted(errors.items()):
        if not 0 < number <= len(lines) or not any(m.code in UNREADABLE for m in mistakes):
            continue
        header = meant.get(_line_before(lines, number))  # `@event(…)` over `async def …:`
        said = _line_meant(lines[number - 1], mistakes, functools.partial(left, number), above,
                           after_header=header is not None and _opens_script(header))  # fmt: skip
        if said is not None:
            meant[number] = said
    if not meant:
        return found
    for number, said in meant.items():  # a line at the left edge put in a script of its own
        rewrite = said.rewrite or ""  # whose lines go one step further, under its last line
        if said.code == "E031" and rewrite.startswith(f"{IN_A_SCRIPT}\n"):
            if not opens_lines(lines, number):
                continue
            last = Code(rewrite.split("\n")[-1].strip())
            meant[number] = replace(said, code="E038").with_values(last=last)
    kept = [item for item in found if item.span.line not in meant or item.severity != "error"]
    return sorted([*kept, *meant.values()], key=lambda item: (item.span, item.code))


def opens_lines(lines: Sequence[str], number: int) -> bool:
    """Whether line ``number`` has lines indented under it."""
    text = lines[number - 1]
    width = len(text) - len(text.lstrip())
    for after in lines[number:]:
        if after.strip() and not after.lstrip().startswith("#"):
            return len(after) - len(after.lstrip()) > width
    return False


def indented_under(lines: Sequence[str], number: int, extra: str) -> list[str]:
    """``lines`` with those indented under line ``number`` indented ``extra`` further."""
    text = lines[number - 1]
    width = len(text) - len(text.lstrip())
    moved = list(lines)
    for index in range(number, len(lines)):
        after = lines[index]
        if after.strip() and len(after) - len(after.lstrip()) <= width:
            break
        moved[index] = extra + after if after.strip() else after
    return moved


def _line_before(lines: Sequence[str], number: int) -> int:
    """The number of the line before line ``number`` that has code (0: none)."""
    before = number - 1
    while before > 0 and (not lines[before - 1].strip() or lines[before - 1].lstrip()[0] == "#"):
        before -= 1
    return before


def _opens_script(said: Diagnostic) -> bool:
    return _opens_script_line(said.rewrite or "")


def _opens_script_line(rewrite: str) -> bool:
    """Whether ``rewrite`` is a script's or procedure's header (a `when` or `to` line)."""
    return rewrite.split(" ", 1)[0] in ("when", "to")


def _line_meant(
    line: str,
    mistakes: Sequence[Diagnostic],
    left: Callable[[str], Sequence[Diagnostic] | None],
    above: Above,
    *,
    after_header: bool = False,
) -> Diagnostic | None:
    """The one message for a line with ``mistakes`` that a habit explains, or None to keep
    its own (``left``: the mistakes the line has when written another way). ``after_header``:
    the line before it means a script's header, so this line means no second one (the SDK's
    `@event(robot.when_bumped, …)` over `async def bumped(robot, …):`)."""

    def holds(text: str) -> bool:
        return left(text) == ()

    number = mistakes[0].span.line
    if _misspelt(mistakes, holds):
        return None
    found_meanings = [
        item for item in meanings(line) if not (after_header and _opens_script_line(item.rewrite))
    ]
    said = [_said(item, number) for item in found_meanings]
    holding, unset = None, None
    own = {item.rewrite for item in mistakes if item.rewrite}
    for item, means in zip(said, found_meanings, strict=True):
        if item.rewrite in own and holds(item.rewrite or ""):  # the line's own message
            break  # already proposes it, and it holds: that message stays
        wrong = left(item.rewrite or "")
        further = _followed(item, means, wrong, holds)
        if further is not None:
            item, wrong = further, ()
        if wrong == ():
            holding = _at_first_change(item, means, holds, above.alone)
            break
        name = _unset_name(wrong, line, above.keywords)
        if unset is None and name is not None:
            unset = item, name
    if holding is not None:
        unread = next(m for m in mistakes if m.code in UNREADABLE)
        return _narrowed(holding, unread.span, line)
    if unset is not None and unset[0].code == "E031":
        item, name = unset
        values = dict(item.values)
        return diagnostic("E036", item.span, written=values["written"], name=name,
                          source=values["source"], write=values["write"])  # fmt: skip
    if said and all(mistake.code in PARSER_WORDS for mistake in mistakes):
        values = dict(said[0].values)
        return diagnostic("E034", said[0].span, written=values["written"],
                          source=values["source"])  # fmt: skip
    return None


def _misspelt(mistakes: Sequence[Diagnostic], holds: Callable[[str], bool]) -> bool:
    """Whether a mistake of the line is a name of the child's own misspelt, whose fix holds
    (`say scroe` is `say score`, not `say "scroe"`): that beats a habit."""
    return any(item.code == "E102" and item.rewrite and holds(item.rewrite) for item in mistakes)


# Mistakes whose fix completes the line the habit meant, not another reading of it: a join for
# text and values, a unit, `set`.
COMPLETING = frozenset({"E121", "E108", "E014", "E026", "E127"})


def _followed(
    said: Diagnostic,
    means: Meaning,
    wrong: Sequence[Diagnostic] | None,
    holds: Callable[[str], bool],
) -> Diagnostic | None:
    """``said``, the child's line with its small habits tidied away, with the line its one
    mistake left then proposes, when that holds (`x = random.randint(1, 6)` tidied is `x =
    random 1 to 6`, which is `set x to random 1 to 6`)."""
    if not wrong or len(wrong) != 1 or said.code != "E031":
        return None
    if means.rewrite != means.tidied and wrong[0].code not in COMPLETING:
        return None
    further = wrong[0].rewrite
    if further is None or "\n" in further or further == said.rewrite or not holds(further):
        return None
    column, end = _caret(means.line, further)
    span = Span(said.span.line, column, said.span.line, end)
    written = means.line[column - 1 : end - 1]
    found = said.with_values(write=write_line(further), written=unquoted(written))
    return replace(found, span=span, rewrite=further)


def _at_first_change(
    said: Diagnostic, means: Meaning, holds: Callable[[str], bool], alone: Callable[[str], bool]
) -> Diagnostic:
    """``said`` with its caret on the first part of the line that must change: when the line
    with only its small habits tidied away holds as well (`if (x > 3) {` is `if (x > 3)`), the
    brackets rootlang also reads are not a mistake, the `{` is."""
    if means.tidied_at is None or means.tidied is None or means.tidied == said.rewrite:
        return said
    column, end, written = means.tidied_at
    if column <= said.span.column or not alone(means.tidied) or not holds(means.tidied):
        return said
    line = said.span.line
    span = Span(line, column, line, end)
    return replace(said, span=span).with_values(written=unquoted(written))


def _unset_name(
    mistakes: Sequence[Diagnostic] | None, line: str, keywords: Callable[[], frozenset[str]]
) -> str | None:
    """The name of the child's own line that has no value yet, when that is the only mistake
    ``mistakes`` (of the line rewritten) has."""
    if not mistakes or any(item.code != "E102" for item in mistakes):
        return None
    names = {str(dict(item.values)["name"]) for item in mistakes}
    words = {word.lower() for word in re.findall(r"\w+", line)}
    if len(names) != 1 or min(names).lower() not in words or min(names).lower() in keywords():
        return None  # `repeat else`: a word of the language is no name to set
    if _NOTE.fullmatch(min(names)):
        return None  # `play Bb3`: a note without its word (E024), no name to set
    return min(names)


# Punctuation as other languages write it: their two-character operators, else one character.
_PUNCTUATION = re.compile(r"\(\)|===|!==|[-+*/%=<>!:]=|\+\+|--|&&|\|\||[^\s\w]")


def _narrowed(said: Diagnostic, unread: Span, line: str) -> Diagnostic:
    """``said`` with its caret on the sign where rootlang could not read the line, when that
    is a later sign of the run of punctuation the caret starts on (`print('hi')`: the `'`, not
    the `(` rootlang reads too; `x -= 2` keeps `-=`)."""
    span = said.span
    if span.line != unread.line or not span.column < unread.column < span.end_column:
        return said
    run = re.match(r"[^\s\w]+", line[span.column - 1 :])
    for sign in _PUNCTUATION.finditer(run.group() if run else ""):
        start, end = span.column + sign.start(), span.column + sign.end()
        if start != unread.column:
            continue
        narrowed = replace(span, column=start, end_column=end)
        return replace(said, span=narrowed).with_values(written=unquoted(sign.group()))
    return said
