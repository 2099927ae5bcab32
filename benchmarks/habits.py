"""How well `rootlang check` answers habits from other tools it was not tuned on.

Each case is one line a child brings from Scratch, Python, JavaScript, turtle Logo or iRobot's
Python SDK, inside a small program, with the word the caret should be on and the lines that
would be a right fix. A case scores when the first mistake on that line is underlined from that
word and its message says "Write:" with one of the right fixes (ignoring case and spacing).
The habits here were written down before the habit table (rootlang/grammar/habits.py) and
were not used to tune it: they are other spellings, other values and other commands of the
same tools. Run: python benchmarks/habits.py [-v] [held_out after last dev set_aside]
"""

from __future__ import annotations

import itertools
import re
import sys
import time

from rootlang.checks import diagnose
from rootlang.diagnostics import RootlangError
from rootlang.formatting import format_source

# (line as the child wrote it, the word the caret should start on, right fixes)
HELD_OUT: list[tuple[str, str, tuple[str, ...]]] = [
    # Scratch
    ("when flag clicked", "flag", ("when started",)),
    ("move 25 steps", "steps", ("move 25 cm",)),
    ("broadcast go", "broadcast", ('send "go"',)),
    ('broadcast "dance" and wait', "broadcast", ('send "dance" and wait',)),
    ('say "Hello!" for 3 seconds', "for", ('say "Hello!"\nwait 3 seconds',)),
    ('think "hmm" for 1 seconds', "think", ('say "hmm"\nwait 1 seconds',)),
    ("wait 2 secs", "secs", ("wait 2 seconds",)),
    ("turn 15 degrees", "15", ("turn right 15 degrees",)),
    ("go to x: 10 y: 20", "x", ("go to x 10 cm y 20 cm",)),
    ("end", "end", ("",)),
    # Python
    ("for n in range(6):", "for", ("repeat 6",)),
    ("for step in range(3)", "for", ("repeat 3",)),
    ("def zigzag():", "def", ("to zigzag",)),
    ("def hop(height):", "def", ("to hop height",)),
    ("x -= 2", "-=", ("change x by -2",)),
    ("x = x - 3", "=", ("change x by -3",)),
    ("elif x < 2:", "elif", ("else if x < 2",)),
    ("time.sleep(0.5)", "time", ("wait 0.5 seconds",)),
    ("sleep(2)", "sleep", ("wait 2 seconds",)),
    ("import random", "import", ("",)),
    ("from time import sleep", "from", ("",)),
    # JavaScript
    ("let speed = 4;", "let", ("set speed to 4",)),
    ("const n = 7", "const", ("set n to 7",)),
    ("x++", "++", ("change x by 1",)),
    ("console.log(x)", "console", ("print x",)),
    ("}", "}", ("",)),
    ("turn left 90 degrees;", ";", ("turn left 90 degrees",)),
    # turtle Logo
    ("FD 30", "FD", ("move 30 cm",)),
    ("bk 5", "bk", ("move backward 5 cm", "move -5 cm")),
    ("lt 45", "lt", ("turn left 45 degrees",)),
    ("back 12", "back", ("move backward 12 cm", "move -12 cm")),
    ("penup", "penup", ("marker up",)),
    ("repeat 3 [fd 20 lt 120]", "[", ("repeat 3\n    move 20 cm\n    turn left 120 degrees",)),
    # iRobot's Python SDK
    ("await robot.turn_left(90)", "await", ("turn left 90 degrees",)),
    ("await robot.arc_right(90, 10)", "await", ("arc right 90 degrees radius 10 cm",)),
    ("robot.set_lights_on_rgb(0, 255, 0)", "robot", ("light rgb 0 255 0",)),
    ("await robot.move(-5)", "await", ("move -5 cm",)),
    # words children invent
    ("repeat 5 time", "time", ("repeat 5",)),
    ("end if", "end", ("",)),
    ("loop forever", "loop", ("forever", "repeat forever")),
]

# A second set, written after the table was built and never used to change it: its score is
# the honest one for habits the table has not seen.
HELD_OUT_AFTER: list[tuple[str, str, tuple[str, ...]]] = [
    ("move 40 steps", "steps", ("move 40 cm",)),
    ("turn right 45", "45", ("turn right 45 degrees",)),
    ("wait 0.5", "0.5", ("wait 0.5 seconds",)),
    ('when I receive "start"', "I", ('when message "start" received',)),
    ('say "Bye" for 0.5 secs', "for", ('say "Bye"\nwait 0.5 seconds',)),
    ("pen_down", "pen_down", ("marker down",)),
    ("for k in range(8):", "for", ("repeat 8",)),
    ("total += 5", "+=", ("change total by 5",)),
    ("x = x + 2", "=", ("change x by 2",)),
    ("print('hi')", "'", ('print "hi"',)),
    ("var count = 0;", "var", ("set count to 0",)),
    ("x--", "--", ("change x by -1",)),
    ("FORWARD 15", "FORWARD", ("move 15 cm",)),
    ("RT 120", "RT", ("turn right 120 degrees",)),
    ("PD", "PD", ("marker down",)),
    ("repeat 6 [fd 5 rt 60]", "[", ("repeat 6\n    move 5 cm\n    turn right 60 degrees",)),
    ("await robot.turn_right(45)", "await", ("turn right 45 degrees",)),
    ("await robot.set_lights_rgb(0, 0, 255)", "await", ("light rgb 0 0 255",)),
    ("robot.set_marker(Marker.DOWN)", "robot", ("marker down",)),
    ("end repeat", "end", ("",)),
]

