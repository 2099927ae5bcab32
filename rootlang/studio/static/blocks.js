// @ts-check
// The blocks pane: Blockly 13 (vendored, a UMD global) with rootlang's blocks, where the child
// put them (the layout kept beside the program), and the running blocks' glow.
import {install, attach} from "../../blocks/root_blocks.js";
import {$, state} from "./page.js";
import {editor} from "./editor.js";
import {drawOnlyInSight} from "./sight.js";

/** @typedef {import("blockly").WorkspaceSvg} WorkspaceSvg */
/** @typedef {import("blockly").BlockSvg} BlockSvg */
/** @typedef {import("./messages").BlocksSetup} BlocksSetup */
/** @typedef {import("./messages").LeftOutJson} LeftOutJson */
/**
 * The blocks as shown at one step of the page's undo history (undo.js).
 * @typedef {{top: {id: string, json: string}[], variables: {id: string, name: string, type: string}[],
 *   leftOut: [string, LeftOutJson][], byLine: [string, string][], notShown: object[],
 *   looseShown: boolean}} BlocksSnapshot
 */

/** The blocks (null: rootlang.blocks is not in this build, or Blockly is missing). */
/** @type {WorkspaceSvg | null} */
export let workspace = null;

/** True while the page itself loads blocks (not a child's edit). */
export let loadingBlocks = false;

/**
 * Where the child put the scripts, and the blocks the text leaves out: the program's sidecar,
 * `{top: {key: [x, y]}, loose: [Blockly's JSON of each block, with its x and y]}`.
 * @type {{top?: Record<string, number[]>, loose?: object[]}}
 */
export let layout = {};

/** The sidecar's loose blocks have been put back on the workspace since the program opened. */
let looseShown = false;
/**
 * The sidecar's loose blocks the page does not show: not put back yet (a program that opened as
 * text only), or that this studio can't make (a newer studio's block, a spoilt one). A layout
 * written keeps them as they were.
 * @type {object[]}
 */
let notShown = [];

/** @param {object} kept */
export function setLayout(kept) {
  layout = kept || {};
  looseShown = false;
  notShown = Array.isArray(layout.loose) ? [...layout.loose] : [];
}

/** The blocks have been shown since the program opened (`layout` is then the page's own). */
export const blocksShown = () => looseShown;

const SCRIPT_GAP_PX = 24;
// A finger, not a mouse: the blocks bigger, and + and − at least 44 px on the screen
const TOUCH = typeof matchMedia === "function" && matchMedia("(pointer: coarse)").matches;
const TOUCH_SCALE = 1.1, TOUCH_TARGET_PX = 44;

/**
 * The workspace, with the toolbox; `onChange` hears every change the child makes (with its
 * event group: the events of one drag, or of one field's edit, share one).
 * @param {BlocksSetup | null} blocks
 * @param {(group: string) => void} onChange
 */
export function setupBlocks(blocks, onChange) {
  if (!blocks || typeof Blockly === "undefined") {
    $("blocks").hidden = true; $("no-blocks").hidden = false; return;
  }
  install(Blockly, blocks.definitions, TOUCH ? Math.ceil(TOUCH_TARGET_PX / TOUCH_SCALE) : undefined);
  labelOnlyDrawnFields();
  // (Blockly's own JSON toolbox, as rootlang.blocks.toolbox() writes it)
  const toolbox = /** @type {import("blockly").utils.toolbox.ToolboxInfo} */ (/** @type {unknown} */ (blocks.toolbox));
  workspace = Blockly.inject("blocks", {
    toolbox: toolbox, media: "/static/vendor/blockly/media/", sounds: false,
    trashcan: true, zoom: {controls: true, wheel: true, startScale: TOUCH ? TOUCH_SCALE : 0.9},
    move: {scrollbars: true, drag: true, wheel: false},
  });
  attach(workspace, toolbox);
  drawOnlyInSight(workspace);
  // (the child's hand or keys on the blocks pane: the blocks still being made are made first)
  for (const kind of ["pointerdown", "keydown"]) $("blocks").addEventListener(kind, finishMaking, true);
  workspace.MAX_UNDO = 0;   // (the page keeps one undo history for both panes: undo.js)
  workspace.addChangeListener(event => {
    if (loadingBlocks || event.isUiEvent) return;
    fittedJson = null;   // (the child's edit: the blocks are not the text's any more)
    onChange(event.group || "");
  });
}

/**
 * A field not drawn yet has no label for a screen reader: Blockly finds that out by asking for
 * its element, which throws, and catching the error, for every field of every block it makes
 * (a 200-line program at 4x CPU: about a second of errors). Asked first whether it is drawn,
 * the answer is the same (it is labelled when it is drawn), without the error.
 */
function labelOnlyDrawnFields() {
  const field = Blockly.Field.prototype;
  const label = field.recomputeAriaContext, element = field.getFocusableElement;
  field.recomputeAriaContext = function () {
    if (this.getFocusableElement === element && !this.fieldGroup_) return false;
    return label.call(this);
  };
}

/**
 * Undo and redo in the blocks (Ctrl+Z, Ctrl+Y, Ctrl+Shift+Z, the workspace's menu) are the
 * page's (undo.js): one history for both panes, not Blockly's own.
 * @param {(redo: boolean) => void} step
 * @param {(redo: boolean) => boolean} can whether there is a step to take that way
 */
export function routeUndo(step, can) {
  if (!workspace) return;
  workspace.undo = redo => step(!!redo);
  workspace.redo = () => step(true);
  const menu = Blockly.ContextMenuRegistry.registry;
  for (const [id, redo] of /** @type {[string, boolean][]} */ ([["undoWorkspace", false], ["redoWorkspace", true]])) {
    const item = menu.getItem(id);
    if (!item || !("displayText" in item) || item.displayText === undefined) continue;
    menu.unregister(id);
    menu.register({...item, preconditionFn: () => can(redo) ? "enabled" : "disabled",
                   callback: () => step(redo)});
  }
}

/**
 * The blocks as the page shows them now, for the page's undo history: every top block (with
 * where it is, and its id), the variables, and which block is which of the text's lines.
 * Each block's JSON is a string; one equal to the same block's in `earlier` is that very
 * string, so the scripts a step leaves alone take no more memory.
 * @param {BlocksSnapshot | null} earlier
 * @returns {BlocksSnapshot | null}
 */
