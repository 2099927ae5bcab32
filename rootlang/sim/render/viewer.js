// @ts-check
// Drawing a run's scene on a canvas (world mm, y up): the one viewer the HTML replay page
// (rootlang/sim/render/replay.js, inlined by html.py) and the studio's stage (static/stage.js,
// fed live) both use. The data is rootlang.sim.render.html's (page_data.d.ts).

/** @typedef {import("./page_data").Shape} Shape */
/** @typedef {import("./page_data").PathShape} PathShape */

/**
 * One stroke of ink to draw: its first `count` points, then `end` (a point part-way to the next).
 * @typedef {{erase: boolean, color: string, w: number, p: number[], count: number,
 *            end?: number[] | null}} InkStroke
 */

/**
 * What to draw: the scene (`view` = left, bottom, right, top), the path the robot went (a line;
 * `widthPx` draws it that many screen pixels wide whatever the zoom), the ink, the robot at
 * `pose` with its light ring (shape `led`) in `ledColor` (null: off), and the overlay.
 * @typedef {{view: number[], background: string, below: Shape[],
 *            path: {shape: PathShape, widthPx?: number} | null, ink: InkStroke[],
 *            robot: Shape[], led: number, ledColor: string | null,
 *            pose: {x: number, y: number, h: number}, overlay: Shape[]}} Picture
 */

/**
 * A shape, in world mm.
 * @param {CanvasRenderingContext2D} ctx
 * @param {Shape} s
 */
export function paint(ctx, s) {
  if (s.k === "label") {
    ctx.globalAlpha = 1;
    ctx.save(); ctx.translate(s.at[0], s.at[1]); ctx.scale(1, -1);
    ctx.font = s.size + "px sans-serif"; ctx.fillStyle = s.color;
    ctx.textAlign = s.anchor === "middle" ? "center" : s.anchor === "end" ? "right" : "left";
    ctx.fillText(s.text, 0, 0); ctx.restore(); return;
  }
  ctx.globalAlpha = s.o === undefined ? 1 : s.o;
  ctx.beginPath();
  if (s.k === "circle") ctx.arc(s.c[0], s.c[1], s.r, 0, 2 * Math.PI);
  else trace(ctx, s.p, s.p.length / 2);
  if (s.k === "polygon") ctx.closePath();
  if (s.f && s.k !== "line") { ctx.fillStyle = s.f; ctx.fill(); }
  if (s.s) { ctx.strokeStyle = s.s; ctx.lineWidth = s.w; ctx.stroke(); }
  ctx.globalAlpha = 1;
}

/**
 * A polyline's first `count` points (flat x, y), then `end` if given.
 * @param {CanvasRenderingContext2D} ctx
 * @param {number[]} p
 * @param {number} count
 * @param {number[] | null} [end]
 */
export function trace(ctx, p, count, end) {
  ctx.moveTo(p[0], p[1]);
  for (let i = 1; i < count; i++) ctx.lineTo(p[2 * i], p[2 * i + 1]);
  if (end) ctx.lineTo(end[0], end[1]);
}

/**
 * The canvas sized to its box (in device pixels) and the transform that fits `view` in it.
 * @param {HTMLCanvasElement} canvas
 * @param {number[]} view
 * @param {{width: number, height: number} | null} [box] the canvas's box on the page (CSS px)
 *   when the caller knows it (a ResizeObserver told it): else asked for, a layout if one is due
 * @returns {DOMMatrix2DInit & {a: number, d: number, e: number, f: number}}
 */
export function fit(canvas, view, box) {
  const r = box || canvas.getBoundingClientRect(), dpr = window.devicePixelRatio || 1;
  sized(canvas, Math.max(1, Math.round(r.width * dpr)), Math.max(1, Math.round(r.height * dpr)));
  const v = view;
  const k = Math.min(canvas.width / (v[2] - v[0]), canvas.height / (v[3] - v[1]));
  const dx = (canvas.width - (v[2] - v[0]) * k) / 2, dy = (canvas.height - (v[3] - v[1]) * k) / 2;
  return {a: k, b: 0, c: 0, d: -k, e: dx - v[0] * k, f: dy + v[3] * k};  // world mm, y up
}

