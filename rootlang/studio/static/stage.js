// @ts-check
// The stage: the robot on its world, drawn by the replay page's viewer (the same scene shapes,
// from rootlang.sim.render's page data: world mm, y up), but fed live from a run's frames.
import {draw} from "../../sim/render/viewer.js";
import {poseAt, inkAt, partial} from "../../sim/render/moment.js";

/** @typedef {import("./messages").StageData} StageData */
/** @typedef {import("./messages").FrameMessage} FrameMessage */
/** @typedef {{kind: string, color: string, w: number, p: number[]}} LiveStroke */

const PATH_STYLE = {k: /** @type {"line"} */ ("line"), s: "#2563eb", f: null, w: 0, o: 0.45};
const PATH_WIDTH_PX = 2;
const MARGIN_MM = 250;   // the robot nearer the edge than this widens the view
const BUBBLE_ABOVE_MM = 120;   // the speech bubble's tail points this far above the robot's centre

export class Stage {
  /**
   * @param {HTMLCanvasElement} canvas
   * @param {HTMLElement} bubble what the robot says, drawn by it
   */
  constructor(canvas, bubble) {
    this.canvas = canvas;
    this.bubble = bubble;
    /** @type {StageData | null} the page data: view, below, robot outline, LED ring index */
    this.data = null;
    /** @type {LiveStroke[]} live ink */
    this.strokes = [];
    /** @type {{x: number, y: number, h: number, led: string | null}} */
    this.pose = {x: 0, y: 0, h: 0, led: null};
    /** @type {number[]} where the robot went (faint, under the ink) */
    this.path = [];
    /** @type {{width: number, height: number} | null} the canvas's box on the page (CSS px) */
    this.box = null;
    /** @type {{width: number, height: number} | null} the speech bubble's size (CSS px) */
    this.bubbleSize = null;
    /** The page's next frame draws the stage (requestAnimationFrame's id; 0: none asked for). */
    this.drawing = 0;
    /** @type {{data: StageData, t: number} | null} a moment of a run shown (the time slider's), not the live stage */
    this.moment = null;
    /** @type {{a: number, d: number, e: number, f: number} | null} world mm -> canvas pixels, as last drawn */
    this.transform = null;
    // (the box as laid out, told: a draw never asks the page for its layout)
    new ResizeObserver(entries => {
      const box = entries[entries.length - 1].contentRect;
      this.box = {width: box.width, height: box.height};
      this.draw();
    }).observe(canvas);
  }

  /**
   * A new run (or a finished one): the scene's shapes; `final` also carries its ink and path.
   * @param {StageData} data
   * @param {boolean} final
   */
  show(data, final) {
    this.data = data;
    const f = data.frames, last = f.t.length - 1, led = data.leds[f.led[last]];
    this.pose = {x: f.x[last], y: f.y[last], h: f.h[last], led: led.mode === "off" ? null : led.color};
    if (final) {
      this.strokes = data.ink.map(s => ({kind: s.k === "erase" ? "erase" : "marker",
                                         color: (s.k !== "erase" && s.s) || "#000", w: s.w, p: s.p}));
      this.path = data.path ? data.path.p.slice() : [];
    } else {
      this.strokes = []; this.path = [this.pose.x, this.pose.y];
    }
    this.draw();
  }

  /**
   * A frame of the run: drawn at the page's next frame, once however many frames came meanwhile,
   * and not at all if nothing moved, lit or was drawn.
   * @param {FrameMessage} f
   */
  frame(f) {
    for (const s of f.ink) {
      const stroke = this.strokes[s.i] || (this.strokes[s.i] = {kind: s.kind, color: s.color || "#000", w: s.w, p: []});
      stroke.p.splice(2 * s.from, Infinity, ...s.p);
    }
    const p = f.pose;
    if (!p || !this.data) return;    // on a robot: no pose to show
    const led = p.led_mode === "off" ? null : p.led, was = this.pose;
    if (!f.ink.length && p.x === was.x && p.y === was.y && p.h === was.h && led === was.led) return;
    this.pose = {x: p.x, y: p.y, h: p.h, led: led};
    const n = this.path.length;
    if (n < 2 || this.path[n - 2] !== p.x || this.path[n - 1] !== p.y) this.path.push(p.x, p.y);
    this.grow(this.data, p.x, p.y);
    this.drawSoon();
  }

  /** The stage changed: drawn at the page's next frame (however many changes came till then). */
  drawSoon() {
    if (!this.drawing) this.drawing = requestAnimationFrame(() => { this.drawing = 0; this.draw(); });
  }

