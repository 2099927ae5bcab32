// rootlang studio: blocks and text side by side (the conversion is the server's, in Python),
// runs streamed from the real runtime and simulator over a WebSocket, and the class folder.
"use strict";

const $ = id => document.getElementById(id);
const SYNC_DELAY_MS = 100;   // after the last keystroke or block move; the round trip stays under 0.3 s
const state = $("state").dataset;   // read by the browser tests
let current = "";                   // the open program's name
let workspace = null, editor = null, stage = null, socket = null;
let loadingBlocks = false, settingText = false;
let running = false, layout = {};
let textTimer = null, blocksTimer = null;
let errorMarks = [], runningLines = [];

// --- talking to the server --------------------------------------------------------------------

// Every request carries the page's language, so what the server says comes back in it.
async function api(method, path, body) {
  const response = await fetch(inPageLanguage(path), {
    method: method, headers: body ? {"Content-Type": "application/json"} : {},
    body: body ? JSON.stringify(body) : undefined,
  });
  const data = await response.json();
  if (!response.ok) throw new Error((data.errors || []).map(e => e.message).join("\n") || response.statusText);
  return data;
}

// The page's sentences in its language (the studio's strings; English until they are known).
let pageWords = {};
function words(key, values) {
  let text = pageWords[key] || key;
  // (a function: a value's own "$&" or "$1" stays as it is)
  for (const [name, value] of Object.entries(values || {})) text = text.replace("{" + name + "}", () => value);
  return text;
}

function say(text, isError) {
  $("status").textContent = text;
  $("status").className = isError ? "error" : "";
}

// --- the text pane ------------------------------------------------------------------------------

CodeMirror.defineSimpleMode("rootlang", {
  start: [
    {regex: /#.*/, token: "comment"},
    {regex: /"(?:[^"\\]|\\.)*"?/, token: "string"},
    {regex: /^(?:when|to)\b/i, token: "keyword", sol: true},
    {regex: /\b(?:repeat|forever|until|if|else|while|then|wait|set|change|by|to|return|stop|send|and|or|not)\b/i, token: "keyword"},
    {regex: /\b(?:move|turn|drive|marker|eraser|light|play|note|say|print|go|arc|undock|dock|sweep|reset|sound|volume)\b/i, token: "builtin"},
    {regex: /-?\d+(?:\.\d+)?\s*(?:mm|cm|m|inch(?:es)?|degrees?|deg|°|seconds?|sec|s|ms|cm\/s|mm\/s|Hz|%)?/i, token: "number"},
    {regex: /\b(?:red|orange|yellow|green|cyan|blue|purple|pink|white|black|rgb)\b/i, token: "atom"},
    {regex: /[a-z_][\w]*/i, token: "variable"},
  ],
  meta: {lineComment: "#"},
});

function setupEditor() {
  editor = CodeMirror.fromTextArea($("text"), {
    mode: "rootlang", lineNumbers: true, indentUnit: 4, tabSize: 4, indentWithTabs: false,
    styleActiveLine: true, matchBrackets: true, gutters: ["CodeMirror-linenumbers", "problems"],
    extraKeys: {Tab: cm => cm.execCommand("insertSoftTab"), "Ctrl-S": () => save(), "Cmd-S": () => save()},
    screenReaderLabel: "Program text",
  });
  editor.getInputField().setAttribute("aria-label", "Program text");
  editor.on("changes", () => {
    if (settingText) return;
    state.textSynced = "no";
    clearTimeout(textTimer);
    textTimer = setTimeout(textChanged, SYNC_DELAY_MS);
  });
}

function setText(text) {
  if (editor.getValue() === text) return;
  settingText = true;
  const cursor = editor.getCursor();
  editor.setValue(text);
  editor.setCursor(cursor);
  settingText = false;
}

async function textChanged() {
  const text = editor.getValue();
  const reply = await api("POST", "/api/blocks", {text: text, name: current});
  if (editor.getValue() !== text) return;   // typed on meanwhile: the next round comes
  if (reply.workspace && workspace) loadWorkspace(reply.workspace);
  showProblems(reply.diagnostics);
  state.textSynced = "yes";
}

