// @ts-check
// Levels: one program seen three ways. Level 1 picture blocks (for children who can't read
// yet), Level 2 word blocks, Level 3 text. Going up always works; going down works when every
// line has a form at the lower level, else the blocks that keep the program up say so. A
// picture block says what it does (speech, and the words shown for grown-ups) when it is
// touched or pointed at. The conversion is the server's (rootlang/blocks/pictures.py).
import * as api from "./api.js";
import {$, state, session, words, say, fixed} from "./page.js";
import {editor} from "./editor.js";
import {workspace, fitText, liveBlock} from "./blocks.js";
import {settle, showProblems} from "./sync.js";

/** @typedef {import("./messages").BlocksSetup} BlocksSetup */
/** @typedef {import("./messages").PictureMeaning} PictureMeaning */

/** @type {BlocksSetup | null} */
let setup = null;
/** @type {Record<string, PictureMeaning>} */
let meanings = {};
/** The blocks marked as keeping the program above Level 1. @type {string[]} */
let marked = [];
/** What was said last (said again only when another block is touched). */
let lastSaid = "";
/** The level the teacher chose before the page was set up (0: none). */
let teachers = 0;

/**
 * The level buttons, the picture blocks' voices; the page starts at `level` (the class's).
 * @param {BlocksSetup | null} blocks
 * @param {number} level
 */
export function setupLevels(blocks, level) {
  setup = blocks;
  meanings = blocks ? blocks.pictures.meanings : {};
  const group = document.createElement("span");
  group.id = "levels";
  group.setAttribute("role", "group");
  group.setAttribute("aria-label", words("level_group"));
  for (const n of [1, 2, 3]) {
    const button = document.createElement("button");
    button.type = "button";
    button.id = "level-" + n;
    button.textContent = String(n);
    button.title = words("level_" + n);
    button.setAttribute("aria-label", words("level_" + n));
    button.disabled = !blocks && n < 3;
    button.addEventListener("click", () => { chooseLevel(n).catch(error => say(String(error.message), true)); });
    group.append(button);
  }
  $("toolbar").insertBefore(group, $("toolbar").querySelector(".spacer"));
  const grownUps = $("grown-ups");   // (at Level 1: the grown-ups' controls, shown on asking)
  grownUps.addEventListener("click", () => {
    const open = grownUps.getAttribute("aria-expanded") !== "true";
    grownUps.setAttribute("aria-expanded", String(open));
    document.body.dataset.grownUps = open ? "open" : "";
  });
  const caption = document.createElement("p");
  caption.id = "level-says";
  caption.setAttribute("role", "status");   // (a live region: what a touched block says)
  caption.setAttribute("aria-label", words("level_says"));
  caption.hidden = true;
  $("blocks-pane").append(caption);
  const pane = $("blocks");
  pane.addEventListener("pointerover", /** @param {PointerEvent} event */ event => {
    if (event.pointerType === "mouse") tell(event);
  });
  pane.addEventListener("pointerdown", tell, true);
  show(blocks ? teachers || level : 3);
}

/**
 * The teacher chose a level for this pupil (or the class): the page shows it, whenever the
 * choice comes (before the page is set up, it starts there): at Level 1, a line with no
 * picture shows as its Level 2 block among the pictures, as when a program opens at Level 1.
 * @param {number} n
 */
export function teacherChose(n) {
  if (!setup) { teachers = n; return; }
  chooseLevel(n, {teacher: true}).catch(error => say(String(error.message), true));
}

/** The level shown now (1, 2 or 3). */
export const level = () => Number(state.level || "2");

/**
 * The program at level `n`: up at once; down when every line has a block there (else the
 * blocks that keep it up are marked, and the level stays), or when the teacher chose it.
 * @param {number} n
 * @param {{teacher?: boolean}} [how]
 */
