// @ts-check
// A narrow screen (a tablet, 1024 px wide or less): the blocks and the text take turns in one
// place, chosen with two tabs, so each gets the room it needs; the stage stays beside them (or
// below them, upright). On a wide screen the tabs are not shown and all three panes are side by
// side (studio.css decides which by the screen's width).
import {$, state} from "./page.js";
import {editor} from "./editor.js";
import {workspace} from "./blocks.js";

const TABS = ["tab-blocks", "tab-text"];

/**
 * Shows the blocks or the text (on a narrow screen; a wide one shows both anyway).
 * @param {string} pane "blocks" or "text"
 */
export function showPane(pane) {
  /** @type {HTMLElement} */ ($("pane-tabs").parentElement).dataset.pane = pane;
  for (const id of TABS) {
    const tab = $(id), chosen = tab.dataset.pane === pane;
    tab.setAttribute("aria-selected", String(chosen));
    tab.tabIndex = chosen ? 0 : -1;
  }
  if (pane === "text") editor.refresh();
  else if (workspace) Blockly.svgResize(workspace);
  state.pane = pane;
}

export function setupPanes() {
  for (const id of TABS) {
    $(id).addEventListener("click", () => showPane($(id).dataset.pane || "blocks"));
    // (the keyboard, as for any tabs: an arrow key goes to the other one)
    $(id).addEventListener("keydown", /** @param {KeyboardEvent} event */ event => {
      if (event.key !== "ArrowLeft" && event.key !== "ArrowRight") return;
      const other = $(TABS[1 - TABS.indexOf(id)]);
      other.focus();
      showPane(other.dataset.pane || "blocks");
    });
  }
  state.pane = "blocks";
}