// --- the blocks pane ----------------------------------------------------------------------------

function setupBlocks(blocks) {
  if (!blocks || typeof Blockly === "undefined") {
    $("blocks").hidden = true; $("no-blocks").hidden = false; return;
  }
  if (typeof RootBlocks !== "undefined") RootBlocks.install(Blockly, blocks.definitions);
  else Blockly.common.defineBlocksWithJsonArray(blocks.definitions);
  workspace = Blockly.inject("blocks", {
    toolbox: blocks.toolbox, media: "/static/vendor/blockly/media/", sounds: false,
    trashcan: true, zoom: {controls: true, wheel: true, startScale: 0.9},
    move: {scrollbars: true, drag: true, wheel: false},
  });
  if (typeof RootBlocks !== "undefined" && RootBlocks.attach) RootBlocks.attach(workspace, blocks.toolbox);
  workspace.addChangeListener(event => {
    if (loadingBlocks || event.isUiEvent) return;
    state.blocksSynced = "no";
    clearTimeout(blocksTimer);
    blocksTimer = setTimeout(blocksChanged, SYNC_DELAY_MS);
  });
}

const SCRIPT_GAP_PX = 24;

function loadWorkspace(json) {
  loadingBlocks = true;
  try {
    Blockly.Events.disable();
    Blockly.serialization.workspaces.load(json, workspace);
    placeBlocks();
  } finally {
    Blockly.Events.enable();
    loadingBlocks = false;
  }
}

async function blocksChanged() {
  if (!workspace) return;
  const json = Blockly.serialization.workspaces.save(workspace);
  try {
    const reply = await api("POST", "/api/text", {workspace: json, name: current});
    setText(reply.text);
    showProblems(reply.diagnostics);
    rememberLayout();
    state.blocksSynced = "yes";
  } catch (error) {
    say(error.message, true);
  }
}

// Top-level block positions: kept in the program's sidecar, keyed by the script's order and its
// header line (where the child put them; placeBlocks stacks the others under them).
function layoutKey(block, index) {
  const line = /^L(\d+)$/.exec(block.id);
  const header = line ? editor.getLine(Number(line[1]) - 1) || "" : block.type;
  return index + ":" + header.trim();
}
function rememberLayout() {
  if (!workspace) return;
  const top = {};
  workspace.getTopBlocks(false).forEach((block, index) => {
    const xy = block.getRelativeToSurfaceXY();
    top[layoutKey(block, index)] = [Math.round(xy.x), Math.round(xy.y)];
  });
  layout = {top: top};
}
function placeBlocks() {
  const top = (layout && layout.top) || {};
  const unplaced = [];
  let bottom = 0;
  workspace.getTopBlocks(false).forEach((block, index) => {
    const xy = top[layoutKey(block, index)];
    if (!xy) { unplaced.push(block); return; }
    block.moveTo(new Blockly.utils.Coordinate(xy[0], xy[1]));
    bottom = Math.max(bottom, xy[1] + block.getHeightWidth().height);
  });
  // Scripts nobody has placed yet go one under another, as tall as they really are drawn.
  let y = bottom > 0 ? bottom + SCRIPT_GAP_PX : SCRIPT_GAP_PX;
  unplaced.forEach(block => {
    block.moveTo(new Blockly.utils.Coordinate(SCRIPT_GAP_PX, y));
    y += block.getHeightWidth().height + SCRIPT_GAP_PX;
  });
}

// --- mistakes, on the text and on their blocks -------------------------------------------------

// Block ids come from source positions: L<line> for a statement or header, L<line>C<col>E<end>
// for an expression; a mistake shows on the expression it is about, else on its line's block.
function blockAt(line, column) {
  if (!workspace) return null;
  const prefix = "L" + line + "C" + column + "E";
  const expression = workspace.getAllBlocks(false).find(block => block.id.startsWith(prefix));
  return expression || workspace.getBlockById("L" + line);
}

