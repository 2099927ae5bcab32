// @ts-check
// The teacher's page: every pupil live (their open program, its mistakes, their run, the last
// run's ending and replay, their checks), one Stop for every run, a message to the class,
// "hands off", the class's progress on a task (checked and exported) and on the adventures.
import {install} from "../../blocks/root_blocks.js";
import * as api from "./api.js";
import {element, keepOpen, translate} from "./classapi.js";
import {$, inPageLanguage, setWords, state, words} from "./page.js";
import {speaker, showSigned} from "./icons.js";

/** @typedef {import("./messages").PupilJson} PupilJson */
/** @typedef {import("./messages").TaskJson} TaskJson */
/** @typedef {import("./messages").ToTeacher} ToTeacher */
/** @typedef {import("./messages").BlocksSetup} BlocksSetup */

/** @type {Map<string, PupilJson>} what the studio last said of each pupil, by name */
const pupils = new Map();
/** @type {TaskJson[]} */
let tasks = [];
/** @type {import("./messages").AdventureProgressJson[]} */
let adventures = [];
let chosen = "", locked = false, muted = false;
/** @type {string | null} */
let shownText = null;
/** @type {import("blockly").WorkspaceSvg | null} */
let workspace = null;

/**
 * @param {string} text
 * @param {boolean} [isError]
 */
function say(text, isError) { $("said").textContent = text; $("said").className = isError ? "refused" : ""; }

// --- the pupils -----------------------------------------------------------------------------------

/** @param {PupilJson} pupil */
function runWords(pupil) {
  if (pupil.run && pupil.run.waiting > 0) {
    return words("waiting_for_place", {program: pupil.run.program, place: pupil.run.waiting});
  }
  if (pupil.run) {
    return pupil.run.robot ? words("running_on_robot", {program: pupil.run.program, robot: pupil.run.robot})
                           : words("running_on_sim", {program: pupil.run.program});
  }
  if (pupil.last) {
    const end = words("end_" + pupil.last.end, {why: pupil.last.stopped_by || ""});
    return words("last_run", {program: pupil.last.program, end: end});
  }
  return words("not_running");
}

/** @param {PupilJson} pupil */
function card(pupil) {
  const button = element("button", {type: "button", class: "pupil" + (pupil.name === chosen ? " chosen" : ""),
                                    "data-pupil": pupil.name});
  const head = element("div");
  head.append(element("span", {class: "name"}, pupil.name), " ",
              element("span", {class: pupil.online ? "online" : "away"},
                      pupil.online ? "● " + words("online") : "○ " + words("away")));
  const errors = pupil.problems.filter(p => p.severity === "error").length;
  const checks = element("div");
  for (const task of tasks) {
    const checked = pupil.checks[task.name];
    if (!checked) continue;
    checks.append(element("span", {class: checked.passed ? "passed" : "failed"},
                          task.name + " " + (checked.passed ? words("passed") : words("failed")) + " "));
  }
  button.append(head, element("div", {}, pupil.program || words("no_program")),
                element("div", {class: pupil.run ? "running" : ""}, runWords(pupil)),
                element("div", {class: errors ? "mistakes" : ""}, errors ? words("mistakes", {count: errors}) : ""),
                checks);
  button.addEventListener("click", () => choose(pupil.name));
  return button;
}

function showPupils() {
  const all = [...pupils.values()].sort((a, b) => a.name.localeCompare(b.name));
  $("pupils").replaceChildren(...(all.length ? all.map(card) : [element("p", {id: "no-pupils"}, words("no_pupils"))]));
  state.pupils = all.map(p => p.name).join(",");
  state.running = all.filter(p => p.run).map(p => p.name).join(",");
  state.checks = all.map(p => p.name + ":" + Object.entries(p.checks)
    .map(([task, c]) => task + "=" + (c.passed ? "passed" : "failed")).join("+")).join(",");
  showProgress(all);
  const shown = pupils.get(chosen);
  if (shown) showDetail(shown).catch(error => say(error.message, true));
}

/**
 * The class's adventures: a row for each pupil, a column for each adventure (✓ passed,
 * ✗ tried and not yet), and how many of their level's they have passed.
 * @param {PupilJson[]} all
 */
