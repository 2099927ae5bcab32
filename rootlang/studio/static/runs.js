// @ts-check
// Runs: streamed from the real runtime and simulator (or a robot) over the WebSocket, drawn on
// the stage, the running lines lit in the text and on the blocks; the robots in range.
import * as api from "./api.js";
import {$, session, state, words, hasWords, say, fixed} from "./page.js";
import {inPageLanguage} from "./page.js";
import {editor} from "./editor.js";
import {glow} from "./blocks.js";
import {settle, showProblems, onEdit} from "./sync.js";
import {Stage} from "./stage.js";
import {play, wake} from "./sound.js";
import {PAGE_ROBOT, myRobot, setupMyRobot, bluetoothWords} from "./my_robot.js";
import {setupDebugger, breakpointLines, runStarted, runEnded, showPaused, showResumed, showWatch} from "./debugger.js";
import {handOver} from "./keyboard.js";
import {setupTimeSlider, hideTimeSlider, timeSliderPaused, timelineCame, timeSliderEnded} from "./timeslider.js";
import {Narrator} from "./narrator.js";

/** @typedef {import("./messages").FromPage} FromPage */
/** @typedef {import("./messages").ToPage} ToPage */
/** @typedef {import("./messages").EndedMessage} EndedMessage */
/** @typedef {import("./messages").StimulusMessage} StimulusMessage */
/** @typedef {import("./messages").BluetoothProfile} BluetoothProfile */

const ALREADY_RUNNING = "E810";   // the server's code for a second run while one goes on

export const stage = new Stage($("canvas"), $("speech"));
/** The stage in words, for a screen reader. */
const narrator = new Narrator();
/** The run's speed (its notes are played at it). */
let runSpeed = 1;
/** @type {WebSocket | null} */
let socket = null;
/** @type {number[]} the text's lines lit as running (1-based, as the run tells them) */
let runningLines = [];
/** @type {number[] | null} the lines to light at the page's next frame (null: as they are) */
let linesToLight = null;
// The running lines change faster than an eye can follow them, and each change repaints the
// text and the blocks (a long script's blocks are many): lit at most this often
const LIGHT_EVERY_MS = 150;
/** When the running lines were last lit (performance.now()). */
let litAt = 0;
/** @type {HTMLElement | null} a printed line to scroll to at the page's next frame */
let lastPrinted = null;
/** @type {number | null} the line a run stopped at with a mistake (0-based), lit until an edit */
let errorLine = null;

// The child changes the program: what the last run said about it is not so any more.
onEdit.push(() => {
  if (errorLine !== null) editor.removeLineClass(errorLine, "background", "error-line");
  errorLine = null;
  fixed("run");
});

/** @returns {Promise<WebSocket>} */
function connect() {
  return new Promise(resolve => {
    if (socket && socket.readyState === WebSocket.OPEN) { resolve(socket); return; }
    const opened = new WebSocket((location.protocol === "https:" ? "wss://" : "ws://") + location.host + inPageLanguage("/ws"));
    socket = opened;
    opened.onmessage = event => {
      const message = /** @type {ToPage} */ (JSON.parse(event.data));
      received(message);
      myRobot()?.fromStudio(message);   // (the page's own robot: its packets, and the watchdog)
    };
    opened.onopen = () => { myRobot()?.studioBack(); resolve(opened); };
    opened.onclose = () => {
      myRobot()?.studioLost();   // nobody steers the robot any more: the page stops it
      if (session.running) finished({type: "ended", end: "disconnected"});
    };
  });
}

/**
 * @param {FromPage} message
 * @returns {boolean} whether it went (the socket is open)
 */
function send(message) {
  if (!socket || socket.readyState !== WebSocket.OPEN) return false;
  socket.send(JSON.stringify(message));
  return true;
}

/** @param {BluetoothProfile} profile  the robots' UUIDs, for the page's own robot */
export function setupRobots(profile) {
  setupMyRobot(profile, {send: send, connect: connect, chosen: robotChosen});
  setupDebugger(send);
  setupTimeSlider(stage, send);
}

