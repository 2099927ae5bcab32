// @ts-check
// Adventures (docs/levels.md): a path of lessons through the levels. In a class (class.js) or
// alone at home, the child picks one from the list of their level's adventures; its starter
// opens as their program, and its goal shows above the stage: a picture of what the robot
// should do and a few words (said aloud at Level 1). Check runs it (a class's tasks too); a
// failed check's hint says what differs (aloud at Level 1 too); a passed one offers the next
// adventure.
import * as api from "./api.js";
import {element} from "./classapi.js";
import {$, say, state, words, withoutSigns} from "./page.js";
import {openProgram, refreshPrograms} from "./files.js";
import {level, speak} from "./levels.js";
import {onward, showSigned, speaker, star, tick} from "./icons.js";

/** @typedef {import("./messages").AdventureJson} AdventureJson */
/** @typedef {import("./messages").TaskJson} TaskJson */

/** @type {AdventureJson[]} */
let adventures = [];
/** A class's tasks (none at home). @type {TaskJson[]} */
let tasks = [];

/**
 * The adventure whose program `program` is (undefined: none).
 * @param {string} program
 */
const adventureFor = program => adventures.find(one => one.program === program);

/**
 * Check (in `bar`, for the program of one of `taskList` or of an adventure), the adventures'
 * list and the goal's panel.
 * @param {HTMLElement} bar
 * @param {TaskJson[]} taskList
 */
export async function setupLessons(bar, taskList) {
  tasks = taskList;
  const checkButton = element("button", {id: "check", type: "button", class: "go", hidden: ""});
  showSigned(checkButton, tick(), words("check"), withoutSigns(words("check")));
  bar.append(checkButton);
  $("toolbar").insertBefore(bar, $("toolbar").querySelector(".spacer"));
  $("status").after(element("div", {id: "check-said", role: "status", "aria-live": "polite"}));
  $("check").addEventListener("click", check);
  await setupAdventures(bar);
  new MutationObserver(showCheck).observe($("state"), {attributes: true, attributeFilter: ["data-open"]});
  showCheck();
}

/**
 * One child at home (the studio is not a class): the adventures and Check, once the page is
 * set up (its words known); their progress is kept in the studio's folder. Nothing when the
 * studio has none to give.
 */
export async function atHome() {
  if (state.ready !== "yes") {
    await new Promise(resolve => {
      const watch = new MutationObserver(() => { if (state.ready === "yes") { watch.disconnect(); resolve(null); } });
      watch.observe($("state"), {attributes: true, attributeFilter: ["data-ready"]});
    });
  }
  try { await refresh(); } catch { return; }
  // (the studio out of reach meanwhile: the page says so, as for any question it asks)
  await setupLessons(element("span", {id: "lessons-bar"}), [])
    .catch(error => say(String(/** @type {Error} */ (error).message), true));
}

/** The program in the page now (saved or not): the text editor's. */
function programText() {
  const editor = /** @type {any} */ (document.querySelector(".CodeMirror"));
  return editor ? String(editor.CodeMirror.getValue()) : "";
}

function showCheck() {
  const open = state.open || "";
  const task = tasks.find(one => one.program === open) || adventureFor(open);
  $("check").hidden = !task;
  $("check-said").textContent = ""; $("check-said").className = "";
  state.checked = "";   // (what Check said was of the program open before)
  showGoal(open);
}

async function check() {
  const said = $("check-said");
  said.className = ""; said.textContent = words("checking");
  state.checked = "";
  $("check").disabled = true;
  const program = state.open || "";   // (the one checked, if another opens meanwhile)
  try {
    const reply = await api.check({name: program, text: programText()});
    said.textContent = reply.said;
    said.className = reply.passed ? "passed" : "failed";
    state.checked = reply.passed ? "passed" : "failed";
    adventureChecked(program, reply.passed, reply.said);
  } catch (error) {
    said.textContent = /** @type {Error} */ (error).message; said.className = "failed";
    state.checked = "refused";
  } finally {
    $("check").disabled = false;
  }
}

/**
 * The list and the goal's panel; the adventures known from the studio.
 * @param {HTMLElement} bar
 */