export function blocksSnapshot(earlier) {
  if (!workspace) return null;
  finishMaking();
  const before = new Map((earlier ? earlier.top : []).map(top => [top.id, top.json]));
  const top = workspace.getTopBlocks(false).map(block => {
    const json = JSON.stringify(Blockly.serialization.blocks.save(block, {addCoordinates: true, addNextBlocks: true}));
    return {id: block.id, json: before.get(block.id) === json ? /** @type {string} */ (before.get(block.id)) : json};
  });
  const variables = workspace.getVariableMap().getAllVariables().map(v => ({id: v.getId(), name: v.getName(), type: v.getType()}));
  return {top: top, variables: variables, leftOut: [...leftOut], byLine: [...byLine],
          notShown: [...notShown], looseShown: looseShown};
}

/**
 * The blocks as they were in `snapshot`: the top blocks that differ (or are gone, or new) are
 * made again as they were there (ids and places too); the ones that are as they were stay; all
 * in the snapshot's order.
 * Not an edit of the child's (no sync, no undo step).
 * @param {BlocksSnapshot} snapshot
 */
export function restoreBlocks(snapshot) {
  if (!workspace) return;
  const into = workspace;
  finishMaking();
  fittedJson = null;
  loadingBlocks = true;
  Blockly.Events.disable();
  try {
    const wanted = new Map(snapshot.top.map(top => [top.id, top.json]));
    for (const block of into.getTopBlocks(false)) {
      const json = JSON.stringify(Blockly.serialization.blocks.save(block, {addCoordinates: true, addNextBlocks: true}));
      if (wanted.get(block.id) === json) wanted.delete(block.id);   // (as it was: it stays)
      else block.dispose(false);
    }
    const variables = into.getVariableMap();
    for (const v of snapshot.variables) {
      if (!variables.getVariableById(v.id)) variables.createVariable(v.name, v.type, v.id);
    }
    for (const json of wanted.values()) Blockly.serialization.blocks.append(JSON.parse(json), into);
    inOrder(into, snapshot.top.map(top => into.getBlockById(top.id)));
  } finally {
    Blockly.Events.enable();
    loadingBlocks = false;
  }
  leftOut.clear(); byLine.clear(); lineOf.clear();
  for (const [id, left] of snapshot.leftOut) leftOut.set(id, left);
  for (const [id, live] of snapshot.byLine) { byLine.set(id, live); lineOf.set(live, id); }
  notShown = [...snapshot.notShown];
  looseShown = snapshot.looseShown;
}

// --- the workspace is the child's: the text's blocks are fitted in, never loaded over it -------
//
// The server's blocks for a text carry ids from the text's lines (L<line>, L<line>C<col>E<end>).
// The live blocks keep ids of their own for as long as they live, so an edit in the text that
// leaves a script as it was leaves that script's blocks (and the child's undo) alone. `byLine`
// says which live block each of the text's ids is now.

/** @type {Map<string, string>} the text's block id -> the live block's */
const byLine = new Map();
/** @type {Map<string, string>} the live block's id -> the text's */
const lineOf = new Map();
/**
 * The live top blocks the text leaves out (loose, or a script not finished), and why.
 * @type {Map<string, import("./messages").LeftOutJson>}
 */
export const leftOut = new Map();

/** @type {Map<string, string>} each variable's name by its id in the server's blocks */
const serverVariables = new Map();

/**
 * Blocks' JSON (Blockly's, or the server's) as text without the blocks' ids: what they are,
 * whichever blocks they are. (Parsed again, it makes new blocks with ids of their own.) A
 * variable is named, not numbered: the server's JSON says only its id (`{"id": "v:n"}`,
 * named in the workspace's list), Blockly's its id, name and type; made from the name, a block
 * takes the workspace's variable of that name (or makes it). Without its id, Blockly gave
 * every such block a new variable `i`, `j`...
 * @param {unknown} json
 */
function withoutIds(json) {
  return JSON.stringify(json, function (key, value) {
    if (key === "id") return undefined;
    // (a block has a type and no name; a variable either a name or no type)
    if (!value || typeof value !== "object" || !("id" in value) || ("type" in value && !("name" in value))) return value;
    const name = value.name ?? serverVariables.get(value.id) ?? workspace?.getVariableMap().getVariableById(value.id)?.getName();
    return name === undefined ? value : {name: name};
  });
}

/**
 * What a block tree is, ids and places aside (as Blockly itself saves it).
 * @param {import("blockly").Block} block
 */
function shape(block) {
  return withoutIds(Blockly.serialization.blocks.save(block, {addCoordinates: false, addNextBlocks: true}));
}

/**
 * The text's blocks loaded on a workspace that is never shown (to compare with the live ones).
 * Blockly labels each field for screen readers as it loads, and a field not on the page throws
 * and catches an error to say it can't be: left out here, the load is about ten times faster
 * (a 500-statement script: 0.9 s -> 0.1 s), and nothing on it is ever read out.
 * @param {object} json
 * @param {import("blockly").Workspace} ghost
 */
function loadUnseen(json, ghost) {
  const label = Blockly.Field.prototype.recomputeAriaContext;
  Blockly.Field.prototype.recomputeAriaContext = () => false;
  try {
    Blockly.serialization.workspaces.load(json, ghost);
  } finally {
    Blockly.Field.prototype.recomputeAriaContext = label;
  }
}

// --- the blocks made a few at a time, between the page's frames --------------------------------
//
// Making and drawing a block is Blockly's slowest work: a 200-line program's blocks took a
// school Chromebook seconds, the page frozen meanwhile. So a fit of the text's blocks is a list
// of steps (a generator: each step makes one block, with its expressions, or finishes the fit),
// run a slice at a time (SLICE_MS), one slice a frame: the page draws, takes keys and scrolls in
// between, and the blocks come from the top down, as they are read. The child's text is
// theirs meanwhile (a text round waits for the blocks being made: sync.js). Anything else that
// reads or changes the blocks finishes the making first, at once (`finishMaking`): the child
// touching the blocks pane (a drag, the toolbox, a key there), an undo, the blocks made into
// text. So no code, and no child, ever works on half-made blocks.

/** How long a slice of the making may take (ms): a task no longer than this is not a long one. */
const SLICE_MS = 50;

/**
 * A fit being made: its steps, and who waits for it (told whether it was all made: true, or
 * dropped for another program: false).
 * @typedef {{steps: Generator<void, void, void>, into: WorkspaceSvg, told: (made: boolean) => void,
 *   failed: (error: unknown) => void, done: Promise<boolean>}} Making
 */
