"""The one catalogue of messages people see, keyed by code.

Messages are written for a 10-year-old: say what happened and what to do, in plain words,
never a token name. Values in braces are filled in by the code that reports the problem.
Codes are grouped by the part of rootlang that reports them; keep each section sorted.

| range | reported by |
|---|---|
| E0xx | reading a program: syntax (rootlang.grammar) |
| E1xx | checking a program: names, units, events (rootlang.checks) |
| E2xx | running a program (rootlang.runtime) |
| E3xx | world files and the simulator (rootlang.sim) |
| E4xx | finding and talking to robots (rootlang.ble, transports) |
| E5xx | packets (rootlang.protocol) |
| E6xx | golden tests and the command line (rootlang.testing, rootlang.cli) |
| E7xx | blocks and formatting (rootlang.blocks, rootlang.formatting) |
| E8xx | the studio (rootlang.studio) |
| E9xx | programs in other languages (rootlang.locale) |
| W1xx | warnings found while checking |
| V0xx | not problems: the words of a run's child's view (rootlang.runtime.trace, the studio) |
| V1xx | not problems: `rootlang test`'s report (rootlang.testing.runner) |
| V2xx | not problems: a paused run, its scripts and values (rootlang.runtime.debugger) |
| V3xx | not problems: an adventure's hints, what a run did differently (rootlang.adventures) |
"""

from __future__ import annotations