# A third set, written down (with the right answers) before the code was changed for it, by a
# hand that had not tuned the table on it: lines children copy from Scratch's site, Python's
# and JavaScript's block headers, uppercase Logo, two Logo commands on one line, SDK calls
# without `await`, and words children invent.
HELD_OUT_NEW: list[tuple[str, str, tuple[str, ...]]] = [
    # Scratch
    ("turn ↻ 15 degrees", "↻", ("turn right 15 degrees",)),
    ("say Hello!", "Hello", ('say "Hello!"',)),
    ("if <touching edge?> then", "<", ("if bumper any pressed",)),
    # Python
    ("while True:", "while", ("forever",)),
    ("for i in range(1, 5):", "for", ("repeat 4",)),
    ("def dance:", "def", ("to dance",)),
    ("sleep 3", "sleep", ("wait 3 seconds",)),
    # JavaScript
    ("function spin() {", "function", ("to spin",)),
    ("if (x > 3) {", "{", ("if x > 3", "if (x > 3)")),
    ("x += 2;", "+=", ("change x by 2",)),
    ('alert("hi")', "alert", ('say "hi"',)),
    # turtle Logo
    ("REPEAT 4 [FD 50 RT 90]", "[", ("repeat 4\n    move 50 cm\n    turn right 90 degrees",)),
    ("fd 10 rt 90", "fd", ("move 10 cm\nturn right 90 degrees",)),
    ("right 90 degrees", "right", ("turn right 90 degrees",)),
    ("forward 20 cm", "forward", ("move 20 cm",)),
    # iRobot's Python SDK
    ("await robot.play_note(Note.A4, 0.5)", "await", ("play note A4 for 0.5 seconds",)),
    ("robot.move(20)", "robot", ("move 20 cm",)),
    # words children invent
    ("wait for 2 seconds", "for", ("wait 2 seconds",)),
    ("set x = 5", "=", ("set x to 5",)),
    ("when program starts", "program", ("when started",)),
]

# A fourth set, the one this round of work was tuned on: written down (with the right answers)
# before the code was changed for it, going through each tool's vocabulary (Scratch's blocks as
# children type them, with their brackets; Python's and JavaScript's statements, operators and
# assignments; Logo's pen, heading and position words; the SDK's methods with keyword arguments
# and its Note and Color values; words children invent). Its figure before and after is in
# docs/language.md; it is not a held-out figure.
DEV: list[tuple[str, str, tuple[str, ...]]] = [
    # Scratch
    ("move (10) steps", "steps", ("move 10 cm", "move (10) cm")),
    ("turn ↺ (45) degrees", "↺", ("turn left 45 degrees", "turn left (45) degrees")),
    ("say Hello for 2 seconds", "Hello", ('say "Hello"\nwait 2 seconds',)),
    ("say Hello", "Hello", ('say "Hello"',)),
    ("think Hmm... for 2 seconds", "think", ('say "Hmm..."\nwait 2 seconds',)),
    ("repeat until <touching edge?>", "<", ("repeat until bumper any pressed",)),
    ("if <(x) > (3)> then", "<", ("if x > 3", "if (x) > (3)")),
    ("when I receive [go]", "I", ('when message "go" received',)),
    ("broadcast [ready]", "broadcast", ('send "ready"',)),
    ("set [score] to (0)", "[", ("set score to 0",)),
    ("set x to (pick random (1) to (6))", "pick", ("set x to random 1 to 6",
                                                   "set x to (random 1 to 6)",
                                                   "set x to (random (1) to (6))")),
    ("set pen color to blue", "set", ("light blue",)),
    ("rest for 0.25 beats", "rest", ("wait 0.25 seconds",)),
    ("stop [all]", "[", ("stop all",)),
    # Python
    ("for i in range(2, 10, 2):", "for", ("repeat 4",)),
    ("for _ in range(3):", "for", ("repeat 3",)),
    ("for i in range(x):", "for", ("repeat x",)),
    ("speed = 10", "=", ("set speed to 10",)),
    ("name = 'Robo'", "=", ('set name to "Robo"',)),
    ("x *= 2", "*=", ("set x to x * 2",)),
    ('print(f"x is {x}")', "f", ('print join("x is ", x)',)),
    ("print(str(x))", "str", ("print x", "print(x)")),
    ('print("x is", x)', "(", ('print "x is", x',)),
    ("await asyncio.sleep(1)", "await", ("wait 1 seconds",)),
    ("x = random.randint(1, 6)", "=", ("set x to random 1 to 6",)),
    ("if x % 2 == 0:", "%", ("if x mod 2 == 0", "if x mod 2 = 0")),
    ("x = True", "=", ("set x to true",)),
    ("if x is 3:", "is", ("if x = 3", "if x == 3")),
    # JavaScript
    ("for (let i = 0; i < 4; i++) {", "for", ("repeat 4",)),
    ("for (let i = 1; i <= 3; i++) {", "for", ("repeat 3",)),
    ("while (x < 10) {", "{", ("while x < 10", "while (x < 10)")),
    ("} else {", "}", ("else",)),
    ("if (x === 3) {", "===", ("if x = 3", "if (x = 3)", "if x == 3", "if (x == 3)")),
    ("if (x > 3 && x < 9) {", "&&", ("if x > 3 and x < 9", "if (x > 3 and x < 9)")),
    ("// turn around", "//", ("# turn around",)),
    ("x = x + 1;", "=", ("change x by 1",)),
    ("set y to Math.round(x)", "Math", ("set y to round x", "set y to round(x)")),
    # turtle Logo
    ("setpc red", "setpc", ("light red",)),
    ("setxy 10 20", "setxy", ("go to x 10 cm y 20 cm",)),
    ("repeat 5 [forward 10 right 72]", "[",
     ("repeat 5\n    move 10 cm\n    turn right 72 degrees",)),
    ("fd :x", "fd", ("move x cm",)),
    ("print :x", ":", ("print x",)),
    ('print "hello', '"', ('print "hello"',)),
    ("pe", "pe", ("eraser down",)),
    # iRobot's Python SDK
    ("await robot.set_marker_down()", "await", ("marker down",)),
    ("await robot.set_eraser_down()", "await", ("eraser down",)),
    ("await robot.move(distance=15)", "await", ("move 15 cm",)),
    ("await robot.navigate_to(20, 10)", "await", ("go to x 20 cm y 10 cm",)),
    ("await robot.set_left_speed(5)", "await", ("set left wheel 5 cm/s",)),
    ("await robot.stop()", "await", ("stop moving",)),
    ("await robot.set_lights(Robot.LIGHT_ON, Color(255, 0, 0))", "await",
     ("light rgb 255 0 0", "light red")),
    ("await robot.play_note(Note.C5_SHARP, 0.25)", "await", ("play note C#5 for 0.25 seconds",)),
    ("await robot.play_note(440, 1)", "await", ("play 440 Hz for 1 seconds",
                                                 "play note A4 for 1 seconds")),
    ('await robot.say("Hello!")', "await", ('say "Hello!"',)),
    ("await robot.stop_sound()", "await", ("stop sound",)),
    ("@event(robot.when_bumped, [True, False])", "@", ("when bumper left pressed",)),
    # words children invent
    ("set x = 5", "=", ("set x to 5",)),
    ("make x 5", "make", ("set x to 5",)),
    ("if x equals 3", "equals", ("if x = 3",)),
    # (the caret on the word out of place since the words' order is read, docs/language.md;
    # it was on `90`, the first word where the two lines differ)
    ("turn 90 degrees right", "right", ("turn right 90 degrees",)),
    ("move forwards 10 cm", "move", ()),  # rootlang reads it
    ("spin 360", "spin", ("turn right 360 degrees", "turn left 360 degrees")),
    ("stop", "stop", ("stop moving", "stop all")),
    ("change x to 5", "change", ("set x to 5",)),  # was "to": the word to change is `change`
    ("increase x by 1", "increase", ("change x by 1",)),
    ("if x > 3 do", "do", ("if x > 3",)),
    ("on start", "on", ("when started",)),
]  # fmt: skip