/** @type {Making | null} */
let makingNow = null;

/** Whether blocks are still being made. */
export const making = () => makingNow !== null;

/** When the blocks being made are all made (true), or were dropped (false). */
export const blocksMade = () => makingNow ? makingNow.done.catch(() => false) : Promise.resolve(true);

/**
 * The text's blocks fitted into the live workspace: a script that is as it was stays (the
 * same blocks, where the child put it); a changed one takes the place of the one it replaces;
 * scripts the text no longer has go; blocks left out of the text are never touched. The first
 * slice is made at once (a statement typed is made then), the rest between the next frames.
 * @param {WorkspaceSvg} into
 * @param {object} json the text's workspace, from the server
 * @returns {Promise<boolean>} when it is all made (true), or dropped (false: another program)
 */
export function fitText(into, json) {
  finishMaking();   // (a fit on top of a half-made one: that one first)
  for (const variable of /** @type {any} */ (json).variables || []) serverVariables.set(variable.id, variable.name);
  /** @type {(made: boolean) => void} */
  let told = () => {};
  /** @type {(error: unknown) => void} */
  let failed = () => {};
  const done = new Promise((resolve, reject) => { told = resolve; failed = reject; });
  makingNow = {steps: fitted(into, json), into: into, told: told, failed: failed, done: done};
  state.blocksMaking = "yes";
  // (each text on a block measured once while they are made: Blockly asks the page's style
  // for each one else, and each asking works out the style of the whole page again)
  Blockly.utils.dom.startTextWidthCache();
  makeSome(SLICE_MS);
  return done;
}

/** The blocks still to make, all made now (before anything else reads or changes them). */
export function finishMaking() {
  if (makingNow) makeSome(Infinity);
}

/** The blocks still to make are not made (the program they were for is gone). */
function dropMaking() {
  const now = makingNow;
  if (!now) return;
  makingOver(now);
  now.steps.return();
  now.told(false);
}

/**
 * The making `now` is over.
 * @param {Making} now
 */
function makingOver(now) {
  if (makingNow !== now) return;
  makingNow = null;
  state.blocksMaking = "";
  Blockly.utils.dom.stopTextWidthCache();
}

/**
 * A slice of the making: a step, then more until `budget` ms have gone, drawn; the next slice
 * after the page's next frame.
 * @param {number} budget
 */
function makeSome(budget) {
  const now = makingNow;
  if (!now) return;
  const into = now.into;
  let finished = false;
  loadingBlocks = true;
  Blockly.Events.disable();
  into.setResizesEnabled(false);   // (once a slice, not once a block)
  /** @type {ReturnType<typeof drawingWhatChanged> | null} */
  let drawing = null;
  try {
    drawing = drawingWhatChanged(into);
    // (the budget from the end of the first step: a fit's first step compares the texts'
    // blocks, and a statement typed is made at once with it)
    finished = Boolean(now.steps.next().done);
    const end = performance.now() + budget;
    while (!finished && performance.now() < end) finished = Boolean(now.steps.next().done);
    drawing.draw();   // (drawn now)
  } catch (error) {   // (told to whoever waits: the text round says it)
    makingOver(now);
    now.failed(error);
    return;
  } finally {
    if (drawing) drawing.end();
    into.setResizesEnabled(true);
    Blockly.Events.enable();
    loadingBlocks = false;
  }
  if (finished) {
    makingOver(now);
    now.told(true);
    return;
  }
  // (a hidden tab draws no frames: its making goes on without them)
  const later = () => setTimeout(() => { if (makingNow === now) makeSome(SLICE_MS); }, 0);
  if (document.hidden) later(); else requestAnimationFrame(later);
}

/**
 * Blocks drawn again only where they changed, while a slice is made. Blockly draws again every
 * block above one asked to be drawn, as any of them might hold it and grow: each slice of a
 * long script drew the whole script above its new blocks again (a 200-line program: 2,900
 * drawings for its 393 blocks, most of the making's time). But a block keeps its shape whatever
 * hangs under it: only a block holding a changed stack in one of its inputs (`repeat`'s inside,
 * an expression's place) may grow. So a block is drawn when it was asked to be itself (made,
 * connected, changed) or holds such a stack; any other only puts its children in place.
 * Blocks waiting to be drawn from before are drawn first, the whole way; everything made is
 * drawn in the slice (`draw`), and Blockly's own drawing is back after (`end`).
 * @param {WorkspaceSvg} into
 */
function drawingWhatChanged(into) {
  drawQueued(into);
  const blockSvg = Blockly.BlockSvg.prototype;
  const {queueRender, renderEfficiently} = blockSvg;
  /** @type {Set<BlockSvg>} blocks asked to be drawn, not yet looked at */
  const asked = new Set();
  /** @type {Set<BlockSvg>} blocks to draw: asked, or holding one asked in an input */
  const changed = new Set();
  const lookAtAsked = () => {
    /** @type {Set<BlockSvg>} blocks whose holders above have been looked at */
    const climbed = new Set();
    for (const block of asked) {
      changed.add(block);
      for (let below = block, above = block.getParent(); above && !climbed.has(below);
        below = above, above = above.getParent()) {
        climbed.add(below);
        if (above.getNextBlock() !== below) changed.add(above);   // (held in an input)
      }
    }
    asked.clear();
  };
  blockSvg.queueRender = function () {
    asked.add(this);
    return queueRender.call(this);
  };
  blockSvg.renderEfficiently = function () {
    lookAtAsked();   // (all asked before the drawing began: Blockly draws a block's children first)
    if (!changed.delete(this)) this.tightenChildrenEfficiently();
    else renderEfficiently.call(this);
  };
  return {
    draw() {
      drawQueued(into);
    },
    end() {
      blockSvg.queueRender = queueRender;
      blockSvg.renderEfficiently = renderEfficiently;
    },
  };
}

/**
 * The blocks waiting to be drawn, drawn. Blockly then bumps loose blocks away from each
 * connection of every script drawn (two blocks that line up must be connected), and asks, for
 * each block of the script and each neighbour, which script it is in: a walk up to the script's
 * top each time (a 500-statement script: 250,000 steps, a tenth of a second on a Chromebook).
 * Nothing is connected or taken apart while blocks are drawn, so each block's top is looked up
 * once here; and a script with no other blocks within a connection's reach of it has nothing
 * to bump (its own blocks are never bumped from it), so it is not looked at block by block.
 * @param {WorkspaceSvg} into
 */
