// @ts-check
// Blocks and text kept in step (the conversion is the server's, in Python), and the mistakes
// the checks find, shown on the text and on their blocks.
import * as api from "./api.js";
import {$, session, state, words, say} from "./page.js";
import {editor, setText, settingText} from "./editor.js";
import {workspace, loadWorkspace, rememberLayout, blockAt} from "./blocks.js";

/** @typedef {import("./messages").DiagnosticJson} DiagnosticJson */

const SYNC_DELAY_MS = 100;   // after the last keystroke or block move; the round trip stays under 0.3 s
/** @type {ReturnType<typeof setTimeout> | undefined} */
let textTimer;
/** @type {ReturnType<typeof setTimeout> | undefined} */
let blocksTimer;
/** @type {import("codemirror").TextMarker[]} */
let errorMarks = [];

/** The child typed: the blocks follow a moment after the last keystroke. */
export function textEdited() {
  if (settingText) return;
  state.textSynced = "no";
  clearTimeout(textTimer);
  textTimer = setTimeout(textChanged, SYNC_DELAY_MS);
}

/** The child changed the blocks: the text follows a moment after. */
export function blocksEdited() {
  state.blocksSynced = "no";
  clearTimeout(blocksTimer);
  blocksTimer = setTimeout(blocksChanged, SYNC_DELAY_MS);
}

/** The text as blocks (when it parses) and its mistakes, now. */
export async function textChanged() {
  clearTimeout(textTimer);
  const text = editor.getValue();
  const reply = await api.toBlocks({text: text, name: session.current});
  if (editor.getValue() !== text) return;   // typed on meanwhile: the next round comes
  if (reply.workspace && workspace) loadWorkspace(workspace, reply.workspace);
  showProblems(reply.diagnostics);
  if (reply.text_only) say(reply.text_only.message, true);   // too long for blocks (E817)
  state.textSynced = "yes";
}

async function blocksChanged() {
  if (!workspace) return;
  const json = Blockly.serialization.workspaces.save(workspace);
  try {
    const reply = await api.toText({workspace: json, name: session.current});
    setText(reply.text);
    showProblems(reply.diagnostics);
    rememberLayout();
    state.blocksSynced = "yes";
  } catch (error) {
    say(String(/** @type {Error} */ (error).message), true);
  }
}

/**
 * Mistakes and warnings: listed under the text, underlined in it, marked in its gutter, and on
 * their blocks.
 * @param {DiagnosticJson[]} diagnostics
 */
export function showProblems(diagnostics) {
  errorMarks.forEach(mark => mark.clear());
  errorMarks = [];
  editor.clearGutter("problems");
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
    if (d.line >= 1) {
      const from = {line: d.line - 1, ch: Math.max(0, d.column - 1)};
      const to = {line: d.end_line - 1, ch: Math.max(d.end_column - 1, d.column)};
      errorMarks.push(editor.markText(from, to, {className: "cm-" + d.severity + "-mark", title: d.message}));
      const dot = document.createElement("span");
      dot.textContent = d.severity === "error" ? "●" : "▲";
      dot.style.color = d.severity === "error" ? "#dc2626" : "#d97706";
      dot.title = d.message;
      editor.setGutterMarker(d.line - 1, "problems", dot);
      const block = blockAt(d.line, d.column);
      if (block) block.setWarningText(d.message);
    }
  }
  state.problems = String(diagnostics.length);
  state.errors = String(diagnostics.filter(d => d.severity === "error").length);
}
