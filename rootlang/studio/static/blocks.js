// @ts-check
// The blocks pane: Blockly 13 (vendored, a UMD global) with rootlang's blocks, where the child
// put them (the layout kept beside the program), and the running blocks' glow.
import {install, attach} from "../../blocks/root_blocks.js";
import {$} from "./page.js";
import {editor} from "./editor.js";

/** @typedef {import("blockly").WorkspaceSvg} WorkspaceSvg */
/** @typedef {import("blockly").BlockSvg} BlockSvg */
/** @typedef {import("./messages").BlocksSetup} BlocksSetup */

/** The blocks (null: rootlang.blocks is not in this build, or Blockly is missing). */
/** @type {WorkspaceSvg | null} */
export let workspace = null;

/** True while the page itself loads blocks (not a child's edit). */
export let loadingBlocks = false;

/** Where the child put the scripts: the program's sidecar, `{top: {key: [x, y]}}`. */
/** @type {{top?: Record<string, number[]>}} */
export let layout = {};

/** @param {object} kept */
export function setLayout(kept) { layout = kept || {}; }

const SCRIPT_GAP_PX = 24;

/**
 * The workspace, with the toolbox; `onChange` hears every change the child makes.
 * @param {BlocksSetup | null} blocks
 * @param {() => void} onChange
 */
export function setupBlocks(blocks, onChange) {
  if (!blocks || typeof Blockly === "undefined") {
    $("blocks").hidden = true; $("no-blocks").hidden = false; return;
  }
  install(Blockly, blocks.definitions);
  // (Blockly's own JSON toolbox, as rootlang.blocks.toolbox() writes it)
  const toolbox = /** @type {import("blockly").utils.toolbox.ToolboxInfo} */ (/** @type {unknown} */ (blocks.toolbox));
  workspace = Blockly.inject("blocks", {
    toolbox: toolbox, media: "/static/vendor/blockly/media/", sounds: false,
    trashcan: true, zoom: {controls: true, wheel: true, startScale: 0.9},
    move: {scrollbars: true, drag: true, wheel: false},
  });
  attach(workspace, toolbox);
  workspace.addChangeListener(event => {
    if (loadingBlocks || event.isUiEvent) return;
    onChange();
  });
}

/**
 * Blocks from the server's conversion, placed where the layout says.
 * @param {WorkspaceSvg} into
 * @param {object} json
 */
export function loadWorkspace(into, json) {
  loadingBlocks = true;
  try {
    Blockly.Events.disable();
    Blockly.serialization.workspaces.load(json, into);
    placeBlocks(into);
  } finally {
    Blockly.Events.enable();
    loadingBlocks = false;
  }
}

// Top-level block positions: kept in the program's sidecar, keyed by the script's order and its
// header line (where the child put them; placeBlocks stacks the others under them).
/**
 * @param {BlockSvg} block
 * @param {number} index
 */
function layoutKey(block, index) {
  const line = /^L(\d+)$/.exec(block.id);
  const header = line ? editor.getLine(Number(line[1]) - 1) || "" : block.type;
  return index + ":" + header.trim();
}

export function rememberLayout() {
  if (!workspace) return;
  /** @type {Record<string, number[]>} */
  const top = {};
  workspace.getTopBlocks(false).forEach((block, index) => {
    const xy = block.getRelativeToSurfaceXY();
    top[layoutKey(block, index)] = [Math.round(xy.x), Math.round(xy.y)];
  });
  layout = {top: top};
}

/** @param {WorkspaceSvg} into */
function placeBlocks(into) {
  const top = (layout && layout.top) || {};
  /** @type {BlockSvg[]} */
  const unplaced = [];
  let bottom = 0;
  into.getTopBlocks(false).forEach((block, index) => {
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

// Block ids come from source positions: L<line> for a statement or header, L<line>C<col>E<end>
// for an expression; a mistake shows on the expression it is about, else on its line's block.
/**
 * @param {number} line
 * @param {number} column
 */
export function blockAt(line, column) {
  if (!workspace) return null;
  const prefix = "L" + line + "C" + column + "E";
  const expression = workspace.getAllBlocks(false).find(block => block.id.startsWith(prefix));
  return expression || workspace.getBlockById("L" + line);
}

/**
 * The running lines' blocks glow.
 * @param {number[]} lines
 */
export function glow(lines) {
  if (!workspace) return;
  workspace.highlightBlock(null);
  for (const line of lines) workspace.highlightBlock("L" + line, true);
}

/**
 * Blockly's own words (its built-in blocks and menus) in the page's language, before the
 * blocks: the file the server names (English's too).
 * @param {string} address
 * @returns {Promise<void>}
 */
export function loadBlocklyWords(address) {
  if (typeof Blockly === "undefined") return Promise.resolve();
  return new Promise(resolve => {
    const script = document.createElement("script");
    script.src = address;
    script.onload = script.onerror = () => resolve();
    document.head.appendChild(script);
  });
}