function drawQueued(into) {
  const block = Blockly.Block.prototype, blockSvg = Blockly.BlockSvg.prototype;
  const {getRootBlock} = block, {bumpNeighbours} = blockSvg;
  /** @type {Map<import("blockly").Block, import("blockly").Block>} */
  const tops = new Map();
  block.getRootBlock = function () {
    /** @type {import("blockly").Block[]} */
    const path = [];
    let at = this, top = tops.get(at);
    while (!top) {
      path.push(at);
      const parent = at.getParent();
      if (parent) top = tops.get(at = parent);
      else top = at;
    }
    for (const below of path) tops.set(below, top);
    return top;
  };
  blockSvg.bumpNeighbours = function () {
    if (this.getParent() || !aloneWhereItIs(this)) bumpNeighbours.call(this);
  };
  try {
    Blockly.renderManagement.triggerQueuedRenders(into);
  } finally {
    block.getRootBlock = getRootBlock;
    blockSvg.bumpNeighbours = bumpNeighbours;
  }
}

/**
 * Whether no other top block (with all it holds) comes within a connection's reach of the
 * script `top`.
 * @param {BlockSvg} top
 */
function aloneWhereItIs(top) {
  const reach = Blockly.config.snapRadius;
  const area = top.getBoundingRectangle();
  area.left -= reach; area.right += reach; area.top -= reach; area.bottom += reach;
  return top.workspace.getTopBlocks(false).every(other => other === top || !area.intersects(other.getBoundingRectangle()));
}

/**
 * The steps of a fit: the quick way (fitChanged) when it can tell, else fitAll.
 * @param {WorkspaceSvg} into
 * @param {object} json
 * @returns {Generator<void, void, void>}
 */
function* fitted(into, json) {
  try {
    if (yield* fitChanged(into, json)) return;
  } catch (error) {   // (a surprise: the blocks are compared as they are now, below)
    console.warn("a text edit fitted the long way", error);
  }
  yield* fitAll(into, json);
}

/** @type {Map<string, boolean>} whether each type of block is a statement (one under another) */
const statementTypes = new Map();
/** A workspace never shown, to ask what a type of block is. */
/** @type {import("blockly").Workspace | null} */
let askWorkspace = null;

/** @param {string} type */
function isStatement(type) {
  let known = statementTypes.get(type);
  if (known === undefined) {
    askWorkspace = askWorkspace || new Blockly.Workspace();
    const block = askWorkspace.newBlock(type);
    known = block.previousConnection !== null;
    block.dispose(false);
    statementTypes.set(type, known);
  }
  return known;
}

/**
 * Whether an input of a block of the server's JSON holds statements (a `repeat`'s inside), not
 * an expression.
 * @param {any} input
 */
const holdsStatements = input => Boolean(input.block && isStatement(input.block.type));

/**
 * A block of the server's JSON without the statements in it and under it (its expressions
 * stay): what one step makes.
 * @param {any} json
 */
function itself(json) {
  const rest = {...json};
  delete rest.next;
  if (rest.inputs) {
    rest.inputs = Object.fromEntries(Object.entries(rest.inputs).filter(([, input]) => !holdsStatements(input)));
  }
  return rest;
}

/**
 * Steps making the statements inside `made` (the live block made of `json` by itself), each
 * statement's own ones after it: top to bottom, as the text reads.
 * @param {WorkspaceSvg} into
 * @param {any} json
 * @param {BlockSvg} made
 * @returns {Generator<void, void, void>}
 */
function* madeInside(into, json, made) {
  for (const [name, input] of Object.entries(json.inputs || {})) {
    if (!holdsStatements(input)) continue;
    const slot = made.getInput(name);
    if (slot && slot.connection) yield* madeChain(into, jsonChain(input.block), slot.connection);
  }
}

/**
 * Steps making the server's JSON statements `blocks`, hanging one under another from `at`.
 * @param {WorkspaceSvg} into
 * @param {any[]} blocks
 * @param {import("blockly").Connection | null} at
 * @returns {Generator<void, void, void>}
 */
function* madeChain(into, blocks, at) {
  for (const json of blocks) {
    if (!at) return;   // (a statement always has one)
    const made = /** @type {BlockSvg} */ (Blockly.serialization.blocks.appendInternal(
      JSON.parse(withoutIds(itself(json))), into, {parentConnection: at}));
    yield;
    yield* madeInside(into, json, made);
    at = made.nextConnection;
  }
}

/**
 * fitText by comparing the text's blocks with every live block (the blocks' own serialization
 * on both sides: any live blocks, any text); the scripts made anew are made a step at a time,
 * the ones in sight first.
 * @param {WorkspaceSvg} into
 * @param {any} json
 * @returns {Generator<void, void, void>}
 */
