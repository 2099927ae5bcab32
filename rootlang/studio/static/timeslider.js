// @ts-check
// Going back in time: a slider over a paused or finished simulated run. Each moment shows the
// robot and the drawing by then (the stage's frames and ink, each point with its time), each
// script's line lit in both panes, the Watch panel's values and the trace's line of that moment,
// all from the run's recording (rootlang/runtime/timeline.py: sent once, then the page moves
// through it by itself). A click on a line of the drawing or of the trace goes to the moment it
// was made and lights the statement that made it.
import {$, state, words, say} from "./page.js";
import {editor} from "./editor.js";
import {light, showWatch} from "./debugger.js";
import {index} from "../../sim/render/moment.js";

/** @typedef {import("./messages").TimelineJson} TimelineJson */
/** @typedef {import("./messages").StageData} StageData */
/** @typedef {import("./messages").PausedMessage} PausedMessage */
/** @typedef {import("./messages").FromPage} FromPage */
/** @typedef {import("./stage.js").Stage} Stage */

const NEAR_PX = 8;   // a click this near a line of the drawing is on it (CSS pixels)

/** @type {Stage | null} */
let stage = null;
/** @type {(message: FromPage) => boolean} */
let send = () => false;
/**
 * The run's moments, once here, with the times of its trace's lines and of its notes' starts.
 * @type {{timeline: TimelineJson, stage: StageData, storyTimes: number[], noteTimes: number[]} | null}
 */
let run = null;
/** @type {string} the lines lit at the moment shown (to light them only when they change) */
let litLines = "";
let asked = false;   // a paused run's moments are asked for (once a pause)
/** @type {number} the trace's line shown as now (-1: none) */
let storyNow = -1;
/** @type {number} the line lit as having made what was clicked (0-based; -1: none) */
let madeLine = -1;
let ownTrace = false;   // the trace's lines are a paused run's, put there for the slider

/**
 * @param {Stage} runStage the studio's stage
 * @param {(message: FromPage) => boolean} sender the run's socket
 */
export function setupTimeSlider(runStage, sender) {
  stage = runStage;
  send = sender;
  const slider = $("time");
  slider.addEventListener("input", () => show(Number(slider.value)));
  // (a paused run's moments come when the slider is first used, not at every step)
  ["focus", "pointerdown"].forEach(event => slider.addEventListener(event, ask));
  $("canvas").addEventListener("click", (/** @type {MouseEvent} */ event) => clickedStage(event));
  $("trace").addEventListener("click", (/** @type {MouseEvent} */ event) => {
    const item = /** @type {HTMLElement} */ (event.target).closest("li");
    if (item && item.dataset.at !== undefined) toStory([...$("trace").children].indexOf(item));
  });
  $("trace").addEventListener("keydown", (/** @type {KeyboardEvent} */ event) => {
    if (!run || (event.key !== "ArrowDown" && event.key !== "ArrowUp")) return;
    event.preventDefault();
    toStory(Math.max(0, Math.min(run.timeline.story.length - 1, storyNow + (event.key === "ArrowDown" ? 1 : -1))));
  });
}

/** A run started, or went on: the live stage again, no slider. */
export function hideTimeSlider() {
  run = null; asked = false;
  $("time-travel").hidden = true;
  stage?.showMoment(null);
  if (ownTrace) { $("trace").replaceChildren(); $("after").hidden = true; ownTrace = false; }
  showMade(-1);
  state.moment = "";
}

/**
 * A run paused: the slider ends at this moment; the moments come when it is used.
 * @param {PausedMessage} message
 */
export function timeSliderPaused(message) {
  run = null; asked = false;
  offer(message.watch.time_s);
}

/**
 * The moments of a paused run, asked for (with the stage and the trace so far).
 * @param {TimelineJson & {stage: StageData, trace: string[]}} message
 */