function showProblems(diagnostics) {
  errorMarks.forEach(mark => mark.clear());
  errorMarks = [];
  editor.clearGutter("problems");
  if (workspace) workspace.getAllBlocks(false).forEach(block => block.setWarningText(null));
  const list = $("problems");
  list.replaceChildren();
  for (const d of diagnostics) {
    const li = document.createElement("li");
    li.className = d.severity;
    li.textContent = d.line ? words("at_line", {line: d.line, message: d.message}) : d.message;
    li.tabIndex = 0;
    li.addEventListener("click", () => { editor.focus(); editor.setCursor(d.line - 1, d.column - 1); });
    list.append(li);
    if (d.line >= 1) {
      const from = {line: d.line - 1, ch: Math.max(0, d.column - 1)};
      const to = {line: d.end_line - 1, ch: Math.max(d.end_column - 1, d.column)};
      errorMarks.push(editor.markText(from, to, {className: "cm-" + d.severity + "-mark", title: d.message}));
      const dot = document.createElement("span");
      dot.textContent = d.severity === "error" ? "●" : "▲";
      dot.style.color = d.severity === "error" ? "#dc2626" : "#d97706";
      dot.title = d.message;
      editor.setGutterMarker(d.line - 1, "problems", dot);
      const block = blockAt(d.line, d.column);
      if (block) block.setWarningText(d.message);
    }
  }
  state.problems = diagnostics.length;
  state.errors = diagnostics.filter(d => d.severity === "error").length;
}

// --- files ----------------------------------------------------------------------------------------

async function refreshPrograms(select) {
  const setup = await api("GET", "/api/setup");
  const chooser = $("program");
  chooser.replaceChildren(...setup.programs.map(p => new Option(p.name, p.name)));
  if (select) chooser.value = select;
  return setup;
}

async function openProgram(name) {
  const data = await api("GET", "/api/program?name=" + encodeURIComponent(name));
  current = name;
  $("program").value = name;
  layout = data.layout || {};
  const address = new URL(location.href);
  address.searchParams.set("open", name);  // (a ?language= stays)
  history.replaceState(null, "", address.pathname + address.search);
  settingText = true;
  editor.setValue(data.text);
  editor.clearHistory();
  settingText = false;
  await textChanged();
  say(words("opened", {name: name}));
  state.open = name;
}

async function save() {
  if (!current) return;
  rememberLayout();
  const reply = await api("PUT", "/api/program", {name: current, text: editor.getValue(), layout: layout});
  setText(reply.text);
  say(words("saved", {name: current}));
  state.saved = current;
}

function askName(question, suggestion) {
  let name = window.prompt(question, suggestion);
  if (!name) return null;
  name = name.trim();
  return name.endsWith(".root") ? name : name + ".root";
}

async function newProgram() {
  const name = askName(words("ask_new_name"), words("suggested_name"));
  if (!name) return;
  try {
    await api("POST", "/api/program", {name: name});
    await refreshPrograms(name);
    await openProgram(name);
  } catch (error) { say(error.message, true); }
}

async function renameProgram() {
  const name = askName(words("ask_rename", {name: current}), current.replace(/\.root$/, ""));
  if (!name || name === current) return;
  try {
    await save();
    await api("POST", "/api/rename", {old: current, new: name});
    await refreshPrograms(name);
    await openProgram(name);
  } catch (error) { say(error.message, true); }
}

// --- running ------------------------------------------------------------------------------------

function connect() {
  return new Promise(resolve => {
    if (socket && socket.readyState === WebSocket.OPEN) { resolve(socket); return; }
    socket = new WebSocket((location.protocol === "https:" ? "wss://" : "ws://") + location.host + inPageLanguage("/ws"));
    socket.onmessage = event => received(JSON.parse(event.data));
    socket.onopen = () => resolve(socket);
    socket.onclose = () => { if (running) finished({end: "disconnected"}); };
  });
}

