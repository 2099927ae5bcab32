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
 * The text, set by the page (the child's cursor stays where it was).
 * @param {string} text
 * @param {{fresh?: boolean}} [how] fresh: a program just opened (its own undo history)
 */
export function setText(text, how) {
  if (editor.getValue() === text && !(how && how.fresh)) return;
  settingText = true;
  try {
    const cursor = editor.getCursor();
    editor.setValue(text);
    if (how && how.fresh) editor.clearHistory();
    else editor.setCursor(cursor);
  } finally {
    settingText = false;
  }
}
