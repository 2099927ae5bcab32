// @ts-check
// Blocks and text kept in step (the conversion is the server's, in Python), and the mistakes
// the checks find, shown on the text and on their blocks.
//
// While the child works with blocks, the workspace is theirs: the text follows from the scripts
// that are complete; a loose block or an unfinished script stays on the workspace, greyed, with
// why on the block (and in the layout sidecar, never in the text). A text edit fits the text's
// blocks in among them (blocks.js fitText): nothing the page shows is silently replaced.
import * as api from "./api.js";
import {$, session, state, words, say, fixed} from "./page.js";
import {editor, setText, settingText} from "./editor.js";
import {mergeEdits} from "./textmerge.js";
import {showPane} from "./panes.js";
import {workspace, fitText, indexText, rememberLayout, blockAt, markLeftOut, showLeftOut,
        restoreLoose, clearBlocks, blocksSnapshot, restoreBlocks, making, blocksMade,
        finishMaking} from "./blocks.js";

/** @typedef {import("./messages").DiagnosticJson} DiagnosticJson */
/** @typedef {import("./messages").LeftOutJson} LeftOutJson */
/**
 * What the page shows at one step of its undo history (undo.js).
 * @typedef {{text: string, agreed: string, problems: DiagnosticJson[], dirty: "" | "text" | "blocks",
 *   blocks: import("./blocks.js").BlocksSnapshot | null}} Snapshot
 */

const SYNC_DELAY_MS = 100;   // after the last keystroke or block move; the round trip stays under 0.3 s
const LINE_ENDED_DELAY_MS = 0;   // a line just ended (Enter): the child has finished a statement
const LOOSE = "E704";        // the server's code for a block lying outside any script
const TOO_SLOW = "E818";     // a conversion stopped at the studio's time (or memory) limit
/** @type {ReturnType<typeof setTimeout> | undefined} */
let textTimer;
/** @type {ReturnType<typeof setTimeout> | undefined} */
let blocksTimer;
/** @type {import("codemirror").TextMarker[]} */
let errorMarks = [];
/** The text the blocks show now: what a blocks round's text is an edit of. */
let agreed = "";
/** The child's block edits so far: a round is in step only if none came while it ran. */
let blockEdits = 0;
/**
 * Called after each edit of the child's (the autosave and the undo history listen): in which
 * pane ("undo": an undo or redo, in either), and the blocks' event group ("" for the text).
 * @type {((pane: "text" | "blocks" | "undo", group: string) => void)[]}
 */
export const onEdit = [];
/** Called whenever the panes are in step again after an edit (undo.js takes a step there). */
/** @type {(() => void)[]} */
export const onQuiet = [];
/** Conversions on their way (a round's answer not back yet). */
let asked = 0;
/** One more each time the page puts back an earlier state (undo): a round asked before that
 * one is for a state the page no longer shows, and its answer is not used. */
let restored = 0;
/**
 * How long the text was when its conversion ran past the studio's time limit (E818): this
 * program is text only while it is that long (0: it is not), and its text is not sent again
 * for nothing (the class's workers stay free); at half that length, the blocks are tried again.
 */
let givenUpAt = 0;
/** Why this program shows as text only ("" while it shows as blocks). */
let textOnlyWhy = "";

/**
 * The child typed: the blocks follow a moment after the last keystroke, at once when a line
 * ended (CodeMirror's changes: a change with more than one line of text is a line break).
 * @param {unknown} [_editor]
 * @param {{text: string[]}[]} [changes]
 */
export function textEdited(_editor, changes) {
  if (settingText) return;
  state.textSynced = "no";
  const lineEnded = (changes || []).some(change => change.text.length > 1);
  followText(lineEnded ? LINE_ENDED_DELAY_MS : SYNC_DELAY_MS);
  onEdit.forEach(listener => listener("text", ""));
}

/**
 * The child changed the blocks: the text follows a moment after.
 * @param {string} group the change's Blockly event group
 */
export function blocksEdited(group) {
  state.blocksSynced = "no";
  blockEdits++;
  followBlocks();
  onEdit.forEach(listener => listener("blocks", group));
}

function followBlocks() {
  clearTimeout(blocksTimer);
  blocksTimer = setTimeout(() => {
    blocksTimer = undefined;
    if (workspace && workspace.isDragging()) followBlocks();  // (the drop comes: then)
    else blocksChanged().catch(sayError).finally(quietNow);
  }, SYNC_DELAY_MS);
}