function* fitAll(into, json) {
  fittedJson = null;
  const wantedJson = /** @type {any[]} */ (json.blocks ? json.blocks.blocks : []);
  /** @type {Map<string, BlockSvg[]>} */
  const live = new Map();
  for (const block of into.getTopBlocks(false)) {
    if (leftOut.has(block.id)) continue;
    const key = shape(block);
    live.set(key, [...(live.get(key) || []), block]);
  }
  // (the text's blocks loaded on a workspace never shown, to compare with the live ones: only
  // when there are live ones, not when a program opens)
  const ghost = live.size ? new Blockly.Workspace() : null;
  try {
    if (ghost) loadUnseen(json, ghost);
    const wanted = wantedJson.map(top => ghost ? ghost.getBlockById(top.id) : null);
    /** @type {(BlockSvg | null)[]} */
    const matched = wanted.map(block => {
      const same = block ? live.get(shape(block)) : undefined;
      return same && same.length ? /** @type {BlockSvg} */ (same.shift()) : null;
    });
    let freed = [...live.values()].flat();
    // A changed script is changed where it changed (a statement typed in a long script is one
    // block made, not the whole script made again): the first script left of its kind
    wanted.forEach((block, index) => {
      const mine = matched[index] || !block ? undefined : freed.find(old => old.type === block.type);
      if (mine && block && patched(mine, block)) {
        matched[index] = mine;
        freed = freed.filter(old => old !== mine);
      }
    });
    const places = freed.map(block => {
      const xy = block.getRelativeToSurfaceXY();
      return [xy.x, xy.y];
    });
    freed.forEach(block => block.dispose(false));
    // where each new script goes: where the child put it (the layout), else where the one it
    // replaces was, else under the others (once it is made)
    const toMake = wantedJson.map((top, index) => ({top: top, index: index,
      xy: matched[index] ? null : (layout.top || {})[layoutKey(top.id, index)] || places.shift() || null}))
      .filter(script => !matched[script.index]);
    const view = into.getMetricsManager().getViewMetrics(true);
    const inSight = (/** @type {number[] | null} */ xy) => xy !== null && xy[0] < view.left + view.width
      && xy[1] < view.top + view.height && xy[1] >= view.top - view.height;
    toMake.sort((a, b) => Number(inSight(b.xy)) - Number(inSight(a.xy)));   // (stable: in the text's order)
    /** @type {BlockSvg[]} */
    const unplaced = [];
    for (const {top, index, xy} of toMake) {
      const made = /** @type {BlockSvg} */ (Blockly.serialization.blocks.append(JSON.parse(withoutIds(itself(top))), into));
      matched[index] = made;
      if (xy) made.moveTo(new Blockly.utils.Coordinate(xy[0], xy[1]));
      else { unplaced.push(made); stackUnplaced(into, unplaced); }
      yield;
      yield* madeInside(into, top, made);
      if (top.next && top.next.block) yield* madeChain(into, jsonChain(top.next.block), made.nextConnection);
      if (!xy) stackUnplaced(into, unplaced);   // (as tall as it is now)
    }
    drawQueued(into);
    stackUnplaced(into, unplaced);
    byLine.clear(); lineOf.clear();
    if (wantedJson.map((top, i) => indexJson(top, matched[i])).every(Boolean)) fittedJson = json;
    glowAgain();
    markBreakpoints();
    inOrder(into, matched);
  } finally {
    if (ghost) ghost.dispose();
  }
}

// --- a text edit fitted by the text's blocks before and after it (fitChanged) -----------------
//
// While the live blocks are exactly the blocks of the text last fitted (`fittedJson`, the
// server's JSON: nothing but fitText has changed them since), a new text's blocks are compared
// with that JSON, not loaded and compared with every live block: only the statements that
// changed are made. Any surprise (a script more or less, a block not where `byLine` says) leaves
// it to fitAll, which compares with the live blocks themselves.

/** The server's JSON of the text the live blocks are now (null: unknown, or changed since). */
/** @type {any} */
let fittedJson = null;

/**
 * A block of the server's JSON as text to compare, ids aside, without the blocks under it
 * (and, at the top, its place): the block itself (`ownKey`), then each of its statement
 * stacks, block by block. Each block is written once: a script's key is made of its blocks'
 * keys, not written again at every level it nests in (a 500-statement script inside two
 * blocks was written out three times an edit).
 * @param {any} block
 * @returns {string}
 */
function jsonKey(block) {
  let key = wholeKeys.get(block);
  if (key === undefined) {
    // (an own key is JSON, with no line break in it: `name[`, `]` and the keys inside are
    // told apart from it by the line breaks before them)
    key = ownKey(block);
    for (const [name, input] of Object.entries(block.inputs || {})) {
      if (!holdsStatements(input)) continue;
      key += "\n" + name + "[" + jsonChain(input.block).map(inner => "\n" + jsonKey(inner)).join("") + "\n]";
    }
    wholeKeys.set(block, key);
  }
  return key;
}

/**
 * A block of the server's JSON itself as text to compare (its fields and expressions), ids
 * and place aside, without the statements in it and under it.
 * @param {any} block
 * @returns {string}
 */
function ownKey(block) {
  let key = ownKeys.get(block);
  if (key === undefined) {
    const rest = itself(block);
    delete rest.x; delete rest.y;
    key = withoutIds(rest);
    ownKeys.set(block, key);
  }
  return key;
}
/** jsonKey's and ownKey's answers (a text's JSON is compared again as the one before the
 * next edit's). */
/** @type {WeakMap<object, string>} */
const wholeKeys = new WeakMap(), ownKeys = new WeakMap();

/**
 * A statement and the ones under it, in the server's JSON.
 * @param {any} first
 * @returns {any[]}
 */
function jsonChain(first) {
  const blocks = [];
  for (let b = first; b; b = b.next && b.next.block) blocks.push(b);
  return blocks;
}

/**
 * @typedef {{slot: import("blockly").Connection, after: BlockSvg | null, gone: BlockSvg[], made: any[]}} ChainEdit
 */

/**
 * How the live block `live` (the text's `was`) becomes `now`: the edits of its statements'
 * stacks pushed on `edits`; false when it can't (the block itself changed, or is not `was`).
 * @param {BlockSvg} live
 * @param {any} was
 * @param {any} now
 * @param {ChainEdit[]} edits
 */
function planned(live, was, now, edits) {
  if (!live || byLine.get(was.id) !== live.id || live.type !== now.type) return false;
  if (jsonKey(was) === jsonKey(now)) return true;
  if (ownKey(was) !== ownKey(now)) return false;
  const statements = live.inputList.filter(input => input.type === Blockly.inputs.inputTypes.STATEMENT)
    .map(input => input.name);
  for (const name of statements) {
    const slot = /** @type {import("blockly").Connection} */ (/** @type {any} */ (live.getInput(name)).connection);
    /** @param {any} block */
    const inside = block => jsonChain(block.inputs && block.inputs[name] && block.inputs[name].block);
    if (!plannedChain(slot, inside(was), inside(now), edits)) return false;
  }
  return true;
}

/**
 * A stack's edit (as fittedChain does it): the same statements at its start and end stay;
 * between them each is changed where it can be, else they go and the new ones are made.
 * @param {import("blockly").Connection} slot
 * @param {any[]} was
 * @param {any[]} now
 * @param {ChainEdit[]} edits
 */
function plannedChain(slot, was, now, edits) {
  const live = /** @type {BlockSvg[]} */ (chain(slot.targetBlock()));
  if (live.length !== was.length || live.some((block, i) => byLine.get(was[i].id) !== block.id)) return false;
  let start = 0, end = 0;
  while (start < was.length && start < now.length && jsonKey(was[start]) === jsonKey(now[start])) start++;
  while (end < was.length - start && end < now.length - start
         && jsonKey(was[was.length - 1 - end]) === jsonKey(now[now.length - 1 - end])) end++;
  const gone = live.slice(start, live.length - end), made = now.slice(start, now.length - end);
  /** @type {ChainEdit[]} */
  const inside = [];
  if (gone.length === made.length && gone.every((block, i) => planned(block, was[start + i], made[i], inside))) {
    edits.push(...inside);
  } else if (gone.length || made.length) {
    edits.push({slot: slot, after: start ? live[start - 1] : null, gone: gone, made: made});
  }
  return true;
}