# DEV's second batch, written down (with the right answers) after DEV was done and before the
# code was changed for it: more of each tool's vocabulary. Tuned on like DEV.
DEV2: list[tuple[str, str, tuple[str, ...]]] = [
    # Scratch
    ("go to x: (0) y: (0)", "x", ("go to x 0 cm y 0 cm",)),
    ("glide (1) secs to x: (10) y: (20)", "glide", ("go to x 10 cm y 20 cm",)),
    ("say [Hi!] for (2) seconds", "[", ('say "Hi!"\nwait 2 seconds',)),
    ("think [Hmm]", "think", ('say "Hmm"',)),
    ("stop [this script]", "[", ("stop this script",)),
    ("play note (60) for (0.5) beats", "(", ("play note C4 for 0.5 seconds",)),
    ("repeat until <(x) = (10)>", "<", ("repeat until x = 10", "repeat until (x) = (10)")),
    ("change [score] by (-1)", "[", ("change score by -1",)),
    ("set light to red", "set", ("light red",)),
    # Python
    ("x = x - 1", "=", ("change x by -1",)),
    ("def square(size, angle):", "def", ("to square size, angle",)),
    ("x = 10  # start value", "=", ("set x to 10",)),
    ('print("x =", x)', "(", ('print "x =", x',)),
    ("import math", "import", ("",)),
    ("while x <= 10:", "while", ()),
    # JavaScript
    ('console.log("x is " + x);', "console", ('print join("x is ", x)',)),
    ("if (!(x > 3)) {", "!", ("if not (x > 3)", "if (not (x > 3))")),
    ("} else if (x > 2) {", "}", ("else if x > 2",)),
    ("while (true) {", "{", ("forever",)),  # was "while": rootlang reads `while (true)`
    # turtle Logo
    ("pu fd 10 pd", "pu", ("marker up\nmove 10 cm\nmarker down",)),
    ("repeat 4 [fd :x rt 90]", "[", ("repeat 4\n    move x cm\n    turn right 90 degrees",)),
    ('setpc "red', "setpc", ("light red",)),
    ('make "x :x + 1', "make", ("set x to x + 1", "change x by 1")),
    # iRobot's Python SDK
    ("await robot.set_lights(Robot.LIGHT_BLINK, Color(0, 0, 255))", "await",
     ("light blink rgb 0 0 255", "light blink blue")),
    ("await robot.say('hi')", "await", ('say "hi"',)),
    ("await robot.play_note(Note.C4, duration=1)", "await", ("play note C4 for 1 seconds",)),
    ("await robot.set_gravity_compensation(Root.GRAVITY_ON, 50)", "await",
     ("set gravity compensation on 50 %",)),
    ("await robot.set_marker(Root.MARKER_UP)", "await", ("marker up",)),
    # words children invent
    ("go 10 cm", "go", ("move 10 cm",)),
    ("walk 10", "walk", ("move 10 cm",)),
    ("if x is bigger than 3", "is", ("if x > 3",)),
    ("until x > 3", "until", ("repeat until x > 3",)),
    ("repeat while x < 3", "repeat", ("while x < 3",)),
    ("when clicked", "clicked", ("when touched",)),
    ("whenever bumped", "whenever", ("when bumped",)),
    ("repeat forever do", "do", ("repeat forever", "forever")),
]  # fmt: skip

# DEV's third batch: written down after DEV2 was done, before the code was changed for it.
DEV3: list[tuple[str, str, tuple[str, ...]]] = [
    ("set y to join [hello] [world]", "[", ('set y to join("hello", "world")',)),
    ("set y to [abs] of (x)", "[", ("set y to abs x", "set y to abs (x)")),
    ("set y to math.sqrt(16)", "math", ("set y to sqrt(16)", "set y to sqrt 16")),
    ("x := 5", ":=", ("set x to 5",)),
    ("when play", "play", ("when started",)),
    ("pause 2", "pause", ("wait 2 seconds",)),
    ("turn 90", "90", ("turn right 90 degrees",)),
    ("move back 10", "back", ("move backward 10 cm",)),
    ('label "hello', "label", ('say "hello"',)),
    ("await robot.arc(Robot.DIR_LEFT, 90, 10)", "await", ("arc left 90 degrees radius 10 cm",)),
    ("await robot.turn(Robot.DIR_RIGHT, 45)", "await", ("turn right 45 degrees",)),
    ("await hand_over()", "await", ("",)),
    ("if x > 3: move 10 cm", ":", ("if x > 3\n    move 10 cm",)),
    ("if :x > 5 [fd 10]", ":", ("if x > 5\n    move 10 cm",)),
    ("set my score to 0", "my", ("set my_score to 0",)),
]  # fmt: skip

