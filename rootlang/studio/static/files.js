// @ts-check
// The class folder's programs: open, save, new, rename.
import * as api from "./api.js";
import {$, session, state, words, say, fixed} from "./page.js";
import {editor, setText} from "./editor.js";
import {layout, setLayout, rememberLayout, blocksShown} from "./blocks.js";
import {opened, settle, onEdit, textOnly, tooSlow} from "./sync.js";
import {showStart} from "./runs.js";
import {keepDraft, draftOf, dropDraft} from "./drafts.js";

const AUTOSAVE_MS = 3000;   // after the child's last edit
const DRAFT_MS = 500;       // the edits kept in this browser, after the child's last one
/** @type {ReturnType<typeof setTimeout> | undefined} */
let autosaveTimer;
/** @type {ReturnType<typeof setTimeout> | undefined} */
let draftTimer;
/** Edits not saved yet (a warning before leaving the page). */
let unsaved = false;

onEdit.push(() => {
  unsaved = true;
  state.unsaved = "yes";
  saveSoon();
  clearTimeout(draftTimer);
  draftTimer = setTimeout(keepEdits, DRAFT_MS);
});

/** What the page shows, kept in this browser until it is saved (see drafts.js). */
function keepEdits() {
  clearTimeout(draftTimer);
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

addEventListener("beforeunload", event => {
  if (!unsaved) return;
  keepEdits();   // (the child may leave anyway)
  event.preventDefault();
  event.returnValue = "";   // (the browser's own words: "Leave the page?")
});

/** @param {unknown} error */
export function saveFailed(error) { say(String(/** @type {Error} */ (error).message), true, "save"); }

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

/** @param {string} name */
export async function openProgram(name) {
  if (unsaved && session.current && session.current !== name) await save();
  say(words("opening", {name: name}));   // (a long program takes a while)
  const data = await api.readProgram(name);
  // edits this browser kept and never saved: on the version they were made on, they are the
  // page's (and saved by themselves); on a version saved since elsewhere, both are kept
  const draft = draftOf(name);
  const back = draft !== null && draft.version === data.version ? draft : null;
  // (not kept aside now, the studio refusing: the draft stays for the next time it opens)
  const aside = draft !== null && !back ? await keepAside(name, draft).catch(() => "") : "";
  session.current = name;
  session.version = data.version;
  $("program").value = name;
  setLayout(back && back.layout ? back.layout : data.layout);   // (a text-only draft: the file's)
  const address = new URL(location.href);
  address.searchParams.set("open", name);  // (a ?language= stays)
  history.replaceState(null, "", address.pathname + address.search);
  setText((back || data).text, {fresh: true});
  unsaved = back !== null; state.unsaved = back ? "yes" : "";
  clearTimeout(autosaveTimer);
  await opened();    // (its blocks alone: never another program's)
  if (back) say(words("draft_back", {name: name}));
  else if (aside) say(words("draft_kept", {name: name, kept: aside}));
  else if (!textOnly()) say(words("opened", {name: name}));   // (else: why it is text only)
  if (back) saveSoon();
  await showStart();   // the robot on its world, before any run
  state.open = name;
}

/**
 * A draft made on a version of ``name`` that was saved over since (in another browser): kept
 * as a program of its own next to it, "NAME not saved.root" (numbered if that is taken);
 * its name. Nothing is lost either way, and nothing is written over.
 * @param {string} name
 * @param {import("./drafts.js").Draft} draft
 */
async function keepAside(name, draft) {
  const stem = name.replace(/\.root$/, "").slice(0, 40);   // (a name has 64 letters at most)
  for (let number = 1; number < 100; number++) {
    const kept = words("draft_name", {name: stem}) + (number > 1 ? ` ${number}` : "") + ".root";
    let made;
    try {
      made = await api.createProgram({name: kept});
    } catch (error) {
      if (error instanceof api.Refused && error.errors[0]?.code === "E803") continue;   // (taken)
      throw error;
    }
    await api.saveProgram({name: kept, text: draft.text, layout: draft.layout,
                           version: made.version, as_written: true});
    dropDraft(name);
    await refreshPrograms(name);
    return kept;
  }
  return "";
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
  const reply = await api.saveProgram({name: name, text: text, layout: layoutNow,
                                       version: session.version, as_written: tooSlow()});
  if (session.current !== name) return;
  session.version = reply.version;
  if (editor.getValue() === text) {
    setText(reply.text);
    unsaved = false; state.unsaved = "";
    clearTimeout(draftTimer);
    dropDraft(name); state.draft = "";
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