/**
 * The blocks follow the text after `delay` ms; with none, as soon as the edit's own work is
 * done (a line just ended: the conversion is asked for before the page draws the new line,
 * and the server works on it meanwhile).
 * @param {number} [delay]
 */
function followText(delay = SYNC_DELAY_MS) {
  clearTimeout(textTimer);
  const follow = () => {
    if (textTimer !== timer) return;   // (followed already, or put off again)
    clearTimeout(timer);
    textTimer = undefined;
    textChanged().catch(sayError).finally(quietNow);
  };
  const timer = setTimeout(follow, delay);
  textTimer = timer;
  if (delay === 0) queueMicrotask(follow);
}

/** Whether the two panes show one program now, with no edit on its way from one to the other. */
const inStep = () => textTimer === undefined && blocksTimer === undefined && asked === 0
  && state.textSynced === "yes" && state.blocksSynced !== "no" && state.outOfStep !== "yes";

function quietNow() {
  if (inStep()) onQuiet.forEach(listener => listener());
}

/** @param {unknown} error */
function sayError(error) { say(String(/** @type {Error} */ (error).message), true, "sync"); }

/**
 * Whatever the child did last is in the other pane too (before a run or a save). Panes already
 * in step are left as they are: a run's mistake stays in the list until the child edits.
 */
export async function settle() {
  if (state.blocksSynced === "no") await blocksChanged();
  else if (state.textSynced !== "yes") await textChanged();
  quietNow();
}

/**
 * Whether the blocks hold an edit their text has not brought into the text yet: a text round
 * then waits for it, since fitting the text's blocks would undo that edit, and the blocks'
 * text would then come back over the typing as if the child had deleted it.
 */
const blocksAhead = () => state.blocksSynced === "no" && state.outOfStep !== "yes";

/**
 * The text as blocks (when it parses) and its mistakes, now: done when its blocks are all made
 * (`how.begun`: once they are begun, the rest of the round goes on by itself).
 * @param {{begun?: boolean}} [how]
 */
export async function textChanged(how = {}) {
  clearTimeout(textTimer);
  textTimer = undefined;
  if (blocksAhead()) { followText(); return; }   // (the blocks' round merges the typing, then this)
  const text = editor.getValue();
  if (givenUpAt && text.length > givenUpAt / 2) {   // still too long to convert in time
    state.textSynced = "yes";
    return;
  }
  let reply;
  const state0 = restored;
  asked++;
  try {
    reply = await api.toBlocks({text: text, name: session.current});
    await blocksMade();   // (blocks still being made for an earlier text: made first)
  } catch (error) {
    if (!(error instanceof api.Refused && error.errors.some(e => e.code === TOO_SLOW))) throw error;
    if (restored !== state0) return;
    if (editor.getValue() !== text) { followText(); return; }
    givenUpAt = text.length;         // (the blocks stay as they are, out of sight)
    showTextOnly(words("text_only_slow"));
    state.textSynced = "yes";
    return;
  } finally {
    asked--;
  }
  if (restored !== state0) return;    // (an undo put back another state meanwhile)
  if (editor.getValue() !== text || blocksAhead()) {   // changed meanwhile: a round for now
    followText();
    return;
  }
  givenUpAt = 0;
  if (reply.workspace) agreed = text;   // (the blocks being made are this text's)
  const made = reply.workspace && workspace ? fitText(workspace, reply.workspace) : Promise.resolve(true);
  asked++;   // (the round is on its way until its blocks are made)
  const rest = made.finally(() => { asked--; })
    .then(whole => whole && restored === state0 ? textFitted(text, reply) : undefined);
  if (how.begun) rest.catch(sayError).finally(quietNow);
  else await rest;
}

/**
 * A text's blocks are made: its mistakes shown, and the panes in step (unless the child typed
 * meanwhile: the round for that does it).
 * @param {string} text
 * @param {import("./messages").BlocksReply} reply
 */