/**
 * Steps making the live blocks the text's `json` by its changes since `fittedJson`; done with
 * false (nothing changed) when that can't be told from the two.
 * @param {WorkspaceSvg} into
 * @param {any} json
 * @returns {Generator<void, boolean, void>}
 */
function* fitChanged(into, json) {
  const was = fittedJson;
  if (!was || !json.blocks || !was.blocks || json.workspaceComments || was.workspaceComments
      || JSON.stringify(json.variables || []) !== JSON.stringify(was.variables || [])) return false;
  const before = was.blocks.blocks, after = json.blocks.blocks;
  if (before.length !== after.length) return false;
  const tops = before.map((/** @type {any} */ top) => into.getBlockById(byLine.get(top.id) || ""));
  const shown = into.getTopBlocks(false).filter(block => !leftOut.has(block.id));
  if (shown.length !== tops.length || tops.some((/** @type {any} */ top) => !top || !shown.includes(top))) return false;
  /** @type {ChainEdit[]} */
  const edits = [];
  if (!before.every((/** @type {any} */ top, /** @type {number} */ i) => planned(tops[i], top, after[i], edits))) return false;
  byLine.clear(); lineOf.clear();
  fittedJson = null;
  for (const edit of edits) edit.gone.forEach(block => block.dispose(true));   // (the blocks under it move up)
  for (const edit of edits) yield* madeChain(into, edit.made, edit.after ? edit.after.nextConnection : edit.slot);
  if (edits.length) drawQueued(into);
  if (!after.every((/** @type {any} */ top, /** @type {number} */ i) => indexJson(top, tops[i]))) {
    byLine.clear(); lineOf.clear();
    return false;   // (fitAll compares with the live blocks: they are right, or made right)
  }
  fittedJson = json;
  glowAgain();
  markBreakpoints();
  return true;
}

/**
 * Which live block each of the text's blocks in `json` is, block by block (false: the two
 * differ somewhere).
 * @param {any} json
 * @param {import("blockly").Block | null} live
 */
function indexJson(json, live) {
  for (let want = json, block = live; want; want = want.next && want.next.block, block = block.getNextBlock()) {
    if (!block || block.type !== want.type) return false;
    byLine.set(want.id, block.id); lineOf.set(block.id, want.id);
    for (const [name, input] of Object.entries(want.inputs || {})) {
      const child = input.block || input.shadow, slot = block.getInput(name);
      if (child && !indexJson(child, slot && slot.connection ? slot.connection.targetBlock() : null)) return false;
    }
    if (block.inputList.some(input => input.connection && input.connection.targetBlock()
                             && !(want.inputs && want.inputs[input.name]))) return false;
    if (!(want.next && want.next.block) && block.getNextBlock()) return false;
  }
  return true;
}

/**
 * These top blocks last in the workspace's order, in this order: the blocks' text lists the
 * scripts in the workspace's order, so a script made anew (by a text edit, an undo) keeps its
 * place in the text at the next block edit.
 * @param {WorkspaceSvg} into
 * @param {(import("blockly").Block | null)[]} blocks
 */
function inOrder(into, blocks) {
  for (const block of blocks) {
    if (block) { into.removeTopBlock(block); into.addTopBlock(block); }
  }
}

/**
 * A block as Blockly saves it, without its id(s) and its next blocks; `inside`: with the
 * blocks in its statement inputs (else without them: the block itself and its expressions).
 * @param {import("blockly").Block} block
 * @param {boolean} inside
 */
function one(block, inside) {
  const saved = /** @type {{inputs?: Record<string, unknown>}} */ (
    Blockly.serialization.blocks.save(block, {addCoordinates: false, addNextBlocks: false}) || {});
  if (!inside && saved.inputs) {
    for (const input of block.inputList) {
      if (input.type === Blockly.inputs.inputTypes.STATEMENT) delete saved.inputs[input.name];
    }
  }
  return withoutIds(saved);
}

/**
 * A new live block like `want` (and its blocks inside), without its next ones, made already
 * hanging from `after` (the blocks under it go under the new one). Made loose first, it would
 * lie at the workspace's corner, drawn at once: a connection of it near one of the script's
 * there makes Blockly bump the child's whole script away by a random few pixels.
 * @param {import("blockly").Block} want
 * @param {import("blockly").Connection} after
 */
function madeLike(want, after) {
  return /** @type {BlockSvg} */ (Blockly.serialization.blocks.appendInternal(
    JSON.parse(one(want, true)), after.getSourceBlock().workspace, {parentConnection: after}));
}

/**
 * The live block changed into `want` where they differ: the same block itself (its fields and
 * expressions), then each of its statement inputs' blocks fitted in turn (`fittedChain`). False
 * (and nothing changed) when the block itself differs: the caller makes it anew.
 * @param {BlockSvg} live
 * @param {import("blockly").Block} want
 */
function patched(live, want) {
  if (live.type !== want.type || one(live, false) !== one(want, false)) return false;
  for (const input of want.inputList) {
    const slot = live.getInput(input.name);
    if (input.type !== Blockly.inputs.inputTypes.STATEMENT || !slot || !slot.connection || !input.connection) continue;
    const liveChain = /** @type {BlockSvg[]} */ (chain(slot.connection.targetBlock()));
    fittedChain(slot.connection, liveChain, chain(input.connection.targetBlock()));
  }
  return true;
}

/**
 * @template {import("blockly").Block} B
 * @param {B | null} first
 * @returns {B[]} it and the blocks under it
 */
function chain(first) {
  const blocks = [];
  for (let b = first; b; b = /** @type {B | null} */ (b.getNextBlock())) blocks.push(b);
  return blocks;
}

/**
 * A live stack of statements fitted to the text's: the same ones at its start and its end stay;
 * between them, each live block is changed into the text's one where it can be (as many on both
 * sides), else those blocks go and the text's are made in their place.
 * @param {import("blockly").Connection} slot where the live stack hangs
 * @param {BlockSvg[]} live
 * @param {import("blockly").Block[]} want
 */