export async function chooseLevel(n, how = {}) {
  if (n === level() || !setup || !workspace) return;
  await settle();
  clearMarks();
  if (n === 3) { show(3); return; }
  if (n === 1 && level() === 3) await chooseLevel(2);   // (what keeps it up is shown on blocks)
  const reply = await api.toBlocks({text: editor.getValue(), name: session.current, level: n});
  if (!reply.workspace) {   // the text does not read as a program: the blocks can't show it
    say(words("level_text_mistake"), true, "level");
    return;
  }
  const above = reply.above || [];
  if (n === 1 && above.length && !how.teacher) {
    marked = above;
    for (const id of above) {
      const block = liveBlock(id);
      if (block) { block.setWarningText(words("level_keeps_up"), "level"); block.addSelect(); }
    }
    say(words("level_kept_up", {count: above.length}), true, "level");
    state.keptUp = above.join(" ");
    return;
  }
  show(n);
  if (!(await fitText(workspace, reply.workspace))) return;   // (another program opened meanwhile)
  showProblems(reply.diagnostics);   // (on the new blocks)
}

function clearMarks() {
  for (const id of marked) {
    const block = liveBlock(id);
    if (block) { block.setWarningText(null, "level"); block.removeSelect(); }
  }
  marked = [];
  state.keptUp = "";
  fixed("level");
}

/**
 * The page at level `n`: its panes, its toolbox, its buttons.
 * @param {number} n
 */
function show(n) {
  state.level = String(n);
  api.setLevel(n);
  document.body.dataset.level = String(n);
  for (const m of [1, 2, 3]) {
    const button = $("level-" + m);
    if (button) button.setAttribute("aria-pressed", String(m === n));
  }
  if (workspace && setup && n < 3) {
    const toolbox = n === 1 ? setup.pictures.toolbox : setup.toolbox;
    workspace.updateToolbox(/** @type {import("blockly").utils.toolbox.ToolboxDefinition} */ (/** @type {unknown} */ (toolbox)));
    Blockly.svgResize(workspace);
  }
  $("level-says").hidden = n !== 1;
  if (n === 3) editor.refresh();
}

/**
 * What a picture block does, in words: its sentence with its number and its picture's name.
 * @param {import("blockly").Block} block
 */
export function meaningOf(block) {
  const said = meanings[block.type];
  if (!said) return "";
  const count = block.getField("N") ? String(block.getFieldValue("N")) : "";
  const what = block.getField("PICK") ? said.what[String(block.getFieldValue("PICK"))] || "" : "";
  const sentence = count === "1" && said.one ? said.one : said.words;
  return sentence.replace("{n}", count).replace("{what}", what);
}

/**
 * A block touched or pointed at (on the workspace or in the toolbox) says what it does.
 * @param {PointerEvent} event
 */
function tell(event) {
  if (!workspace) return;
  const group = /** @type {Element | null} */ (event.target instanceof Element ? event.target.closest("[data-id]") : null);
  if (!group) return;
  const id = group.getAttribute("data-id") || "";
  const flyout = workspace.getFlyout();
  const block = workspace.getBlockById(id) || (flyout ? flyout.getWorkspace().getBlockById(id) : null);
  if (!block) return;
  const sentence = meaningOf(block);
  if (!sentence) return;
  $("level-says").textContent = sentence;
  state.said = sentence;
  if (sentence === lastSaid && event.type === "pointerover") return;
  lastSaid = sentence;
  speak(sentence);
}

/**
 * Said aloud in the page's language (the browser's speech; nothing when it has none, or the
 * sound is off: the words are shown all the same).
 * @param {string} sentence
 */
export function speak(sentence) {
  if (typeof speechSynthesis === "undefined" || state.muted === "yes") return;
  speechSynthesis.cancel();
  const utterance = new SpeechSynthesisUtterance(sentence);
  utterance.lang = document.documentElement.lang || "en";
  utterance.rate = 0.9;
  speechSynthesis.speak(utterance);
}
