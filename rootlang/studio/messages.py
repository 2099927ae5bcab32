"""The contract between the studio's server and its page: every HTTP body and WebSocket message.

Described once, here, as TypedDicts: the server builds its replies as these types (mypy checks
it), ``static/messages.d.ts`` is written from them (``python -m rootlang.studio.messages``) and
the page's JavaScript names them in its JSDoc (``tsc --checkJs`` checks it), and the tests check
what the server really sends against them (:func:`rootlang.jstypes.problems`). The replay page's
data (:class:`rootlang.sim.render.html.PageData`) is written the same way, as
``rootlang/sim/render/page_data.d.ts``.

The page branches on a message's ``type`` and a diagnostic's ``code``, never on its words (those
are in the page's language).
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Literal, TypedDict

from rootlang.jstypes import declarations
from rootlang.sim.render import html

# --- what every reply may carry ------------------------------------------------------------------


class DiagnosticJson(TypedDict):
    """A mistake, warning or refusal: its catalogue code, where (1-based lines and columns; 0
    when it is about no place), and its message in the page's language, also as rendered text."""

    file: str
    line: int
    column: int
    end_line: int
    end_column: int
    code: str
    severity: Literal["error", "warning"]
    message: str
    rendered: str


class ErrorsReply(TypedDict):
    """Any refused HTTP request (status 4xx/5xx)."""

    errors: list[DiagnosticJson]


# --- HTTP -----------------------------------------------------------------------------------------


class ProgramFileJson(TypedDict):
    name: str
    size: int
    modified: float


class PictureMeaning(TypedDict):
    """What a Level 1 block says aloud: ``words`` (``{n}`` its number, ``{what}`` its picture
    menu's choice), ``one`` for the number 1 ("" as ``words``), ``what`` each choice in words."""

    words: str
    one: str
    what: dict[str, str]


class PicturesSetup(TypedDict):
    """Level 1: its toolbox, and what each picture block says (its definitions are among the
    blocks')."""

    toolbox: dict[str, object]
    meanings: dict[str, PictureMeaning]


class BlocksSetup(TypedDict):
    definitions: list[dict[str, object]]  # Blockly's JSON block definitions
    toolbox: dict[str, object]  # Blockly's JSON toolbox
    pictures: PicturesSetup


class SetupInLanguage(TypedDict):
    strings: dict[str, str]  # the page's words, by key
    english: dict[str, str]  # the same in English (the words the page's HTML holds)
    blockly_messages: str  # the address of Blockly's own words file
    blocks: BlocksSetup | None  # None: rootlang.blocks is not in this build
    syntax: dict[str, list[str]]  # the text pane's coloured words, by CodeMirror token name
    light_colours: dict[str, str]  # the language's colours a light shows, name -> "#rrggbb"


class BluetoothProfile(TypedDict):
    """The robots' GATT as the page links one over Web Bluetooth (``rootlang.ble.profile``):
    what the browser's chooser filters on (the Root Identifier service, or iRobot's company id
    in the manufacturer data) and the UUIDs the page uses."""

    identifier: str
    company: int
    uart: str
    rx: str  # packets to the robot (write with response)
    tx: str  # packets from the robot (notify)
    information: str  # Device Information
    serial: str
    firmware: str
    hardware: str


class SetupReply(SetupInLanguage):
    """``GET /api/setup``."""

    folder: str
    programs: list[ProgramFileJson]
    worlds: list[str]
    speeds: list[float]
    languages: dict[str, str]  # code -> the language's name in itself
    language: str
    bluetooth: BluetoothProfile


class ProgramReply(TypedDict):
    """``GET /api/program?name=``."""

    name: str
    text: str
    version: str  # the file's version: a Save sends it back (E819 if the file changed since)
    layout: dict[str, object]  # the blocks' places (the sidecar); {} when there is none


class _Named(TypedDict):
    name: str
    text: str


class SaveRequest(_Named, total=False):
    """``PUT /api/program``: ``version`` is the one the page opened or last saved (left out,
    the file is saved whatever it holds); ``as_written``: saved as it is, not formatted (a
    program too long to convert in time would be too long to format too)."""

    layout: dict[str, object]
    version: str
    as_written: bool