async function textFitted(text, reply) {
  if (editor.getValue() !== text) return;
  showProblems(reply.diagnostics);
  fixed("sync");
  // too long for blocks (E817): text only, the blocks pane and the status line say why
  if (reply.text_only) showTextOnly(reply.text_only.message);
  else if (reply.workspace || textOnlyWhy === "") showTextOnly("");
  // The blocks its sidecar kept out of the text, as soon as the program shows as blocks: when
  // it opens, or when it comes back from text only (made short enough again). Until then they
  // stay in the layout a Save writes (blocks.js rememberLayout), and are put back only once.
  if (workspace && !textOnlyWhy && restoreLoose(workspace) > 0) await blocksChanged();
  if (editor.getValue() === text) state.textSynced = "yes";
}

/**
 * The program shows as text only, and the blocks pane and the status line say `why` (""
 * shows the blocks again).
 * @param {string} why
 */
function showTextOnly(why) {
  textOnlyWhy = why;
  $("text-only").textContent = why;
  $("text-only").hidden = why === "";
  if (workspace) {
    const hidden = why !== "";
    if ($("blocks").hidden !== hidden) {
      $("blocks").hidden = hidden;
      if (!hidden) Blockly.svgResize(workspace);
    }
  }
  if (why) {
    say(why, true, "text_only");
    showPane("text");   // (a narrow screen shows one of the two: the text, then)
  } else {
    fixed("text_only");
  }
  state.textOnly = why ? "yes" : "";
}

/** Why the program open shows as text only ("": it shows as blocks). */
export const textOnly = () => textOnlyWhy;

/** The program open is too long to convert (or format) within the studio's time limit. */
export const tooSlow = () => givenUpAt > 0;

/** The blocks' complete scripts as text; the rest greyed, with why. */
export async function blocksChanged() {
  clearTimeout(blocksTimer);
  if (!workspace) return;
  finishMaking();   // (never half-made blocks as text)
  const edits = blockEdits;
  const json = Blockly.serialization.workspaces.save(workspace);
  const state0 = restored;
  let reply;
  asked++;
  try {
    reply = await api.toText({workspace: json, name: session.current});
  } catch (error) {           // they can't be a text now: both stay as they are, and it is said
    if (restored !== state0) return;
    say(words("out_of_step"), true, "out_of_step");
    state.outOfStep = "yes";
    throw error instanceof api.Refused ? new Error(words("out_of_step")) : error;
  } finally {
    asked--;
  }
  if (restored !== state0) return;   // (an undo put back another state meanwhile)
  state.outOfStep = "";
  markLeftOut(reply.left_out, childWords);   // (first: a text round leaves these alone)
  // The child may have typed meanwhile: their lines stay, the blocks' lines join them.
  const typed = editor.getValue();
  const merged = mergeEdits(agreed, reply.text, typed);
  agreed = reply.text;
  if (merged === null) {      // the same lines changed in both at once: both stay, it is said
    say(words("out_of_step"), true, "out_of_step");
    state.outOfStep = "yes";
    return;
  }
  fixed("out_of_step"); fixed("sync");
  setText(merged);
  if (merged !== reply.text) followText();   // the typing is not in the blocks yet
  // which block is which line of the new text (for mistakes, the glow of a run, the layout):
  // the reply carries the text's own blocks, so no second request
  if (editor.getValue() === reply.text) indexText(workspace, reply.workspace);
  showProblems(reply.diagnostics);
  rememberLayout();
  state.leftOut = String(reply.left_out.length);
  if (edits === blockEdits) state.blocksSynced = "yes";
}

/**
 * Why a block is left out, in the page's words: on the script (or loose block) and on the block
 * inside it that misses something.
 * @param {LeftOutJson} left
 */
function childWords(left) {
  if (left.diagnostic.code === LOOSE) return {top: words("left_loose"), here: ""};
  if (left.diagnostic.code === "E703") return {top: words("left_unfinished"), here: words("left_missing")};
  return {top: words("left_unfinished") + "\n" + left.diagnostic.message, here: ""};
}

/**
 * A program just opened: its blocks, then the blocks its sidecar kept out of the text (a
 * program that opens as text only gets them when it has blocks again: textChanged).
 */
export async function opened() {
  clearTimeout(blocksTimer); blocksTimer = undefined;
  if (workspace) clearBlocks(workspace);
  agreed = "";                // (no blocks yet)
  givenUpAt = 0;
  state.textSynced = "no";    // (until its blocks are all made: a Run or a Save waits for them)
  showTextOnly("");
  // (and the blocks its sidecar kept, unless it is text only); the page is the child's once
  // the first blocks are made, the rest come between frames
  await textChanged({begun: true});
}

