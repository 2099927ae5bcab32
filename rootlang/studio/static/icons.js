// @ts-check
// Signs drawn as inline SVG, never as emoji: many school computers (and headless Chromium) have
// no emoji font, and there an emoji is an empty box. A sign is drawn in the text's colour, and
// the words beside it say what it means (a screen reader reads the words: the sign is hidden).
const SVG = "http://www.w3.org/2000/svg";

/**
 * A speaker: with sound waves when the sound is on, crossed out when it is off.
 * @param {boolean} on
 * @returns {SVGSVGElement}
 */
export function speaker(on) {
  const sign = document.createElementNS(SVG, "svg");
  sign.setAttribute("viewBox", "0 0 24 24");
  sign.setAttribute("class", "sign");
  sign.setAttribute("aria-hidden", "true");
  sign.setAttribute("focusable", "false");
  sign.dataset.sign = on ? "sound-on" : "sound-off";
  const body = document.createElementNS(SVG, "path");
  body.setAttribute("d", "M3 9h4l5-4v14l-5-4H3z");
  body.setAttribute("fill", "currentColor");
  const lines = document.createElementNS(SVG, "path");
  lines.setAttribute("d", on ? "M15.5 8.5a5 5 0 0 1 0 7M18.5 5.5a9 9 0 0 1 0 13" : "M16 9l6 6M22 9l-6 6");
  lines.setAttribute("fill", "none");
  lines.setAttribute("stroke", "currentColor");
  lines.setAttribute("stroke-width", "2");
  lines.setAttribute("stroke-linecap", "round");
  sign.append(body, lines);
  return sign;
}

/**
 * A drawing (a picture at Level 1), from its shapes: [tag, attributes] each.
 * @param {[string, Record<string, string>][]} shapes
 * @returns {SVGSVGElement}
 */
function drawing(shapes) {
  const sign = document.createElementNS(SVG, "svg");
  sign.setAttribute("viewBox", "0 0 40 40");
  sign.setAttribute("class", "picture");
  sign.setAttribute("aria-hidden", "true");
  sign.setAttribute("focusable", "false");
  for (const [tag, attributes] of shapes) {
    const shape = document.createElementNS(SVG, tag);
    Object.entries(attributes).forEach(([name, value]) => shape.setAttribute(name, value));
    sign.append(shape);
  }
  return sign;
}

/** A tick (Check: did the robot do it?), white on the green button. */
export const tick = () => drawing([["path", {d: "M8 21l8 8 16-18", fill: "none", stroke: "#fff",
  "stroke-width": "6", "stroke-linecap": "round", "stroke-linejoin": "round"}]]);

/** Two arrows onward (the next adventure), white on the green button. */
export const onward = () => drawing([["path", {d: "M6 8l13 12-13 12zM21 8l13 12-13 12z", fill: "#fff",
  stroke: "#14532d", "stroke-width": "2", "stroke-linejoin": "round"}]]);

/** A star (the adventures). */
export const star = () => drawing([["path", {
  d: "M20 3l5 11 12 1-9 8 3 12-11-6-11 6 3-12-9-8 12-1z", fill: "#facc15", stroke: "#1f2937",
  "stroke-width": "2", "stroke-linejoin": "round"}]]);

/**
 * A button shows its sign and its words; its accessible name is ``label`` (or the words). At
 * Level 1 (levels.css) the sign alone: the words stay its name, and its tooltip.
 * @param {HTMLElement} button
 * @param {SVGSVGElement} sign
 * @param {string} text
 * @param {string} [label]
 */
export function showSigned(button, sign, text, label) {
  const words = document.createElement("span");
  words.className = "words";
  words.textContent = text;
  button.replaceChildren(sign, words);
  button.classList.add("pictured");
  button.setAttribute("aria-label", label || text);
  button.title = label || text;
}