export function timelineCame(message) {
  if ($("time-travel").hidden) return;   // (the run went on meanwhile)
  $("trace").replaceChildren(...message.trace.map(text => {
    const li = document.createElement("li"); li.textContent = text; return li;
  }));
  $("after").hidden = !message.trace.length;
  ownTrace = true;
  attach(message, message.stage);
}

/**
 * A simulated run ended: the slider over all of it (its trace is on the page already).
 * @param {TimelineJson | undefined} timeline
 * @param {StageData | undefined} stageData
 */
export function timeSliderEnded(timeline, stageData) {
  if (!timeline || !stageData) return;
  offer(timeline.end_ms / 1000);
  attach(timeline, stageData);
  $("watch").hidden = false;   // (the run's buttons have gone; its values at each moment stay)
}

/** @param {number} seconds the run's length so far */
function offer(seconds) {
  const slider = $("time");
  slider.max = seconds.toFixed(1);
  slider.value = slider.max;
  $("time-travel").hidden = false;
  said(Number(slider.value));
}

function ask() {
  if (run || asked) return;
  asked = send({type: "debug", action: "timeline"});
}

/**
 * @param {TimelineJson} timeline
 * @param {StageData} stageData
 */
function attach(timeline, stageData) {
  run = {timeline: timeline, stage: stageData, storyTimes: timeline.story.map(told => told[0]),
         noteTimes: timeline.notes.map(note => note[0])};
  litLines = "";
  [...$("trace").children].forEach((li, i) => {
    const told = timeline.story[i];
    if (told) /** @type {HTMLElement} */ (li).dataset.at = String(told[0]);
  });
  storyNow = -1;
  state.timeline = "yes";
  if (document.activeElement === $("time") || Number($("time").value) < Number($("time").max)) show(Number($("time").value));
}

/** @param {number} seconds of the run */
function said(seconds) {
  const text = words("time_at", {seconds: seconds.toFixed(1), total: Number($("time").max).toFixed(1)});
  $("time").setAttribute("aria-valuetext", text);
  $("time-shown").textContent = text;
}

/**
 * The run at this moment: the stage, the scripts' lines, the values, the trace's line.
 * @param {number} seconds of the run
 */
function show(seconds) {
  said(seconds);
  if (!run) { ask(); return; }
  const {timeline, stage: data} = run;
  const ms = Math.round(seconds * 1000);
  stage?.showMoment({data: data, t: (ms + timeline.recording_offset_ms) / 1000});
  const program = timeline.programs[at(timeline.program, ms)];
  const robot = timeline.robots[at(timeline.robot, ms)] || [];
  const note = timeline.notes[index(run.noteTimes, ms - 0.5) - 1];   // (the last begun before)
  const playing = note && (note[1] === null || note[1] >= ms) ? [note[2]] : [];
  if (program) {
    showWatch({type: "watch", places: program.places, lines: [
      ...program.values, ...robot, poseWords(timeline, ms), ...program.messages, ...playing,
    ], watch: /** @type {any} */ ({variables: program.variables, calls: program.calls})});
    const lines = program.places.filter(p => p.state === "next" || p.state === "running").map(p => p.line);
    if (lines.join() !== litLines) { light(lines); litLines = lines.join(); }
  }
  showStory(index(run.storyTimes, ms) - 1);
  showMade(-1);
  state.moment = seconds.toFixed(1);
}

/**
 * Which value a step function has at `ms` (its first before anything changed).
 * @param {[number[], number[]]} steps when each change came, and to which value
 * @param {number} ms
 */
function at(steps, ms) {
  return steps[1][changed(steps[0], ms)];
}

/**
 * The last change before `ms` (the first if none): a run paused at a moment pauses before
 * anything else due then happens (rootlang/runtime/timeline.py).
 * @param {number[]} times whole ms, in order
 * @param {number} ms
 */
function changed(times, ms) {
  return Math.max(0, index(times, ms - 0.5) - 1);
}

/**
 * Where the robot reckoned it was at `ms`, as a paused run says it (cm, whole degrees).
 * @param {TimelineJson} timeline
 * @param {number} ms
 */
