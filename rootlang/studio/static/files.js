// @ts-check
// The class folder's programs: open, save, new, rename.
import * as api from "./api.js";
import {$, session, state, words, say, fixed} from "./page.js";
import {editor, setText} from "./editor.js";
import {layout, setLayout, rememberLayout, blocksShown} from "./blocks.js";
import {opened, settle, onEdit, textOnly, tooSlow} from "./sync.js";
import {showStart} from "./runs.js";

const AUTOSAVE_MS = 3000;   // after the child's last edit
/** @type {ReturnType<typeof setTimeout> | undefined} */
let autosaveTimer;
/** Edits not saved yet (a warning before leaving the page). */
let unsaved = false;

onEdit.push(() => {
  unsaved = true;
  state.unsaved = "yes";
  saveSoon();
});

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
  if (select) chooser.value = select;
  return setup;
}

/** @param {string} name */
export async function openProgram(name) {
  if (unsaved && session.current && session.current !== name) await save();
  say(words("opening", {name: name}));   // (a long program takes a while)
  const data = await api.readProgram(name);
  session.current = name;
  session.version = data.version;
  $("program").value = name;
  setLayout(data.layout);
  const address = new URL(location.href);
  address.searchParams.set("open", name);  // (a ?language= stays)
  history.replaceState(null, "", address.pathname + address.search);
  setText(data.text, {fresh: true});
  unsaved = false; state.unsaved = "";
  clearTimeout(autosaveTimer);
  await opened();    // (its blocks alone: never another program's)
  if (!textOnly()) say(words("opened", {name: name}));   // (else: why it is text only)
  await showStart();   // the robot on its world, before any run
  state.open = name;
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
  // Text only, the hidden blocks are not the text's now: the layout is the one they had when
  // last shown (the loose blocks as the child left them), or, never shown since it opened, the
  // sidecar is left as it was. Too long to convert in time, the text is saved as it is
  // written, not sent to be formatted for nothing.
  if (!textOnly()) rememberLayout();
  const text = editor.getValue();
  const reply = await api.saveProgram({name: name, text: text,
                                       layout: textOnly() && !blocksShown() ? undefined : layout,
                                       version: session.version, as_written: tooSlow()});
  if (session.current !== name) return;
  session.version = reply.version;
  if (editor.getValue() === text) {
    setText(reply.text);
    unsaved = false; state.unsaved = "";
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
