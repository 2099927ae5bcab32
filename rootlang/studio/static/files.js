// @ts-check
// The class folder's programs: open, save, new, rename, and "Keep mine as a new program".
import * as api from "./api.js";
import {$, session, state, words, say, fixed} from "./page.js";
import {editor, setText} from "./editor.js";
import {layout, setLayout, rememberLayout, blocksShown, workspace} from "./blocks.js";
import {opened, settle, onEdit, textOnly, tooSlow} from "./sync.js";
import {showStart} from "./runs.js";
import {keepDraft, draftsLeft, dropDraft, dropKept} from "./drafts.js";
import {startHistory, forgetHistory, pageChanged} from "./undo.js";
import {keepBreakpoints, restoreBreakpoints} from "./debugger.js";

const AUTOSAVE_MS = 3000;   // after the child's last edit
// The edits kept in this browser at most this long after the first one not kept yet: steady
// typing is kept every half second too (a throttle, not a wait for a pause).
const DRAFT_MS = 500;
/** @type {ReturnType<typeof setTimeout> | undefined} */
let autosaveTimer;
/** @type {ReturnType<typeof setTimeout> | undefined} */
let draftTimer;
/** Edits not saved yet (a warning before leaving the page). */
let unsaved = false;
const CHANGED_SINCE = "E819";   // a Save refused: the file was saved from elsewhere since

onEdit.push(() => {
  unsaved = true;
  state.unsaved = "yes";
  saveSoon();
  if (draftTimer === undefined) draftTimer = setTimeout(keepEdits, DRAFT_MS);
});

/** What the page shows, kept in this browser until it is saved (see drafts.js). */
function keepEdits() {
  clearTimeout(draftTimer);
  draftTimer = undefined;
  if (!unsaved || !session.current) return;
  keepDraft(session.current, {text: editor.getValue(), version: session.version, layout: pageLayout()});
  state.draft = session.current;
}

/**
 * The blocks' places and the blocks left out of the text, as a Save writes them. Text only,
 * the hidden blocks are not the text's now: the layout is the one they had when last shown
 * (the loose blocks as the child left them), or, never shown since it opened, none (the
 * sidecar stays as it was).
 */
function pageLayout() {
  if (!textOnly()) rememberLayout();
  return textOnly() && !blocksShown() ? undefined : layout;
}

/** Refusals that pass by themselves: hands off (E845), a restarted class studio that does not
 * know the page yet (E842, until the page comes back in). Never a changed file (E819): the child
 * decides that one. */
const PASSING = new Set(["E845", "E842"]);

/**
 * Saves by itself a moment after the child's last edit, and again each moment while that save
 * is refused for a passing reason or the studio is out of reach, until it is saved: edits made
 * just before "hands off" or a restart wait for no new edit.
 */
function saveSoon() {
  clearTimeout(autosaveTimer);
  autosaveTimer = setTimeout(() => {
    save({automatic: true}).catch(error => {
      saveFailed(error);
      const refused = error instanceof api.Refused ? error.errors[0]?.code || "" : "";
      if (unsaved && (!(error instanceof api.Refused) || PASSING.has(refused))) saveSoon();
    });
  }, AUTOSAVE_MS);
}

addEventListener("pagehide", () => { if (unsaved) keepEdits(); });
addEventListener("beforeunload", event => {
  if (!unsaved) return;
  keepEdits();   // (the child may leave anyway)
  event.preventDefault();
  event.returnValue = "";   // (the browser's own words: "Leave the page?")
});

/**
 * Whether the child can change the program: not while none is open (the page would take their
 * work and keep none of it), nor while one opens (what they typed would be written over).
 * @param {boolean} yes
 */
export function setEditable(yes) {
  editor.setOption("readOnly", !yes);
  if (workspace) workspace.setIsReadOnly(!yes);
  state.editable = yes ? "yes" : "";
}

/** @param {unknown} error */
export function saveFailed(error) {
  say(String(/** @type {Error} */ (error).message), true, "save");
  // the file was saved from elsewhere since: the child's own can be kept as a new program
  if (error instanceof api.Refused && error.errors.some(e => e.code === CHANGED_SINCE)) {
    $("keep-mine").hidden = false;
  }
}

/**
 * The program chooser, refreshed from the setup (which it returns).
 * @param {string} [select]
 */