export async function run() {
  if (session.running) return;
  wake();   // (a click of the child's: the page may sound from now on)
  await settle();    // the child's last edit is in both panes: the blocks' index follows the text that runs
  if (Number(state.errors) > 0) { say(words("fix_first"), true, "mistakes"); return; }
  await connect();
  $("output").replaceChildren(); $("trace").replaceChildren(); stage.speak("");
  $("after").hidden = true; $("replay").hidden = true;
  session.running = true; state.ended = ""; state.running = "yes";
  showRunning(true);
  say(words("starting"));
  const robot = $("robot").value;
  const link = robot === PAGE_ROBOT ? myRobot() : null;
  if (link) {
    try { await link.ready(); } catch (error) {   // linked again after the last run ended it
      session.running = false; state.running = "no"; showRunning(false);
      say(bluetoothWords(error), true);
      return;
    }
  }
  send({type: "run", name: session.current, text: editor.getValue(), world: $("world").value,
        speed: Number($("speed").value), robot: robot === "" || link ? null : robot,
        link: link ? "page" : null, breakpoints: breakpointLines()});
}

export function stop() {
  send({type: "stop"});
  myRobot()?.stopPressed();
}

/**
 * Run or Stop, whichever can be pressed now (the focus goes with it: Run's to Stop and back).
 * @param {boolean} running
 */
function showRunning(running) {
  const [from, to] = running ? [$("run"), $("stop")] : [$("stop"), $("run")];
  handOver(from, to, () => { from.disabled = true; to.disabled = false; });
}

/** The run going on is the simulator's (not a robot's). */
let simulated = false;

/** @param {ToPage} message */
function received(message) {
  if (message.type === "waiting") {
    say(message.message);   // a place for the run: the server says its place in the queue
  } else if (message.type === "started") {
    runSpeed = message.speed === undefined ? 1 : message.speed;
    runStarted();   // (simulated or on a robot: it can be paused)
    simulated = Boolean(message.stage);
    hideTimeSlider();
    narrator.reset();
    if (message.stage) {
      stage.show(message.stage, false);
      say(words("running_world", {world: message.stage.world.name}));
    } else {
      say(words("running_robot", {robot: message.robot || ""}));
    }
  } else if (message.type === "frame") {
    stage.frame(message);
    narrator.frame(message);
    lightSoon(Object.values(message.running));
    message.printed.forEach(text => addLine($("output"), text, true));
    message.said.forEach(text => stage.speak(text));
    play(message.notes, runSpeed);
    state.t = message.t.toFixed(2);
    state.lag = Math.max(0, Date.now() / 1000 - message.sent_at).toFixed(3);
  } else if (message.type === "paused") {
    showPaused(message);
    if (simulated) timeSliderPaused(message);   // (a robot's run keeps no moments to go back to)
  } else if (message.type === "resumed") {
    hideTimeSlider();
    showResumed();
  } else if (message.type === "timeline") {
    timelineCame(message);
  } else if (message.type === "watch") {
    showWatch(message);
  } else if (message.type === "ended") {
    finished(message);
  } else if (message.type === "error") {
    say(message.message, true);
    if (!session.running || message.code === ALREADY_RUNNING) return;
    session.running = false; showRunning(false); state.running = "no";
    runEnded();
  }
}

/**
 * @param {HTMLElement} list
 * @param {string} text
 * @param {boolean} [soon] scrolled to at the page's next frame (a run prints many in a frame)
 */
function addLine(list, text, soon) {
  const li = document.createElement("li"); li.textContent = text; list.append(li);
  if (!soon) { li.scrollIntoView({block: "nearest"}); return; }
  if (!lastPrinted) requestAnimationFrame(() => { lastPrinted?.scrollIntoView({block: "nearest"}); lastPrinted = null; });
  lastPrinted = li;
}

/**
 * The running lines, lit at the page's next frame: the last ones the run told by then, and
 * only if they changed (frames come faster than a slow computer's page draws them).
 * @param {number[]} lines
 */
function lightSoon(lines) {
  if (linesToLight === null) {
    const light = () => requestAnimationFrame(() => { if (linesToLight) highlight(linesToLight); linesToLight = null; });
    const wait = litAt + LIGHT_EVERY_MS - performance.now();
    if (wait > 0) setTimeout(light, wait); else light();
  }
  linesToLight = lines;
}

