// The teacher's page: every pupil live (their open program, its mistakes, their run, the last
// run's ending and replay, their checks), one Stop for every run, a message to the class,
// "hands off", and the class's progress on a task (checked and exported).
import {install} from "../../blocks/root_blocks.js";
import {api, inPageLanguage, keepOpen, setWords, translate, words} from "./classapi.js";

const $ = id => document.getElementById(id);
const state = $("state").dataset;   // read by the browser tests and the benchmark
const pupils = new Map();           // name -> what the studio last said of them
let tasks = [], chosen = "", locked = false, workspace = null, shownText = null;

function add(tag, className, text) {
  const element = document.createElement(tag);
  if (className) element.className = className;
  if (text !== undefined) element.textContent = text;
  return element;
}

function say(text, isError) { $("said").textContent = text; $("said").className = isError ? "refused" : ""; }

// --- the pupils -----------------------------------------------------------------------------------

function runWords(pupil) {
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

function card(pupil) {
  const button = add("button", "pupil" + (pupil.name === chosen ? " chosen" : ""));
  button.type = "button";
  button.dataset.pupil = pupil.name;
  const head = add("div");
  head.append(add("span", "name", pupil.name), " ",
              add("span", pupil.online ? "online" : "away", pupil.online ? "● " + words("online") : "○ " + words("away")));
  const program = add("div", "", pupil.program || words("no_program"));
  const run = add("div", pupil.run ? "running" : "", runWords(pupil));
  const errors = pupil.problems.filter(p => p.severity === "error").length;
  const problems = add("div", errors ? "mistakes" : "", errors ? words("mistakes", {count: errors}) : "");
  const checks = add("div");
  for (const task of tasks) {
    const checked = pupil.checks[task.name];
    if (!checked) continue;
    checks.append(add("span", checked.passed ? "passed" : "failed",
                      task.name + " " + (checked.passed ? words("passed") : words("failed")) + " "));
  }
  button.append(head, program, run, problems, checks);
  button.setAttribute("aria-label", pupil.name + ": " + runWords(pupil));
  button.addEventListener("click", () => choose(pupil.name));
  return button;
}

function showPupils() {
  const list = $("pupils");
  const cards = [...pupils.values()].sort((a, b) => a.name.localeCompare(b.name)).map(card);
  list.replaceChildren(...(cards.length ? cards : [$("no-pupils") || add("p", "", words("no_pupils"))]));
  state.pupils = [...pupils.keys()].sort().join(",");
  state.running = [...pupils.values()].filter(p => p.run).map(p => p.name).sort().join(",");
  state.checks = [...pupils.values()].map(p => p.name + ":" + Object.entries(p.checks)
    .map(([task, c]) => task + "=" + (c.passed ? "passed" : "failed")).join("+")).sort().join(",");
  if (chosen && pupils.has(chosen)) showDetail(pupils.get(chosen));
}

function choose(name) { chosen = name; shownText = null; showPupils(); }

// --- one pupil's program, read-only: blocks (the studio's own conversion) and text --------------

async function showDetail(pupil) {
  $("detail-name").textContent = words("program_of", {name: pupil.name, program: pupil.program || "—"});
  const last = $("detail-last");
  last.replaceChildren();
  if (pupil.last) {
    last.append(add("p", "", runWords(pupil)));
    if (pupil.last.error) last.append(add("p", "mistakes", words("at_line", {line: pupil.last.error.line, message: pupil.last.error.message})));
    if (pupil.last.replay) {
      const link = add("a", "", words("replay"));
      link.href = pupil.last.replay; link.download = pupil.last.program.replace(/\.root$/, "") + "-replay.html";
      last.append(link);
    }
    const trace = add("ol");
    pupil.last.trace.forEach(line => trace.append(add("li", "", line)));
    last.append(trace);
  }
  pupil.problems.forEach(p => last.append(add("p", "mistakes", words("at_line", {line: p.line, message: p.message}))));
  if (pupil.text === shownText) return;
  shownText = pupil.text;
  $("detail-text").textContent = pupil.text;
  state.shownText = pupil.text;
  if (!workspace) return;
  const reply = await api("POST", "/api/blocks", {text: pupil.text, name: pupil.program});
  if (reply.workspace && shownText === pupil.text) {
    Blockly.Events.disable();
    try { Blockly.serialization.workspaces.load(reply.workspace, workspace); workspace.cleanUp(); }
    finally { Blockly.Events.enable(); }
    state.shownBlocks = String(workspace.getAllBlocks(false).length);
  }
}

function loadScript(address) {
  if (typeof Blockly === "undefined") return Promise.resolve();
  return new Promise(resolve => {
    const script = document.createElement("script");
    script.src = address;
    script.onload = script.onerror = () => resolve();
    document.head.appendChild(script);
  });
}

function setupBlocks(blocks) {
  if (!blocks || typeof Blockly === "undefined") return;
  install(Blockly, blocks.definitions);
  workspace = Blockly.inject("detail-blocks", {readOnly: true, media: "/static/vendor/blockly/media/",
                                               sounds: false, zoom: {controls: true, startScale: 0.7}});
}

// --- what the studio sends -----------------------------------------------------------------------

function received(message) {
  if (message.type === "class") {
    pupils.clear();
    tasks = message.tasks;
    $("task").replaceChildren(...tasks.map(task => new Option(task.title + " (" + task.program + ")", task.name)));
    exportLinks();
  }
  for (const pupil of message.pupils || []) pupils.set(pupil.name, pupil);
  if ("locked" in message) showLocked(message.locked);
  showPupils();
  state.lag = Math.max(0, Date.now() / 1000 - message.sent_at).toFixed(3);
  state.updates = String(Number(state.updates || 0) + 1);
}

function showLocked(value) {
  locked = value;
  $("lock").textContent = locked ? words("unlock") : words("lock");
  $("lock").setAttribute("aria-pressed", String(locked));
  state.locked = locked ? "yes" : "no";
}

function exportLinks() {
  const task = encodeURIComponent($("task").value);
  $("export-csv").href = inPageLanguage("/api/teacher/export?format=csv&task=" + task);
  $("export-junit").href = inPageLanguage("/api/teacher/export?format=junit&task=" + task);
}

// --- what the teacher does ---------------------------------------------------------------------------

async function act(work) {
  try { await work(); } catch (error) { say(error.message, true); }
}

async function stopAll() {
  const reply = await api("POST", "/api/teacher/stop");
  say(words("stopped_all", {count: reply.stopped, seconds: reply.seconds.toFixed(2)}));
  state.stopped = String(reply.stopped);
}

async function send() {
  await api("POST", "/api/teacher/notice", {text: $("message").value});
  say(words("sent"));
  state.sent = $("message").value;
}

async function checkAll() {
  say(words("checking"));
  const reply = await api("POST", "/api/teacher/check", {task: $("task").value});
  const results = Object.values(reply.results);
  say(words("checked_all", {passed: results.filter(r => r.passed).length, count: results.length}));
}

async function enter() {
  const setup = await api("GET", "/api/teacher/setup");
  setWords(setup.strings);
  document.documentElement.lang = setup.language;
  translate(document);
  $("login").hidden = true; $("toolbar").hidden = false; document.querySelector("main").hidden = false;
  await loadScript(setup.blockly_messages);   // Blockly's own words, before the blocks
  setupBlocks(setup.blocks);
  $("stop-all").addEventListener("click", () => act(stopAll));
  $("lock").addEventListener("click", () => act(() => api("POST", "/api/teacher/lock", {locked: !locked}).then(r => showLocked(r.locked))));
  $("send").addEventListener("click", () => act(send));
  $("check-all").addEventListener("click", () => act(checkAll));
  $("task").addEventListener("change", exportLinks);
  keepOpen("/ws/teacher", received, online => { state.online = online ? "yes" : "no"; });
  state.ready = "yes";
}

async function start() {
  try {
    await enter();
  } catch (error) {
    if (error.status !== 401) throw error;
    const who = await api("GET", "/api/pupil");   // the page's words, before the code
    setWords(who.strings);
    translate(document);
    $("login").hidden = false;
    state.login = "yes";
    $("login").addEventListener("submit", event => {
      event.preventDefault();
      act(async () => {
        try {
          await api("POST", "/api/teacher/login", {code: $("code").value});
        } catch (refused) {
          $("refused").textContent = refused.message; state.refused = refused.message; return;
        }
        await enter();
      });
    });
  }
}

start().catch(error => say(error.message, true));