class NameRequest(TypedDict):
    """``POST /api/program`` (a new program from the starter)."""

    name: str


class SavedReply(TypedDict):
    """``PUT`` and ``POST /api/program``: the text as written (canonical when it parses),
    and its version now."""

    name: str
    text: str
    version: str


class RenameRequest(TypedDict):
    """``POST /api/rename``."""

    old: str
    new: str


class RenamedReply(TypedDict):
    name: str


class _TextRequest(TypedDict):
    text: str
    name: str


class TextRequest(_TextRequest, total=False):
    """``POST /api/blocks``: text to turn into blocks (``level`` 1: picture blocks where a
    line has one)."""

    level: int


class StageRequest(TypedDict):
    """``POST /api/stage``: the stage before a run (``world``: the page's choice, "" for the
    program's own); the answer is :class:`StageData`."""

    name: str
    text: str
    world: str


class _BlocksReply(TypedDict):
    workspace: dict[str, object] | None  # Blockly's workspace serialization
    diagnostics: list[DiagnosticJson]


class BlocksReply(_BlocksReply, total=False):
    """The text's blocks (None when it does not parse, or when ``text_only`` says (E817) the
    program is too long for blocks) and what the checks say about it."""

    text_only: DiagnosticJson
    above: list[str]  # asked for Level 1: the blocks with no picture (their text ids)


class _WorkspaceRequest(TypedDict):
    workspace: dict[str, object]
    name: str


class WorkspaceRequest(_WorkspaceRequest, total=False):
    """``POST /api/text``: blocks to turn into text (``level`` 1: the text's own blocks as
    Level 1's)."""

    level: int


class LeftOutJson(TypedDict):
    """A top block not in the text (loose, or a script not finished): ``top`` its id, ``block``
    the block inside it at fault ("" when the reason names none), and why (E70x)."""

    top: str
    block: str
    diagnostic: DiagnosticJson


class TextReply(TypedDict):
    """The text of the complete scripts, its own blocks (as ``POST /api/blocks`` answers them
    for ``text``: ids from its lines), and the top blocks left out of it."""

    text: str
    workspace: dict[str, object]
    diagnostics: list[DiagnosticJson]
    left_out: list[LeftOutJson]


class RobotJson(TypedDict):
    name: str
    address: str
    model: str | None
    battery: int | None
    rssi: int
    touched: bool


class RobotsReply(TypedDict):
    """``GET /api/robots``: the robots in range, strongest first."""

    robots: list[RobotJson]


# --- the WebSocket: from the page -----------------------------------------------------------------


class _Run(TypedDict):
    type: Literal["run"]
    name: str
    text: str
    world: str  # "" for the program's own
    speed: float  # one of the setup's speeds (0: as fast as it goes)
    robot: str | None  # a robot's address, or None for the simulator


class RunMessage(_Run, total=False):
    """Run this text (``name`` is the program it is, for its folder and its own world); with
    ``link`` "page", on the robot this page has linked (Web Bluetooth); a simulated run pauses
    at its ``breakpoints`` (source lines)."""

    link: Literal["page"] | None
    breakpoints: list[int]


class _Debug(TypedDict):
    type: Literal["debug"]
    action: Literal["pause", "resume", "step", "breakpoints", "timeline"]


class DebugMessage(_Debug, total=False):
    """A simulated run's Pause, Resume or Step, or its new ``breakpoints`` (source lines)."""

    breakpoints: list[int]


class RobotLinkedMessage(TypedDict):
    """The page linked a robot over Web Bluetooth: its name and Device Information."""

    type: Literal["robot_linked"]
    name: str
    serial: str
    firmware: str
    hardware: str


class RobotUnlinkedMessage(TypedDict):
    type: Literal["robot_unlinked"]


class _RobotWritten(TypedDict):
    type: Literal["robot_written"]
    n: int