function showProgress(all) {
  $("progress").hidden = !adventures.length;
  const head = element("tr");
  head.append(element("th", {scope: "col"}, words("adventure_pupil")),
              ...adventures.map(one => element("th", {scope: "col", title: one.title},
                                                one.level + "·" + one.title)),
              element("th", {scope: "col"}, "✓"));
  const rows = all.map(pupil => {
    const row = element("tr");
    row.append(element("th", {scope: "row"}, pupil.name));
    for (const one of adventures) {
      const done = pupil.adventures[one.name];
      const cell = element("td", done === undefined ? {} : {class: done ? "passed" : "failed",
                                   title: done ? words("passed") : words("adventure_not_yet")},
                           done === undefined ? "" : done ? "✓" : "✗");
      row.append(cell);
    }
    const mine = adventures.filter(one => one.level === pupil.level);
    row.append(element("td", {}, mine.filter(one => pupil.adventures[one.name]).length + " / " + mine.length));
    return row;
  });
  const table = element("table");
  table.append(element("caption", {class: "unseen"}, words("adventure_progress")), head, ...rows);
  $("progress-table").replaceChildren(table);
  state.adventures = all.map(p => p.name + ":" + Object.entries(p.adventures)
    .map(([name, done]) => name + "=" + (done ? "passed" : "failed")).join("+")).join(",");
}

/** @param {string} name */
function choose(name) { chosen = name; shownText = null; showPupils(); }

// --- one pupil's program, read-only: blocks (the studio's own conversion) and text --------------

/** @param {PupilJson} pupil */
async function showDetail(pupil) {
  $("detail-name").textContent = words("program_of", {name: pupil.name, program: pupil.program || "—"});
  $("pupil-level").value = String(pupil.level);
  $("pupil-level-label").hidden = false;
  const last = $("detail-last");
  last.replaceChildren();
  if (pupil.last) {
    last.append(element("p", {}, runWords(pupil)));
    const error = pupil.last.error;
    if (error) last.append(element("p", {class: "mistakes"}, words("at_line", {line: error.line, message: error.message})));
    if (pupil.last.replay) {
      last.append(element("a", {href: pupil.last.replay,
                                download: pupil.last.program.replace(/\.root$/, "") + "-replay.html"}, words("replay")));
    }
    const trace = element("ol");
    pupil.last.trace.forEach(line => trace.append(element("li", {}, line)));
    last.append(trace);
  }
  pupil.problems.forEach(p => last.append(element("p", {class: "mistakes"}, words("at_line", {line: p.line, message: p.message}))));
  if (pupil.text === shownText) return;
  shownText = pupil.text;
  $("detail-text").textContent = pupil.text;
  state.shownText = pupil.text;
  if (!workspace) return;
  const reply = await api.toBlocks({text: pupil.text, name: pupil.program});
  if (reply.workspace && shownText === pupil.text) {
    Blockly.Events.disable();
    try { Blockly.serialization.workspaces.load(reply.workspace, workspace); workspace.cleanUp(); }
    finally { Blockly.Events.enable(); }
    state.shownBlocks = String(workspace.getAllBlocks(false).length);
  }
}

/** @param {string} address */
function loadScript(address) {
  return new Promise(resolve => {
    const script = element("script", {src: address});
    script.onload = script.onerror = () => resolve(undefined);
    document.head.appendChild(script);
  });
}

/** @param {BlocksSetup | null} blocks */
function setupBlocks(blocks) {
  if (!blocks || typeof Blockly === "undefined") return;
  install(Blockly, blocks.definitions);
  workspace = Blockly.inject("detail-blocks", {readOnly: true, media: "/static/vendor/blockly/media/",
                                               sounds: false, zoom: {controls: true, startScale: 0.7}});
}

// --- what the studio sends -----------------------------------------------------------------------

/** @param {ToTeacher} message */
function received(message) {
  if (message.type === "class") {
    pupils.clear();
    tasks = message.tasks;
    adventures = message.adventures;
    $("task").replaceChildren(...tasks.map(task => new Option(task.title + " (" + task.program + ")", task.name)));
    exportLinks();
  }
  for (const pupil of message.pupils) pupils.set(pupil.name, pupil);
  showLocked(message.locked);
  if (message.type === "class") showMuted(message.muted);
  if (message.type === "class") { $("class-level").value = String(message.level); state.level = String(message.level); }
  showPupils();
  state.lag = Math.max(0, Date.now() / 1000 - message.sent_at).toFixed(3);
  state.updates = String(Number(state.updates || 0) + 1);
}

/** @param {boolean} value */
function showLocked(value) {
  locked = value;
  $("lock").textContent = locked ? words("unlock") : words("lock");
  $("lock").setAttribute("aria-pressed", String(locked));
  state.locked = locked ? "yes" : "no";
}

