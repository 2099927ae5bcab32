// @ts-check
// Two edits of one text, made at once (the blocks changed the text while the child typed in it),
// put together line by line: each edit is the lines it changed between the lines both left alone.

/**
 * How much two texts (or two lists of lines) share at their start and, after that, at their end.
 * @template {string | string[]} T
 * @param {T} a
 * @param {T} b
 * @returns {[number, number]}
 */
export function sameEnds(a, b) {
  const most = Math.min(a.length, b.length);
  let head = 0;
  while (head < most && a[head] === b[head]) head++;
  let tail = 0;
  while (tail < most - head && a[a.length - 1 - tail] === b[b.length - 1 - tail]) tail++;
  return [head, tail];
}

/**
 * Both edits of `base`, when they change different lines; null when they change the same ones
 * (then neither may be written over the other without asking).
 * @param {string} base the text both edits started from
 * @param {string} ours one edit of it (the blocks' text)
 * @param {string} theirs the other (the child's typing)
 * @returns {string | null}
 */
export function mergeEdits(base, ours, theirs) {
  if (ours === base || ours === theirs) return theirs;
  if (theirs === base) return ours;
  const b = base.split("\n"), o = ours.split("\n"), t = theirs.split("\n");
  const [oursHead, oursTail] = sameEnds(b, o);
  const [theirsHead, theirsTail] = sameEnds(b, t);
  if (b.length - oursTail <= theirsHead) {        // ours ends where theirs begins, or before
    return [...o.slice(0, o.length - (b.length - theirsHead)), ...t.slice(theirsHead)].join("\n");
  }
  if (b.length - theirsTail <= oursHead) {        // theirs ends where ours begins, or before
    return [...t.slice(0, t.length - (b.length - oursHead)), ...o.slice(oursHead)].join("\n");
  }
  return null;
}