# A fifth set, written at the same time as DEV by the same hand, but set aside: it was run only
# once, after the work on DEV was done, and never used to change the code. (Still one hand's
# idea of the tools, so the figure for habits written by someone else may be lower.)
SET_ASIDE: list[tuple[str, str, tuple[str, ...]]] = [
    # Scratch
    ("move (-20) steps", "steps", ("move -20 cm", "move (-20) cm")),
    ("turn ↻ (30) degrees", "↻", ("turn right 30 degrees", "turn right (30) degrees")),
    ("say Ouch! for 1 seconds", "Ouch", ('say "Ouch!"\nwait 1 seconds',)),
    ("think Hello", "think", ('say "Hello"',)),
    ("wait until <touching edge?>", "<", ("wait until bumper any pressed",)),
    ("broadcast (start) and wait", "broadcast", ('send "start" and wait',)),
    ("change [score] by (1)", "[", ("change score by 1",)),
    ("set pen color to green", "set", ("light green",)),
    ("say hello world", "hello", ('say "hello world"',)),
    ("when I receive [dance]", "I", ('when message "dance" received',)),
    # Python
    ("for j in range(1, 11):", "for", ("repeat 10",)),
    ("total = 0", "=", ("set total to 0",)),
    ("x /= 2", "/=", ("set x to x / 2",)),
    ("x = x * 3", "=", ("set x to x * 3",)),
    ("while x != 10:", "while", ()),  # accepted as written: no mistake wanted
    ('print("done!")', "print", ()),
    ("if x == 1 or x == 2:", "if", ()),
    ("time.sleep(0.25)", "time", ("wait 0.25 seconds",)),
    # JavaScript
    ("for (let k = 0; k < 6; k++) {", "for", ("repeat 6",)),
    ("if (x !== 3) {", "!==", ("if x != 3", "if (x != 3)")),
    ("while (x > 0 || x < -5) {", "||", ("while x > 0 or x < -5", "while (x > 0 or x < -5)")),
    ("let speed = 10;", "let", ("set speed to 10",)),
    ('console.log("done");', "console", ('print "done"',)),
    ("x -= 1;", "-=", ("change x by -1",)),
    # turtle Logo
    ("setpencolor blue", "setpencolor", ("light blue",)),
    ("setx 10", "setx", ("go to x 10 cm y position y",)),
    ("repeat 8 [fd 10 rt 45]", "[", ("repeat 8\n    move 10 cm\n    turn right 45 degrees",)),
    ("back 30", "back", ("move backward 30 cm", "move -30 cm")),
    ("seth 180", "seth", ("go to x position x y position y facing 270 degrees",)),
    # iRobot's Python SDK
    ("await robot.set_marker_up()", "await", ("marker up",)),
    ("await robot.turn_left(angle=45)", "await", ("turn left 45 degrees",)),
    ("await robot.set_wheel_speeds(-5, 5)", "await", ("set wheels left -5 cm/s right 5 cm/s",)),
    ("await robot.play_note(Note.E4, Note.QUARTER)", "await", ("play note E4 for 0.25 seconds",)),
    ("await robot.wait(1.5)", "await", ("wait 1.5 seconds",)),
    ("await robot.arc_left(angle=90, radius=10)", "await", ("arc left 90 degrees radius 10 cm",)),
    # words children invent
    ("move 10 cm forward", "forward", ("move forward 10 cm", "move 10 cm")),
    ("add 1 to x", "add", ("change x by 1",)),
    ("loop 3", "loop", ("repeat 3",)),
    ("while x < 5 do", "do", ("while x < 5",)),
    ("spin around", "spin", ("turn right 360 degrees", "turn left 360 degrees")),
]  # fmt: skip

# Two sets written by another hand, who read only the language's docs (not the table, its tests
# or these sets) and never ran rootlang on them. The first (``other``) was measured at the start
# of a round (19/40), then its misses were seen while the round went on; the second
# (``other2``) was written mid-round and never seen by those changing the code: its figure is
# the honest one for habits nobody has tuned on. A later round needs a new one.
OTHER_HAND: list[tuple[str, str, tuple[str, ...]]] = [
    # Scratch
    ("when this sprite clicked", "this", ("when touched",)),
    ("play note 60 for 0.5 beats", "60", ("play note C4 for 0.5 seconds",)),
    ("rest for 0.25 beats", "rest", ("wait 0.25 seconds",)),
    ("glide 1 secs to x: 50 y: 20", "glide", ("go to x 50 cm y 20 cm",)),
    ("stop all sounds", "all", ("stop sound",)),
    ("when timer > 10", "10", ("when timer > 10 seconds",)),
    ("turn clockwise 30 degrees", "clockwise", ("turn right 30 degrees",)),
    ("if <x = 10> then", "<", ("if x = 10",)),
    # Python
    ("x *= 2", "*=", ("set x to x * 2", "change x by x")),
    ("x = random.randint(1, 6)", "=", ("set x to random 1 to 6",)),
    ("if x % 2 == 0:", "%", ("if x mod 2 = 0", "if x mod 2 == 0")),
    ("pass", "pass", ("",)),
    ("if x is 3:", "is", ("if x = 3", "if x == 3")),
    ("exit()", "exit", ("stop all",)),
    ("global x", "global", ("",)),
    ('print(f"x is {x}")', "f", ('print "x is", x', 'print join("x is ", x)')),
    ("print(math.sqrt(16))", "math", ("print sqrt 16", "print(sqrt 16)", "print sqrt(16)")),
    # JavaScript
    ("} else {", "}", ("else",)),
    ("for (let i = 0; i < 6; i++) {", "for", ("repeat 6",)),
    ("if (x === 10) {", "===", ("if x = 10", "if x == 10")),
    ("// turn around", "//", ("# turn around",)),
    ("while (x < 10) {", "{", ("while x < 10", "while (x < 10)")),
    ("x = Math.round(x)", "=", ("set x to round x",)),
    # Logo
    ("left 60", "left", ("turn left 60 degrees",)),
    ('make "x 5', "make", ("set x to 5",)),
    ('make "x :x + 1', "make", ("change x by 1", "set x to x + 1")),
    ("print :x", ":", ("print x",)),
    ("to square :size", ":", ("to square size",)),
    ("setxy 10 20", "setxy", ("go to x 10 cm y 20 cm",)),
    # iRobot SDK
    ("@event(robot.when_play)", "@event", ("when started",)),
    ("await robot.set_wheel_speeds(5, -5)", "await", ("set wheels left 5 cm/s right -5 cm/s",)),
    ("await robot.set_lights_spin_rgb(0, 255, 0)", "await", ("light spin rgb 0 255 0",)),
    ("await robot.navigate_to(20, 10)", "await", ("go to x 20 cm y 10 cm",)),
    ("await robot.reset_navigation()", "await", ("reset position",)),
    # invented words
    ("zoom 20 cm", "zoom", ("move 20 cm", "move forward 20 cm")),
    ("spin left 180 degrees", "spin", ("turn left 180 degrees",)),
    ("glow green", "glow", ("light green",)),
    ("draw on", "draw", ("marker down", "pen down")),
    ("sing note E4 for 1 second", "sing", ("play note E4 for 1 second",)),
    ("pause 3 seconds", "pause", ("wait 3 seconds",)),
]

