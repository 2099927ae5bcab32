// @ts-check
// The text pane: CodeMirror 5 (vendored, a UMD global) with rootlang's colours.
import {$} from "./page.js";
import {sameEnds} from "./textmerge.js";

/**
 * A regex source matching any of these words or phrases (a phrase's spaces: any spaces).
 * @param {string[]} words longest first (the server's order), so a phrase wins over its first word
 */
const anyOf = words => words.map(word => word.replace(/[.*+?^${}()|[\]\\/]/g, "\\$&").replace(/ /g, "\\s+")).join("|");

// (a word ends where no letter, digit or _ follows: in every language, not only English's \b)
const WORD_END = "(?![\\p{L}\\p{N}_])";

/**
 * The text pane's colours for a program in the page's language: the words come from the
 * server's setup (its keyword tables, English's words too), never from a list of the page's.
 * @param {string} language
 * @param {Record<string, string[]>} syntax words by CodeMirror token name; `unit`: after a number
 */
export function colourWords(language, syntax) {
  const words = /** @type {{regex: RegExp, token: string}[]} */ ([]);
  for (const [token, list] of Object.entries(syntax)) {
    if (token !== "unit" && list.length) words.push({regex: new RegExp("(?:" + anyOf(list) + ")" + WORD_END, "iu"), token: token});
  }
  const units = syntax.unit && syntax.unit.length ? "(?:\\s*(?:" + anyOf(syntax.unit) + ")" + WORD_END + ")?" : "";
  const name = "rootlang-" + language;
  CodeMirror.defineSimpleMode(name, {
    start: [
      {regex: /#.*/, token: "comment"},
      {regex: /"(?:[^"\\]|\\.)*"?/, token: "string"},
      {regex: new RegExp("-?\\d+(?:\\.\\d+)?" + units, "iu"), token: "number"},
      ...words,
      {regex: /[\p{L}_][\p{L}\p{N}_]*/u, token: "variable"},
    ],
    meta: {lineComment: "#"},
  });
  editor.setOption("mode", name);
}

/** The program's text. */
export const editor = CodeMirror.fromTextArea($("text"), {
  mode: "text/plain", readOnly: true,   // (until a program opens: files.js setEditable)
  lineNumbers: true, indentUnit: 4, tabSize: 4, indentWithTabs: false,
  gutters: ["CodeMirror-linenumbers", "problems"],
  undoDepth: 0,   // (the page keeps one undo history for both panes: undo.js)
  screenReaderLabel: "Program text",
  // (the addons' options: active-line.js and matchbrackets.js read them)
  .../** @type {object} */ ({styleActiveLine: true, matchBrackets: true}),
});
editor.getInputField().setAttribute("aria-label", "Program text");

/** Gutters whose marks stay with their lines when the page sets the text (a breakpoint on a
 * line a Save spells canonically, or the blocks rewrite, is not lost). */
export const keptGutters = /** @type {string[]} */ ([]);

/** @param {string} line a line as written: the same statement however it is spaced or cased */
const sameLine = line => line.replace(/\s+/g, "").toLowerCase();

/** The kept gutters' marks: each line's text and its mark. */
function keptMarks() {
  /** @type {{gutter: string, line: number, text: string, mark: HTMLElement}[]} */
  const marks = [];
  editor.eachLine(handle => {
    const markers = /** @type {{gutterMarkers?: Record<string, HTMLElement>}} */ (handle).gutterMarkers;
    for (const gutter of keptGutters) {
      if (markers && markers[gutter]) {
        marks.push({gutter: gutter, line: Number(editor.getLineNumber(handle)), text: sameLine(handle.text), mark: markers[gutter]});
      }
    }
  });
  return marks;
}

/**
 * The marks, after the page set the text, each on the line of its statement: one the text took
 * away, or left on a line that holds another statement now, goes to the nearest line to where
 * it was that holds its own (none: the statement is gone, and its mark).
 * @param {ReturnType<typeof keptMarks>} marks
 */
function putBack(marks) {
  const now = new Map(keptMarks().map(mark => [mark.mark, mark]));
  for (const mark of marks) {
    const left = now.get(mark.mark);
    if (left && left.text === mark.text) continue;
    if (left) editor.setGutterMarker(left.line, left.gutter, null);
    let found = -1;
    for (let away = 0; away < editor.lineCount() && found < 0; away++) {
      for (const line of [mark.line - away, mark.line + away]) {
        if (line >= 0 && line < editor.lineCount() && sameLine(editor.getLine(line)) === mark.text
            && !(editor.lineInfo(line).gutterMarkers || {})[mark.gutter]) { found = line; break; }
      }
    }
    if (found >= 0) editor.setGutterMarker(found, mark.gutter, mark.mark);
  }
}

/**
 * The line the child has begun where the cursor stands, only its indentation typed yet (Enter
 * indents the new line as the one above): its number and spaces, else null.
 * @returns {{line: number, spaces: string} | null}
 */
function lineBegun() {
  const cursor = editor.getCursor();
  const spaces = editor.getLine(cursor.line);
  return spaces && !spaces.trim() && cursor.ch === spaces.length ? {line: cursor.line, spaces: spaces} : null;
}

/**
 * The begun line's indentation, back where the text the page set left that line empty (a
 * canonical text, a Save's, has no spaces on an empty line): taken away, the child's next
 * words would start at the line's beginning, out of the script they were writing.
 * @param {{line: number, spaces: string}} begun
 */
function keepLineBegun(begun) {
  const cursor = editor.getCursor();
  if (cursor.line !== begun.line || editor.getLine(begun.line) !== "") return;
  editor.replaceRange(begun.spaces, {line: begun.line, ch: 0}, undefined, "setValue");
  editor.setCursor({line: begun.line, ch: begun.spaces.length});
}

/** True while the page itself sets the text (not a child's edit). */
export let settingText = false;

/**
 * The text, set by the page: only the lines that differ are replaced, so the child's cursor and
 * the rest of the text stay as they were. Not an edit of the child's (no sync, no undo step).
 * @param {string} text
 * @param {{fresh?: boolean, cursor?: boolean}} [how] fresh: a program just opened; cursor: the
 *   cursor goes to the end of what changed (an undo: the child sees what it did)
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
      const put = text.slice(head, text.length - tail);
      const marks = keptMarks();
      const begun = lineBegun();
      editor.replaceRange(put, from, to, "setValue");
      putBack(marks);
      if (how && how.cursor) editor.setCursor(editor.posFromIndex(text.length - tail));
      else if (begun) keepLineBegun(begun);
    }
  } finally {
    settingText = false;
  }
}
