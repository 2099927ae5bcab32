// @ts-check
// The text pane's undo (Ctrl-Z) holds the child's own typing only. A change the page makes to
// the text (the blocks' text after a block edit, a save's canonical form) is no undo step: the
// child's earlier edits are moved past it, so each still undoes exactly what was typed, where it
// now is. An edit the page's change overlaps can't be undone without undoing the page's change
// too: it and the edits before it leave the history (the text keeps them: nothing is lost).
//
// CodeMirror 5's history, as getHistory() gives it: `done` is oldest first; a change event's
// `changes` each put in [from, to) (in the text as it was right after that change), `text` being
// the lines that were there before; selection events sit between them.

/** @typedef {{line: number, ch: number}} Pos */
/** @typedef {{from: Pos, to: Pos, lines: string[]}} Edit [from, to) replaced by these lines */
/** @typedef {{from: Pos, to: Pos, text: string[]}} Change a change as the history keeps it */
/** @typedef {{anchor: Pos, head: Pos}} Range */
/** @typedef {{changes: Change[]} | {ranges: Range[], primIndex: number}} HistoryEvent */
/** @typedef {{done: HistoryEvent[], undone: HistoryEvent[]}} History */

/**
 * @param {Pos} a
 * @param {Pos} b
 */
const compare = (a, b) => a.line - b.line || a.ch - b.ch;

/**
 * Where the lines an edit puts in end.
 * @param {Edit} edit
 */
function endOf(edit) {
  const last = edit.lines[edit.lines.length - 1];
  return edit.lines.length === 1 ? {line: edit.from.line, ch: edit.from.ch + last.length}
                                 : {line: edit.from.line + edit.lines.length - 1, ch: last.length};
}

/**
 * Where a place in the text is after an edit. At an insertion's very place, a place stays
 * before it (`after` false: the end of a span) or goes after it (`after` true: a start); a
 * place inside a replaced span goes to its start.
 * @param {Pos} pos
 * @param {Edit} edit
 * @param {boolean} after
 * @returns {Pos}
 */
function moved(pos, edit, after) {
  const start = compare(pos, edit.from);
  const insertion = compare(edit.from, edit.to) === 0;
  if (start < 0 || (start === 0 && !(after && insertion))) return pos;
  if (compare(pos, edit.to) < 0) return edit.from;
  const end = endOf(edit);
  return pos.line === edit.to.line ? {line: end.line, ch: end.ch + pos.ch - edit.to.ch}
                                   : {line: pos.line + end.line - edit.to.line, ch: pos.ch};
}

/**
 * The history as it is after the page's edit of the text (which is not in it); redo is
 * emptied (the page's edit is newer than anything undone).
 * @param {History} history as editor.getHistory() gave it just before the edit
 * @param {Edit} edit the page's, in the text as it was then
 * @returns {History}
 */
export function withoutPageEdit(history, edit) {
  const done = history.done.slice();
  let page = edit;   // the page's edit, in the text as it was after the event looked at
  for (let i = done.length - 1; i >= 0; i--) {
    const event = done[i];
    if ("ranges" in event) {
      done[i] = {primIndex: event.primIndex, ranges: event.ranges.map(range =>
        ({anchor: moved(range.anchor, page, false), head: moved(range.head, page, false)}))};
      continue;
    }
    const changes = event.changes.slice();
    for (let j = changes.length - 1; j >= 0; j--) {   // (undo takes an event's changes last first)
      const change = changes[j];
      if (compare(change.from, page.to) < 0 && compare(change.to, page.from) > 0) {
        return {done: done.slice(i + 1), undone: []};   // overlapped: from here back, no undo
      }
      changes[j] = {from: moved(change.from, page, true), to: moved(change.to, page, false),
                    text: change.text};
      // the page's edit in the text before this change (undoing it puts `text` back)
      const undo = {from: change.from, to: change.to, lines: change.text};
      page = {from: moved(page.from, undo, true), to: moved(page.to, undo, false), lines: page.lines};
    }
    done[i] = {changes: changes};
  }
  return {done: done, undone: []};
}
