// Made by `python -m rootlang.studio.messages` from the Python types: do not edit.

import type { CircleShape, EraseInk, Frames, LabelShape, LedState, PageData, PathShape } from "../../sim/render/page_data";

/** A mistake, warning or refusal: its catalogue code, where (1-based lines and columns; 0 when it is about no place), and its message in the page's language, also as rendered text. */
export interface DiagnosticJson {
  file: string;
  line: number;
  column: number;
  end_line: number;
  end_column: number;
  code: string;
  severity: "error" | "warning";
  message: string;
  rendered: string;
}

/** Any refused HTTP request (status 4xx/5xx). */
export interface ErrorsReply {
  errors: DiagnosticJson[];
}

export interface ProgramFileJson {
  name: string;
  size: number;
  modified: number;
}

/** What a Level 1 block says aloud: ``words`` (``{n}`` its number, ``{what}`` its picture menu's choice), ``one`` for the number 1 ("" as ``words``), ``what`` each choice in words. */
export interface PictureMeaning {
  words: string;
  one: string;
  what: Record<string, string>;
}

/** Level 1: its toolbox, and what each picture block says (its definitions are among the blocks'). */
export interface PicturesSetup {
  toolbox: Record<string, unknown>;
  meanings: Record<string, PictureMeaning>;
}

export interface BlocksSetup {
  definitions: Record<string, unknown>[];
  toolbox: Record<string, unknown>;
  pictures: PicturesSetup;
}

/** ``GET /api/setup``. */
export interface SetupReply {
  strings: Record<string, string>;
  english: Record<string, string>;
  blockly_messages: string;
  blocks: BlocksSetup | null;
  syntax: Record<string, string[]>;
  light_colours: Record<string, string>;
  folder: string;
  programs: ProgramFileJson[];
  worlds: string[];
  speeds: number[];
  languages: Record<string, string>;
  language: string;
  bluetooth: BluetoothProfile;
}

/** ``GET /api/program?name=``. */
export interface ProgramReply {
  name: string;
  text: string;
  version: string;
  layout: Record<string, unknown>;
}

/** ``PUT /api/program``: ``version`` is the one the page opened or last saved (left out, the file is saved whatever it holds); ``as_written``: saved as it is, not formatted (a program too long to convert in time would be too long to format too). */
export interface SaveRequest {
  name: string;
  text: string;
  layout?: Record<string, unknown>;
  version?: string;
  as_written?: boolean;
}

/** ``POST /api/program`` (a new program from the starter). */
export interface NameRequest {
  name: string;
}

/** ``PUT`` and ``POST /api/program``: the text as written (canonical when it parses), and its version now. */
export interface SavedReply {
  name: string;
  text: string;
  version: string;
}

/** ``POST /api/rename``. */
export interface RenameRequest {
  old: string;
  new: string;
}

export interface RenamedReply {
  name: string;
}

/** ``POST /api/blocks``: text to turn into blocks (``level`` 1: picture blocks where a line has one). */
export interface TextRequest {
  text: string;
  name: string;
  level?: number;
}

/** ``POST /api/stage``: the stage before a run (``world``: the page's choice, "" for the program's own); the answer is :class:`StageData`. */
export interface StageRequest {
  name: string;
  text: string;
  world: string;
}

/** The text's blocks (None when it does not parse, or when ``text_only`` says (E817) the program is too long for blocks) and what the checks say about it. */
export interface BlocksReply {
  workspace: Record<string, unknown> | null;
  diagnostics: DiagnosticJson[];
  text_only?: DiagnosticJson;
  above?: string[];
}

/** ``POST /api/text``: blocks to turn into text (``level`` 1: the text's own blocks as Level 1's). */
export interface WorkspaceRequest {
  workspace: Record<string, unknown>;
  name: string;
  level?: number;
}

/** A top block not in the text (loose, or a script not finished): ``top`` its id, ``block`` the block inside it at fault ("" when the reason names none), and why (E70x). */
export interface LeftOutJson {
  top: string;
  block: string;
  diagnostic: DiagnosticJson;
}

/** The text of the complete scripts, its own blocks (as ``POST /api/blocks`` answers them for ``text``: ids from its lines), and the top blocks left out of it. */
export interface TextReply {
  text: string;
  workspace: Record<string, unknown>;
  diagnostics: DiagnosticJson[];
  left_out: LeftOutJson[];
}