function poseWords(timeline, ms) {
  const [times, xs, ys, hs] = timeline.poses;
  const i = changed(times, ms);
  const cm = (/** @type {number} */ mm) => String(Math.round(mm) / 10 || 0);
  const heading = ((Math.round(hs[i]) % 360) + 360) % 360;
  return timeline.pose_words.replace("{x}", cm(xs[i])).replace("{y}", cm(ys[i])).replace("{heading}", String(heading));
}

/** @param {number} now the trace's line of this moment (-1: none yet) */
function showStory(now) {
  if (now === storyNow) return;
  const items = $("trace").children;
  if (storyNow >= 0 && items[storyNow]) items[storyNow].classList.remove("now");
  storyNow = now;
  const item = items[now];
  if (!item) return;
  item.classList.add("now");
  if (/** @type {HTMLDetailsElement} */ ($("after")).open) item.scrollIntoView({block: "nearest"});
}

/**
 * To the moment of the trace's line `i`, its line lit as having made it.
 * @param {number} i
 */
function toStory(i) {
  if (!run) return;
  const told = run.timeline.story[i];
  if (!told) return;
  goTo(told[0] + 1, told[1]);   // (just after: what happened then is done)
  showStory(i);
}

/**
 * The slider to `ms`, and the statement on `line` lit as what made the moment (0: none).
 * @param {number} ms of the run
 * @param {number} line 1-based
 */
function goTo(ms, line) {
  const slider = $("time");
  slider.value = (ms / 1000).toFixed(3);
  show(ms / 1000);
  if (line) {
    light([line]);
    litLines = String(line);
    showMade(line - 1);
    editor.scrollIntoView({line: line - 1, ch: 0});
    say(words("made_by", {line: line, seconds: (ms / 1000).toFixed(1)}));
  }
  state.madeBy = String(line || "");
}

/** @param {number} line 0-based, lit as what made the moment shown (-1: none) */
function showMade(line) {
  if (madeLine >= 0) editor.removeLineClass(madeLine, "background", "made-line");
  madeLine = line;
  if (line >= 0) editor.addLineClass(line, "background", "made-line");
}

/**
 * A click on the stage: on a line of the drawing shown, to when that point was drawn, and the
 * movement that drew it lit.
 * @param {MouseEvent} event
 */
function clickedStage(event) {
  if (!run || !stage || !stage.transform) return;
  const {timeline, stage: data} = run;
  const shown = (Number($("time").value) * 1000 + timeline.recording_offset_ms) / 1000;
  const dpr = window.devicePixelRatio || 1, to = stage.transform;
  const x = (event.offsetX * dpr - to.e) / to.a, y = (event.offsetY * dpr - to.f) / to.d;
  const near = NEAR_PX * dpr / Math.abs(to.a);
  let best = near, when = -1;
  for (const stroke of data.ink) {
    if (stroke.k === "erase" || !stroke.t) continue;
    const times = stroke.t, p = stroke.p, reach = Math.max(near, stroke.w / 2);
    for (let i = 0; i < times.length && times[i] <= shown; i++) {
      const j = Math.min(i + 1, times.length - 1);
      const [ax, ay, bx, by] = [p[2 * i], p[2 * i + 1], p[2 * j], p[2 * j + 1]];
      const length = (bx - ax) ** 2 + (by - ay) ** 2;
      const f = length ? Math.max(0, Math.min(1, ((x - ax) * (bx - ax) + (y - ay) * (by - ay)) / length)) : 0;
      const distance = Math.hypot(ax + (bx - ax) * f - x, ay + (by - ay) * f - y);
      if (distance <= Math.min(best, reach)) { best = distance; when = times[i] + (times[j] - times[i]) * f; }
    }
  }
  if (when < 0) return;
  const ms = Math.min(Math.round(when * 1000) - timeline.recording_offset_ms, timeline.end_ms);
  const motion = timeline.motions.find(m => m[0] <= ms && (m[1] === null || ms <= m[1]));
  goTo(ms, motion ? motion[2] : 0);
}
