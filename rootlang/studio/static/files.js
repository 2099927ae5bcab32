// @ts-check
// The class folder's programs: open, save, new, rename.
import * as api from "./api.js";
import {$, session, state, words, say} from "./page.js";
import {editor, setText} from "./editor.js";
import {layout, setLayout, rememberLayout} from "./blocks.js";
import {textChanged} from "./sync.js";

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
  const data = await api.readProgram(name);
  session.current = name;
  session.version = data.version;
  $("program").value = name;
  setLayout(data.layout);
  const address = new URL(location.href);
  address.searchParams.set("open", name);  // (a ?language= stays)
  history.replaceState(null, "", address.pathname + address.search);
  setText(data.text, {fresh: true});
  await textChanged();
  say(words("opened", {name: name}));
  state.open = name;
}

export async function save() {
  if (!session.current) return;
  rememberLayout();
  const reply = await api.saveProgram({name: session.current, text: editor.getValue(), layout: layout,
                                       version: session.version});
  session.version = reply.version;
  setText(reply.text);
  say(words("saved", {name: session.current}));
  state.saved = session.current;
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