export interface RobotJson {
  name: string;
  address: string;
  model: string | null;
  battery: number | null;
  rssi: number;
  touched: boolean;
}

/** ``GET /api/robots``: the robots in range, strongest first. */
export interface RobotsReply {
  robots: RobotJson[];
}

/** Run this text (``name`` is the program it is, for its folder and its own world); with ``link`` "page", on the robot this page has linked (Web Bluetooth); a simulated run pauses at its ``breakpoints`` (source lines). */
export interface RunMessage {
  type: "run";
  name: string;
  text: string;
  world: string;
  speed: number;
  robot: string | null;
  link?: "page" | null;
  breakpoints?: number[];
}

/** A hand on the robot: ``touch`` (with ``sensors``), ``bump`` (with ``sensors``) or ``nose``. */
export interface StimulusMessage {
  type: "stimulus";
  action: "touch" | "bump" | "nose";
  sensors?: string[];
}

/** Stop: the nose button (``when stopped`` scripts run). */
export interface StopMessage {
  type: "stop";
}

export interface WorldJson {
  name: string;
  model: string;
}

/** The stage: the replay page's data, and the world it shows. */
export interface StageData {
  view: number[];
  background: string;
  below: (LabelShape | CircleShape | PathShape)[];
  ink: (PathShape | EraseInk)[];
  path: PathShape | null;
  overlay: (LabelShape | CircleShape | PathShape)[];
  robot: (LabelShape | CircleShape | PathShape)[];
  led: number;
  leds: LedState[];
  frames: Frames;
  events: [number, string, string, number][];
  said: [number, string][];
  title: string;
  subtitle: string;
  world: WorldJson;
}

/** The run waits for a free place (the studio's cap on runs at once): ``place`` in the queue, and the words that say so in the page's language; told again as the queue moves. ``started`` follows once it runs (or ``ended``, if it is stopped or replaced first). */
export interface WaitingMessage {
  type: "waiting";
  place: number;
  message: string;
}

/** A run started: in the simulator with ``stage`` (and its time limit and speed), on a robot with ``stage`` None and the ``robot`` described. */
export interface StartedMessage {
  type: "started";
  stage: StageData | null;
  time_limit?: number;
  speed?: number;
  robot?: string;
}

/** One stroke's new points. */
export interface Ink {
  i: number;
  kind: string;
  color: string | null;
  w: number;
  p: number[];
  from: number;
}

export interface PoseJson {
  x: number;
  y: number;
  h: number;
  led: string | null;
  led_mode: string;
}

/** About 25 a second while a run goes on; ``pose`` in the simulator. */
export interface FrameMessage {
  type: "frame";
  t: number;
  ink: Ink[];
  running: Record<string, number>;
  printed: string[];
  said: string[];
  notes: NoteJson[];
  happened: string[];
  sent_at: number;
  n: number;
  pose?: PoseJson;
}

export interface WorldPose {
  x_mm: number;
  y_mm: number;
  heading_deg: number;
}

/** A marker or eraser line, in world millimetres. */
export interface StrokeJson {
  kind: string;
  color: string;
  width_mm: number;
  t_ms: number;
  points: number[][];
}

export interface NoteJson {
  t_ms: number;
  frequency_hz: number;
  duration_ms: number;
  end_hz: number;
}

export interface LightJson {
  t_ms: number;
  mode: string;
  rgb: number[];
}

/** A run ended: how (``end``), and what it left. ``end``: finished, stopped, error, mistakes (the text had mistakes: ``errors``), limit (a limit of the run's: ``code``, ``limit``, ``error``), crashed (``reason``, ``error``), disconnected (the page lost the server: made by the page itself). */
export interface EndedMessage {
  type: "ended";
  end: string;
  stopped_by?: string | null;
  sim_time_s?: number;
  error?: DiagnosticJson | null;
  errors?: DiagnosticJson[];
  warnings?: DiagnosticJson[];
  printed?: string[];
  said?: string[];
  world_pose?: WorldPose | null;
  robot?: string | null;
  world?: string | null;
  pose?: WorldPose | null;
  strokes?: StrokeJson[];
  notes?: NoteJson[];
  lights?: LightJson[];
  trace?: string[];
  replay?: string;
  stage?: StageData;
  code?: string;
  limit?: string;
  reason?: string;
  link?: LinkFigures;
  timeline?: TimelineJson;
}

