// @ts-check
// A polite live region for a screen reader (WCAG 4.1.3) that stays something a child can listen
// to: the studio's stage (narrator.js) and the replay page speak through it.

/** At most one announcement in this long (ms). */
export const ANNOUNCE_GAP_MS = 1500;

/**
 * A polite live region that speaks at most once per `gapMs`, saying what came meanwhile at once;
 * of what came with the same `kind` ("light", "motion"), only the last is said.
 * @param {HTMLElement} region
 * @param {number} gapMs
 * @returns {(text: string, kind?: string) => void}
 */
export function announcer(region, gapMs) {
  /** @type {{text: string, kind: string}[]} */
  let waiting = [];
  let last = -Infinity;
  /** @type {ReturnType<typeof setTimeout> | null} */
  let timer = null;
  const speak = () => {
    timer = null;
    last = performance.now();
    region.textContent = waiting.map(one => one.text).join(". ");
    region.dataset.announced = String(Number(region.dataset.announced || 0) + 1);
    waiting = [];
  };
  return (text, kind) => {
    waiting = waiting.filter(one => !kind || one.kind !== kind);
    waiting.push({text: text, kind: kind || ""});
    if (timer === null) timer = setTimeout(speak, Math.max(0, last + gapMs - performance.now()));
  };
}
