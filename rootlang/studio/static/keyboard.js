// @ts-check
// The page from the keyboard alone. Tab in the text indents, as a programmer expects; Escape then
// Tab (or Shift+Tab) leaves the text, as CodeMirror 6 and MakeCode do: no keyboard trap (WCAG
// 2.1.2). A hint under the text says so while the text has the focus.
import {$, words} from "./page.js";
import {editor} from "./editor.js";

// After Escape, until the next key, Tab and Shift+Tab are the browser's (false: CodeMirror lets
// the key be, and no keymap under this one sees it)
/** @type {import("codemirror").KeyMap} */
const LEAVING = {Tab: false, "Shift-Tab": false};

/** @param {boolean} on Escape pressed in the text: Tab now leaves it */
function showEscaped(on) {
  editor.removeKeyMap(LEAVING);
  if (on) editor.addKeyMap(LEAVING);
  $("text-hint").textContent = words(on ? "text_hint_escaped" : "text_hint");
  $("text-hint").classList.toggle("escaped", on);
}

export function setupKeyboard() {
  editor.addKeyMap({
    Tab: cm => cm.execCommand("insertSoftTab"),
    "Shift-Tab": cm => cm.execCommand("indentLess"),
    Esc: cm => { cm.execCommand("singleSelection"); showEscaped(true); },
  });
  editor.on("keydown", (_cm, event) => {
    const key = /** @type {KeyboardEvent} */ (event).key;
    if (key !== "Escape" && key !== "Tab" && key !== "Shift") showEscaped(false);
  });
  editor.on("focus", () => { showEscaped(false); $("text-hint").hidden = false; });
  editor.on("blur", () => { showEscaped(false); $("text-hint").hidden = true; });
  editor.getInputField().setAttribute("aria-describedby", "text-hint");
}

/**
 * The focus after a button that goes away (disabled) under it: to the one that takes its place
 * (Run's to Stop, Stop's to Run), so a keyboard's place on the page is never lost.
 * @param {HTMLButtonElement} from
 * @param {HTMLButtonElement} to
 * @param {() => void} change disables `from`, enables `to`
 */
export function handOver(from, to, change) {
  const had = document.activeElement === from;
  change();
  if (had && !to.disabled) to.focus();
}