/** A message the server could not act on (nothing else happened). */
export interface ErrorMessage {
  file: string;
  line: number;
  column: number;
  end_line: number;
  end_column: number;
  code: string;
  severity: "error" | "warning";
  message: string;
  rendered: string;
  type: "error";
}

/** The robots' GATT as the page links one over Web Bluetooth (``rootlang.ble.profile``): what the browser's chooser filters on (the Root Identifier service, or iRobot's company id in the manufacturer data) and the UUIDs the page uses. */
export interface BluetoothProfile {
  identifier: string;
  company: number;
  uart: string;
  rx: string;
  tx: string;
  information: string;
  serial: string;
  firmware: string;
  hardware: string;
}

/** The page linked a robot over Web Bluetooth: its name and Device Information. */
export interface RobotLinkedMessage {
  type: "robot_linked";
  name: string;
  serial: string;
  firmware: string;
  hardware: string;
}

export interface RobotUnlinkedMessage {
  type: "robot_unlinked";
}

/** The page wrote packet ``n`` to its robot (or could not: ``error``). */
export interface RobotWrittenMessage {
  type: "robot_written";
  n: number;
  error?: string | null;
}

/** A packet from the page's robot (its TX notification), 40 hex digits. */
export interface RobotNotifyMessage {
  type: "robot_notify";
  data: string;
}

/** The page's robot's link dropped (a GATT disconnect): the run on it ends. */
export interface RobotLostMessage {
  type: "robot_lost";
}

/** The page stopped its robot itself, and why (its safety rules: the studio was quiet, the tab hidden, the run not stopped after Stop, the page closing, the socket lost): the run on it ends, saying so. Sent at once, or when the socket is back. */
export interface RobotStoppedMessage {
  type: "robot_stopped";
  why: "silence" | "hidden" | "stop" | "pagehide" | "socket";
}

/** The studio's answer to a linked robot: the packets the page sends by itself (Stop and Reset; the hello light and chirp), made from the protocol table, and its timing rules. */
export interface RobotLinkMessage {
  type: "robot_link";
  robot: string;
  stop: string;
  hello: string[];
  write_timeout_s: number;
  silence_s: number;
  hidden_s: number;
  stop_grace_s: number;
}

/** A packet of the run's for the page to write to its robot (then ``robot_written``); ``moves``: the robot moves after it (True), stops (False), or neither changes (None). */
export interface RobotPacketMessage {
  type: "robot_packet";
  n: number;
  data: string;
  moves: boolean | null;
}

/** How long a run's packets took through the page to the robot and back (acknowledged). */
export interface LinkFigures {
  packets?: number;
  median_ms?: number;
  p95_ms?: number;
  max_ms?: number;
}

/** A simulated run's Pause, Resume or Step, or its new ``breakpoints`` (source lines). */
export interface DebugMessage {
  type: "debug";
  action: "pause" | "resume" | "step" | "breakpoints" | "timeline";
  breakpoints?: number[];
}

/** Where one script of a paused run is (rootlang.runtime.debugger.Place), and in words. */
export interface PlaceJson {
  script: string;
  state: "next" | "starting" | "running" | "waiting" | "finished";
  line: number;
  span: number[] | null;
  words: string;
}

export interface NamedJson {
  name: string;
  value: string;
  script: string;
}

export interface CallJson {
  script: string;
  procedure: string;
  parameters: NamedJson[];
}

export interface LoopJson {
  script: string;
  line: number;
  round: number;
  count: number;
}

export interface SentJson {
  message: string;
  by: string;
  waiting: boolean;
}

export interface WatchPoseJson {
  x_mm: number;
  y_mm: number;
  heading_degrees: number;
}

/** A paused run's values (rootlang.runtime.debugger.Watch). */
export interface WatchJson {
  time_s: number;
  variables: NamedJson[];
  calls: CallJson[];
  loops: LoopJson[];
  bumpers: string[];
  touched: string[];
  colors: string;
  light_percent: number[];
  pose: WatchPoseJson;
  messages: SentJson[];
  note: string;
}