async function setupAdventures(bar) {
  const open = element("button", {id: "adventures-open", type: "button", "aria-haspopup": "dialog"});
  showSigned(open, star(), words("adventures"), withoutSigns(words("adventures")));
  bar.append(open);
  const list = element("dialog", {id: "adventure-list", "aria-labelledby": "adventure-list-title"});
  list.append(element("h2", {id: "adventure-list-title"}), element("ul", {id: "adventure-cards"}),
              element("button", {id: "adventure-list-close", type: "button"}, words("close")));
  document.body.append(list);
  const goal = element("section", {id: "adventure", "aria-labelledby": "adventure-title", hidden: ""});
  const buttons = element("div", {class: "adventure-buttons"});
  const hear = element("button", {id: "adventure-hear", type: "button"});
  showSigned(hear, speaker(true), words("adventure_hear"));
  const onwards = element("button", {id: "adventure-next", type: "button", class: "go", hidden: ""});
  showSigned(onwards, onward(), words("adventure_next"), withoutSigns(words("adventure_next")));
  buttons.append(hear, onwards);
  goal.append(element("h2", {id: "adventure-title"}), element("img", {id: "adventure-picture", alt: ""}),
              element("p", {id: "adventure-goal"}), buttons);
  $("stage-pane").prepend(goal);
  open.addEventListener("click", () => { showList().catch(error => say(String(error.message), true)); });
  $("adventure-list-close").addEventListener("click", () => list.close());
  $("adventure-hear").addEventListener("click", () => speak($("adventure-goal").textContent || ""));
  $("adventure-next").addEventListener("click", () => { next().catch(error => say(String(error.message), true)); });
  await refresh();
}

async function refresh() {
  adventures = (await api.adventures()).adventures;
  state.adventuresPassed = adventures.filter(one => one.passed).map(one => one.name).join(" ");
}

/** The list of the adventures at the level the page shows (the class's, or the pupil's own). */
async function showList() {
  await refresh();
  const shown = level();
  $("adventure-list-title").textContent = words("adventures_at_level", {level: shown});
  const cards = adventures.filter(one => one.level === shown).map(one => {
    const button = element("button", {type: "button", class: "adventure-card", "data-adventure": one.name});
    const mark = one.passed ? "✓ " : "";
    button.append(element("img", {src: one.picture, alt: ""}), element("span", {}, mark + one.title));
    if (one.passed) button.setAttribute("aria-label", words("adventure_done", {title: one.title}));
    button.addEventListener("click", () => { start(one).catch(error => say(String(error.message), true)); });
    const item = element("li");
    item.append(button);
    return item;
  });
  $("adventure-cards").replaceChildren(...cards);
  const list = /** @type {HTMLDialogElement} */ ($("adventure-list"));
  list.showModal();
  const first = list.querySelector(".adventure-card");
  if (first instanceof HTMLElement) first.focus();
}

/**
 * The pupil takes on `adventure`: its program (their own, or a copy of its starter) opens.
 * @param {AdventureJson} adventure
 */
async function start(adventure) {
  /** @type {HTMLDialogElement} */ ($("adventure-list")).close();
  const reply = await api.startAdventure({name: adventure.name});
  const setup = await refreshPrograms(reply.program);
  await openProgram(reply.program);
  const world = /** @type {HTMLSelectElement} */ ($("world"));
  const known = [...world.options].some(option => option.value === adventure.world);
  if (!known && setup.worlds.includes(adventure.world)) {   // (its own, copied to the folder now)
    world.append(new Option(adventure.world, adventure.world));
  }
  if (!adventure.world || setup.worlds.includes(adventure.world)) {   // (run as it is checked)
    world.value = adventure.world;
    world.dispatchEvent(new Event("change"));
  }
  showGoal(reply.program);
  if (level() === 1) speak(adventure.goal);
}

/**
 * The goal of the program open now, when it is an adventure's (else the panel hides).
 * @param {string} program
 */
function showGoal(program) {
  const adventure = adventureFor(program);
  $("adventure").hidden = !adventure;
  $("adventure-next").hidden = true;
  state.adventure = adventure ? adventure.name : "";
  const said = $("check-said");   // (what Check says: by the goal, where the child looks)
  if (adventure && said.parentElement !== $("adventure")) $("adventure").append(said);
  if (!adventure && said.parentElement === $("adventure")) $("status").after(said);
  if (!adventure) return;
  $("adventure-title").textContent = adventure.title;
  $("adventure-goal").textContent = adventure.goal;
  const picture = /** @type {HTMLImageElement} */ ($("adventure-picture"));
  picture.src = adventure.picture;
  picture.alt = adventure.goal;
}

/**
 * A check of the open program was told: a hint is said aloud at Level 1; passed, the next
 * adventure is offered.
 * @param {string} program
 * @param {boolean} passed
 * @param {string} said
 */
function adventureChecked(program, passed, said) {
  const adventure = adventureFor(program);
  if (!adventure) return;
  if (level() === 1) speak(said.replace(/`/g, ""));   // (code's quotes are not said)
  if (passed) {
    adventure.passed = true;
    state.adventuresPassed = adventures.filter(one => one.passed).map(one => one.name).join(" ");
  }
  $("adventure-next").hidden = !passed || !following(adventure);
}

/**
 * The adventure after `adventure` at the same level (one not passed first), if any.
 * @param {AdventureJson} adventure
 */
function following(adventure) {
  const same = adventures.filter(one => one.level === adventure.level);
  const after = same.slice(same.indexOf(adventure) + 1);
  return after.find(one => !one.passed) || after[0];
}

async function next() {
  const now = adventureFor(state.open || "");
  const then = now ? following(now) : undefined;
  if (then) await start(then);
}