MESSAGES: dict[str, str] = {
    # --- E0xx: syntax (rootlang.grammar) ---
    "E001": "I didn't expect {found} here. I was expecting {expected}.{suggestion}",
    "E002": 'This text has no closing quote. Put a " at the end of the text.',
    "E003": "This line is indented with a mix of tabs and spaces. "
    "Indent with spaces only (4 for each step).",
    "E004": "`{command}` can't stand at the left edge on its own. "
    "Put it inside a script: indent it under `when started`.",
    "E005": "Use `to` in `set`: write `set {name} to ...`, not `set {name} = ...`.",
    "E006": "`repeat` needs a number of times, like `repeat 4`, "
    "or `repeat forever`, or `repeat until ...`.",
    "E007": "This `else` has no `if` before it. "
    "Put `else` right after the lines of an `if`, lined up with the `if`.",
    "E008": "This line is indented more than the line before it, "
    "but that line doesn't start a block. Line it up with the line before it{where}.",
    "E009": "This line needs some indented lines under it.",
    "E010": "This line's indentation doesn't line up with any line above it. Indent it "
    "{inner} spaces to keep it in the block above, or {outer} to end that block.",
    "E011": "I don't know the event `when {word}`.{suggestion}",
    "E012": "I don't understand the character {character} here.",
    "E013": "This line stops too early: I was expecting {expected}.",
    "E014": "I don't know the unit `{unit}`.{suggestion} Units I know: {known}.",
    "E015": "This number is too big for me.",
    "E016": "`{word}` starts something new, so it must be at the left edge, not indented.",
    "E017": "Round brackets with commas, like `(a, b)`, only go right after a procedure's name "
    "or `min`, `max` or `join`.",
    "E018": "This line is inside too many things for me to read: at most {limit} blocks can go "
    "inside each other, and at most {limit} calculations inside each other in one line. Split it "
    "into smaller steps, or make a procedure.",
    "E019": 'Text goes between double quotes, like `say "hi"`, not single quotes.',
    "E020": "A name can only use the letters a to z, digits and _, not {character} "
    "(in text between double quotes any letter is fine).",
    "E021": "I don't know the event `when {words}`. Events look like `when started`, "
    '`when bumped`, `when touched`, `when color red seen` or `when message "go" received`.',
    "E022": "For one side, write the event as `{event}`.",
    "E023": 'I don\'t know the {what} "{written}". Did you mean "{replacement}"?{more}{write}',
    "E024": "A word is missing before `{written}`: I was expecting `{replacement}`.{write}",
    "E025": "`{written}` doesn't belong here.{write}",
    "E026": "To give `{name}` a value, rootlang uses `set`, not `=`.{write}",
    "E027": "I can't read `{written}`: write numbers with digits only, without `e`, "
    "like `{example}`.",
    "E028": "Every line of this program is indented, and there is no `when started`. "
    "Put `when started` on the first line, at the left edge, and indent the rest under it.",
    "E029": 'I don\'t know the {what} "{written}".{more}',
    "E030": "To give `{name}` a value, write `set {name} to` and then the value.",
    "E031": "`{written}` is written that way in {source}.{write}",
    "E032": "`{written}` isn't needed: a block ends where its lines stop being indented. "
    "Delete this line.",
    "E033": "`{written}` isn't needed: everything rootlang knows is there already. "
    "Delete this line.",
    "E034": "`{written}` is written that way in {source}, not in rootlang.",
    "E035": "This program has no `when started`, so nothing in it would run. Put `when started` "
    "on the first line, at the left edge, and indent the other lines under it.",
    "E036": "`{written}` is written that way in {source}.{write}\nThen give `{name}` a value on a "
    "line before this one, like `set {name} to 0`.",
    "E037": "`{written}` only changes how things look on the screen in {source}: a robot has "
    "nothing like it. Delete this line.",
    "E038": "`{written}` is written that way in {source}.{write}\nThen move the lines under it one "
    "step to the right, under {last}.",
    # --- E1xx: checks (rootlang.checks) ---
    "E101": 'I don\'t know the command "{name}".{suggestion}',
    "E102": 'I don\'t know the name "{name}": set it first, like `set {name} to 0`.{suggestion}',
    "E103": "`{name}` needs {expected} but got {given}.",
    "E104": "There are two procedures called `{name}`. Give one of them another name.",
    "E105": "The procedure `{name}` has two parameters called `{parameter}`.",
    "E106": "`return` only works inside a procedure (a `to ...` block).",
    "E107": "`{name}` doesn't give back a value (it has no `return` with a value), "
    "so it can't be used here.",
    "E108": "{command} needs {wanted}, like `{example}`.{write}",
    "E109": "{command} needs {wanted}, like `{example}`, but this is {actual}.",
    "E110": "I can't {action} {left} and {right}.",
    "E111": "The colour sensor can only see white, black, red, green and blue, not {color}.",
    "E112": "`{keyword}` needs something true or false, like `bumper left pressed` or `x > 3`, "
    "but this is {actual}.",
    "E113": "`{function}` needs {wanted}, but this is {actual}.",
    "E114": "`{unit}` can only follow a plain number, but this is already {actual}.",
    "E115": "I can't take the square root of {value}: it is below zero.",
    "E116": "`{name}` is the name of a procedure, so it can't be used as a variable too.",
    "E117": "A `when stopped` script can light up and make sounds, but not move the robot.",
    "E118": 'I don\'t know the name "{words}". To say words, put them in double quotes.{write}',
    "E119": "`{word}` is an event: it goes after `when`, like `when {word}`. "
    "Here, `{read}` asks about {sensor}.{write}",
    "E120": "I don't know the colour `{word}`. {colours}",
    "E121": "To put text and other values together, use `join`: `join({values})`.",
    "E122": "`{name}` needs {wanted} for `{parameter}`: line {line} uses it in `{inside}`. "
    "Write `{example}`.",
    "E123": "The {robot} can drive at most {limit}, not {value}.",
    "E124": "`{word}` is an event: it goes after `when`, like `when {word}`.",
    "E125": "To put text and other values together, use `join` with the values between its "
    "brackets, separated by commas.",
    "E126": "`{name}` needs {wanted} for `{parameter}`: line {line} uses it in `{inside}`.",
    "E127": "`{number}` is a plain number, but it is compared with {wanted}: give it a unit, "
    "like `{example}`.{write}",
    "E128": "`{name}` is one of rootlang's own words, so it can't be a variable's name: where "
    "the program reads it, it would mean that word. Pick another name, like `my_{name}`.",
    # --- E2xx: run time (rootlang.runtime) ---
    "E201": "The {robot} can't do `{command}`.",
    "E202": "The {robot} has no {sensor}.",
    "E203": "The robot didn't answer `{command}` within {seconds}.",
    "E204": "I can't divide by zero.",
    "E205": "`{command}` can't use {value}: the {robot} can only do {allowed}.",
    "E206": "`{name}` called itself more than {limit} times inside itself, so I stopped it. "
    "Does it have a way to stop calling itself?",
    "E207": "The robot disconnected: {reason}.",
    "E208": "I can't talk to the robot any more: {reason}.",
    "E209": "`{name}` has no value yet: set it first, like `set {name} to 0`.",
    "E210": "`random {low} to {high}`: the first number must not be bigger than the second.",
    "E211": "`repeat` needs a whole number of times that isn't negative, not {value}.",
    "E212": "The `when stopped` scripts took longer than {seconds}, so I ended them.",
    "E213": "The robot didn't confirm `{command}` after {tries} tries: "
    "the link to it is too bad. Move closer to the robot and try again.",
    "E214": "This number is too big for me to work with (it grew past every number I can hold). "
    "Does something keep multiplying it?",
    "E215": "`{name}` called itself {depth} times, each time from inside so many calculations "
    "(brackets inside brackets) that I ran out of room. Make it call itself fewer times, or work "
    "the value out in smaller steps.",
    "E216": "This program needed more memory than this computer could give it, so I stopped it. "
    "Does something keep growing, like text joined to itself in a loop?",
    "E218": "The program stopped all of a sudden ({how}), so I stopped the robot.",
    "E219": "The program stopped all of a sudden ({how}) and the robot didn't confirm that it "
    "stopped: press its button, or pick it up.",
    "E217": "The {what} can be {low} to {high}, not {value}.",
    "E220": "This program kept the computer busy for {limit} of its time and had run for only "
    "{ran} of the robot's, so I stopped it here. Does a loop repeat forever, many times a second, "
    "without waiting?",
    # --- E3xx: worlds and the simulator (rootlang.sim) ---
    "E301": "I can't find the world file {path}.",
    "E302": "I can't read the world file {path}: {reason}.",
    "E303": "In the world file {path}, `{key}` should be {expected}, not {got}.",
    "E304": "In the world file {path}, I don't know the key `{key}`.{hint}",
    "E305": "In the world file {path}, `{key}` is missing: it should be {expected}.",
    "E306": "There is no world called {name}, neither in the worlds folder next to the program "
    "nor among rootlang's own. Worlds I know: {known}.{suggestion}",
    "E312": "I can't write the picture {path}: {reason}.",
    # --- E4xx: robots and connections (rootlang.ble) ---
    "E401": 'I couldn\'t find a robot called "{wanted}" within {seconds}. '
    "Robots I did find: {robots}.",
    "E402": "I couldn't find any robot within {seconds}. Check that the robot is "
    "switched on (its lights are on), close by and not connected to another app or tablet, "
    "and that this computer's Bluetooth is on. "
    "No robot at hand? `rootlang run --sim` uses the simulator when no robot is found.",
    "E403": "I can see {count} robots: {robots}. Touch the top of the robot you want "
    "(or choose one with --robot NAME).",
    "E404": "Nobody touched a robot within {seconds}. Robots in range: {robots}. "
    "Touch the top of one, or choose one with --robot NAME.",
    "E405": "I couldn't connect to {robot}: {reason}. Move closer and try again; if it keeps "
    "failing, switch the robot off and on again.",
    "E406": "{robot} doesn't look like a Root or Create 3 robot: it has no {part}.",
    "E407": "I can't use Bluetooth ({backend}): {reason}. Check that Bluetooth is switched on "
    "and that this program may use it. "
    "No robot at hand? `rootlang run --sim` uses the simulator when no robot is found.",
    "E408": "This needs the optional package bumble. Install it with: "
    "pip install 'rootlang[virtual]' (in rootlang's own folder: pip install -e '.[virtual]')",
    "E409": 'I couldn\'t open the Bluetooth transport "{spec}": {reason}.',
    "E410": "\"{name}\" can't be a robot's name: {reason}.",
    # --- E5xx: packets (rootlang.protocol) ---
    "E501": "A packet must be exactly 20 bytes long, but I got {length}.",
    "E502": "This packet is damaged: its checksum byte is {found} but its bytes give {expected}.",
    "E503": 'There is no packet called "{name}".{hint}',
    "E504": "{packet}: {field} must be {allowed}, not {value}.",
    "E505": '{packet} has no field called "{field}".{hint} Its fields: {fields}.',
    "E506": "{packet} needs a value for {field} ({allowed}).",
    "E507": "A packet id must be a whole number from 0 to 255, not {value}.",
    "E508": '"{text}" is not a packet in hexadecimal: {reason}.',
    "E509": "Device {device} has no {kind} numbered {command}, so I can't read this packet.",
    "E510": 'I can\'t tell which protocol version {model} firmware "{firmware}" speaks.',
    "E511": 'I can\'t read "{text}" as a value for {field}: {reason}.',
    "E512": 'Write fields as name=value, like left=100; "{text}" has no "=".',
    # --- E6xx: tests and the command line (rootlang.testing, rootlang.cli) ---
    "E601": "I can't find the file {path}.",
    "E602": "I can't read {path}: {reason}.",
    "E603": "Stopped (Ctrl-C).",
    "E604": "{path} already exists. Pick another name, or move the old file away first.",
    "E605": "{path} is not a program: programs end in .root.",
    "E606": "There is no golden file {golden} yet. If this run's output is right, "
    "save it with `rootlang test --update`.",
    "E607": "I can't find the world {world} that this line names. Name a world file in the "
    "program's own folder, or one of these worlds: {known}.{suggestion}",
    "E608": "There is no folder {path} to put the new program in.",
    "E609": "I found no .root programs in {paths}.",
    "E611": "This program was still computing after {limit} of the computer's time, "
    "so I stopped it. Does it loop forever without waiting?",
    "E612": "This program needed more memory than its cap of {limit}, so I stopped it.",
    "E613": "This program's test run crashed: {reason}.",
    "E614": "{path} is a folder, not a program. Name one .root program inside it.",
    "E615": "{path} isn't plain text, so it can't be a program. "
    "Save it as plain text (UTF-8) and try again.",
    "E616": "A program's world must be in the program's own folder, so {world} can't be used. "
    "Put the world file next to the program, or name one of these worlds: {known}.",
    "E617": "{option} is for one program, but this names {count}. "
    "Name one program, or leave {option} out to try them all.",
    "E618": "A report is written as JSON or CSV, so its file must end in .json or .csv, "
    "not {suffix}.",
    "E619": "I can't write the report {path}: {reason}.",
    "E620": "--shard wants K/N, a share K of N machines, like 2/8 (K from 1 to N), not {text}.",
    "E621": "The computer was too busy to finish testing this program within {limit}, so I "
    "stopped it. This is not the program's fault: test it again, or fewer at once (--jobs).",
    "E622": "I can't write {path}: {reason}.",
    "E699": "Something went wrong inside rootlang itself: {error}. "
    "This is our mistake, not yours. Run again with --debug and send the output to your teacher.",
    # --- E7xx: blocks and formatting (rootlang.blocks, rootlang.formatting) ---
    "E701": "This is not a blocks workspace: {reason}. "
    'A workspace looks like {{"blocks": {{"languageVersion": 0, "blocks": [...]}}}}.',
    "E702": "I don't know the block `{block}` (id {id}).",
    "E703": "The `{block}` block (id {id}) needs {needs}.",
    "E704": "The `{block}` block (id {id}) is lying outside any script. "
    "Put it under a `when` block or a `to` block, or delete it.",
    "E705": "The `{block}` block (id {id}) has {what}, which a program can't hold: {fix}",
    "E706": "{path} would be changed by `rootlang format`.",
    "E707": "These blocks don't make a program that reads back as it is written: {reason}. "
    "Change the blocks at that line.",
    "E708": "I couldn't write this program out again without changing what it does, so I left "
    "it as it was. This is our mistake, not yours: show it to your teacher.",
    # --- E8xx: the studio (rootlang.studio) ---
    "E801": "{name} can't be a program's name here. Use letters, digits, spaces, - or _, "
    "ending in .root, like my-dance.root (no folders).",
    "E802": "There is no program {name} in the class folder.",
    "E803": "There is already a program called {name}. Pick another name.",
    "E804": "The studio only answers its own page, not one from {origin}.",
    "E805": "The studio could not use this request: {reason}.",
    "E806": "The studio could not use this message: {reason}.",
    "E807": "There is no folder {path} to work in. Name a folder that exists, or leave it out "
    "to use this one.",
    "E808": "I can't read or save {name}: {reason}.",
    "E809": "Blocks are not part of this rootlang, so only the text can be edited.",
    "E810": "A program is already running. Press Stop first.",
    "E811": "This program was still computing after {limit} of the computer's time, "
    "so I stopped it. Does it loop forever without waiting?",
    "E812": "This program needed more memory than its cap of {limit}, so I stopped it.",
    "E813": "This run crashed: {reason}. This is our mistake, not yours.",
    "E814": "The studio can't listen on {host} port {port}: {reason}. "
    "Try another port with --port.",
    "E815": "Looking for robots got no answer from Bluetooth. Check that Bluetooth is on, "
    "then scan again.",
    "E816": "Connect your robot first (the button Connect a robot), or run in the simulator.",
    "E820": "The computer was too busy to finish this run within {limit}, so I stopped it. "
    "This is not your program's fault: run it again in a moment.",
    "E825": "So many programs are waiting to run that the studio can't take yours now. "
    "Press Run again in a moment.",
    "E817": "This program is too long to show as blocks ({lines} lines; blocks go up to "
    "{most}), so it opens as text only.",
    "E818": "I stopped working on this program: {reason}. The rest of the class goes on; "
    "try a shorter program, or ask your teacher.",
    "E819": "{name} was changed since you opened it (in another tab, or by someone else), so "
    "I did not save over it. Press the button Keep mine as a new program: yours is saved next "
    "to it under a new name, and {name} stays as the other one saved it.",
    # the class: pupils, the teacher's page, tasks that check themselves
    "E840": "{task} is not a task yet: its folder needs the starter {program} and the golden file "
    "{golden}.",
    "E841": "The task {task} can't be used: {reason}.",
    "E842": "Type your name first: the studio keeps each pupil's work in their own folder.",
    "E843": "{name} can't be a pupil's name. Use letters, digits, spaces, - or _ (at most 32), "
    "starting with a letter or a digit.",
    "E844": "Someone is already working as {name} on another computer. Type your own name, or ask "
    "your teacher.",
    "E845": "Hands off! Your teacher has paused the class for a moment.",
    "E846": "That is not the teacher's code. It is the code the studio printed when it started.",
    "E847": "This is the teacher's page: type the code the studio printed when it started.",
    "E848": "{name} is not the program of a task, so there is nothing to check it against.",
    "E849": "Too many wrong codes. Wait a minute, then try again.",
    "E850": "The adventure {adventure} can't be used: {reason}.",
    "E851": "{name} is not an adventure. Pick one from the list of adventures.",
    # --- E9xx: programs in other languages (rootlang.locale) ---
    "E901": 'I don\'t know the language "{language}". Write one of these: {known}.',
    "E902": "I can't translate this program to {language} without changing what it does: "
    "the name `{name}` is a word of that language. Give it another name first.",
    # --- W1xx: warnings (rootlang.checks) ---
    "W101": "{robot} has no {sensor}, so this script will never run on it.",
    "W102": "{robot} can't {action}, so this line will stop the program with an error on it.",
    "W103": "This `when stopped` script waits {duration}, but it only gets 2 seconds.",
    "W104": "This program has no `when` script, so nothing happens when it runs. "
    "Add a `when started` script with the commands to run.",
    "W105": "{robots} can drive at most {limit}, not {value} "
    "(this line would stop the program with an error).",
    "W106": "`{written}` is how {source} says it. It works, and rootlang has its own word for "
    "it.{write}",
    # --- V0xx: the child's view of a run (rootlang.runtime.trace, rootlang.studio) ---
    "V001": "the end: {by}",
    "V002": "stopped by an error",
    "V003": "the robot disconnected: {by}",
    "V004": "stopped by {by}",
    "V005": "... {times} more time, until {seconds} s",
    "V006": "... {times} more times, until {seconds} s",
    "V007": "line {line}",
    "V008": "error:",
    "V010": "`{script}` starts",
    "V011": "`{script}` finished",
    "V012": "`{script}` stopped",
    "V013": "`{script}` cancelled",
    "V014": "`{script}` error",
    "V015": "ended: finished ({by})",
    "V016": "ended: stopped ({by})",
    "V017": "ended: time_limit ({by})",
    "V018": "ended: error ({by})",
    "V019": "ended: disconnected ({by})",
    # why a run ended, as the trace records it (in English) and the view says it
    "V020": "every script finished",
    "V021": "stop all",
    "V022": "the robot's stop button",
    "V023": "Ctrl-C",
    "V024": "cancelled",
    "V025": "the time limit of {seconds} s",
    "V026": "a run-time error",
    "V027": "the Stop button",
    "V028": "the studio",
    "V029": "the page was closed",
    "V031": "the page's Bluetooth link to the robot dropped",
    "V032": "the page lost the studio",
    "V033": "this page stopped the robot: it heard nothing from the studio for {seconds} s",
    "V034": "this page stopped the robot: it was hidden for {seconds} s",
    "V035": "this page stopped the robot: the run had not stopped {seconds} s after Stop",
    # what else the runtime records of a run (in English) that a view shows
    "V030": "connected to {robot} (protocol {version})",
    # a task's check, in plain words (rootlang.testing.tasks), and who stopped a run
    "V040": "Well done: your robot did it!",
    "V041": "Your program has mistakes to fix first (they are marked in the text).",
    "V042": "Your robot ended {across} left of the target.",
    "V043": "Your robot ended {across} right of the target.",
    "V044": "Your robot ended {along} above the target.",
    "V045": "Your robot ended {along} below the target.",
    "V046": "Your robot ended {across} left of and {along} above the target.",
    "V047": "Your robot ended {across} left of and {along} below the target.",
    "V048": "Your robot ended {across} right of and {along} above the target.",
    "V049": "Your robot ended {across} right of and {along} below the target.",
    "V050": "Your robot ended in the right place, but turned {degrees}° away from the way it "
    "should face.",
    "V051": "Your robot drew nothing, but the task wants a drawing.",
    "V052": "Your drawing misses the target's line at x {x}, y {y}: the nearest line you drew is "
    "{distance} away.",
    "V053": "Your robot drew a line where the target has none, at x {x}, y {y} ({distance} from "
    "the target's lines).",
    "V054": "Your robot drew a line at x {x}, y {y}, but the task wants no drawing.",
    "V055": "Your robot ended in the right place, but did it differently from the target, from "
    "line {line} of your program on.",
    "V056": "Your robot did something different from the target.",
    "V057": "Your program stopped with an error on line {line}. Run it to see the error.",
    "V058": "the teacher",
    # what `rootlang new` and `rootlang format` say they did
    # why a file could not be read or written (the {reason} of E302, E312, E602, E619, E622)
    "V063": "it isn't plain text (UTF-8)",
    "V064": "there is no such file or folder",
    "V065": "it is a folder",
    "V066": "I'm not allowed to (no permission)",
    "V067": "the disk is full",
    "V068": "it can only be read, not written",
    "V060": "Wrote {path}. Try it in the simulator, then open {picture} to see what it drew:",
    "V061": "formatted {path}",
    "V062": "Files formatted: {changed}. Already in canonical form: {unchanged}.",
    # what the studio leaves out of a run's text, so no run floods the server or the page
    "V070": "… (cut: the studio shows at most {count} characters of a line)",
    "V071": "… more was printed: the studio shows the first {count} printed lines of a run",
    "V072": "… more was said: the studio shows the first {count} things said in a run",
    "V073": "… the run went on: the studio shows the first {count} lines of what happened",
    # a run waiting for a free place (the studio's cap on runs at once), and one replaced
    "V074": "Waiting for a free place… (number {place} in the queue)",
    "V075": "your new run",
    # the starter program `rootlang new` and the studio's New write: its first comment, and what
    # its robot says at the end
    "V076": "{name}.root: my first program "
    "(change it, then try it with `rootlang sim {command_line}`)",
    "V077": "I drew a square",
    # why the studio stopped working on a program (E818's {reason})
    "V080": "it took more than {seconds} seconds",
    "V081": "it needed more than {limit} MB of memory",
    "V082": "its blocks are nested too deep",
    "V083": "the worker doing it crashed",
    "V084": "the studio is stopping",
    # `rootlang check`'s last line, and the label of a warning
    "V090": "Mistakes: {errors}. Warnings: {warnings}. Programs checked: {checked}.",
    "V091": "warning:",
    # the child's view: a command cut short, and wheels that stalled
    "V092": "line {line}: {command} — stopped after {seconds} s: line {by} started a new one",
    "V093": "line {line}: {command} — stopped after {seconds} s by a newer command",
    "V094": "the robot pushed against something for {seconds} s",
    "V095": "the robot ran into something and its wheels got stuck",
    "V096": "line {line}: {command} — stopped at once: line {by} started a new one",
    "V097": "line {line}: {command} — stopped at once by a newer command",
    "V098": "No mistakes found. Programs checked: {checked}.",
    # --- V1xx: `rootlang test`'s report (its outcomes, headlines and last lines) ---
    "V100": "passed",
    "V101": "updated",
    "V102": "failed",
    "V103": "no golden file",
    "V104": "over the CPU-time limit",
    "V105": "not finished in time (the computer was too busy)",
    "V106": "over the memory cap",
    "V107": "crashed",
    "V110": "FAILED {program}: {reason}",
    "V111": "FAILED {program}: its output differs from {golden}",
    "V112": "NOT FINISHED {program}: the computer was too busy to finish it in time",
    "V114": "updated {golden}",
    "V115": "The first difference comes from line {line} of {program}:",
    "V116": "{golden} (expected)",
    "V117": "this run",
    "V118": "1 program in {seconds} s: {outcomes}",
    "V119": "{count} programs in {seconds} s: {outcomes}",
    "V120": "({count} ran until their simulated time limit)",
    "V121": "nothing to test",
    "V122": "If the new output is right, run again with --update to save it.",
    # --- V2xx: a paused run: where its scripts are, and its values (rootlang.runtime.debugger) ---
    "V200": "`{script}`: about to do `{command}` (line {line})",
    "V201": "`{script}`: waiting for `{command}` to end (line {line})",
    "V202": "`{script}`: not running, waiting for its event",
    "V203": "`{script}`: finished",
    "V204": "After {seconds} s:",
    "V205": "The robot is at x {x} cm, y {y} cm, heading {heading}°.",
    "V206": "{name} is now {value}",
    "V207": "{name} = {value} (in `{script}`)",
    "V208": "`{procedure}` is running with {parameters}",
    "V209": "The loop on line {line} is in round {round} of {count}.",
    "V210": "The loop on line {line} is in round {round}.",
    "V211": "Bumpers pressed: {keyword}.",
    "V212": "Touched: {keyword}.",
    "V213": "Colours under the sensors, left to right: {colors} "
    "(W white, K black, R red, G green, B blue).",
    "V214": "Light: left {left} %, right {right} %.",
    "V215": 'Message "{message}" was sent by `{script}`.',
    "V216": '`{script}` sent message "{message}" and waits for its scripts to end.',
    "V217": "Playing: {note}.",
    "V218": "none",
    "V219": "{name} = {value}",
    "V220": "`{script}`: started, its first line is `{command}` (line {line})",
    # --- V3xx: adventures: what a run did differently from the goal (rootlang.adventures) ---
    "V300": "The goal's robot does something {event}, but yours does nothing then.",
    "V301": "Your robot never turns, but the goal's robot does.",
    "V302": 'The goal\'s robot does something when the message "{name}" comes, '
    "but yours never gets it: is it sent?",
    "V303": "Your drawing has {count} sides, but the goal's has {goal}.",
    "V304": "Your robot turned {count} times, but the goal's robot turns {goal} times.",
    "V305": "At turn {number}, your robot turned left, but the goal's robot turns right.",
    "V306": "At turn {number}, your robot turned right, but the goal's robot turns left.",
    "V307": "At turn {number}, your robot turned less than the goal's robot does.",
    "V308": "At turn {number}, your robot turned more than the goal's robot does.",
    "V309": "Your robot stopped {distance} short: the goal's robot drives {distance} further.",
    "V310": "Your robot went {distance} too far: the goal's robot drives {distance} less.",
    "V311": "The goal's robot lights up {colour}, but yours never does.",
    "V312": "Your robot lit up {colour}, but the goal's robot lights up {goal} there.",
    "V313": "Your robot played {count} notes, but the goal's robot plays {goal}.",
    "V314": "Your robot said {count} things, but the goal's robot says {goal}.",
    "V315": 'Thing number {number} your robot said, "{said}", '
    "is not what the goal's robot says there.",
    "V316": "This adventure wants you to make a block of your own (`to ...`) and use it.",
    "V317": "This adventure wants you to use a variable (`set ... to ...`).",
    "V318": "This adventure wants you to use a loop (`repeat`).",
    "V319": "This adventure wants you to send a message (`send ...`).",
}