OTHER_HAND_2: list[tuple[str, str, tuple[str, ...]]] = [
    # Scratch
    ("set x to pick random 1 to 10", "pick", ("set x to random 1 to 10",)),
    ("wait until bumper left pressed?", "?", ("wait until bumper left pressed",)),
    ("broadcast dance and wait", "broadcast", ('send "dance" and wait',)),
    ("say [Hello]", "[", ('say "Hello"',)),
    ("say (y position)", "y", ("say position y", "say (position y)")),
    ("stop other scripts in sprite", "in", ("stop other scripts",)),
    ("set x to abs of x", "of", ("set x to abs x",)),
    # Python
    ("x /= 2", "/=", ("set x to x / 2",)),
    ("print(str(x))", "str", ("print x", "print(x)")),
    ('"""draw a square"""', '"""', ("# draw a square",)),
    ("turtle.forward(50)", "turtle", ("move 50 cm", "move forward 50 cm")),
    ("t.left(72)", "t", ("turn left 72 degrees",)),
    ("t.penup()", "t", ("marker up", "pen up")),
    ("turtle.backward(25)", "turtle", ("move backward 25 cm", "move -25 cm")),
    ("turtle.done()", "turtle", ("",)),
    # JavaScript
    ("/* spiral time */", "/*", ("# spiral time",)),
    ("else {", "{", ("else",)),
    ("if (x > 3 || x < 0) {", "||", ("if x > 3 or x < 0", "if (x > 3 or x < 0)")),
    ("if (x !== 5) {", "!==", ("if x != 5", "if (x != 5)")),
    ("document.write(x);", "document", ("print x", "print(x)")),
    ("const spin = () => {", "const", ("to spin",)),
    # Logo
    ("home", "home", ("go to x 0 cm y 0 cm facing 90 degrees", "go to x 0 cm y 0 cm")),
    ("penerase", "penerase", ("eraser down",)),
    ("show :x", "show", ("print x",)),
    ("print [Hello Root]", "[", ('print "Hello Root"',)),
    ("hideturtle", "hideturtle", ("",)),
    ("]", "]", ("",)),
    # iRobot SDK
    ("await robot.wait(1.5)", "await", ("wait 1.5 seconds",)),
    ("await robot.set_lights_off()", "await", ("light off",)),
    ("@event(robot.when_bumped, [True, False])", "@event", ("when bumper left pressed",)),
    ("robot.play()", "robot", ("",)),
    ("async def play(robot):", "async", ("when started",)),
    # invented words
    ("move 10 centimeters", "centimeters", ("move 10 cm",)),
    ("turn around", "around", ("turn right 180 degrees", "turn left 180 degrees")),
    ("move back 5 cm", "back", ("move backward 5 cm",)),
    ("lights blue", "lights", ("light blue",)),
    ("marker on", "on", ("marker down", "pen down")),
    ("turn 45 degrees left", "left", ("turn left 45 degrees",)),  # (was `45`: see DEV)
    ("add 2 to x", "add", ("change x by 2", "set x to x + 2")),
    ("do 3 times", "do", ("repeat 3", "repeat 3 times")),
]

# A third set by another hand, written late in the round from the docs (which by then listed
# every habit the table knows: so these are what it did not list), never seen before it was
# measured: 31/40 at 3a65288.
OTHER_HAND_3: list[tuple[str, str, tuple[str, ...]]] = [
    # Scratch
    ("glide 1 secs to x: 20 y: 10", "glide", ("go to x 20 cm y 10 cm",)),
    ("stop all sounds", "all", ("stop sound",)),
    ("when this sprite clicked", "this", ("when touched",)),
    ("when [timer] > (10)", "[", ("when timer > 10 seconds",)),
    ("stop [other scripts in sprite]", "[", ("stop other scripts",)),
    ("play note 60 for 0.5 beats", "60", ("play note C4 for 0.5 seconds",)),
    ("think [Hmm]", "think", ('say "Hmm"', 'print "Hmm"')),
    # Python (incl. turtle)
    ("t.right(72)", "t", ("turn right 72 degrees",)),
    ("turtle.penup()", "turtle", ("marker up",)),
    ("turtle.circle(20)", "turtle", ("arc left 360 degrees radius 20 cm",)),
    ('turtle.pencolor("red")', "turtle", ("light red",)),
    ("pass", "pass", ("",)),
    ("from time import sleep", "from", ("",)),
    ("sleep(2)", "sleep", ("wait 2 seconds",)),
    ("print(math.sqrt(x))", "math", ("print sqrt x", "print sqrt(x)")),
    # JavaScript
    ("const size = 10;", "const", ("set size to 10",)),
    ("await sleep(1000);", "await", ("wait 1000 ms", "wait 1 second", "wait 1 seconds")),
    ("} else {", "}", ("else",)),
    ("for (;;) {", "for", ("forever", "repeat forever")),
    ("if (x >= 3 || x <= 0) {", "||", ("if x >= 3 or x <= 0",)),
    ('alert("Hi!")', "alert", ('say "Hi!"', 'print "Hi!"')),
    # Logo
    ("forward 25", "forward", ("move 25 cm", "move forward 25 cm")),
    ('make "x :x + 1', "make", ("change x by 1", "set x to x + 1")),
    ("to square :size", ":size", ("to square size",)),
    ("setpos [10 20]", "setpos", ("go to x 10 cm y 20 cm",)),
    (
        "ifelse :x > 3 [fd 10] [bk 10]",
        "ifelse",
        ("if x > 3\n    move 10 cm\nelse\n    move backward 10 cm",),
    ),
    ("fd 10 rt 90", "fd", ("move 10 cm\nturn right 90 degrees",)),
    # iRobot Python SDK
    ("await robot.arc_right(90, 10)", "await", ("arc right 90 degrees radius 10 cm",)),
    ("await robot.set_wheel_speeds(5, -5)", "await", ("set wheels left 5 cm/s right -5 cm/s",)),
    ('await robot.say("Hello")', "await", ('say "Hello"',)),
    ("robot.set_lights_spin_rgb(0, 128, 255)", "robot", ("light spin rgb 0 128 255",)),
    ("robot = Root(Bluetooth())", "robot", ("",)),
    # words and phrasings children invent
    ("go forward 10 cm", "go", ("move forward 10 cm",)),
    ("turn around", "around", ("turn right 180 degrees", "turn left 180 degrees")),
    ("wait for 3 seconds", "for", ("wait 3 seconds",)),
    ("move 10 cm and turn right 90 degrees", "and", ("move 10 cm\nturn right 90 degrees",)),
    ("turn right 90 degrees 4 times", "4", ("repeat 4\n    turn right 90 degrees",)),
    ("increase x by 2", "increase", ("change x by 2",)),
    ("marker on", "on", ("marker down",)),
    ("stop everything", "everything", ("stop all",)),
]

