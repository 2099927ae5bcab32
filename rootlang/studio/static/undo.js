// @ts-check
// The page's one undo history, for both panes. Ctrl+Z (and Ctrl+Y, Ctrl+Shift+Z) in the text or
// in the blocks walks back (and forward again) through the child's own edits in the order they
// were made, whichever pane each was made in: an undo puts back the whole page as it was before
// that edit (the text, the blocks and where they lay, the loose blocks, the mistakes), so the two
// panes are always in step after it, and never show a state the child did not see.
//
// A step is one edit of the child's, as both panes showed it once the other pane had followed:
// - in the text, a run of typing: it ends when the child moves the cursor (a click, an arrow
//   key, Home, End ...), leaves the text, pauses for more than TYPING_PAUSE_MS, or edits the
//   blocks;
// - in the blocks, one action: what Blockly groups as one (a drag and drop, a block from the
//   toolbox, a field's edit, a deletion);
// - edits made in both panes before either followed the other (within a moment) are one step.
// Changes the page makes itself (the blocks' text after a block edit, which belongs to that
// edit; a Save's canonical text; a program opened) are no steps. A new edit after an undo drops
// the steps that were undone (no redo then), as in any editor.
import {state} from "./page.js";
import {editor} from "./editor.js";
import {routeUndo} from "./blocks.js";
import {onEdit, onQuiet, snapshot, restore, settle} from "./sync.js";

/** @typedef {import("./sync.js").Snapshot} Snapshot */

const TYPING_PAUSE_MS = 1250;   // (CodeMirror's own: a pause in typing starts a new step)
const MOST_STEPS = 200;
const MOST_CHARACTERS = 20_000_000;   // what all steps' texts and blocks may hold (a long program)

/** What the page showed after each step, oldest first; `at` is the one it shows now. */
/** @type {Snapshot[]} */
let steps = [];
let at = -1;
/**
 * The child's run of edits the step shown now is (the next edit of the same run joins it):
 * in which pane, the blocks' event group, when the last edit came; null: the next edit is a
 * step of its own.
 * @type {{pane: string, group: string, last: number} | null}
 */
let run = null;
/** Edits since the step shown now that are in no step yet; `own`: they start a new one. */
/** @type {{own: boolean} | null} */
let pending = null;
/** Undos and redos wait for one another (each may first wait for the panes to be in step). */
let queue = Promise.resolve();

/** The history starts again at what the page shows (a program just opened). */
export function startHistory() {
  steps = [snapshot(null)];
  at = 0;
  run = null;
  pending = null;
  show();
}

/** No history while a program opens (nothing to step through until it is open). */
export function forgetHistory() {
  steps = [];
  at = -1;
  run = null;
  pending = null;
  show();
}

/**
 * The page changed what it shows without changing the program (a Save's canonical text): the
 * step shown now is as the page shows it (unless an edit is on its way: its step will be).
 */
export function pageChanged() {
  if (pending || at < 0) return;
  steps[at] = snapshot(at > 0 ? steps[at - 1] : null);
}

/** The child's next edit is a step of its own (the cursor moved, the text was left ...). */
export function endRun() { run = null; }

onEdit.push((pane, group) => {
  if (pane === "undo" || at < 0) return;
  const now = Date.now();
  const same = run !== null && run.pane === pane
    && (pane === "text" ? now - run.last <= TYPING_PAUSE_MS : group !== "" && group === run.group);
  run = {pane: pane, group: group, last: now};
  steps.length = at + 1;   // (a new edit: what was undone can't be redone)
  if (pending) pending.own = pending.own || !same;
  else pending = {own: !same || at === 0};   // (the opened program is no step to join)
  show();
});

onQuiet.push(() => {
  if (pending) take();
  // (a program opened while its blocks were still being made: its step gets them now)
  else if (at >= 0 && !steps[at].blocks) pageChanged();
});

/** The edits on their way are a step now (or join the step shown, when of the same run). */
function take() {
  if (!pending) return;
  const shot = snapshot(steps[at] || null);
  if (pending.own) {
    steps.push(shot);
    at = steps.length - 1;
  } else {
    steps[at] = shot;
  }
  pending = null;
  let size = steps.reduce((sum, step) => sum + weight(step), 0);
  while (steps.length > MOST_STEPS || (size > MOST_CHARACTERS && at > 1)) {
    size -= weight(/** @type {Snapshot} */ (steps.shift()));
    at--;
  }
  show();
}

/** @param {Snapshot} step roughly how much it holds (its scripts shared with other steps count each time) */
const weight = step => step.text.length + (step.blocks ? step.blocks.top.reduce((sum, top) => sum + top.json.length, 0) : 0);

/**
 * One step back (an undo) or forward (a redo), after the steps before it (Ctrl+Z held down).
 * @param {boolean} redo
 */
export function stepHistory(redo) {
  queue = queue.then(() => go(redo)).catch(error => console.warn("undo", error));
  return queue;
}

/** @param {boolean} redo */
async function go(redo) {
  if (at < 0) return;
  if (pending) {
    // an edit not in a step yet: the panes follow it first (if the studio answers), so the
    // step it makes is the page in step; if not, the page as it is now
    await settle().catch(() => {});
    take();
  }
  const to = at + (redo ? 1 : -1);
  if (to < 0 || to >= steps.length) return;
  at = to;
  run = null;
  restore(steps[at]);
  show();
  onEdit.forEach(listener => listener("undo", ""));   // (saved by itself, kept as a draft)
}

/** @param {boolean} redo whether there is a step to take that way */
const can = redo => redo ? at + 1 < steps.length && !pending : at > 0 || pending !== null;

/** For the browser tests: the step shown, of how many, and whether an edit is on its way. */
function show() {
  state.history = `${at}/${steps.length}${pending ? "+" : ""}`;
}

/** Ctrl+Z, Ctrl+Y and Ctrl+Shift+Z in both panes step through this history. */
export function setupUndo() {
  const back = () => { stepHistory(false); };
  const forward = () => { stepHistory(true); };
  const keys = /** @type {import("codemirror").KeyMap} */ (editor.getOption("extraKeys") || {});
  editor.setOption("extraKeys", {...keys, "Ctrl-Z": back, "Cmd-Z": back,
                                 "Ctrl-Y": forward, "Shift-Ctrl-Z": forward, "Shift-Cmd-Z": forward});
  // the cursor moved by the child (not by typing), or the text left: the typing's step ends
  editor.on("mousedown", endRun);
  editor.on("touchstart", endRun);
  editor.on("blur", endRun);
  editor.on("keydown", (_, event) => {
    if (/^(Arrow|Page|Home|End)/.test(event.key)) endRun();
  });
  routeUndo(redo => { stepHistory(redo); }, can);
}
