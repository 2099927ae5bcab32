// @ts-check
// The HTML replay page's script: plays a run back (the data in <script id="run">, written by
// rootlang/sim/render/html.py), drawn by the viewer the studio's stage uses too.
import {draw} from "./viewer.js";
import {index, partial, poseAt, inkAt} from "./moment.js";
import {ANNOUNCE_GAP_MS, announcer} from "./announce.js";

/** @typedef {import("./page_data").PageData} PageData */

/** @param {string} id */
const $ = id => /** @type {HTMLElement} */ (document.getElementById(id));

// The run: a scene (the same shapes the SVG and PNG draw), the robot's frames and the events.
const run = /** @type {PageData} */ (JSON.parse($("run").textContent || "{}"));
// the page's own words, in the page's language (html.py: the studio's words, the catalogue's)
const words = /** @type {{play: string, pause: string, line: string}} */ (
  JSON.parse($("words").textContent || "{}"));
// every text from the run goes in as textContent: whatever a student wrote, it stays text
$("title").textContent = run.title || run.subtitle;
$("subtitle").textContent = run.title ? run.subtitle : "";
const frames = run.frames;           // columns: t (s), x, y (mm), h (deg), led (colour index)
const last = frames.t.length - 1;
const duration = frames.t[last];
const canvas = /** @type {HTMLCanvasElement} */ ($("canvas"));
const slider = /** @type {HTMLInputElement} */ ($("slider"));
const playButton = $("play");
const startButton = $("start");
const speedSelect = /** @type {HTMLSelectElement} */ ($("speed"));
const state = $("state").dataset;    // read by the tests
let now = 0, playing = false, lastTick = 0;

/** The ink drawn by `now`, and how many points of it. */
const inkNow = () => inkAt(run.ink, now);
/** @param {number} t */
const pose = t => poseAt(frames, t);

function show() {
  const ink = inkNow();
  const p = pose(now), led = run.leds[p.led];
  const lit = led.mode !== "off" && (led.mode !== "blink" || Math.floor(now * 2) % 2 === 0);
  let path = null;
  if (run.path) {                      // the path under the ink, as in the still pictures
    const part = partial(run.path.p, run.path.t || [], now);
    const points = run.path.p.slice(0, 2 * part.n).concat(part.end || []);
    if (part.n > 0) path = {shape: Object.assign({}, run.path, {p: points})};
  }
  const transform = draw(canvas, {
    view: run.view, background: run.background, below: run.below, path: path, ink: ink.strokes,
    robot: run.robot, led: run.led, ledColor: lit ? led.color : null, pose: p, overlay: run.overlay,
  });
  showEvents();
  $("clock").textContent = now.toFixed(1) + " s / " + duration.toFixed(1) + " s";
  slider.value = String(now);
  state.t = now.toFixed(3); state.x = p.x.toFixed(1); state.y = p.y.toFixed(1);
  state.h = (((p.h % 360) + 360) % 360).toFixed(1); state.ink = String(ink.points);
  state.playing = String(playing);
  state.led = lit ? led.color : "off";
  if (probe) {                         // the colour drawn at a world point (#probe=x,y)
    const px = probe[0] * transform.a + transform.e, py = probe[1] * transform.d + transform.f;
    const ctx = /** @type {CanvasRenderingContext2D} */ (canvas.getContext("2d"));
    state.probe = ctx.getImageData(Math.floor(px), Math.floor(py), 1, 1).data.slice(0, 3).join(",");
  }
}

// --- events and speech ---
const list = $("events");
run.events.forEach(e => {             // [time s, text, kind, program line or 0]
  const li = document.createElement("li");
  const time = document.createElement("time"); time.textContent = e[0].toFixed(1) + " s";
  const where = document.createElement("span"); where.className = "where";
  where.textContent = e[3] ? words.line.replace("{line}", String(e[3])) : "";
  const what = document.createElement("span"); what.className = "what"; what.textContent = e[1];
  li.dataset.kind = e[2]; li.append(time, where, what); list.append(li);
});
const eventTimes = run.events.map(e => e[0]);
// the events a playing replay passes, said to a screen reader (at most once in 1.5 s, together)
const say = announcer($("heard"), ANNOUNCE_GAP_MS);
let shownEvent = -2;
function showEvents() {
  const current = index(eventTimes, now) - 1;
  if (current === shownEvent) return;
  if (shownEvent !== -2) {   // (not as the page opens: as it plays, or is moved to a moment)
    const from = current > shownEvent ? shownEvent + 1 : current;
    run.events.slice(Math.max(0, from), current + 1).forEach(e => say(e[1]));
  }
  shownEvent = current;
  [...list.children].forEach((li, i) => {
    li.className = (/** @type {HTMLElement} */ (li)).dataset.kind
      + (i < current ? " past" : i === current ? " now" : "");
  });
  if (current >= 0) list.children[current].scrollIntoView({block: "nearest"});
  const said = run.said.filter(s => s[0] <= now).pop();
  $("speech").textContent = said ? "“" + said[1] + "”" : "";   // (no emoji: many computers have no emoji font)
  state.event = String(current);
}

// --- playing ---
function tick() {
  if (!playing) return;
  const t = performance.now();
  now = Math.min(duration, now + (t - lastTick) / 1000 * Number(speedSelect.value));
  lastTick = t;
  if (now >= duration) setPlaying(false);
  show();
  if (playing) setTimeout(tick, 30);   // timers (not animation frames) also run in headless tests
}
/** @param {boolean} on */
function setPlaying(on) {
  if (on && now >= duration) now = 0;
  playing = on; playButton.textContent = on ? words.pause : words.play;
  if (on) startButton.hidden = true;
  if (on) { lastTick = performance.now(); setTimeout(tick, 30); }
}
playButton.addEventListener("click", () => { setPlaying(!playing); show(); });
startButton.addEventListener("click", () => { setPlaying(true); show(); });
slider.max = String(duration);
slider.addEventListener("input", () => { now = Number(slider.value); show(); });
window.addEventListener("resize", show);

// #t=3.5 shows that moment, #speed=10&play plays from the start (handy in links); the tests also
// read #state and ask for #probe=x,y (the colour at a world point)
const options = new URLSearchParams(location.hash.slice(1));
const probe = options.has("probe") ? (options.get("probe") || "").split(",").map(Number) : null;
const speed = options.get("speed");
if (speed !== null) {
  if (![...speedSelect.options].some(o => o.value === speed)) speedSelect.add(new Option(speed + "×", speed));
  speedSelect.value = speed;
}
if (options.has("t")) { now = Math.min(duration, Number(options.get("t"))); startButton.hidden = true; }
show();
if (options.has("play")) setPlaying(true);
