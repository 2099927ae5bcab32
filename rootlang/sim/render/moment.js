// @ts-check
// A run at one moment, from its page data (rootlang.sim.render.html): where the robot was and
// how much ink there was by then. The HTML replay page (replay.js) and the studio's time slider
// (static/timeslider.js) both go back and forth in a run with it.

/** @typedef {import("./page_data").Frames} Frames */
/** @typedef {import("./page_data").PathShape} PathShape */
/** @typedef {import("./page_data").EraseInk} EraseInk */
/** @typedef {import("./viewer.js").InkStroke} InkStroke */

/**
 * The number of entries with time <= t (binary search).
 * @param {number[]} times in order
 * @param {number} t
 */
export function index(times, t) {
  let lo = 0, hi = times.length;
  while (lo < hi) { const mid = (lo + hi) >> 1; if (times[mid] <= t) lo = mid + 1; else hi = mid; }
  return lo;
}

/**
 * How much of a timed polyline exists at time t: its first `n` points, then `end`.
 * @param {number[]} p
 * @param {number[]} times
 * @param {number} t
 * @returns {{n: number, end: number[] | null}}
 */
export function partial(p, times, t) {
  const n = index(times, t);
  if (n === 0 || n === times.length) return {n: n, end: null};
  const f = (t - times[n - 1]) / (times[n] - times[n - 1]);
  return {n: n, end: [p[2*n-2] + (p[2*n] - p[2*n-2]) * f, p[2*n-1] + (p[2*n+1] - p[2*n-1]) * f]};
}

/**
 * Where the robot was at time t (s), between the frames about it; `led` its light's index.
 * @param {Frames} frames
 * @param {number} t
 */
export function poseAt(frames, t) {
  const last = frames.t.length - 1;
  const n = Math.max(1, Math.min(last, index(frames.t, t)));
  const i = n - 1, j = Math.min(n, last);
  const span = frames.t[j] - frames.t[i];
  const f = span > 0 ? Math.min(1, Math.max(0, (t - frames.t[i]) / span)) : 1;
  const turn = ((frames.h[j] - frames.h[i]) % 360 + 540) % 360 - 180;
  return {x: frames.x[i] + (frames.x[j] - frames.x[i]) * f,
          y: frames.y[i] + (frames.y[j] - frames.y[i]) * f,
          h: frames.h[i] + turn * f, led: frames.led[t >= frames.t[j] ? j : i]};
}

/**
 * The ink drawn by time t (ink is in time order), and how many points of it.
 * @param {(PathShape | EraseInk)[]} ink
 * @param {number} t
 */
export function inkAt(ink, t) {
  /** @type {InkStroke[]} */
  const strokes = [];
  let points = 0;
  for (const s of ink) {
    const part = partial(s.p, s.t || [], t);
    if (part.n === 0) break;
    points += part.n;
    const color = s.k === "erase" ? "#000" : s.s || "#000";
    strokes.push({erase: s.k === "erase", color: color, w: s.w, p: s.p, count: part.n, end: part.end});
  }
  return {strokes, points};
}