/** @param {boolean} value */
function showMuted(value) {
  muted = value;
  showSigned($("mute-class"), speaker(!muted), muted ? words("unmute_class") : words("mute_class"));
  $("mute-class").setAttribute("aria-pressed", String(muted));
  state.muted = muted ? "yes" : "no";
}

function exportLinks() {
  const task = encodeURIComponent($("task").value);
  $("export-csv").href = inPageLanguage("/api/teacher/export?format=csv&task=" + task);
  $("export-junit").href = inPageLanguage("/api/teacher/export?format=junit&task=" + task);
}

// --- what the teacher does ---------------------------------------------------------------------------

/** @param {() => Promise<void>} work */
async function act(work) {
  try { await work(); } catch (error) { say(/** @type {Error} */ (error).message, true); }
}

async function stopAll() {
  const reply = await api.stopAll();
  say(words("stopped_all", {count: reply.stopped, seconds: reply.seconds.toFixed(2)}));
  state.stopped = String(reply.stopped);
}

async function send() {
  await api.tellClass({text: $("message").value});
  say(words("sent"));
  state.sent = $("message").value;
}

async function checkAll() {
  say(words("checking"));
  const reply = await api.checkClass({task: $("task").value});
  const results = Object.values(reply.results);
  say(words("checked_all", {passed: results.filter(r => r.passed).length, count: results.length}));
}

async function enter() {
  const setup = await api.teacherSetup();
  setWords(setup.strings);
  document.documentElement.lang = setup.language;
  translate(document);
  $("login").hidden = true; $("toolbar").hidden = false; $("main").hidden = false;
  if (typeof Blockly !== "undefined") await loadScript(setup.blockly_messages);   // its words first
  setupBlocks(setup.blocks);
  $("stop-all").addEventListener("click", () => act(stopAll));
  $("lock").addEventListener("click", () => act(async () => showLocked((await api.lockClass({locked: !locked})).locked)));
  $("mute-class").addEventListener("click", () => act(async () => showMuted((await api.muteClass({muted: !muted})).muted)));
  $("send").addEventListener("click", () => act(send));
  setupLevels();
  $("check-all").addEventListener("click", () => act(checkAll));
  $("task").addEventListener("change", exportLinks);
  keepOpen("/ws/teacher", received, online => { state.online = online ? "yes" : "no"; }, stillTheTeacher);
  state.ready = "yes";
}

/** The levels (docs/levels.md): one menu for the class, one for the pupil shown. */
function setupLevels() {
  const menu = (/** @type {string} */ id, /** @type {string} */ label) => {
    const select = element("select", {id: id, "aria-label": label});
    for (const n of [1, 2, 3]) select.append(new Option(words("level_" + n), String(n)));
    return /** @type {HTMLSelectElement} */ (select);
  };
  const forClass = menu("class-level", words("level_for_class"));
  const classLabel = element("label");
  classLabel.append(words("level_for_class") + " ", forClass);
  $("toolbar").insertBefore(classLabel, $("toolbar").querySelector(".spacer"));
  forClass.addEventListener("change", () => act(async () => {
    state.level = String((await api.chooseLevel({level: Number(forClass.value), pupil: ""})).level);
  }));
  const forPupil = menu("pupil-level", words("level_for_pupil"));
  const label = element("label", {id: "pupil-level-label", hidden: ""});
  label.append(words("level_for_pupil") + " ", forPupil);
  $("detail-name").after(label);
  forPupil.addEventListener("change", () => act(async () => {
    await api.chooseLevel({level: Number(forPupil.value), pupil: chosen});
  }));
}

/** Back in touch with the studio: a restarted one makes a new code, so its page asks for it. */
async function stillTheTeacher() {
  try {
    await api.teacherSetup();
  } catch (error) {
    const refused = /** @type {api.Refused} */ (error);
    if (refused.errors && refused.errors[0]?.code === "E847") location.reload();
    throw error;
  }
}

/** The code first, unless this browser is already the teacher's (E847: it is not). */
async function start() {
  try {
    await enter();
    return;
  } catch (error) {
    const refused = /** @type {api.Refused} */ (error);
    if (!refused.errors || refused.errors[0]?.code !== "E847") throw error;
  }
  setWords((await api.who()).strings);   // the page's words, before the code
  translate(document);
  $("login").hidden = false;
  state.login = "yes";
  $("login").addEventListener("submit", /** @param {Event} event */ event => {
    event.preventDefault();
    act(async () => {
      try {
        await api.teacherLogin({code: $("code").value});
      } catch (refused) {
        $("refused").textContent = /** @type {Error} */ (refused).message;
        return;
      }
      await enter();
    });
  });
}

start().catch(error => say(error.message, true));
