// @ts-check
// Drafts: a program's edits not saved yet, kept in this browser (localStorage) until they are
// saved, so a page closed, reloaded or crashed while the studio was out of reach loses nothing.
// One per program of the folder the page works in (a pupil's own, in a class).
import {session} from "./page.js";

/** @typedef {{text: string, version: string, layout?: Record<string, unknown>}} Draft */

/** @param {string} name */
const keyOf = name => `rootlang.draft ${session.folder} ${name}`;

/**
 * @param {string} name
 * @param {Draft} draft
 */
export function keepDraft(name, draft) {
  try {
    localStorage.setItem(keyOf(name), JSON.stringify(draft));
  } catch { /* the browser's storage full or off: the studio's own saves go on as before */ }
}

/**
 * @param {string} name
 * @returns {Draft | null}
 */
export function draftOf(name) {
  try {
    const kept = JSON.parse(localStorage.getItem(keyOf(name)) || "null");
    return kept && typeof kept.text === "string" && typeof kept.version === "string" ? kept : null;
  } catch {
    return null;   // (spoilt: there is nothing to bring back)
  }
}

/** @param {string} name */
export function dropDraft(name) {
  try { localStorage.removeItem(keyOf(name)); } catch { /* (as in keepDraft) */ }
}