async function run() {
  if (running) return;
  clearTimeout(textTimer);
  await textChanged();    // the blocks' ids follow the text that runs, so highlights match
  if (Number(state.errors) > 0) { say(words("fix_first"), true); return; }
  const ws = await connect();
  $("output").replaceChildren(); $("trace").replaceChildren(); $("speech").textContent = "";
  $("after").hidden = true; $("replay").hidden = true;
  running = true; state.ended = ""; state.running = "yes";
  $("run").disabled = true; $("stop").disabled = false;
  say(words("starting"));
  const robot = $("robot").value;
  ws.send(JSON.stringify({type: "run", name: current, text: editor.getValue(),
                          world: $("world").value, speed: Number($("speed").value),
                          robot: robot === "" ? null : robot}));
}

function received(message) {
  if (message.type === "started") {
    if (message.stage) {
      stage.show(message.stage, false);
      say(words("running_world", {world: message.stage.world.name}));
    } else {
      say(words("running_robot", {robot: message.robot}));
    }
  } else if (message.type === "frame") {
    stage.frame(message);
    highlight(message.running);
    message.printed.forEach(text => addLine($("output"), text));
    message.said.forEach(text => { $("speech").textContent = words("said", {text: text}); });
    state.t = message.t.toFixed(2);
    state.lag = Math.max(0, Date.now() / 1000 - message.sent_at).toFixed(3);
  } else if (message.type === "ended") {
    finished(message);
  } else if (message.type === "error") {
    say(message.message, true);
    if (!running) return;
    if (/already running/.test(message.message)) return;
    running = false; $("run").disabled = false; $("stop").disabled = true; state.running = "no";
  }
}

function addLine(list, text) {
  const li = document.createElement("li"); li.textContent = text; list.append(li);
  li.scrollIntoView({block: "nearest"});
}

function highlight(lines) {
  runningLines.forEach(line => editor.removeLineClass(line, "background", "running-line"));
  runningLines = Object.values(lines || {}).map(line => line - 1);
  runningLines.forEach(line => editor.addLineClass(line, "background", "running-line"));
  if (workspace) {
    workspace.highlightBlock(null);
    Object.values(lines || {}).forEach(line => workspace.highlightBlock("L" + line, true));
  }
  state.lines = Object.values(lines || {}).join(",");
}

function finished(outcome) {
  running = false; state.running = "no";
  $("run").disabled = false; $("stop").disabled = true;
  highlight({});
  if (outcome.stage) stage.show(outcome.stage, true);
  const key = "end_" + outcome.end;
  const said = pageWords[key] ? words(key, {why: outcome.stopped_by || ""}) : outcome.end;
  say(said, Boolean(outcome.error || outcome.errors));
  if (outcome.error) {
    addLine($("output"), outcome.error.rendered);
    showProblems([outcome.error]);
    if (outcome.error.line) editor.addLineClass(outcome.error.line - 1, "background", "error-line");
  }
  if (outcome.errors) showProblems(outcome.errors);
  (outcome.trace || []).forEach(line => addLine($("trace"), line));
  $("after").hidden = !(outcome.trace && outcome.trace.length);
  if (outcome.replay) {
    $("replay").href = outcome.replay; $("replay").hidden = false;
    $("replay").download = current.replace(/\.root$/, "") + "-replay.html";
  }
  if (outcome.world_pose) {
    state.finalX = outcome.world_pose.x_mm; state.finalY = outcome.world_pose.y_mm;
    state.finalH = outcome.world_pose.heading_deg;
  }
  state.ended = outcome.end;
}

async function findRobots() {
  say(words("looking"));
  $("scan").disabled = true;
  try {
    const reply = await api("GET", "/api/robots");
    const chooser = $("robot");
    chooser.replaceChildren(new Option(words("simulator"), ""), ...reply.robots.map(robot =>
      new Option(robot.name + " (" + robot.model + ", " + robot.rssi + " dBm)", robot.address)));
    if (reply.robots.length) chooser.value = reply.robots[0].address;
    say(reply.robots.length ? words("found_robots", {count: reply.robots.length}) : words("no_robots"));
    state.robots = reply.robots.length;
    robotChosen();
  } catch (error) {
    say(error.message, true);
  } finally {
    $("scan").disabled = false;
  }
}