export async function refreshPrograms(select) {
  const setup = await api.setup();
  const chooser = $("program");
  chooser.replaceChildren(...setup.programs.map(p => new Option(p.name, p.name)));
  session.folder = setup.folder;
  if (select) chooser.value = select;
  return setup;
}

/**
 * Opens `name`. `how.make`: a program the folder does not have yet is made (from the starter,
 * as New makes one): a link to a worksheet's program (`?open=dance.root`) gives the child that
 * program to work on, never a page that takes their typing and keeps none of it.
 * @param {string} name
 * @param {{make?: boolean}} [how]
 */
export async function openProgram(name, how) {
  if (unsaved && session.current && session.current !== name) await save();
  say(words("opening", {name: name}));   // (a long program takes a while)
  setEditable(false);   // (typing while it opens would be written over)
  forgetHistory();
  try {
    await openNow(name, how);
  } finally {
    setEditable(session.current !== "");
  }
}

/**
 * @param {string} name
 * @param {{make?: boolean}} [how]
 */
async function openNow(name, how) {
  let data, made = false;
  try {
    data = await api.readProgram(name);
  } catch (error) {
    if (!(how && how.make && error instanceof api.Refused && error.errors.some(e => e.code === "E802"))) throw error;
    await api.createProgram({name: name});
    await refreshPrograms(name);
    data = await api.readProgram(name);
    made = true;
  }
  // Edits this browser kept and never saved (this tab's before a reload, a gone tab's): the
  // newest one made on the version the file has now is the page's (and saved by itself); every
  // other one (made on a version saved over since elsewhere, or a second tab's) is kept as a
  // program of its own next to it. None is dropped unseen, and nothing is written over.
  const left = (await draftsLeft(name)).filter(draft => {
    if (draft.text !== data.text) return true;
    dropKept(draft.key);   // (the file holds it already)
    return false;
  });
  const same = left.filter(draft => draft.version === data.version);
  const back = same.length ? same[same.length - 1] : null;
  /** @type {string[]} */
  const aside = [];
  for (const draft of left) {
    if (draft === back) continue;
    // (not kept aside now, the studio refusing: the draft stays for the next time it opens)
    const kept = await keepAside(name, draft).catch(() => "");
    if (kept) aside.push(kept);
  }
  session.current = name;
  session.version = data.version;
  $("program").value = name;
  $("keep-mine").hidden = true;
  setLayout(back && back.layout ? back.layout : data.layout);   // (a text-only draft: the file's)
  const address = new URL(location.href);
  address.searchParams.set("open", name);  // (a ?language= stays)
  history.replaceState(null, "", address.pathname + address.search);
  setText((back || data).text, {fresh: true});
  restoreBreakpoints();   // (this browser's, for this program: a reload keeps them)
  unsaved = back !== null; state.unsaved = back ? "yes" : "";
  clearTimeout(autosaveTimer);
  if (back) {   // this tab's draft now (a gone tab's is taken over, not copied)
    dropKept(back.key);
    keepDraft(name, {text: back.text, version: back.version, layout: back.layout});
    state.draft = name;
  }
  await opened();    // (its blocks alone: never another program's)
  startHistory();    // (its own undo history: what it shows now is where undo stops)
  if (back && aside.length) say(words("draft_back", {name: name}) + " " + words("draft_kept", {name: name, kept: aside.join(", ")}));
  else if (back) say(words("draft_back", {name: name}));
  else if (aside.length) say(words("draft_kept", {name: name, kept: aside.join(", ")}));
  else if (made) say(words("made_for_link", {name: name}));
  else if (!textOnly()) say(words("opened", {name: name}));   // (else: why it is text only)
  if (back) saveSoon();
  await showStart();   // the robot on its world, before any run
  setEditable(true);
  state.open = name;
}

/**
 * `text` (with `layout`) saved as a new program next to `name`, named `stem` (numbered if that
 * is taken: a name nobody has, so nothing is written over); its name.
 * @param {string} stem
 * @param {string} text
 * @param {Record<string, unknown> | undefined} layoutNow
 */
async function saveAsNew(stem, text, layoutNow) {
  for (let number = 1; number < 100; number++) {
    const kept = stem + (number > 1 ? ` ${number}` : "") + ".root";
    let made;
    try {
      made = await api.createProgram({name: kept});
    } catch (error) {
      if (error instanceof api.Refused && error.errors[0]?.code === "E803") continue;   // (taken)
      throw error;
    }
    await api.saveProgram({name: kept, text: text, layout: layoutNow, version: made.version,
                           as_written: true});
    return kept;
  }
  return "";
}