class RobotWrittenMessage(_RobotWritten, total=False):
    """The page wrote packet ``n`` to its robot (or could not: ``error``)."""

    error: str | None


class RobotNotifyMessage(TypedDict):
    """A packet from the page's robot (its TX notification), 40 hex digits."""

    type: Literal["robot_notify"]
    data: str


class RobotLostMessage(TypedDict):
    """The page's robot's link dropped (a GATT disconnect): the run on it ends."""

    type: Literal["robot_lost"]


class RobotStoppedMessage(TypedDict):
    """The page stopped its robot itself, and why (its safety rules: the studio was quiet, the
    tab hidden, the run not stopped after Stop, the page closing, the socket lost): the run on
    it ends, saying so. Sent at once, or when the socket is back."""

    type: Literal["robot_stopped"]
    why: Literal["silence", "hidden", "stop", "pagehide", "socket"]


class _Stimulus(TypedDict):
    type: Literal["stimulus"]
    action: Literal["touch", "bump", "nose"]


class StimulusMessage(_Stimulus, total=False):
    """A hand on the robot: ``touch`` (with ``sensors``), ``bump`` (with ``sensors``) or
    ``nose``."""

    sensors: list[str]


class StopMessage(TypedDict):
    """Stop: the nose button (``when stopped`` scripts run)."""

    type: Literal["stop"]


# --- the WebSocket: to the page -------------------------------------------------------------------


class WorldJson(TypedDict):
    name: str
    model: str


class StageData(html.PageData):
    """The stage: the replay page's data, and the world it shows."""

    world: WorldJson


class WaitingMessage(TypedDict):
    """The run waits for a free place (the studio's cap on runs at once): ``place`` in the
    queue, and the words that say so in the page's language; told again as the queue moves.
    ``started`` follows once it runs (or ``ended``, if it is stopped or replaced first)."""

    type: Literal["waiting"]
    place: int
    message: str


class _Started(TypedDict):
    type: Literal["started"]
    stage: StageData | None


class StartedMessage(_Started, total=False):
    """A run started: in the simulator with ``stage`` (and its time limit and speed), on a
    robot with ``stage`` None and the ``robot`` described."""

    time_limit: float
    speed: float
    robot: str


class InkPiece(TypedDict):
    """Stroke ``i``'s points from its point ``from`` on (flat x, y in mm): replaces the rest."""

    i: int
    kind: str  # "marker" or "eraser"
    color: str | None
    w: float
    p: list[float]


InkPieceFrom = TypedDict("InkPieceFrom", {"from": int})  # ("from" is a Python word)


class Ink(InkPiece, InkPieceFrom):
    """One stroke's new points."""


class PoseJson(TypedDict):
    x: float
    y: float
    h: float
    led: str | None  # "#rrggbb", or None when the light is off
    led_mode: str


class _FrameBase(TypedDict):
    type: Literal["frame"]
    t: float  # the run's time, s
    ink: list[Ink]
    running: dict[str, int]  # script -> the line it is at now
    printed: list[str]  # new since the last frame
    said: list[str]
    notes: list[NoteJson]  # begun since the last frame (the page plays them)
    # what the robot felt since the last frame, as its replay's timeline names it ("bumper
    # left", "touch front left", "nose button", "cliff"): the page says it to a screen reader
    happened: list[str]
    sent_at: float  # the worker's wall clock (s since 1970), to measure the lag
    n: int  # the frame's number in its run (from 1): a page that fell behind gets frames merged


class FrameMessage(_FrameBase, total=False):
    """About 25 a second while a run goes on; ``pose`` in the simulator."""

    pose: PoseJson


class PlaceJson(TypedDict):
    """Where one script of a paused run is (rootlang.runtime.debugger.Place), and in words."""

    script: str
    state: Literal["next", "starting", "running", "waiting", "finished"]
    line: int
    span: list[int] | None
    words: str


class NamedJson(TypedDict):
    name: str
    value: str
    script: str


class CallJson(TypedDict):
    script: str
    procedure: str
    parameters: list[NamedJson]


