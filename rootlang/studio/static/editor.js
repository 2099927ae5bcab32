// @ts-check
// The text pane: CodeMirror 5 (vendored, a UMD global) with rootlang's colours.
import {$} from "./page.js";

CodeMirror.defineSimpleMode("rootlang", {
  start: [
    {regex: /#.*/, token: "comment"},
    {regex: /"(?:[^"\\]|\\.)*"?/, token: "string"},
    {regex: /^(?:when|to)\b/i, token: "keyword", sol: true},
    {regex: /\b(?:repeat|forever|until|if|else|while|then|wait|set|change|by|to|return|stop|send|and|or|not)\b/i, token: "keyword"},
    {regex: /\b(?:move|turn|drive|marker|eraser|light|play|note|say|print|go|arc|undock|dock|sweep|reset|sound|volume)\b/i, token: "builtin"},
    {regex: /-?\d+(?:\.\d+)?\s*(?:mm|cm|m|inch(?:es)?|degrees?|deg|°|seconds?|sec|s|ms|cm\/s|mm\/s|Hz|%)?/i, token: "number"},
    {regex: /\b(?:red|orange|yellow|green|cyan|blue|purple|pink|white|black|rgb)\b/i, token: "atom"},
    {regex: /[a-z_][\w]*/i, token: "variable"},
  ],
  meta: {lineComment: "#"},
});

/** The program's text. */
export const editor = CodeMirror.fromTextArea($("text"), {
  mode: "rootlang", lineNumbers: true, indentUnit: 4, tabSize: 4, indentWithTabs: false,
  gutters: ["CodeMirror-linenumbers", "problems"],
  extraKeys: {Tab: cm => cm.execCommand("insertSoftTab")},
  screenReaderLabel: "Program text",
  // (the addons' options: active-line.js and matchbrackets.js read them)
  .../** @type {object} */ ({styleActiveLine: true, matchBrackets: true}),
});
editor.getInputField().setAttribute("aria-label", "Program text");

/** True while the page itself sets the text (not a child's edit). */
export let settingText = false;

/**
 * The text, set by the page: only the lines that differ are replaced, so the child's cursor and
 * the rest of the text stay as they were.
 * @param {string} text
 * @param {{fresh?: boolean}} [how] fresh: a program just opened (its own undo history)
 */
export function setText(text, how) {
  if (editor.getValue() === text && !(how && how.fresh)) return;
  settingText = true;
  try {
    if (how && how.fresh) {
      editor.setValue(text);
      editor.clearHistory();
    } else {
      const now = editor.getValue();
      const [head, tail] = sameEnds(now, text);
      const from = editor.posFromIndex(head), to = editor.posFromIndex(now.length - tail);
      editor.replaceRange(text.slice(head, text.length - tail), from, to, "setValue");
    }
  } finally {
    settingText = false;
  }
}

/**
 * How many characters two texts share at their start and (after that) at their end.
 * @param {string} a
 * @param {string} b
 * @returns {[number, number]}
 */
function sameEnds(a, b) {
  const most = Math.min(a.length, b.length);
  let head = 0;
  while (head < most && a[head] === b[head]) head++;
  let tail = 0;
  while (tail < most - head && a[a.length - 1 - tail] === b[b.length - 1 - tail]) tail++;
  return [head, tail];
}