/** @param {string} name its stem, short enough for a name with more words (64 letters at most) */
const stemOf = name => name.replace(/\.root$/, "").slice(0, 40);

/**
 * A draft made on a version of ``name`` that was saved over since (in another browser or tab):
 * kept as a program of its own next to it, "NAME not saved.root" (numbered if that is taken);
 * its name. Nothing is lost either way, and nothing is written over.
 * @param {string} name
 * @param {import("./drafts.js").KeptDraft} draft
 */
async function keepAside(name, draft) {
  const kept = await saveAsNew(words("draft_name", {name: stemOf(name)}), draft.text, draft.layout);
  if (!kept) return "";
  dropKept(draft.key);
  await refreshPrograms(name);
  return kept;
}

/**
 * "Keep mine as a new program" (offered when a Save is refused because the file was saved from
 * elsewhere since, E819): what this page shows is saved as a new program under a fresh name,
 * and opened; the program it was is left as it was saved.
 */
export async function keepMine() {
  const name = session.current;
  if (!name) return;
  try {
    await settle();
    const kept = await saveAsNew(words("mine_name", {name: stemOf(name)}), editor.getValue(), pageLayout());
    if (!kept) return;
    unsaved = false; state.unsaved = "";   // (its edits are the new program's now)
    clearTimeout(autosaveTimer);
    clearTimeout(draftTimer); draftTimer = undefined;
    dropDraft(name); state.draft = "";
    await refreshPrograms(kept);
    await openProgram(kept);
    say(words("kept_mine", {name: name, kept: kept}));
  } catch (error) { say(String(/** @type {Error} */ (error).message), true); }
}

/**
 * Saves what the page shows: the text of the complete scripts, and the blocks' places and the
 * blocks left out of the text in the sidecar.
 * @param {{automatic?: boolean}} [how]
 */
export async function save(how) {
  clearTimeout(autosaveTimer);
  if (!session.current) return;
  const name = session.current;
  await settle();
  // (too long to convert in time, the text is saved as it is written, not sent to be formatted
  // for nothing)
  const layoutNow = pageLayout();
  const text = editor.getValue();
  let reply;
  try {
    reply = await api.saveProgram({name: name, text: text, layout: layoutNow,
                                   version: session.version, as_written: tooSlow()});
  } catch (error) {
    if (session.current === name) keepEdits();   // (refused: kept in this browser, at once)
    throw error;
  }
  if (session.current !== name) return;
  session.version = reply.version;
  $("keep-mine").hidden = true;
  if (editor.getValue() === text) {
    setText(reply.text);   // (the breakpoints stay on their statements' lines)
    keepBreakpoints();
    pageChanged();   // (the canonical text is no step of the child's)
    unsaved = false; state.unsaved = "";
    clearTimeout(draftTimer); draftTimer = undefined;
    dropDraft(name); state.draft = "";
  } else if (unsaved) {
    keepEdits();   // (typed meanwhile: kept on the version saved now)
  }
  // (a save by itself says so quietly, on the Save button: the status line keeps what it said)
  fixed("save");
  if (how && how.automatic) $("save").title = words("autosaved", {name: name});
  else say(words("saved", {name: name}));
  state.saved = name;
  state.saves = String(Number(state.saves || 0) + 1);
}

/**
 * @param {string} question
 * @param {string} suggestion
 */
function askName(question, suggestion) {
  let name = window.prompt(question, suggestion);
  if (!name) return null;
  name = name.trim();
  return name.endsWith(".root") ? name : name + ".root";
}

export async function newProgram() {
  const name = askName(words("ask_new_name"), words("suggested_name"));
  if (!name) return;
  try {
    await api.createProgram({name: name});
    await refreshPrograms(name);
    await openProgram(name);
  } catch (error) { say(String(/** @type {Error} */ (error).message), true); }
}

export async function renameProgram() {
  const current = session.current;
  const name = askName(words("ask_rename", {name: current}), current.replace(/\.root$/, ""));
  if (!name || name === current) return;
  try {
    await save();
    await api.renameProgram({old: current, new: name});
    await refreshPrograms(name);
    await openProgram(name);
  } catch (error) { say(String(/** @type {Error} */ (error).message), true); }
}