class LoopJson(TypedDict):
    script: str
    line: int
    round: int
    count: int


class SentJson(TypedDict):
    message: str
    by: str
    waiting: bool


class WatchPoseJson(TypedDict):
    x_mm: float
    y_mm: float
    heading_degrees: float


class WatchJson(TypedDict):
    """A paused run's values (rootlang.runtime.debugger.Watch)."""

    time_s: float
    variables: list[NamedJson]
    calls: list[CallJson]
    loops: list[LoopJson]
    bumpers: list[str]
    touched: list[str]
    colors: str
    light_percent: list[float]
    pose: WatchPoseJson
    messages: list[SentJson]
    note: str


class PausedMessage(TypedDict):
    """A simulated run paused (``reason``: step, breakpoint, pause, time): where each script
    is and the values; nothing of the run goes on until Resume, Step or Stop."""

    type: Literal["paused"]
    reason: Literal["step", "breakpoint", "pause", "time"]
    places: list[PlaceJson]
    watch: WatchJson
    lines: list[str]


class WatchMessage(TypedDict):
    """A paced run's places and values as it goes (about five times a second; a pause's are
    exact)."""

    type: Literal["watch"]
    places: list[PlaceJson]
    watch: WatchJson
    lines: list[str]


class ResumedMessage(TypedDict):
    """The paused run goes on (``step``: until the next statement of any script begins)."""

    type: Literal["resumed"]
    step: bool


class MomentProgramJson(TypedDict):
    """The program's part of a moment (rootlang.runtime.timeline.ProgramState): where each
    script is, the variables and calls (to see a value change), and the Watch panel's lines:
    ``values`` (variables, calls, loops) and ``messages``."""

    places: list[PlaceJson]
    variables: list[NamedJson]
    calls: list[CallJson]
    values: list[str]
    messages: list[str]


class TimelineJson(TypedDict):
    """A simulated run's moments (docs/studio.md, "Going back in time"), times in ms of the run.
    ``program`` and ``robot``: when each changed, and which of ``programs`` / ``robots`` (the
    readings' lines) it changed to; ``notes``: each note's start, end and words; ``poses``:
    where the robot reckoned it was (times; x, y mm; heading degrees), said with
    ``pose_words`` ({x}, {y} in cm, {heading} in whole degrees); the stage's frames are
    ``recording_offset_ms`` later in the recording's time; ``motions``: each movement's start,
    end and line; ``story``: the time and line of each line of the child's view of the
    trace."""

    end_ms: int
    program: tuple[list[int], list[int]]
    programs: list[MomentProgramJson]
    robot: tuple[list[int], list[int]]
    robots: list[list[str]]
    notes: list[tuple[int, int | None, str]]
    poses: tuple[list[int], list[float], list[float], list[float]]
    recording_offset_ms: int
    pose_words: str
    motions: list[tuple[int, int | None, int]]
    story: list[tuple[int, int]]


class TimelineMessage(TimelineJson):
    """A paused run's moments so far (asked for by the time slider), with the stage and the
    child's view of the trace so far."""

    type: Literal["timeline"]
    stage: StageData
    trace: list[str]


class RobotLinkMessage(TypedDict):
    """The studio's answer to a linked robot: the packets the page sends by itself (Stop and
    Reset; the hello light and chirp), made from the protocol table, and its timing rules."""

    type: Literal["robot_link"]
    robot: str  # the robot described ("Root RT1 "Root-07"")
    stop: str
    hello: list[str]
    write_timeout_s: float
    silence_s: float  # the page stops a moving robot when the studio says nothing this long
    hidden_s: float  # ... or when the page has been hidden this long
    stop_grace_s: float  # ... or when a run goes on this long after Stop


class RobotPacketMessage(TypedDict):
    """A packet of the run's for the page to write to its robot (then ``robot_written``);
    ``moves``: the robot moves after it (True), stops (False), or neither changes (None)."""

    type: Literal["robot_packet"]
    n: int
    data: str
    moves: bool | None


