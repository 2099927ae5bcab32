// @ts-check
// The studio page in a class: who is working (their own folder), the teacher's messages and
// "hands off", Check for a task's (or an adventure's) program, and the adventures. When the
// studio is not a class, the adventures alone (one child at home: adventures.js).
import {join, who as askWho} from "./api.js";
import {element, keepOpen} from "./classapi.js";
import {$, fixed, say, setWords, state, words} from "./page.js";
import {muteClass} from "./sound.js";
import {teacherChose} from "./levels.js";
import {atHome, setupLessons} from "./adventures.js";

/** @typedef {import("./messages").ToClassPage} ToClassPage */

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
  try { who = await askWho(); } catch { await atHome(); return; }   // not a class: no /api/pupil
  if (!who.class || !who.name) return;
  const name = who.name;
  setWords(who.strings);
  const bar = element("span", {id: "class-bar"});
  bar.append(element("span", {class: "who"}, words("you_are", {name: who.name})));
  document.body.insertBefore(element("div", {id: "notice", role: "alert", hidden: ""}),
                             document.querySelector("main"));
  document.body.append(element("div", {id: "hands-off", hidden: "", role: "alert"}, words("hands_off")));
  await setupLessons(bar, who.tasks);
  if (who.notice) received({type: "notice", text: who.notice, at: 0});
  received({type: "locked", locked: who.locked});
  received({type: "muted", muted: who.muted});
  received({type: "level", level: who.level});
  state.pupil = who.name;
  keepOpen("/ws/class", received, online => { state.classOnline = online ? "yes" : "no"; },
           () => comeBackAs(name));
}

start();