function fittedChain(slot, live, want) {
  const whole = /** @param {import("blockly").Block} b */ b => one(b, true);
  let start = 0, end = 0;
  while (start < live.length && start < want.length && whole(live[start]) === whole(want[start])) start++;
  while (end < live.length - start && end < want.length - start
         && whole(live[live.length - 1 - end]) === whole(want[want.length - 1 - end])) end++;
  const oldOnes = live.slice(start, live.length - end), newOnes = want.slice(start, want.length - end);
  if (oldOnes.length === newOnes.length && oldOnes.every((b, i) => patched(b, newOnes[i]))) return;
  for (const b of oldOnes) {
    b.dispose(true);   // (the blocks under it move up)
  }
  let after = start ? live[start - 1].nextConnection : slot;
  for (const w of newOnes) {
    if (!after) break;   // (a statement always has one)
    after = madeLike(w, after).nextConnection;
  }
  // (drawn now, as a block appended is: the scripts after it are placed by their heights)
  drawQueued(/** @type {WorkspaceSvg} */ (slot.getSourceBlock().workspace));
}

/**
 * After the blocks changed the text: which live block each of the text's ids is now.
 * @param {WorkspaceSvg} live
 * @param {object} json the new text's workspace
 */
export function indexText(live, json) {
  finishMaking();
  Blockly.Events.disable();
  const ghost = new Blockly.Workspace();
  try {
    loadUnseen(json, ghost);
    const wanted = ghost.getTopBlocks(false);
    /** @type {Map<string, BlockSvg[]>} */
    const byShape = new Map();
    for (const block of live.getTopBlocks(false)) {
      if (leftOut.has(block.id)) continue;
      const key = shape(block);
      byShape.set(key, [...(byShape.get(key) || []), block]);
    }
    const matched = wanted.map(block => (byShape.get(shape(block)) || []).shift() || null);
    const others = [...byShape.values()].flat().length;   // (live scripts the text has not)
    fittedJson = indexBlocks(wanted, matched) && others === 0 ? json : null;
  } finally {
    ghost.dispose();
    Blockly.Events.enable();
  }
}

/**
 * @param {import("blockly").Block[]} wanted the text's top blocks
 * @param {(import("blockly").Block | null)[]} matched the live ones, in the same order
 * @returns {boolean} whether each of the text's blocks has its live one
 */
function indexBlocks(wanted, matched) {
  byLine.clear(); lineOf.clear();
  let whole = true;
  wanted.forEach((block, i) => {
    const twin = matched[i];
    const ours = block.getDescendants(true), theirs = twin ? twin.getDescendants(true) : [];
    if (!twin || ours.length !== theirs.length) { whole = false; return; }
    ours.forEach((b, j) => { byLine.set(b.id, theirs[j].id); lineOf.set(theirs[j].id, b.id); });
  });
  glowAgain();
  markBreakpoints();
  return whole;
}

/** The text's block ids (L<line>...) that are on the workspace now. */
export const textIds = () => [...byLine.keys()];

/**
 * The live block for one of the text's ids (L<line>...): the one the text's line is now.
 * @param {string} id
 */
export function liveBlock(id) {
  const found = byLine.get(id);
  return found && workspace ? workspace.getBlockById(found) : null;
}

/**
 * The text's line a block is (0: none, or a block that is a part of a line).
 * @param {string} id a live block's id
 */
export function lineOfBlock(id) {
  const found = /^L(\d+)$/.exec(lineOf.get(id) || "");
  return found ? Number(found[1]) : 0;
}

// Top-level block positions: kept in the program's sidecar, keyed by the script's order and its
// header line (where the child put them; the others are stacked under them).
/**
 * @param {string} id the text's id of a top block
 * @param {number} index
 */
function layoutKey(id, index) {
  const line = /^L(\d+)$/.exec(id);
  const header = line ? editor.getLine(Number(line[1]) - 1) || "" : id;
  return index + ":" + header.trim();
}

/**
 * Where the child put the scripts, and the blocks left out of the text (kept whole: the
 * sidecar is the only place they are written).
 */
export function rememberLayout() {
  if (!workspace || making()) return;   // (the blocks being made are put where it says)
  /** @type {Record<string, number[]>} */
  const top = {};
  /** @type {object[]} */
  const loose = [...notShown];
  let index = 0;
  for (const block of workspace.getTopBlocks(false)) {
    if (leftOut.has(block.id)) {
      const saved = Blockly.serialization.blocks.save(block, {addCoordinates: true, addNextBlocks: true});
      if (saved) loose.push(saved);
    } else {
      const xy = block.getRelativeToSurfaceXY();
      top[layoutKey(lineOf.get(block.id) || "", index++)] = [Math.round(xy.x), Math.round(xy.y)];
    }
  }
  layout = {top: top, loose: loose};
}

/**
 * No blocks (a program opens): not an edit of the child's, so no sync and no undo step.
 * @param {WorkspaceSvg} ws
 */
export function clearBlocks(ws) {
  dropMaking();
  loadingBlocks = true;
  Blockly.Events.disable();
  try {
    ws.clear();
  } finally {
    Blockly.Events.enable();
    loadingBlocks = false;
  }
  leftOut.clear(); byLine.clear(); lineOf.clear(); glowing.clear();
  fittedJson = null;
  looseShown = false;
  notShown = Array.isArray(layout.loose) ? [...layout.loose] : [];
  ws.clearUndo();
}

/**
 * The blocks left out of the text that the sidecar kept, back on the workspace (once: later
 * calls put nothing back, so blocks coming back from text only are never doubled); how many.
 * @param {WorkspaceSvg} into
 */
export function restoreLoose(into) {
  if (looseShown) return 0;
  looseShown = true;
  const kept = notShown;
  notShown = [];
  loadingBlocks = true;
  Blockly.Events.disable();
  try {
    for (const json of kept) {
      const before = new Set(into.getTopBlocks(false));
      try {
        const block = Blockly.serialization.blocks.append(/** @type {any} */ (json), into);
        leftOut.set(block.id, {top: block.id, block: "", diagnostic: /** @type {any} */ (null)});
      } catch (error) {   // never half made on the workspace: kept in the layout as it was
        into.getTopBlocks(false).filter(block => !before.has(block)).forEach(block => block.dispose(false));
        notShown.push(json);
        console.warn("a kept block could not be put back", error);
      }
    }
  } finally {
    Blockly.Events.enable();
    loadingBlocks = false;
  }
  return kept.length;
}