// --- the page's undo history (undo.js) takes and puts back what the two panes show -------------

/** @type {DiagnosticJson[]} the mistakes and warnings shown now */
let shownProblems = [];

/**
 * What the page shows now: the text, the blocks, the mistakes; `dirty` says which pane has an
 * edit the other has not followed yet ("" when they are in step).
 * @param {Snapshot | null} earlier the step before (its blocks' strings are shared)
 * @returns {Snapshot}
 */
export function snapshot(earlier) {
  const dirty = state.blocksSynced === "no" ? "blocks" : inStep() ? "" : "text";
  // (blocks still being made: none, the text makes them again if it is put back)
  return {text: editor.getValue(), agreed: agreed, problems: shownProblems, dirty: dirty,
          blocks: textOnlyWhy || making() ? null : blocksSnapshot(earlier ? earlier.blocks : null)};
}

/**
 * The page shows `shot` again (an undo or a redo): the text and the blocks as they were, and
 * their mistakes; an edit that had not reached the other pane then is sent on again. A round
 * on its way for what the page showed before is not used. Not an edit of the child's.
 * @param {Snapshot} shot
 */
export function restore(shot) {
  restored++;
  clearTimeout(textTimer); textTimer = undefined;
  clearTimeout(blocksTimer); blocksTimer = undefined;
  setText(shot.text, {cursor: true});
  if (shot.blocks) {
    restoreBlocks(shot.blocks);
    agreed = shot.agreed;
    showProblems(shot.problems);
    rememberLayout();
  }
  state.outOfStep = ""; fixed("out_of_step");
  state.textSynced = "yes"; state.blocksSynced = "yes";
  if (shot.dirty === "blocks") {
    state.blocksSynced = "no"; blockEdits++; followBlocks();
  } else if (shot.dirty === "text" || !shot.blocks) {
    state.textSynced = "no"; followText();
  }
}

/**
 * Mistakes and warnings: listed under the text, underlined in it, marked in its gutter, and on
 * their blocks.
 * @param {DiagnosticJson[]} diagnostics
 */
export function showProblems(diagnostics) {
  shownProblems = diagnostics;
  const marked = diagnostics.filter(d => d.line >= 1);
  // (the editor's changes in one operation: CodeMirror measures the page once, not once each;
  // none when it has no marks to take away or make)
  if (errorMarks.length || marked.length) editor.operation(() => {
    errorMarks.forEach(mark => mark.clear());
    errorMarks = [];
    editor.clearGutter("problems");
    for (const d of marked) {
      const from = {line: d.line - 1, ch: Math.max(0, d.column - 1)};
      const to = {line: d.end_line - 1, ch: Math.max(d.end_column - 1, d.column)};
      errorMarks.push(editor.markText(from, to, {className: "cm-" + d.severity + "-mark", title: d.message}));
      const dot = document.createElement("span");
      dot.textContent = d.severity === "error" ? "●" : "▲";
      dot.style.color = d.severity === "error" ? "#dc2626" : "#d97706";
      dot.title = d.message;
      editor.setGutterMarker(d.line - 1, "problems", dot);
    }
  });
  if (workspace) workspace.getAllBlocks(false).forEach(block => block.setWarningText(null));
  const list = $("problems");
  list.replaceChildren();
  for (const d of diagnostics) {
    const li = document.createElement("li");
    li.className = d.severity;
    li.textContent = d.line ? words("at_line", {line: d.line, message: d.message}) : d.message;
    li.tabIndex = 0;
    li.addEventListener("click", () => { editor.focus(); editor.setCursor(d.line - 1, d.column - 1); });
    list.append(li);
    const block = d.line >= 1 ? blockAt(d.line, d.column) : null;
    if (block) block.setWarningText(d.message);
  }
  showLeftOut();
  state.problems = String(diagnostics.length);
  state.errors = String(diagnostics.filter(d => d.severity === "error").length);
  // (a narrow screen shows the blocks or the text: the Text tab says when the text has mistakes)
  $("tab-text").dataset.mistakes = state.errors;
  $("tab-text").setAttribute("aria-label", words(state.errors === "0" ? "tab_text" : "tab_text_mistakes"));
  if (state.errors === "0") fixed("mistakes");
}