/**
 * A canvas this many pixels (set only when it differs: setting it, even to the same, makes
 * the canvas anew).
 * @param {HTMLCanvasElement} canvas
 * @param {number} width
 * @param {number} height
 */
function sized(canvas, width, height) {
  if (canvas.width !== width) canvas.width = width;
  if (canvas.height !== height) canvas.height = height;
}

/**
 * Draws `picture` on `canvas` (sized to its box); returns the transform from world mm to the
 * canvas's pixels.
 * @param {HTMLCanvasElement} canvas
 * @param {Picture} picture
 * @param {{width: number, height: number} | null} [box] the canvas's box, if known (see `fit`)
 */
export function draw(canvas, picture, box) {
  const transform = fit(canvas, picture.view, box);
  const ctx = /** @type {CanvasRenderingContext2D} */ (canvas.getContext("2d"));
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  ctx.fillStyle = picture.background; ctx.fillRect(0, 0, canvas.width, canvas.height);
  ctx.setTransform(transform);
  ctx.lineCap = "round"; ctx.lineJoin = "round";
  picture.below.forEach(s => paint(ctx, s));
  if (picture.path && picture.path.shape.p.length > 2) {   // the path under the ink
    const {shape, widthPx} = picture.path;
    paint(ctx, widthPx ? Object.assign({}, shape, {w: widthPx / transform.a}) : shape);
  }
  const ink = inkLayer(canvas, transform, picture.ink);
  ctx.save(); ctx.setTransform(1, 0, 0, 1, 0, 0); ctx.drawImage(ink, 0, 0); ctx.restore();
  const p = picture.pose, ledColor = picture.ledColor;
  ctx.save(); ctx.translate(p.x, p.y); ctx.rotate(p.h * Math.PI / 180);
  picture.robot.forEach((s, i) => paint(ctx, i === picture.led && ledColor !== null && s.k !== "label"
    ? Object.assign({}, s, {s: ledColor}) : s));
  ctx.restore();
  picture.overlay.forEach(s => paint(ctx, s));
  return transform;
}

/** Each canvas's ink layer, kept from one picture to the next (not a new canvas for each). */
const inkLayers = /** @type {WeakMap<HTMLCanvasElement, HTMLCanvasElement>} */ (new WeakMap());

/**
 * Marker ink on a layer of its own: an eraser clears the ink under it (not the floor).
 * @param {HTMLCanvasElement} canvas
 * @param {DOMMatrix2DInit} transform
 * @param {InkStroke[]} strokes
 */
function inkLayer(canvas, transform, strokes) {
  let layer = inkLayers.get(canvas);
  if (!layer) inkLayers.set(canvas, layer = document.createElement("canvas"));
  sized(layer, canvas.width, canvas.height);
  const ink = /** @type {CanvasRenderingContext2D} */ (layer.getContext("2d"));
  ink.setTransform(1, 0, 0, 1, 0, 0);
  ink.globalCompositeOperation = "source-over";
  ink.clearRect(0, 0, layer.width, layer.height);
  ink.setTransform(transform); ink.lineCap = "round"; ink.lineJoin = "round";
  for (const s of strokes) {
    if (s.count < 1) continue;
    ink.globalCompositeOperation = s.erase ? "destination-out" : "source-over";
    ink.beginPath(); trace(ink, s.p, s.count, s.end);
    if (s.count === 1 && !s.end) ink.lineTo(s.p[0], s.p[1] + 0.01);   // a dot
    ink.strokeStyle = s.color; ink.lineWidth = s.w; ink.stroke();
  }
  return layer;
}
