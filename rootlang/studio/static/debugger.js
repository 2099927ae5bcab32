// @ts-check
// Seeing inside a run (simulated or on a robot): Pause, Step and Resume; breakpoints on the text's lines (the
// gutter, or F9 on the cursor's line) and on blocks (their menu); the paused scripts' lines lit
// in both panes; the Watch panel with the values (a value changed since the last pause stands out).
import {$, session, state, words, say} from "./page.js";
import {editor, keptGutters} from "./editor.js";
import {glow, lineOfBlock, breakpointsFrom, markBreakpoints} from "./blocks.js";

/** @typedef {import("./messages").FromPage} FromPage */
/** @typedef {import("./messages").PausedMessage} PausedMessage */
/** @typedef {import("./messages").WatchMessage} WatchMessage */

const GUTTER = "breakpoints";
const KEPT = "rootlang-breakpoints/";   // + folder/program: this browser keeps them (a reload)
/** @type {(message: FromPage) => boolean} */
let send = () => false;
/** @type {number[]} the text's lines lit as paused (0-based) */
let pausedLines = [];
/** @type {Map<string, string>} the values at the last pause, by where and name */
let lastValues = new Map();
let paused = false;

/** @param {(message: FromPage) => boolean} sender the run's socket */
export function setupDebugger(sender) {
  send = sender;
  $("pause").addEventListener("click", () => send({type: "debug", action: "pause"}));
  $("step").addEventListener("click", () => send({type: "debug", action: "step"}));
  $("resume").addEventListener("click", () => send({type: "debug", action: "resume"}));
  editor.setOption("gutters", [GUTTER, ...(editor.getOption("gutters") || []).filter(g => g !== GUTTER)]);
  editor.on("gutterClick", (_cm, line, gutter) => { if (gutter === GUTTER || gutter === "CodeMirror-linenumbers") toggle(line + 1); });
  editor.addKeyMap({F9: () => toggle(editor.getCursor().line + 1)});
  keptGutters.push(GUTTER);   // (a Save's canonical text keeps them on their lines)
  breakpointsFrom(breakpointLines, () => words("breakpoint_on_block"));
  if (typeof Blockly !== "undefined") blockMenu();
}

/** The breakpoints' lines (1-based), as a run takes them: they move with the text's edits. */
export function breakpointLines() {
  /** @type {number[]} */
  const lines = [];
  editor.eachLine(handle => {
    const markers = /** @type {{gutterMarkers?: Record<string, HTMLElement>}} */ (handle).gutterMarkers;
    if (markers && markers[GUTTER]) lines.push(Number(editor.getLineNumber(handle)) + 1);
  });
  return lines;
}

/** @param {number} line 1-based */
function has(line) {
  return breakpointLines().includes(line);
}

/**
 * A breakpoint on the line, or none any more; a run going on is told at once.
 * @param {number} line 1-based
 */
export function toggle(line) {
  const on = !has(line);
  editor.setGutterMarker(line - 1, GUTTER, on ? dot() : null);
  markBreakpoints();
  keepBreakpoints();
  say(words(on ? "breakpoint_set" : "breakpoint_cleared", {line: line}));
  if (session.running) send({type: "debug", action: "breakpoints", breakpoints: breakpointLines()});
}

/** @returns {HTMLElement} a breakpoint's red dot in the text's margin */
function dot() {
  const marker = document.createElement("span");
  marker.className = "breakpoint";
  marker.textContent = "●";
  marker.title = words("breakpoint_remove");
  return marker;
}

/** @returns {string} where this browser keeps the open program's breakpoints */
function keptAt() {
  return KEPT + session.folder + "/" + session.current;
}

/** The breakpoints, kept in this browser with their lines' text (a Save, or an edit, keeps them). */
export function keepBreakpoints() {
  if (!session.current) return;
  const kept = breakpointLines().map(line => ({line: line, text: editor.getLine(line - 1)}));
  try {
    if (kept.length) localStorage.setItem(keptAt(), JSON.stringify(kept));
    else localStorage.removeItem(keptAt());
  } catch { /* the browser's storage full or off: they last as long as the page */ }
}

/**
 * A program just opened (a reload too): the breakpoints this browser kept for it, each on its
 * line if that line still holds the statement it was on (else it is gone: the program changed).
 */
export function restoreBreakpoints() {
  /** @type {{line: number, text: string}[]} */
  let kept = [];
  try { kept = JSON.parse(localStorage.getItem(keptAt()) || "[]"); } catch { return; }
  if (!Array.isArray(kept)) return;
  for (const {line, text} of kept) {
    if (typeof line !== "number" || editor.getLine(line - 1) !== text || has(line)) continue;
    editor.setGutterMarker(line - 1, GUTTER, dot());
  }
  markBreakpoints();
}

