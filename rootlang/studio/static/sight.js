// @ts-check
// Blocks out of sight are not drawn. Each change of the page (a running line lit, a watched
// value, the status) makes Chromium sort the drawing of every block on the workspace into
// layers again; a block's next block is drawn inside it, so a long script is a drawing nested
// hundreds deep, and with 500 statements that sorting was most of a slow Chromebook's time
// while a run went on (benchmarks/studio_frames.py --trace). A block far from the view is
// hidden (CSS `visibility`, so it keeps its place and size, and Blockly measures it as ever);
// each block says for itself whether it is seen, as its next block sits inside it.

/** @typedef {import("blockly").WorkspaceSvg} WorkspaceSvg */
/** @typedef {import("blockly").BlockSvg} BlockSvg */

const SEEN = "root-seen", UNSEEN = "root-unseen";
/** Blocks this much of the view's height above or below it are drawn too (a scroll shows them
 * drawn already; the next look comes at the page's next frame). */
const MARGIN = 0.5;

/** @type {WeakMap<BlockSvg, boolean>} whether each block was seen at the last look */
const seen = new WeakMap();

/**
 * From now on, only the blocks in or near the view are drawn: looked at again at the page's
 * next frame after any change of the drawing's blocks or places (blocks made, moved, changed,
 * by the child or by the page with Blockly's events off; a scroll or a zoom moves the whole
 * drawing) or of its size. A block taken up to be dragged is drawn whole, with all it holds.
 * @param {WorkspaceSvg} workspace
 */
export function drawOnlyInSight(workspace) {
  let queued = false;
  const soon = () => {
    if (queued) return;
    queued = true;
    requestAnimationFrame(() => { queued = false; look(workspace); });
  };
  new MutationObserver(soon).observe(workspace.getCanvas(), {
    childList: true, subtree: true, attributes: true, attributeFilter: ["transform"],
  });
  new ResizeObserver(soon).observe(workspace.getParentSvg());
  workspace.addChangeListener(event => {
    if (!(event instanceof Blockly.Events.BlockDrag && event.isStart)) return;
    workspace.getBlockById(event.blockId || "")?.getDescendants(false).forEach(block => mark(block, true));
  });
}

/** @param {WorkspaceSvg} workspace */
function look(workspace) {
  if (workspace.isDragging()) return;   // (the block dragged stays drawn whole until dropped)
  const view = workspace.getMetricsManager().getViewMetrics(true);
  const top = view.top - view.height * MARGIN, bottom = view.top + view.height * (1 + MARGIN);
  const left = view.left - view.width * MARGIN, right = view.left + view.width * (1 + MARGIN);
  for (const first of workspace.getTopBlocks(false)) {
    const {x, y} = first.getRelativeToSurfaceXY();
    /** @type {[BlockSvg, number, number][]} each block, with where it is on the workspace */
    const todo = [[first, x, y]];
    for (let next = todo.pop(); next; next = todo.pop()) {   // (a list: scripts nest deep)
      const [block, bx, by] = next;
      const below = block.getNextBlock();   // (its height holds the blocks below it too)
      const height = below ? below.relativeCoords.y : block.height;
      mark(block, by < bottom && by + height > top && bx < right && bx + block.width > left);
      for (const child of block.getChildren(false)) {
        todo.push([child, bx + child.relativeCoords.x, by + child.relativeCoords.y]);
      }
    }
  }
}

/**
 * @param {BlockSvg} block
 * @param {boolean} inSight
 */
function mark(block, inSight) {
  if (seen.get(block) === inSight) return;
  seen.set(block, inSight);
  const root = block.getSvgRoot();
  root.classList.toggle(SEEN, inSight);
  root.classList.toggle(UNSEEN, !inSight);
}