class LinkFigures(TypedDict, total=False):
    """How long a run's packets took through the page to the robot and back (acknowledged)."""

    packets: int
    median_ms: float
    p95_ms: float
    max_ms: float


class WorldPose(TypedDict):
    x_mm: float
    y_mm: float
    heading_deg: float


class StrokeJson(TypedDict):
    """A marker or eraser line, in world millimetres."""

    kind: str
    color: str
    width_mm: int
    t_ms: int
    points: list[list[int]]


class NoteJson(TypedDict):
    t_ms: int
    frequency_hz: float
    duration_ms: int
    end_hz: float


class LightJson(TypedDict):
    t_ms: int
    mode: str
    rgb: list[int]


class _Ended(TypedDict):
    type: Literal["ended"]
    end: str


class EndedMessage(_Ended, total=False):
    """A run ended: how (``end``), and what it left.

    ``end``: finished, stopped, error, mistakes (the text had mistakes: ``errors``), limit (a
    limit of the run's: ``code``, ``limit``, ``error``), crashed (``reason``, ``error``),
    disconnected (the page lost the server: made by the page itself).
    """

    stopped_by: str | None
    sim_time_s: float
    error: DiagnosticJson | None
    errors: list[DiagnosticJson]
    warnings: list[DiagnosticJson]
    printed: list[str]
    said: list[str]
    world_pose: WorldPose | None
    # the session's outcome (rootlang/app/session.py: the same as `rootlang sim --json`)
    robot: str | None  # the model
    world: str | None
    pose: WorldPose | None  # the robot's own estimate when the program ended (mm, degrees)
    strokes: list[StrokeJson]
    notes: list[NoteJson]
    lights: list[LightJson]
    trace: list[str]
    replay: str  # the replay page's address, to download
    stage: StageData
    code: str
    limit: str
    reason: str
    link: LinkFigures  # a run on the page's own robot
    timeline: TimelineJson  # a simulated run's moments, for the time slider


class ErrorMessage(DiagnosticJson):
    """A message the server could not act on (nothing else happened)."""

    type: Literal["error"]


FromPage = (
    RunMessage | StimulusMessage | StopMessage | RobotLinkedMessage | RobotUnlinkedMessage
    | RobotWrittenMessage | RobotNotifyMessage | RobotLostMessage | RobotStoppedMessage
    | DebugMessage
)  # fmt: skip
ToPage = (
    WaitingMessage | StartedMessage | FrameMessage | EndedMessage | ErrorMessage | RobotLinkMessage
    | RobotPacketMessage | PausedMessage | ResumedMessage | WatchMessage | TimelineMessage
)  # fmt: skip


# --- a class (rootlang.studio.classroom): the pupils' pages --------------------------------------


class PupilRequest(TypedDict):
    """``POST /api/pupil``: the name the pupil typed (the cookie comes back with the reply)."""

    name: str


class PupilReply(TypedDict):
    name: str  # as their folder is called (tidied; an earlier folder's letter case)


class TaskJson(TypedDict):
    name: str
    program: str  # the program the task checks (NAME.root)
    title: str
    check: Literal["golden", "pose", "drawing", "pose and drawing"]


WhoReply = TypedDict(
    "WhoReply",
    {
        "class": bool,
        "name": str | None,  # None: the page has not said who it is yet
        "tasks": list[TaskJson],
        "locked": bool,
        "muted": bool,
        "notice": str,
        "level": int,  # the level the teacher chose for this pupil, or for the class
        "language": str,
        "strings": dict[str, str],
    },
)  # ("class" is a Python word)
WhoReply.__doc__ = """``GET /api/pupil``: who this page is, the class's tasks, lock and message."""


class CheckRequest(_Named):
    """``POST /api/check``: the text as it is in the page, and the program (a task's) it is."""


class CheckedJson(TypedDict):
    """A check: did the robot do it; if not, the first difference, in the page's words
    (``said``) and as a report's line."""

    passed: bool
    said: str
    first_difference: str


class CheckReply(CheckedJson):
    task: TaskJson


class NoticeMessage(TypedDict):
    """To a pupil's page (``/ws/class``): the teacher's message."""

    type: Literal["notice"]
    text: str
    at: float