# This round's own set, written down (with the right answers) before the code was changed for
# it: Scratch's blocks as scratchblocks writes them (`[x v]` drop-downs, round slots in headers
# and stops), Python's turtle module with any name, its set-up lines, C-style loops and
# declarations (JavaScript, Arduino, MakeCode), Logo's `ifelse` and prefix arithmetic, event
# words used as conditions. Tuned on like DEV.
DEV4: list[tuple[str, str, tuple[str, ...]]] = [
    # Scratch
    ("when [timer] > (20)", "[", ("when timer > 20 seconds",)),
    ("stop [other scripts in sprite v]", "[", ("stop other scripts",)),
    ("set [speed v] to (5)", "[", ("set speed to 5",)),
    ("change [x v] by (2)", "[", ("change x by 2",)),
    ("if <(x) < (5)> then", "<", ("if x < 5", "if (x) < (5)")),
    ("wait until <touching [edge v]?>", "<", ("wait until bumper any pressed",)),
    ("say (join [x is ] (x))", "[", ('say join("x is ", x)',)),
    ("when I receive [start v]", "I", ('when message "start" received',)),
    ("broadcast [go v] and wait", "broadcast", ('send "go" and wait',)),
    ("say (x) for (2) seconds", "for", ("say x\nwait 2 seconds",)),
    ("set [x v] to (pick random (1) to (10))", "[", ("set x to random 1 to 10",)),
    ("stop [all v]", "[", ("stop all",)),
    # Python (incl. turtle)
    ("turtle.circle(50)", "turtle", ("arc left 360 degrees radius 50 cm",)),
    ('t.pencolor("blue")', "t", ("light blue",)),
    ("turtle.setheading(180)", "turtle", ("go to x position x y position y facing 180 degrees",)),
    ("t.goto(10, -20)", "t", ("go to x 10 cm y -20 cm",)),
    ("t.home()", "t", ("go to x 0 cm y 0 cm", "go to x 0 cm y 0 cm facing 0 degrees")),
    ("turtle.color('green')", "turtle", ("light green",)),
    ("t = turtle.Turtle()", "t", ("",)),
    ("turtle.exitonclick()", "turtle", ("",)),
    ("global count", "global", ("",)),
    ("print('x is', x)", "'", ('print "x is", x',)),
    # JavaScript, MakeCode, Arduino
    ("for(;;){", "for", ("forever", "repeat forever")),
    ("for (var i = 0; i < 8; i++) {", "for", ("repeat 8",)),
    ("for (let i = 10; i > 0; i--) {", "for", ("repeat 10",)),
    ("for (int i = 0; i < 5; i++) {", "for", ("repeat 5",)),
    ("while (1) {", "while", ("forever", "repeat forever")),
    ("delay(250);", "delay", ("wait 250 ms",)),
    ("basic.pause(500)", "basic", ("wait 500 ms",)),
    ("basic.forever(function () {", "basic", ("forever", "repeat forever")),
    ("void loop() {", "void", ("forever", "repeat forever")),
    ("int speed = 10;", "int", ("set speed to 10",)),
    ("Serial.println(x);", "Serial", ("print x",)),
    ('basic.showString("Hi")', "basic", ('say "Hi"', 'print "Hi"')),
    ("music.playTone(262, 500)", "music", ("play 262 Hz for 500 ms",
                                           "play 262 Hz for 0.5 seconds")),
    # turtle Logo
    ("ifelse :x < 5 [rt 90] [lt 90]", "ifelse",
     ("if x < 5\n    turn right 90 degrees\nelse\n    turn left 90 degrees",)),
    ("if :x = 3 [pu fd 5]", ":", ("if x = 3\n    marker up\n    move 5 cm",)),
    ("pu home pd", "pu", ("marker up\ngo to x 0 cm y 0 cm\nmarker down",)),
    ("print sum :x 1", "sum", ("print x + 1",)),
    # iRobot's Python SDK
    ("await robot.set_wheel_speeds(left=10, right=10)", "await",
     ("set wheels left 10 cm/s right 10 cm/s",)),
    # words children invent
    ("if bumped", "bumped", ("if bumper any pressed",)),
    ("wait until bumped", "bumped", ("wait until bumper any pressed",)),
    ("move forward 10 steps", "steps", ("move forward 10 cm",)),
    ("go backwards 5 cm", "go", ("move backward 5 cm",)),
    ("say hi 3 times", "3", ('repeat 3\n    say "hi"',)),
    ("repeat 4x", "4x", ("repeat 4",)),
]  # fmt: skip