function robotChosen() {
  const onRobot = $("robot").value !== "";
  $("world").disabled = onRobot; $("speed").disabled = onRobot;
  document.querySelectorAll("#robot-buttons button, #bumper-buttons button").forEach(b => { b.disabled = onRobot; });
}

function stimulate(data) {
  if (!running || !socket) return;
  socket.send(JSON.stringify(Object.assign({type: "stimulus"}, data)));
}

// --- the page's language --------------------------------------------------------------------------

// Chosen in the page (kept in this browser), or ?language=xx, else ("") the studio's own default;
// once the setup has come, the one it is in.
let pageLanguage = new URLSearchParams(location.search).get("language")
  || localStorage.getItem("rootlang.language") || "";

function inPageLanguage(path) {
  if (!pageLanguage) return path;
  const address = new URL(path, location.href);
  address.searchParams.set("language", pageLanguage);
  return address.pathname + address.search;
}

// The page's words in its language: the Language menu lists the studio's languages (each named
// in itself); each [data-i18n] element's English words are replaced, so the signs around them
// (◤, ▶) stay; its accessible name follows.
function translatePage(setup) {
  pageLanguage = setup.language;
  document.documentElement.lang = setup.language;
  $("language").replaceChildren(...Object.entries(setup.languages).map(([code, name]) => new Option(name, code)));
  $("language").value = setup.language;
  if (setup.language === "en") return;
  document.querySelectorAll("[data-i18n]").forEach(element => {
    const key = element.dataset.i18n;
    const english = setup.english[key], local = setup.strings[key];
    if (!english || !local) return;
    element.textContent = element.textContent.replace(english, local);
    if (element.hasAttribute("aria-label")) element.setAttribute("aria-label", element.textContent.trim());
  });
}

// Blockly's own words (its built-in blocks and menus) in the page's language, before the blocks:
// the file the server names (English's too).
function loadBlocklyWords(address) {
  if (typeof Blockly === "undefined") return Promise.resolve();
  return new Promise(resolve => {
    const script = document.createElement("script");
    script.src = address;
    script.onload = script.onerror = () => resolve();
    document.head.appendChild(script);
  });
}

function chooseLanguage() {
  localStorage.setItem("rootlang.language", $("language").value);
  const address = new URL(location.href);
  address.searchParams.set("language", $("language").value);
  location.href = address.toString();
}

// --- start --------------------------------------------------------------------------------------

async function start() {
  setupEditor();
  stage = new Stage($("canvas"));
  const setup = await refreshPrograms();
  pageWords = setup.strings;
  translatePage(setup);
  $("language").addEventListener("change", chooseLanguage);
  $("world").replaceChildren(new Option(words("its_own"), ""),
                             ...setup.worlds.map(name => new Option(name, name)));
  await loadBlocklyWords(setup.blockly_messages);
  setupBlocks(setup.blocks);
  $("program").addEventListener("change", () => openProgram($("program").value));
  $("new").addEventListener("click", newProgram);
  $("rename").addEventListener("click", renameProgram);
  $("save").addEventListener("click", () => save().catch(error => say(error.message, true)));
  $("run").addEventListener("click", run);
  $("scan").addEventListener("click", findRobots);
  $("robot").addEventListener("change", robotChosen);
  $("stop").addEventListener("click", () => { if (socket) socket.send(JSON.stringify({type: "stop"})); });
  document.querySelectorAll("[data-touch]").forEach(button => button.addEventListener("click",
    () => stimulate({action: "touch", sensors: [button.dataset.touch]})));
  document.querySelectorAll("[data-bump]").forEach(button => button.addEventListener("click",
    () => stimulate({action: "bump", sensors: button.dataset.bump.split(" ")})));
  document.querySelector("[data-nose]").addEventListener("click", () => stimulate({action: "nose"}));
  const wanted = new URLSearchParams(location.search).get("open");
  const first = wanted || (setup.programs[0] && setup.programs[0].name);
  if (first) await openProgram(first).catch(error => say(error.message, true));
  else say(words("no_programs"));
  state.ready = "yes";
}

start().catch(error => say(error.message, true));