class LockedMessage(TypedDict):
    """To a pupil's page (``/ws/class``): hands off (True), or work again."""

    type: Literal["locked"]
    locked: bool


class MutedMessage(TypedDict):
    """To a pupil's page (``/ws/class``): the teacher muted the class's sounds (True), or not."""

    type: Literal["muted"]
    muted: bool


class LevelMessage(TypedDict):
    """To a pupil's page (``/ws/class``): the level the teacher chose for them (1 picture
    blocks, 2 word blocks, 3 text)."""

    type: Literal["level"]
    level: int


ToClassPage = NoticeMessage | LockedMessage | MutedMessage | LevelMessage


class AdventureJson(TypedDict):
    """An adventure as a page lists it (docs/levels.md, "Adventures")."""

    name: str
    program: str  # the pupil's program for it (NAME.root)
    level: int  # the level it is for
    title: str  # in the page's language
    goal: str  # what the robot should do, in a few words (spoken at Level 1)
    picture: str  # the goal as a picture: an SVG ``data:`` URI
    world: str  # the world it is checked in, as the page's World menu names it ("": the floor)
    passed: bool  # the pupil has passed its check (kept in their folder)


class AdventuresReply(TypedDict):
    """``GET /api/adventures``: every adventure, by level then name, for the pupil."""

    adventures: list[AdventureJson]


class AdventureRequest(TypedDict):
    """``POST /api/adventure``: the pupil starts (or goes back to) an adventure: its starter
    is copied into their folder, never over their own program."""

    name: str


class AdventureReply(TypedDict):
    program: str


class AdventureProgressJson(TypedDict):
    """An adventure as the teacher's page shows the class's progress on it."""

    name: str
    level: int
    title: str


# --- a class: the teacher's page ------------------------------------------------------------------


class LoginRequest(TypedDict):
    """``POST /api/teacher/login``: the code the studio printed."""

    code: str


class LoginReply(TypedDict):
    teacher: bool


class TeacherSetupReply(SetupInLanguage):
    """``GET /api/teacher/setup``."""

    language: str
    languages: dict[str, str]


class StopAllReply(TypedDict):
    """``POST /api/teacher/stop``: the runs stopped, how many had ended when it answered."""

    stopped: int
    ended: int
    seconds: float


class NoticeRequest(TypedDict):
    """``POST /api/teacher/notice``."""

    text: str


class NoticeReply(TypedDict):
    notice: str


class LockRequest(TypedDict):
    """``POST /api/teacher/lock`` (and its reply)."""

    locked: bool


class LevelRequest(TypedDict):
    """``POST /api/teacher/level`` (and its reply): the level for ``pupil``'s pages ("": the
    class's, for every pupil the teacher has not chosen one for)."""

    level: int
    pupil: str


class MuteRequest(TypedDict):
    """``POST /api/teacher/mute`` (and its reply): no robot sounds in the pupils' pages."""

    muted: bool


class ClassCheckRequest(TypedDict):
    """``POST /api/teacher/check``: check everyone's saved program for this task."""

    task: str


class ClassCheckReply(TypedDict):
    task: str
    results: dict[str, CheckedJson]  # by pupil


class ProblemJson(TypedDict):
    severity: Literal["error", "warning"]
    line: int
    message: str


class PupilRunJson(TypedDict):
    program: str
    robot: str | None  # None: the simulator
    since: float
    waiting: int  # its place in the queue for a free place to run; 0: it runs


class LineMessage(TypedDict):
    line: int
    message: str


class LastRunJson(TypedDict):
    program: str
    robot: str | None
    end: str
    stopped_by: str | None
    error: LineMessage | None
    replay: str | None
    trace: list[str]  # the end of what happened, in the pupil's words


