// @ts-check
// The studio page in a class: who is working (their own folder), the teacher's messages and
// "hands off", Check for a task's (or an adventure's) program, and the adventures. Does nothing when the studio is not a class.
import {check as checkProgram, join, who as askWho} from "./api.js";
import {element, keepOpen} from "./classapi.js";
import {$, fixed, say, setWords, state, words} from "./page.js";
import {muteClass} from "./sound.js";
import {teacherChose} from "./levels.js";
import {adventureChecked, adventureFor, setupAdventures, showGoal} from "./adventures.js";

/** @typedef {import("./messages").TaskJson} TaskJson */
/** @typedef {import("./messages").ToClassPage} ToClassPage */

/** @type {TaskJson[]} */
let tasks = [];

/** The program in the page now (saved or not): the text editor's. */
function programText() {
  const editor = /** @type {any} */ (document.querySelector(".CodeMirror"));
  return editor ? String(editor.CodeMirror.getValue()) : "";
}

function showCheck() {
  const open = state.open || "";
  const task = tasks.find(one => one.program === open) || adventureFor(open);
  $("check").hidden = !task;
  if (task) $("check").title = task.title;
  $("check-said").textContent = ""; $("check-said").className = "";
  showGoal(open);
}

async function check() {
  const said = $("check-said");
  said.className = ""; said.textContent = words("checking");
  state.checked = "";
  $("check").disabled = true;
  try {
    const reply = await checkProgram({name: state.open || "", text: programText()});
    said.textContent = reply.said;
    said.className = reply.passed ? "passed" : "failed";
    state.checked = reply.passed ? "passed" : "failed";
    adventureChecked(state.open || "", reply.passed, reply.said);
  } catch (error) {
    said.textContent = /** @type {Error} */ (error).message; said.className = "failed";
    state.checked = "refused";
  } finally {
    $("check").disabled = false;
  }
}

/** @param {ToClassPage} message */
function received(message) {
  if (message.type === "notice") {
    $("notice").textContent = words("teacher_says", {text: message.text});
    $("notice").hidden = !message.text;
    state.notice = message.text;
  } else if (message.type === "locked") {
    $("hands-off").hidden = !message.locked;
    state.locked = message.locked ? "yes" : "no";
    if (message.locked && document.activeElement instanceof HTMLElement) document.activeElement.blur();
  } else if (message.type === "muted") {
    muteClass(message.muted);
  } else if (message.type === "level") {
    teacherChose(message.level);
  }
}

/**
 * Back in touch with the studio: if it has forgotten this page's pupil (it was restarted), the
 * page comes in again under the same name, so the child's work on it is saved in their folder.
 * Someone else in under the name meanwhile (E844): the page says so, keeps the work, tries later.
 * @param {string} name
 */
async function comeBackAs(name) {
  if ((await askWho()).name) return;
  try {
    await join({name: name});
    fixed("class");
  } catch (error) {
    say(/** @type {Error} */ (error).message, true, "class");
    throw error;
  }
}

async function start() {
  let who;
  try { who = await askWho(); } catch { return; }   // not a class: there is no /api/pupil
  if (!who.class || !who.name) return;
  const name = who.name;
  setWords(who.strings);
  tasks = who.tasks;
  const bar = element("span", {id: "class-bar"});
  bar.append(element("span", {class: "who"}, words("you_are", {name: who.name})),
             element("button", {id: "check", type: "button", class: "go", hidden: ""}, words("check")));
  $("toolbar").insertBefore(bar, $("toolbar").querySelector(".spacer"));
  $("status").after(element("div", {id: "check-said", role: "status", "aria-live": "polite"}));
  document.body.insertBefore(element("div", {id: "notice", role: "alert", hidden: ""}),
                             document.querySelector("main"));
  document.body.append(element("div", {id: "hands-off", hidden: "", role: "alert"}, words("hands_off")));
  $("check").addEventListener("click", check);
  await setupAdventures();
  new MutationObserver(showCheck).observe($("state"), {attributes: true, attributeFilter: ["data-open"]});
  showCheck();
  if (who.notice) received({type: "notice", text: who.notice, at: 0});
  received({type: "locked", locked: who.locked});
  received({type: "muted", muted: who.muted});
  received({type: "level", level: who.level});
  state.pupil = who.name;
  keepOpen("/ws/class", received, online => { state.classOnline = online ? "yes" : "no"; },
           () => comeBackAs(name));
}

start();