/** A simulated run paused (``reason``: step, breakpoint, pause, time): where each script is and the values; nothing of the run goes on until Resume, Step or Stop. */
export interface PausedMessage {
  type: "paused";
  reason: "step" | "breakpoint" | "pause" | "time";
  places: PlaceJson[];
  watch: WatchJson;
  lines: string[];
}

/** The paused run goes on (``step``: until the next statement of any script begins). */
export interface ResumedMessage {
  type: "resumed";
  step: boolean;
}

/** A paced run's places and values as it goes (about five times a second; a pause's are exact). */
export interface WatchMessage {
  type: "watch";
  places: PlaceJson[];
  watch: WatchJson;
  lines: string[];
}

/** The program's part of a moment (rootlang.runtime.timeline.ProgramState): where each script is, the variables and calls (to see a value change), and the Watch panel's lines: ``values`` (variables, calls, loops) and ``messages``. */
export interface MomentProgramJson {
  places: PlaceJson[];
  variables: NamedJson[];
  calls: CallJson[];
  values: string[];
  messages: string[];
}

/** A simulated run's moments (docs/studio.md, "Going back in time"), times in ms of the run. ``program`` and ``robot``: when each changed, and which of ``programs`` / ``robots`` (the readings' lines) it changed to; ``notes``: each note's start, end and words; ``poses``: where the robot reckoned it was (times; x, y mm; heading degrees), said with ``pose_words`` ({x}, {y} in cm, {heading} in whole degrees); the stage's frames are ``recording_offset_ms`` later in the recording's time; ``motions``: each movement's start, end and line; ``story``: the time and line of each line of the child's view of the trace. */
export interface TimelineJson {
  end_ms: number;
  program: [number[], number[]];
  programs: MomentProgramJson[];
  robot: [number[], number[]];
  robots: string[][];
  notes: ([number, number | null, string])[];
  poses: [number[], number[], number[], number[]];
  recording_offset_ms: number;
  pose_words: string;
  motions: ([number, number | null, number])[];
  story: [number, number][];
}

/** A paused run's moments so far (asked for by the time slider), with the stage and the child's view of the trace so far. */
export interface TimelineMessage {
  end_ms: number;
  program: [number[], number[]];
  programs: MomentProgramJson[];
  robot: [number[], number[]];
  robots: string[][];
  notes: ([number, number | null, string])[];
  poses: [number[], number[], number[], number[]];
  recording_offset_ms: number;
  pose_words: string;
  motions: ([number, number | null, number])[];
  story: [number, number][];
  type: "timeline";
  stage: StageData;
  trace: string[];
}

/** ``POST /api/pupil``: the name the pupil typed (the cookie comes back with the reply). */
export interface PupilRequest {
  name: string;
}

export interface PupilReply {
  name: string;
}

export interface TaskJson {
  name: string;
  program: string;
  title: string;
  check: "golden" | "pose" | "drawing" | "pose and drawing";
}

/** An adventure as a page lists it (docs/levels.md, "Adventures"). */
export interface AdventureJson {
  name: string;
  program: string;
  level: number;
  title: string;
  goal: string;
  picture: string;
  world: string;
  passed: boolean;
}

/** ``GET /api/adventures``: every adventure, by level then name, for the pupil. */
export interface AdventuresReply {
  adventures: AdventureJson[];
}

/** ``POST /api/adventure``: the pupil starts (or goes back to) an adventure: its starter is copied into their folder, never over their own program. */
export interface AdventureRequest {
  name: string;
}

export interface AdventureReply {
  program: string;
}

/** An adventure as the teacher's page shows the class's progress on it. */
export interface AdventureProgressJson {
  name: string;
  level: number;
  title: string;
}

/** ``GET /api/pupil``: who this page is, the class's tasks, lock and message. */
export interface WhoReply {
  class: boolean;
  name: string | null;
  tasks: TaskJson[];
  locked: boolean;
  muted: boolean;
  notice: string;
  level: number;
  language: string;
  strings: Record<string, string>;
}

/** ``POST /api/check``: the text as it is in the page, and the program (a task's) it is. */
export interface CheckRequest {
  name: string;
  text: string;
}

/** A check: did the robot do it; if not, the first difference, in the page's words (``said``) and as a report's line. */
export interface CheckedJson {
  passed: boolean;
  said: string;
  first_difference: string;
}

export interface CheckReply {
  passed: boolean;
  said: string;
  first_difference: string;
  task: TaskJson;
}