class PupilJson(TypedDict):
    """A pupil as the teacher's page shows them."""

    name: str
    program: str  # the program their page has open ("" before any)
    text: str  # as it is in their page now, saved or not
    problems: list[ProblemJson]
    run: PupilRunJson | None
    last: LastRunJson | None
    checks: dict[str, CheckedJson]  # by task
    online: bool  # a page of theirs is open
    level: int  # the level their pages show (chosen for them, else the class's)
    own_level: bool  # the teacher chose it for them (not the class's)
    adventures: dict[str, bool]  # the adventures they have checked: passed (at least once)


class ClassMessage(TypedDict):
    """To the teacher's page (``/ws/teacher``) when it connects: the whole class."""

    type: Literal["class"]
    pupils: list[PupilJson]
    tasks: list[TaskJson]
    adventures: list[AdventureProgressJson]
    locked: bool
    muted: bool
    level: int  # the class's
    notice: str
    sent_at: float


class PupilsMessage(TypedDict):
    """To the teacher's page, at most every 0.1 s: the pupils that changed."""

    type: Literal["pupils"]
    pupils: list[PupilJson]
    locked: bool
    sent_at: float


ToTeacher = ClassMessage | PupilsMessage

STUDIO_TYPES = (
    DiagnosticJson, ErrorsReply, ProgramFileJson, PictureMeaning, PicturesSetup, BlocksSetup,
    SetupReply, ProgramReply,
    SaveRequest, NameRequest, SavedReply, RenameRequest, RenamedReply, TextRequest, StageRequest,
    BlocksReply, WorkspaceRequest, LeftOutJson, TextReply, RobotJson, RobotsReply, RunMessage,
    StimulusMessage, StopMessage, WorldJson, StageData, WaitingMessage, StartedMessage, Ink,
    PoseJson, FrameMessage, WorldPose, StrokeJson, NoteJson, LightJson, EndedMessage, ErrorMessage,
    BluetoothProfile, RobotLinkedMessage, RobotUnlinkedMessage, RobotWrittenMessage,
    RobotNotifyMessage, RobotLostMessage, RobotStoppedMessage, RobotLinkMessage,
    RobotPacketMessage, LinkFigures, DebugMessage, PlaceJson, NamedJson, CallJson, LoopJson,
    SentJson, WatchPoseJson, WatchJson, PausedMessage, ResumedMessage, WatchMessage,
    MomentProgramJson, TimelineJson, TimelineMessage,
    PupilRequest, PupilReply, TaskJson, AdventureJson, AdventuresReply, AdventureRequest,
    AdventureReply, AdventureProgressJson, WhoReply, CheckRequest, CheckedJson, CheckReply,
    NoticeMessage, LockedMessage, LoginRequest, LoginReply, TeacherSetupReply, StopAllReply,
    NoticeRequest, NoticeReply, LockRequest, LevelRequest, LevelMessage, MuteRequest,
    MutedMessage, ClassCheckRequest,
    ClassCheckReply, ProblemJson, PupilRunJson, LineMessage, LastRunJson, PupilJson, ClassMessage,
    PupilsMessage,
)  # fmt: skip
PAGE_DATA_TYPES = (
    html.LabelShape, html.CircleShape, html.PathShape, html.EraseInk, html.LedState, html.Frames,
    html.PageData,
)  # fmt: skip

PACKAGE = Path(__file__).resolve().parents[1]
STUDIO_DTS = PACKAGE / "studio" / "static" / "messages.d.ts"
PAGE_DATA_DTS = PACKAGE / "sim" / "render" / "page_data.d.ts"


def written() -> dict[Path, str]:
    """The two ``.d.ts`` files, as :func:`rootlang.jstypes.declarations` writes them."""
    return {
        PAGE_DATA_DTS: declarations(PAGE_DATA_TYPES, {"Shape": html.Shape}, {}),
        STUDIO_DTS: declarations(
            STUDIO_TYPES,
            {
                "FromPage": FromPage,
                "ToPage": ToPage,
                "ToClassPage": ToClassPage,
                "ToTeacher": ToTeacher,
            },
            {"../../sim/render/page_data": PAGE_DATA_TYPES},
        ),
    }


def main() -> int:
    for path, text in written().items():
        path.write_text(text, encoding="utf-8")
        print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