/**
 * Scripts nobody has placed yet go under all the others, one under another, as tall as they
 * really are drawn.
 * @param {WorkspaceSvg} into
 * @param {BlockSvg[]} unplaced
 */
function stackUnplaced(into, unplaced) {
  let bottom = 0;
  for (const block of into.getTopBlocks(false)) {
    if (unplaced.includes(block)) continue;
    bottom = Math.max(bottom, block.getRelativeToSurfaceXY().y + block.getHeightWidth().height);
  }
  let y = bottom > 0 ? bottom + SCRIPT_GAP_PX : SCRIPT_GAP_PX;
  unplaced.forEach(block => {
    block.moveTo(new Blockly.utils.Coordinate(SCRIPT_GAP_PX, y));
    y += block.getHeightWidth().height + SCRIPT_GAP_PX;
  });
}

/**
 * The blocks the text leaves out: greyed, and why on the very block (in the page's words).
 * @param {import("./messages").LeftOutJson[]} found
 * @param {(left: import("./messages").LeftOutJson) => {top: string, here: string}} say
 */
export function markLeftOut(found, say) {
  fittedJson = null;   // (indexText, next, tells which blocks are the text's)
  leftOut.clear();
  for (const left of found) leftOut.set(left.top, left);
  showLeftOut(say);
}

/** @type {(left: import("./messages").LeftOutJson) => {top: string, here: string}} */
let lastSay = () => ({top: "", here: ""});
/** @type {Set<BlockSvg>} the blocks shown greyed (the tops of the blocks left out) */
let greyed = new Set();

/**
 * (Again, after the warnings were cleared.)
 * @param {(left: import("./messages").LeftOutJson) => {top: string, here: string}} [say]
 */
export function showLeftOut(say) {
  if (say) lastSay = say;
  if (!workspace) return;
  // (a block put back in a script is grey no more)
  /** @type {Set<BlockSvg>} */
  const greyedNow = new Set();
  for (const id of leftOut.keys()) {
    const block = workspace.getBlockById(id);
    if (block) greyedNow.add(block);
  }
  for (const block of greyed) {
    if (!greyedNow.has(block) && !block.isDisposed()) block.getSvgRoot().classList.remove("root-left-out");
  }
  for (const block of greyedNow) block.getSvgRoot().classList.add("root-left-out");
  greyed = greyedNow;
  for (const left of leftOut.values()) {
    const top = workspace.getBlockById(left.top);
    if (!top || !left.diagnostic) continue;
    const words = lastSay(left);
    top.setWarningText(words.top, "root-left-out");
    const here = left.block && left.block !== left.top ? workspace.getBlockById(left.block) : null;
    if (here && words.here) here.setWarningText(words.here, "root-left-out");
  }
}

// A mistake shows on the expression it is about (L<line>C<col>E<end>), else on its line's block.
/**
 * @param {number} line
 * @param {number} column
 */
export function blockAt(line, column) {
  const prefix = "L" + line + "C" + column + "E";
  const expression = [...byLine.keys()].find(id => id.startsWith(prefix));
  return liveBlock(expression || "L" + line);
}

/** @type {Record<"running" | "paused", number[]>} the lines whose blocks glow, by who lit them */
const glowLines = {running: [], paused: []};
/** @type {Set<BlockSvg>} the live blocks that glow now */
const glowing = new Set();
const GLOW = "root-running";

/**
 * The blocks of the lines running now (runs.js) and of those a pause or a moment gone back to
 * shows (debugger.js) glow: each says its own lines, and one's never puts out the other's.
 * Only the blocks whose glow changes are touched, each on its own outline (Blockly's own
 * highlight marks the block's group, which holds every block under it in its script: the page
 * would work out the style of all of them again). After the text changed the blocks, the
 * lines' new blocks glow.
 * @param {number[]} lines
 * @param {"running" | "paused"} by
 */
export function glow(lines, by) {
  glowLines[by] = lines;
  glowAgain();
}

/** The glowing lines' blocks glow (again, after the blocks changed). */
function glowAgain() {
  if (!workspace) return;
  const lines = [...glowLines.running, ...glowLines.paused];
  const lit = new Set(lines.map(line => liveBlock("L" + line)).filter(block => block !== null));
  for (const block of glowing) if (!lit.has(block)) block.pathObject.svgPath.classList.remove(GLOW);
  for (const block of lit) if (!glowing.has(block)) block.pathObject.svgPath.classList.add(GLOW);
  glowing.clear();
  lit.forEach(block => glowing.add(block));
}

/** @type {() => number[]} the lines with a breakpoint now (debugger.js tells: they move with edits) */
let breakpointsNow = () => [];
/** @type {() => string} a breakpoint's words, on its block's dot */
let breakpointWords = () => "";
/** @type {Map<BlockSvg, SVGElement>} the live blocks with a breakpoint, and their dot */
const marked = new Map();
const MARK = "root-breakpoint";

/**
 * @param {() => number[]} lines where the breakpoints are (their blocks are marked)
 * @param {() => string} title what a block's mark says
 */
export function breakpointsFrom(lines, title) {
  breakpointsNow = lines; breakpointWords = title;
}

/**
 * A breakpoint shows on its block too, as in the text's margin: a red dot at the block's top
 * left and a red outline (the block's own, as a running block glows). After the text changed
 * the blocks, the lines' new blocks are marked.
 */
export function markBreakpoints() {
  if (!workspace) return;
  const lines = breakpointsNow();
  const now = new Set(lines.map(line => liveBlock("L" + line)).filter(block => block !== null));
  for (const [block, dot] of marked) {
    if (now.has(block)) continue;
    dot.remove();
    block.pathObject?.svgPath?.classList.remove(MARK);   // (a block deleted since has none)
    marked.delete(block);
  }
  for (const block of now) {
    if (marked.has(block)) continue;
    const dot = document.createElementNS("http://www.w3.org/2000/svg", "circle");
    dot.setAttribute("class", "root-breakpoint-dot");
    dot.setAttribute("r", "7"); dot.setAttribute("cx", "0"); dot.setAttribute("cy", "0");
    const words = document.createElementNS("http://www.w3.org/2000/svg", "title");
    words.textContent = breakpointWords();
    dot.append(words);
    block.getSvgRoot().append(dot);
    block.pathObject.svgPath.classList.add(MARK);
    marked.set(block, dot);
  }
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