/** The blocks' menu: Stop here / Don't stop here, on the block's line. */
function blockMenu() {
  const registry = Blockly.ContextMenuRegistry.registry;
  if (registry.getItem("rootlang_breakpoint")) return;
  registry.register({
    id: "rootlang_breakpoint",
    scopeType: Blockly.ContextMenuRegistry.ScopeType.BLOCK,
    weight: 0,
    displayText: scope => {
      const line = scope.block ? lineOfBlock(scope.block.id) : 0;
      return words(line && has(line) ? "breakpoint_remove" : "breakpoint_add");
    },
    preconditionFn: scope => (scope.block && lineOfBlock(scope.block.id) ? "enabled" : "hidden"),
    callback: scope => {
      const line = scope.block ? lineOfBlock(scope.block.id) : 0;
      if (line) toggle(line);
    },
  });
}

/** A run started (simulated or on a robot: it can be paused). */
export function runStarted() {
  paused = false;
  lastValues = new Map();
  buttons(true);
  $("watch-lines").replaceChildren();
}

export function runEnded() {
  const had = ["pause", "step", "resume"].some(id => document.activeElement === $(id));
  paused = false;
  light([]);
  buttons(false);
  if (had) $("run").focus();   // (the buttons go away: the keyboard goes on from Run)
}

/**
 * The buttons and the Watch panel are there while a run goes on (else they'd only take room).
 * @param {boolean} running
 */
function buttons(running) {
  const [pause, step, resume] = ["pause", "step", "resume"].map(id => /** @type {HTMLButtonElement} */ ($(id)));
  pause.disabled = !running || paused;
  step.disabled = !running;
  resume.disabled = !running || !paused;
  [pause, step, resume, $("watch")].forEach(element => { element.hidden = !running; });
}

/** @returns {boolean} whether the run is paused now */
export function isPaused() {
  return paused;
}

/** @param {PausedMessage} message */
export function showPaused(message) {
  paused = true;
  // the statements the scripts are at (one that has just started is at none yet)
  light(message.places.filter(place => place.state === "next" || place.state === "running")
    .map(place => place.line));
  say(words("paused", {seconds: message.watch.time_s.toFixed(1)}));
  const pausedFrom = document.activeElement === $("pause");
  buttons(true);
  showWatch(message);
  if (pausedFrom) $("step").focus();   // (Pause is off now: the keyboard goes on from Step)
}

/**
 * The Watch panel: where each script is, then the values (a value changed since the last look
 * stands out); while the run goes on, about five times a second (exact when paused).
 * @param {PausedMessage | WatchMessage} message
 */
export function showWatch(message) {
  // the values' lines come first in the watch's words: one a variable, then one a call
  const {variables, calls} = message.watch;
  /** @type {Map<string, string>} */
  const values = new Map();
  const changed = message.lines.map((_line, index) => {
    /** @type {[string, string][]} */
    const shown = index < variables.length
      ? [[variables[index].script + "\n" + variables[index].name, variables[index].value]]
      : index < variables.length + calls.length
        ? calls[index - variables.length].parameters.map(p => [calls[index - variables.length].script + "\n" + calls[index - variables.length].procedure + "\n" + p.name, p.value])
        : [];
    shown.forEach(([key, value]) => values.set(key, value));
    return shown.some(([key, value]) => lastValues.has(key) && lastValues.get(key) !== value);
  });
  showLines($("watch-lines"), [...message.places.map(place => /** @type {[string, boolean]} */ (
    [place.words, false])), ...message.lines.map((line, index) => /** @type {[string, boolean]} */ (
    [line, changed[index]]))]);
  lastValues = values;
}

/** The paused run goes on (a step pauses again soon). */
export function showResumed() {
  const resumedFrom = document.activeElement === $("resume");
  paused = false;
  buttons(true);
  if (resumedFrom) $("pause").focus();   // (Resume is off now)
}

/**
 * The list's lines become these, each line touched only where it differs: new elements five
 * times a second made Chromium sort the whole page's drawing (every block) into layers again,
 * most of a slow Chromebook's time while a run goes on (benchmarks/studio_frames.py --trace).
 * @param {HTMLElement} list
 * @param {[string, boolean][]} lines each line's words, and whether its value just changed
 */
function showLines(list, lines) {
  lines.forEach(([text, changed], index) => {
    const li = list.children[index] ?? list.appendChild(document.createElement("li"));
    if (li.textContent !== text) li.textContent = text;
    li.classList.toggle("changed", changed);
  });
  while (list.children.length > lines.length) list.lastElementChild?.remove();
}

/** @param {number[]} lines 1-based: the paused scripts' statements, lit in both panes */
export function light(lines) {
  pausedLines.forEach(line => editor.removeLineClass(line, "background", "paused-line"));
  pausedLines = lines.filter(line => line > 0).map(line => line - 1);
  pausedLines.forEach(line => editor.addLineClass(line, "background", "paused-line"));
  glow(lines.filter(line => line > 0), "paused");
  state.paused = pausedLines.map(line => line + 1).join(",");
}
