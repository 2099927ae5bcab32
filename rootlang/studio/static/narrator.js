// @ts-check
// The stage in words, for a screen reader (WCAG 4.1.3): what the robot does, in the child's words
// and the page's language ("bumped on the left", "said “hi”", "the light turned green"), through
// one polite live region (announce.js: what happens meanwhile is said together, at most one
// announcement in 1.5 s).
import {$, words} from "./page.js";
import {ANNOUNCE_GAP_MS, announcer} from "../../sim/render/announce.js";

/** @typedef {import("./messages").FrameMessage} FrameMessage */

const STILL_AFTER_FRAMES = 25;   // a second without moving (frames come 25 a second): it stopped

/** @param {string} hex "#rrggbb" */
const rgb = hex => [1, 3, 5].map(i => parseInt(hex.slice(i, i + 2), 16));

/** @type {[string, number[]][]} the language's colours a light shows, and their red, green, blue */
let lightColours = [];

/**
 * Learn the language's colours a light shows (the setup's `light_colours`: rootlang/colors.py).
 * @param {Record<string, string>} colours name -> "#rrggbb"
 */
export function knowLightColours(colours) {
  lightColours = Object.entries(colours).map(([name, hex]) => [name, rgb(hex)]);
}

/**
 * The name of the language's colour nearest "#rrggbb" (a colour of its own: `light green`).
 * @param {string} hex
 */
function colourName(hex) {
  const [r, g, b] = rgb(hex);
  const distance = (/** @type {number[]} */ [r2, g2, b2]) => (r - r2) ** 2 + (g - g2) ** 2 + (b - b2) ** 2;
  let nearest = "white", least = Infinity;
  for (const [name, colour] of lightColours) {
    if (distance(colour) < least) [nearest, least] = [name, distance(colour)];
  }
  return nearest;
}

/** What the stage says of a run, frame by frame. */
export class Narrator {
  constructor() {
    this.say = announcer($("heard"), ANNOUNCE_GAP_MS);
    /** @type {{x: number, y: number, h: number} | null} */
    this.pose = null;
    /** @type {string | null | undefined} the light's colour (null: off; undefined: not known yet) */
    this.light = undefined;
    this.motion = "still";
    this.stillFrames = 0;
  }

  /** A run starts. */
  reset() { this.pose = null; this.light = undefined; this.motion = "still"; this.stillFrames = 0; }

  /** @param {FrameMessage} frame */
  frame(frame) {
    frame.said.forEach(text => this.say(words("heard_said", {text: text})));
    frame.happened.forEach(happening => this.felt(happening));
    const p = frame.pose;
    if (!p) return;
    const light = p.led_mode === "off" || p.led === "#000000" ? null : p.led;  // (black: nothing lit)
    if (this.light !== undefined && light !== this.light) {
      this.say(light ? words("heard_light", {colour: words("colour_" + colourName(light))}) : words("heard_light_off"),
               "light");
    }
    this.light = light;
    const before = this.pose;
    this.pose = {x: p.x, y: p.y, h: p.h};
    if (!before) return;
    const moved = Math.hypot(p.x - before.x, p.y - before.y) > 0.5, turned = Math.abs(p.h - before.h) > 0.5;
    const motion = moved ? "moving" : turned ? "turning" : "still";
    if (motion !== "still") {
      this.stillFrames = 0;
      if (motion !== this.motion) this.say(words("heard_" + motion), "motion");
      this.motion = motion;
    } else if (this.motion !== "still" && ++this.stillFrames >= STILL_AFTER_FRAMES) {
      this.motion = "still";
      this.say(words("heard_still"), "motion");
    }
    const label = words("stage_label", {
      x: (p.x / 10).toFixed(0), y: (p.y / 10).toFixed(0), h: (((p.h % 360) + 360) % 360).toFixed(0)});
    const canvas = $("canvas");   // (changed only when the words change: 25 frames a second)
    if (canvas.getAttribute("aria-label") !== label) canvas.setAttribute("aria-label", label);
  }

  /**
   * What the robot felt, as its replay's timeline names it ("bumper left", "touch front left,
   * back right", "nose button", "cliff"): the simulator's walls and the stage's buttons alike.
   * @param {string} happening
   */
  felt(happening) {
    const [what, ...rest] = happening.split(" "), detail = rest.join(" ");
    if (what === "bumper" && ["left", "right", "both"].includes(detail)) {
      this.say(words("heard_bump_" + detail));
    } else if (what === "touch" && detail !== "released") {
      // (the simulator's names, as the stage's buttons have them: "back left" says back_left)
      const where = detail.split(", ").map(part => words(part.replace(" ", "_")));
      this.say(words("heard_touch", {where: where.join(", ")}));
    } else if (happening === "nose button") {
      this.say(words("heard_nose"));
    } else if (happening === "cliff") {
      this.say(words("heard_cliff"));
    }
  }
}
