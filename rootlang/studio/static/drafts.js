// @ts-check
// Drafts: the edits a tab has not saved yet, kept in this browser (localStorage) until that tab
// saves them, so a tab closed, reloaded or crashed while the studio was out of reach (or its
// save refused) loses nothing. One per tab and program of the folder the page works in (a
// pupil's own, in a class): each tab has an id of its own (in its sessionStorage, so a reload
// is the same tab), and never writes over, or drops, another tab's draft. A tab that is gone
// (closed, crashed) leaves its drafts to the next tab that opens their program (files.js).
//
// Which tabs live: each holds a Web Lock named by its id for as long as it lives (the browser
// lets it go when the tab goes, however it goes). Where the page has no Web Locks (a studio on
// a network over plain http is no "secure context"), the tabs answer each other on a
// BroadcastChannel instead.
import {session} from "./page.js";

/** @typedef {{text: string, version: string, layout?: Record<string, unknown>}} Draft */
/** @typedef {Draft & {key: string, tab: string, time: number}} KeptDraft a draft and whose */

const PREFIX = "rootlang.draft/";          // + tab / folder / name
const LEGACY = "rootlang.draft ";          // an older studio's one draft per program: + folder name
const TAB_KEY = "rootlang.tab";
const LOCK = "rootlang.tab ";              // + tab
const ANSWER_MS = 300;                     // (no Web Locks) how long a live tab has to answer

/** This tab's id ("" until `claimTab`). */
let tab = "";

const fresh = () => Date.now().toString(36) + "-" + Math.random().toString(36).slice(2, 10);

/** @type {BroadcastChannel | null} */
let channel = null;

/**
 * Whether this tab now holds the lock of `id` (it then holds it as long as it lives).
 * @param {string} id
 * @returns {Promise<boolean>}
 */
function hold(id) {
  return new Promise(resolve => {
    navigator.locks.request(LOCK + id, {ifAvailable: true}, lock => {
      resolve(lock !== null);
      return lock ? new Promise(() => {}) : undefined;   // (held until the tab goes)
    }).catch(() => resolve(false));
  });
}

/**
 * Of these tab ids, the ones a live tab of this browser has (this one's too).
 * @param {string[]} ids
 * @returns {Promise<Set<string>>}
 */
async function liveTabs(ids) {
  if (navigator.locks) {
    const held = (await navigator.locks.query()).held || [];
    return new Set(held.map(lock => (lock.name || "").slice(LOCK.length)).filter(id => ids.includes(id)));
  }
  const live = new Set(ids.filter(id => id === tab));
  if (!channel || ids.every(id => live.has(id))) return live;
  const asked = channel;
  /** @param {MessageEvent} event */
  const heard = event => { if (event.data && ids.includes(event.data.alive)) live.add(event.data.alive); };
  asked.addEventListener("message", heard);
  asked.postMessage({ask: ids});
  await new Promise(resolve => setTimeout(resolve, ANSWER_MS));
  asked.removeEventListener("message", heard);
  return live;
}

/**
 * This tab's id: the one its sessionStorage kept (a reload), unless another live tab has it
 * too (a tab duplicated copies sessionStorage): then a new one.
 */
export async function claimTab() {
  let id = "";
  try { id = sessionStorage.getItem(TAB_KEY) || ""; } catch { /* (storage off: a new id) */ }
  if (navigator.locks) {
    if (!id || !(await hold(id))) {
      id = fresh();
      await hold(id);
    }
  } else if (typeof BroadcastChannel === "function") {
    channel = new BroadcastChannel("rootlang.tabs");
    if (!id || (await liveTabs([id])).has(id)) id = fresh();
    channel.addEventListener("message", event => {
      if (event.data && Array.isArray(event.data.ask) && event.data.ask.includes(tab)) {
        channel?.postMessage({alive: tab});
      }
    });
  } else {
    id = id || fresh();
  }
  tab = id;
  try { sessionStorage.setItem(TAB_KEY, id); } catch { /* (as above) */ }
}

/** @param {string} name */
const keyOf = name => PREFIX + [tab, session.folder, name].join("/");

/**
 * This tab's draft of `name` (replacing its earlier one; never another tab's).
 * @param {string} name
 * @param {Draft} draft
 */
export function keepDraft(name, draft) {
  try {
    const kept = {...draft, folder: session.folder, name: name, tab: tab, time: Date.now()};
    localStorage.setItem(keyOf(name), JSON.stringify(kept));
  } catch { /* the browser's storage full or off: the studio's own saves go on as before */ }
}

/** @param {string} name this tab's draft of it goes (it is saved) */
export function dropDraft(name) { dropKept(keyOf(name)); }

/** @param {string} key a draft brought back or kept as a program: it goes */
export function dropKept(key) {
  try { localStorage.removeItem(key); } catch { /* (as in keepDraft) */ }
}

/**
 * The drafts of `name` that no live tab holds, oldest first: this tab's own (kept before a
 * reload), and every one a tab that is gone left (an older studio's too). Another live tab's
 * draft is that tab's to save.
 * @param {string} name
 * @returns {Promise<KeptDraft[]>}
 */
export async function draftsLeft(name) {
  /** @type {KeptDraft[]} */
  const found = [];
  try {
    for (let i = 0; i < localStorage.length; i++) {
      const key = localStorage.key(i) || "";
      if (!key.startsWith(PREFIX) && key !== LEGACY + session.folder + " " + name) continue;
      let kept;
      try { kept = JSON.parse(localStorage.getItem(key) || "null"); } catch { continue; }   // (spoilt)
      if (!kept || typeof kept.text !== "string" || typeof kept.version !== "string") continue;
      if (key.startsWith(PREFIX) && (kept.folder !== session.folder || kept.name !== name)) continue;
      found.push({text: kept.text, version: kept.version, layout: kept.layout, key: key,
                  tab: typeof kept.tab === "string" ? kept.tab : "", time: Number(kept.time) || 0});
    }
  } catch {
    return [];   // (storage off: there is nothing to bring back)
  }
  const others = found.map(draft => draft.tab).filter(id => id && id !== tab);
  const live = others.length ? await liveTabs(others) : new Set();
  return found.filter(draft => !live.has(draft.tab)).sort((a, b) => a.time - b.time);
}
