// The studio page in a class: who is working (their own folder), the teacher's messages and
// "hands off", and Check for a task's program. Does nothing when the studio is not a class.
import {api, keepOpen, setWords, words} from "./classapi.js";

const $ = id => document.getElementById(id);
const state = $("state").dataset;   // read by the browser tests
let tasks = [];

function add(tag, attributes, text) {
  const element = document.createElement(tag);
  Object.entries(attributes).forEach(([name, value]) => element.setAttribute(name, value));
  if (text) element.textContent = text;
  return element;
}

// The program in the page now (saved or not): the CodeMirror editor's text.
function programText() {
  const editor = document.querySelector(".CodeMirror");
  return editor ? editor.CodeMirror.getValue() : "";
}

function taskOf(name) { return tasks.find(task => task.program === name); }

function showCheck() {
  const task = taskOf(state.open || "");
  $("check").hidden = !task;
  if (task) $("check").title = task.title;
  $("check-said").textContent = ""; $("check-said").className = "";
}

async function check() {
  const said = $("check-said");
  said.className = ""; said.textContent = words("checking");
  state.checked = "";
  $("check").disabled = true;
  try {
    const reply = await api("POST", "/api/check", {name: state.open, text: programText()});
    said.textContent = reply.said;
    said.className = reply.passed ? "passed" : "failed";
    state.checked = reply.passed ? "passed" : "failed";
  } catch (error) {
    said.textContent = error.message; said.className = "failed";
    state.checked = "refused";
  } finally {
    $("check").disabled = false;
  }
}

function received(message) {
  if (message.type === "notice") {
    $("notice").textContent = words("teacher_says", {text: message.text});
    $("notice").hidden = !message.text;
    state.notice = message.text;
  } else if (message.type === "locked") {
    $("hands-off").hidden = !message.locked;
    state.locked = message.locked ? "yes" : "no";
    if (message.locked && document.activeElement) document.activeElement.blur();
  }
}

async function start() {
  let who;
  try { who = await api("GET", "/api/pupil"); } catch { return; }   // not a class
  if (!who.class || !who.name) return;
  setWords(who.strings);
  tasks = who.tasks;
  const bar = add("span", {id: "class-bar"});
  bar.append(add("span", {class: "who"}, words("you_are", {name: who.name})),
             add("button", {id: "check", type: "button", class: "go", hidden: ""}, words("check")));
  $("toolbar").insertBefore(bar, $("toolbar").querySelector(".spacer"));
  $("status").after(add("div", {id: "check-said", role: "status", "aria-live": "polite"}));
  const notice = add("div", {id: "notice", role: "alert", hidden: ""});
  document.body.insertBefore(notice, document.querySelector("main"));
  const cover = add("div", {id: "hands-off", hidden: "", role: "alert"}, words("hands_off"));
  document.body.append(cover);
  $("check").addEventListener("click", check);
  new MutationObserver(showCheck).observe($("state"), {attributes: true, attributeFilter: ["data-open"]});
  showCheck();
  if (who.notice) received({type: "notice", text: who.notice});
  received({type: "locked", locked: who.locked});
  state.pupil = who.name;
  keepOpen("/ws/class", received, online => { state.classOnline = online ? "yes" : "no"; });
}

start();