# A fourth set by another hand (from the docs alone, never running rootlang), measured before
# this round's changes landed: 31/40 at f540774. Its misses were then seen, and mended as
# families (MakeCode's calls, Arduino's C, turtle colours, units written out, `plus`).
OTHER_HAND_4: list[tuple[str, str, tuple[str, ...]]] = [
    # Scratch
    ("turn clockwise 15 degrees", "clockwise", ("turn right 15 degrees",)),
    ("think [Hello!]", "think", ('say "Hello!"', 'print "Hello!"')),
    ("stop [all]", "[", ("stop all",)),
    ("broadcast [ready] and wait", "broadcast", ('send "ready" and wait',)),
    ("when this sprite clicked", "this", ("when touched",)),
    ("play note 60 for 0.5 beats", "60", ("play note C4 for 0.5 seconds",)),
    ("when flag clicked", "flag", ("when started",)),
    ("set [x] to (pick random 1 to 10)", "[", ("set x to random 1 to 10",)),
    # Python (with turtle)
    ("t.forward(100)", "t", ("move 100 cm", "move forward 100 cm")),
    ("turtle.left(120)", "turtle", ("turn left 120 degrees",)),
    ("pendown()", "pendown", ("marker down", "pen down")),
    ('turtle.pencolor("green")', "turtle", ("light green",)),
    ("turtle.done()", "turtle", ("",)),
    ("from turtle import *", "from", ("",)),
    ("sleep(2)", "sleep", ("wait 2 seconds",)),
    ('print(str(x) + " points")', "str", ('print join(x, " points")', 'print(join(x, " points"))')),
    # JavaScript / MakeCode / Arduino
    ("var count = 0;", "var", ("set count to 0",)),
    ("basic.pause(500)", "basic", ("wait 500 ms", "wait 0.5 seconds")),
    ("basic.forever(function () {", "basic", ("forever", "repeat forever")),
    ('basic.showString("Hi")', "basic", ('say "Hi"', 'print "Hi"')),
    ("void setup() {", "void", ("when started",)),
    ("Serial.println(x);", "Serial", ("print x",)),
    ("int steps = 4;", "int", ("set steps to 4",)),
    # turtle Logo
    ("forward 50", "forward", ("move 50 cm", "move forward 50 cm")),
    ("left 45", "left", ("turn left 45 degrees",)),
    ("back 10", "back", ("move backward 10 cm", "move -10 cm")),
    ("penerase", "penerase", ("eraser down",)),
    ('make "size 20', "make", ("set size to 20",)),
    ("to square :size", ":size", ("to square size",)),
    # iRobot Python SDK
    ("await robot.set_wheel_speeds(5, -5)", "await", ("set wheels left 5 cm/s right -5 cm/s",)),
    ("await robot.wait(1.5)", "await", ("wait 1.5 seconds",)),
    ("await robot.set_lights_spin_rgb(255, 255, 0)", "await", ("light spin rgb 255 255 0",)),
    ("await robot.arc_right(90, 10)", "await", ("arc right 90 degrees radius 10 cm",)),
    ("robot.play()", "robot", ("",)),
    # invented words / mixed habits
    ("go forward 10 cm", "go", ("move forward 10 cm", "move 10 cm")),
    ("turn around", "around", ("turn right 180 degrees", "turn left 180 degrees")),
    ("wait 1 minute", "minute", ("wait 60 seconds", "wait 60000 ms")),
    ("marker on", "on", ("marker down", "pen down")),
    ("set x to x plus 1", "plus", ("set x to x + 1", "change x by 1")),
    ("if x is 3", "is", ("if x = 3",)),
]

_WRITE = re.compile(r"Write(?: these lines)?: ?(.*)$", re.S)


def shown_fix(message: str) -> str | None:
    """The line(s) a message says to write, as lines without the indentation of the line."""
    found = _WRITE.search(message)
    if found is None:
        return None
    # the line(s) to write end where the message goes on with a sentence of its own (E036)
    first, *rest = found.group(1).split("\n")
    if first.strip():
        return "\n".join(re.findall(r"`([^`]*)`", first))
    lines = list(itertools.takewhile(lambda line: line[:1].isspace(), rest))
    base = min((len(line) - len(line.lstrip()) for line in lines), default=0)
    return "\n".join(line[base:].rstrip() for line in lines)


def _same(a: str, b: str) -> bool:
    def norm(text: str) -> list[str]:
        return [" ".join(line.lower().split()) + f"@{len(line) - len(line.lstrip())}"
                for line in text.split("\n") if line.strip()]  # fmt: skip

    return norm(a) == norm(b)


def _same_program(program: str, number: int, fix: str, wanted: str) -> bool:
    """Whether the program with the fix in place of line ``number`` is the program with the
    wanted line there, as `rootlang format` writes them (`round(x)` is `round x`)."""
    lines = program.split("\n")
    indent = lines[number - 1][: len(lines[number - 1]) - len(lines[number - 1].lstrip())]

    def written(answer: str) -> str | None:
        placed = [indent + part for part in answer.split("\n")] if answer else []
        try:
            return format_source("\n".join(lines[: number - 1] + placed + lines[number:]))
        except RootlangError:
            return None

    mine = written(fix)
    return mine is not None and mine == written(wanted)


def score(line: str, word: str, fixes: tuple[str, ...]) -> tuple[bool, str]:
    # each line where a child would write it: a script or procedure header at the left edge,
    # an `else if` after an `if`, a loop with a line under it
    opening = (fixes[0] if fixes else line).split(" ")[0]
    if opening in ("when", "to"):
        program, number = f"{line}\n    move 1 cm\n", 1
    elif fixes and fixes[0].startswith("else"):
        program = f"when started\n    set x to 1\n    if x > 3\n        move 1 cm\n    {line}\n"
        program, number = program + "        move 2 cm\n", 5
    elif opening in ("repeat", "forever", "if", "while"):
        program, number = f"when started\n    set x to 1\n    {line}\n        move 1 cm\n", 3
    else:
        program, number = f"when started\n    set x to 1\n    {line}\n", 3
    said = diagnose(program, "t.root")
    mistakes = [d for d in said if d.severity == "error"]
    on_line = [d for d in mistakes if d.span.line == number]
    if not fixes:  # a habit rootlang accepts as it is: right when no mistake is found in it
        return not on_line, "accepted" if not on_line else f"told: {on_line[0].english}"
    # a line rootlang accepts as written may get a warning that shows rootlang's own word
    on_line = on_line or [d for d in said if d.span.line == number and d.severity == "warning"]
    if not on_line:
        return False, f"no mistake on the line ({[d.english for d in mistakes]})"
    first = on_line[0]
    text = program.split("\n")[number - 1]
    caret = text[first.span.column - 1 :].startswith(word)
    fix = shown_fix(first.english)
    if fix is None and fixes == ("",) and "delete" in first.english.lower():
        fix = ""
    right = fix is not None and any(
        _same(fix, wanted) or _same_program(program, number, fix, wanted) for wanted in fixes
    )
    if fix == "" and fixes == ("",):
        right = True
    return caret and right, f"caret {'ok' if caret else 'off'}: {first.english}"