/** To a pupil's page (``/ws/class``): the teacher's message. */
export interface NoticeMessage {
  type: "notice";
  text: string;
  at: number;
}

/** To a pupil's page (``/ws/class``): hands off (True), or work again. */
export interface LockedMessage {
  type: "locked";
  locked: boolean;
}

/** ``POST /api/teacher/login``: the code the studio printed. */
export interface LoginRequest {
  code: string;
}

export interface LoginReply {
  teacher: boolean;
}

/** ``GET /api/teacher/setup``. */
export interface TeacherSetupReply {
  strings: Record<string, string>;
  english: Record<string, string>;
  blockly_messages: string;
  blocks: BlocksSetup | null;
  syntax: Record<string, string[]>;
  light_colours: Record<string, string>;
  language: string;
  languages: Record<string, string>;
}

/** ``POST /api/teacher/stop``: the runs stopped, how many had ended when it answered. */
export interface StopAllReply {
  stopped: number;
  ended: number;
  seconds: number;
}

/** ``POST /api/teacher/notice``. */
export interface NoticeRequest {
  text: string;
}

export interface NoticeReply {
  notice: string;
}

/** ``POST /api/teacher/lock`` (and its reply). */
export interface LockRequest {
  locked: boolean;
}

/** ``POST /api/teacher/level`` (and its reply): the level for ``pupil``'s pages ("": the class's, for every pupil the teacher has not chosen one for). */
export interface LevelRequest {
  level: number;
  pupil: string;
}

/** To a pupil's page (``/ws/class``): the level the teacher chose for them (1 picture blocks, 2 word blocks, 3 text). */
export interface LevelMessage {
  type: "level";
  level: number;
}

/** ``POST /api/teacher/mute`` (and its reply): no robot sounds in the pupils' pages. */
export interface MuteRequest {
  muted: boolean;
}

/** To a pupil's page (``/ws/class``): the teacher muted the class's sounds (True), or not. */
export interface MutedMessage {
  type: "muted";
  muted: boolean;
}

/** ``POST /api/teacher/check``: check everyone's saved program for this task. */
export interface ClassCheckRequest {
  task: string;
}

export interface ClassCheckReply {
  task: string;
  results: Record<string, CheckedJson>;
}

export interface ProblemJson {
  severity: "error" | "warning";
  line: number;
  message: string;
}

export interface PupilRunJson {
  program: string;
  robot: string | null;
  since: number;
  waiting: number;
}

export interface LineMessage {
  line: number;
  message: string;
}

export interface LastRunJson {
  program: string;
  robot: string | null;
  end: string;
  stopped_by: string | null;
  error: LineMessage | null;
  replay: string | null;
  trace: string[];
}

/** A pupil as the teacher's page shows them. */
export interface PupilJson {
  name: string;
  program: string;
  text: string;
  problems: ProblemJson[];
  run: PupilRunJson | null;
  last: LastRunJson | null;
  checks: Record<string, CheckedJson>;
  online: boolean;
  level: number;
  own_level: boolean;
  adventures: Record<string, boolean>;
}

/** To the teacher's page (``/ws/teacher``) when it connects: the whole class. */
export interface ClassMessage {
  type: "class";
  pupils: PupilJson[];
  tasks: TaskJson[];
  adventures: AdventureProgressJson[];
  locked: boolean;
  muted: boolean;
  level: number;
  notice: string;
  sent_at: number;
}

/** To the teacher's page, at most every 0.1 s: the pupils that changed. */
export interface PupilsMessage {
  type: "pupils";
  pupils: PupilJson[];
  locked: boolean;
  sent_at: number;
}

export type FromPage = RunMessage | StimulusMessage | StopMessage | RobotLinkedMessage | RobotUnlinkedMessage | RobotWrittenMessage | RobotNotifyMessage | RobotLostMessage | RobotStoppedMessage | DebugMessage;
export type ToPage = WaitingMessage | StartedMessage | FrameMessage | EndedMessage | ErrorMessage | RobotLinkMessage | RobotPacketMessage | PausedMessage | ResumedMessage | WatchMessage | TimelineMessage;
export type ToClassPage = NoticeMessage | LockedMessage | MutedMessage | LevelMessage;
export type ToTeacher = ClassMessage | PupilsMessage;