  /**
   * The robot left the view: widen it (kept square-ish by the fit).
   * @param {StageData} data
   * @param {number} x
   * @param {number} y
   */
  grow(data, x, y) {
    const v = data.view;
    if (x - MARGIN_MM < v[0] || x + MARGIN_MM > v[2] || y - MARGIN_MM < v[1] || y + MARGIN_MM > v[3]) {
      data.view = [Math.min(v[0], x - MARGIN_MM), Math.min(v[1], y - MARGIN_MM),
                   Math.max(v[2], x + MARGIN_MM), Math.max(v[3], y + MARGIN_MM)];
    }
  }

  /**
   * The robot says something: a bubble by it (until it says something else, or a run starts).
   * @param {string} text
   */
  speak(text) {
    this.bubble.textContent = text;
    this.bubble.hidden = !text;
    this.bubbleSize = null;
    this.drawSoon();
  }

  /**
   * The bubble above the robot, wherever the robot is drawn (kept inside the stage).
   * @param {{a: number, d: number, e: number, f: number}} transform world mm -> canvas pixels
   */
  placeBubble(transform) {
    if (this.bubble.hidden) return;
    const dpr = window.devicePixelRatio || 1, p = this.pose;
    const x = (transform.a * p.x + transform.e) / dpr;
    const y = (transform.d * (p.y + BUBBLE_ABOVE_MM) + transform.f) / dpr;
    const box = this.box || {width: this.canvas.clientWidth, height: this.canvas.clientHeight};
    // (its size measured once for what it says: not a layout asked for at every frame)
    const size = this.bubbleSize || (this.bubbleSize = {width: this.bubble.offsetWidth, height: this.bubble.offsetHeight});
    const half = size.width / 2;
    this.bubble.style.left = Math.max(0, Math.min(box.width - 2 * half, x - half)) + "px";
    this.bubble.style.top = Math.max(0, Math.min(box.height - size.height, y - size.height)) + "px";
    const state = document.getElementById("state");
    if (state) { state.dataset.bubbleX = x.toFixed(0); state.dataset.bubbleY = y.toFixed(0); }
  }

  /**
   * A moment of a run (`t`: seconds of its recording) drawn instead of the live stage, as the
   * replay page draws it; null: the live stage again.
   * @param {{data: StageData, t: number} | null} moment
   */
  showMoment(moment) {
    this.moment = moment;
    this.bubble.hidden = moment !== null || !this.bubble.textContent;
    this.draw();
  }

  /** The stage drawn now (a draw the next frame would make is not needed then). */
  draw() {
    if (this.drawing) { cancelAnimationFrame(this.drawing); this.drawing = 0; }
    if (this.moment) { this.drawMoment(this.moment.data, this.moment.t); return; }
    const data = this.data;
    if (!data) return;
    const p = this.pose;
    const transform = draw(this.canvas, {
      view: data.view, background: data.background, below: data.below,
      path: {shape: Object.assign({}, PATH_STYLE, {p: this.path}), widthPx: PATH_WIDTH_PX * (window.devicePixelRatio || 1)},
      ink: this.strokes.filter(s => s && s.p.length >= 2).map(s => ({
        erase: s.kind === "erase" || s.kind === "eraser", color: s.color, w: s.w, p: s.p, count: s.p.length / 2,
      })),
      robot: data.robot, led: data.led, ledColor: p.led, pose: p, overlay: [],
    }, this.box);
    this.transform = transform;
    this.placeBubble(transform);
    this.tell(p, String(this.strokes.filter(s => s && s.p.length > 2).length));
  }

  /**
   * @param {StageData} data
   * @param {number} t seconds of the run's recording
   */
  drawMoment(data, t) {
    const p = poseAt(data.frames, t), led = data.leds[p.led];
    const ink = inkAt(data.ink, t);
    let path = null;
    if (data.path) {
      const part = partial(data.path.p, data.path.t || [], t);
      const points = data.path.p.slice(0, 2 * part.n).concat(part.end || []);
      if (part.n > 0) path = {shape: Object.assign({}, PATH_STYLE, {p: points}), widthPx: PATH_WIDTH_PX * (window.devicePixelRatio || 1)};
    }
    this.transform = draw(this.canvas, {
      view: data.view, background: data.background, below: data.below, path: path, ink: ink.strokes,
      robot: data.robot, led: data.led, ledColor: led.mode === "off" ? null : led.color, pose: p, overlay: [],
    }, this.box);
    this.tell(p, String(ink.strokes.filter(s => s.count > 1).length));
  }

  /**
   * What the stage shows, for the tests (#state).
   * @param {{x: number, y: number, h: number}} p
   * @param {string} strokes
   */
  tell(p, strokes) {
    const state = document.getElementById("state");
    if (state) {
      state.dataset.x = p.x.toFixed(1); state.dataset.y = p.y.toFixed(1);
      state.dataset.h = (((p.h % 360) + 360) % 360).toFixed(1);
      state.dataset.strokes = strokes;
    }
  }
}