# A fifth set by another hand (from the docs alone, never running rootlang), sealed all round:
# only its count was looked at until the round's end (31/40 at 89e0897, before the round's
# changes; 37/40 on dd97feb; 39/40 on the round's last habits, 5baad9a). Then its one miss was
# seen (`play C4`: a note written without `note`) and mended as a kind of value.
OTHER_HAND_5: list[tuple[str, str, tuple[str, ...]]] = [
    # Scratch
    ("play note 60 for 0.5 beats", "60", ("play note C4 for 0.5 seconds",)),
    ("broadcast go and wait", "broadcast", ('send "go" and wait',)),
    ("when this sprite clicked", "this", ("when touched",)),
    (
        "think Hmm for 2 seconds",
        "think",
        ('say "Hmm"\nwait 2 seconds', 'print "Hmm"\nwait 2 seconds'),
    ),
    ("stop other scripts in sprite", "in", ("stop other scripts",)),
    ("if <x > 5> then", "<", ("if x > 5", "if x > 5 then")),
    (
        "point in direction 180",
        "point",
        (
            "go to x position x y position y facing -90 degrees",
            "go to x position x y position y facing 270 degrees",
        ),
    ),
    ("set x to pick random 1 to 10", "pick", ("set x to random 1 to 10",)),
    # Python (with turtle)
    ("from turtle import *", "from", ("",)),
    ("t.left(90)", "t", ("turn left 90 degrees",)),
    ("turtle.penup()", "turtle", ("marker up",)),
    ("turtle.backward(30)", "turtle", ("move backward 30 cm", "move -30 cm")),
    ("turtle.done()", "turtle", ("",)),
    ("pass", "pass", ("",)),
    ("def spin():", "def", ("to spin",)),
    ("for i in range(1, 5):", "for", ("repeat 4",)),
    # JavaScript / MakeCode / Arduino
    ("basic.pause(500)", "basic", ("wait 500 ms", "wait 0.5 seconds")),
    ('basic.showString("Hi")', "basic", ('say "Hi"', 'print "Hi"')),
    ("basic.forever(function () {", "basic", ("forever", "repeat forever")),
    ("var count = 0;", "var", ("set count to 0",)),
    ("Serial.println(x);", "Serial", ("print x",)),
    ("tone(8, 440, 500);", "tone", ("play 440 Hz for 500 ms", "play 440 Hz for 0.5 seconds")),
    ("function zigzag() {", "function", ("to zigzag",)),
    # Logo
    ("lt 45", "lt", ("turn left 45 degrees",)),
    ("back 20", "back", ("move backward 20 cm", "move -20 cm")),
    ('make "size 10', "make", ("set size to 10",)),
    ("to square :size", ":size", ("to square size",)),
    (
        "repeat 3 [forward 50 left 120]",
        "[",
        (
            "repeat 3\n    move 50 cm\n    turn left 120 degrees",
            "repeat 3\n    move forward 50 cm\n    turn left 120 degrees",
        ),
    ),
    ("right 90", "right", ("turn right 90 degrees",)),
    # iRobot SDK
    ("await robot.arc_right(90, 15)", "await", ("arc right 90 degrees radius 15 cm",)),
    ("await robot.set_wheel_speeds(5, -5)", "await", ("set wheels left 5 cm/s right -5 cm/s",)),
    ("await robot.reset_navigation()", "await", ("reset position",)),
    ("await robot.set_lights_spin_rgb(0, 0, 255)", "await", ("light spin rgb 0 0 255",)),
    (
        "@event(robot.when_touched, [True, False, False, False])",
        "@event",
        ("when touch front left pressed",),
    ),
    # invented words / mixed habits
    ("turn clockwise 30 degrees", "clockwise", ("turn right 30 degrees",)),
    ("go forward 10 cm", "go", ("move forward 10 cm", "move 10 cm")),
    ("wait for 2 seconds", "for", ("wait 2 seconds",)),
    ("turn around", "around", ("turn right 180 degrees", "turn left 180 degrees")),
    ("set x to x plus 1", "plus", ("set x to x + 1", "change x by 1")),
    ("play C4 for 1 second", "C4", ("play note C4 for 1 second",)),
]


SETS = {  # python benchmarks/habits.py [-v] [SET ...]: these sets, else all of them
    "held_out": ("held-out habits", HELD_OUT),
    "after": ("habits seen after", HELD_OUT_AFTER),
    "last": ("habits written last", HELD_OUT_NEW),
    "dev": ("habits tuned on in the last round (DEV)", DEV),
    "dev2": ("habits tuned on in the last round, second batch (DEV2)", DEV2),
    "dev3": ("habits tuned on in the last round, third batch (DEV3)", DEV3),
    "set_aside": ("habits set aside in the last round", SET_ASIDE),
    "other": ("habits by another hand, seen during the round", OTHER_HAND),
    "other2": ("habits by another hand, seen at the end of the round", OTHER_HAND_2),
    "other3": ("habits by another hand, seen at the very end (31/40 before)", OTHER_HAND_3),
    "dev4": ("habits tuned on in this round (DEV4)", DEV4),
    "other4": ("habits by another hand, seen mid-round (31/40 before)", OTHER_HAND_4),
    "other5": ("habits by another hand, sealed until the round's end (39/40 then)", OTHER_HAND_5),
}


def main() -> None:
    verbose = "-v" in sys.argv
    chosen = [arg for arg in sys.argv[1:] if not arg.startswith("-")]
    for key, (name, cases) in SETS.items():
        if chosen and key not in chosen:
            continue
        start = time.perf_counter()
        good = 0
        for line, word, fixes in cases:
            ok, why = score(line, word, fixes)
            good += ok
            if verbose or not ok:
                print(f"{'ok ' if ok else 'NO '} {line!r}: {why}")
        took = time.perf_counter() - start
        share = 100 * good / len(cases)
        print(f"{name}: {good}/{len(cases)} = {share:.0f}% with the caret on the word and a "
              f"right fix ({took / len(cases) * 1000:.0f} ms a program)")  # fmt: skip


if __name__ == "__main__":
    main()