/** @param {number[]} lines the lines running now, one for each script running (1-based) */
function highlight(lines) {
  linesToLight = null;   // (a frame's lines still to light are older than these)
  if (lines.length === runningLines.length && lines.every((line, i) => line === runningLines[i])) return;
  litAt = performance.now();
  editor.operation(() => {
    runningLines.forEach(line => editor.removeLineClass(line - 1, "background", "running-line"));
    lines.forEach(line => editor.addLineClass(line - 1, "background", "running-line"));
  });
  glow(lines, "running");
  runningLines = lines;
  state.lines = lines.join(",");
}

/** @param {EndedMessage} outcome */
function finished(outcome) {
  session.running = false; state.running = "no";
  showRunning(false);
  highlight([]);
  runEnded();   // (after Run is back: a focus on the debugger's buttons goes to it)
  if (outcome.stage) stage.show(outcome.stage, true);
  const key = "end_" + outcome.end;
  const said = hasWords(key) ? words(key, {why: outcome.stopped_by || ""}) : outcome.end;
  say(said, Boolean(outcome.error || outcome.errors), "run");
  if (outcome.error) {
    addLine($("output"), outcome.error.rendered);
    showProblems([outcome.error]);
    if (outcome.error.line) {
      errorLine = outcome.error.line - 1;
      editor.addLineClass(errorLine, "background", "error-line");
    }
  }
  if (outcome.errors) showProblems(outcome.errors);
  hideTimeSlider();   // (a paused run's trace and moments make way for the whole run's)
  (outcome.trace || []).forEach(line => addLine($("trace"), line));
  $("after").hidden = !(outcome.trace && outcome.trace.length);
  timeSliderEnded(outcome.timeline, outcome.stage);
  if (outcome.replay) {
    $("replay").href = outcome.replay; $("replay").hidden = false;
    $("replay").download = session.current.replace(/\.root$/, "") + "-replay.html";
  }
  if (outcome.world_pose) {
    state.finalX = String(outcome.world_pose.x_mm); state.finalY = String(outcome.world_pose.y_mm);
    state.finalH = String(outcome.world_pose.heading_deg);
  }
  state.ended = outcome.end;
}

/**
 * The stage before a run: the chosen world (or the program's own) with the robot where a run
 * starts; a world that can't be loaded is said, and the stage stays as it was.
 */
export async function showStart() {
  if (session.running || !session.current) return;
  const name = session.current;
  state.stage = "";
  try {
    const data = await api.stage({name: name, text: editor.getValue(), world: $("world").value});
    if (session.running || session.current !== name) return;
    stage.speak("");
    stage.show(data, false);
    state.stage = "start";
    fixed("world");
  } catch (error) {
    say(String(/** @type {Error} */ (error).message), true, "world");
  }
}

export async function findRobots() {
  say(words("looking"));
  $("scan").disabled = true;
  try {
    const reply = await api.robots();
    const chooser = $("robot");
    chooser.replaceChildren(new Option(words("simulator"), ""), ...reply.robots.map(robot =>
      new Option(robot.name + " (" + robot.model + ", " + robot.rssi + " dBm)", robot.address)));
    if (reply.robots.length) chooser.value = reply.robots[0].address;
    say(reply.robots.length ? words("found_robots", {count: reply.robots.length}) : words("no_robots"));
    state.robots = String(reply.robots.length);
    robotChosen();
  } catch (error) {
    say(String(/** @type {Error} */ (error).message), true);
  } finally {
    $("scan").disabled = false;
  }
}

export function robotChosen() {
  const onRobot = $("robot").value !== "";
  $("world").disabled = onRobot; $("speed").disabled = onRobot;
  document.querySelectorAll("#robot-buttons button, #bumper-buttons button").forEach(b => {
    /** @type {HTMLButtonElement} */ (b).disabled = onRobot;
  });
}

/**
 * A hand on the robot while it runs.
 * @param {Omit<StimulusMessage, "type">} data
 */
export function stimulate(data) {
  if (!session.running || !socket) return;
  send(Object.assign({type: /** @type {"stimulus"} */ ("stimulus")}, data));
}
