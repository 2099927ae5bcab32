// @ts-check
// What the class's pages share (the pupil's name page, the class bar on the studio page, the
// teacher's page): their words on the page's elements, and WebSockets that come back.
import {inPageLanguage, words} from "./page.js";

/**
 * Each [data-i18n] element's text in the page's language (its accessible name follows), each
 * [data-i18n-label] element's accessible name, and each [data-i18n-placeholder] field's
 * placeholder; and the page's title ([data-i18n] on <title>).
 * @param {ParentNode} root
 */
export function translate(root) {
  root.querySelectorAll("[data-i18n]").forEach(found => {
    const key = /** @type {HTMLElement} */ (found).dataset.i18n || "";
    const local = words(key);
    if (local === key) return;
    found.textContent = local;
    if (found.hasAttribute("aria-label")) found.setAttribute("aria-label", local);
  });
  root.querySelectorAll("[data-i18n-label]").forEach(found => {
    const key = /** @type {HTMLElement} */ (found).dataset.i18nLabel || "";
    if (words(key) !== key) found.setAttribute("aria-label", words(key));
  });
  root.querySelectorAll("[data-i18n-placeholder]").forEach(found => {
    const field = /** @type {HTMLInputElement} */ (found);
    const key = field.dataset.i18nPlaceholder || "";
    if (words(key) !== key) { field.placeholder = words(key); field.setAttribute("aria-label", words(key)); }
  });
}

/**
 * A WebSocket to the studio that comes back after a lost link (the studio restarted, Wi-Fi).
 * Before each new try, ``comeBack`` (if given) makes the page known to the studio again: a
 * restarted studio has forgotten who it was. A try it can't make yet waits for the next one.
 * @template T
 * @param {string} path
 * @param {(message: T) => void} onMessage
 * @param {(open: boolean) => void} onState
 * @param {() => Promise<void>} [comeBack]
 */
export function keepOpen(path, onMessage, onState, comeBack) {
  const again = () => setTimeout(() => {
    (comeBack ? comeBack() : Promise.resolve()).then(open, again);
  }, 2000);
  const open = () => {
    const socket = new WebSocket((location.protocol === "https:" ? "wss://" : "ws://") + location.host + inPageLanguage(path));
    socket.onmessage = event => onMessage(JSON.parse(event.data));
    socket.onopen = () => onState(true);
    socket.onclose = () => { onState(false); again(); };
  };
  open();
}

/**
 * A new element.
 * @template {keyof HTMLElementTagNameMap} K
 * @param {K} tag
 * @param {Record<string, string>} [attributes]
 * @param {string} [text]
 * @returns {HTMLElementTagNameMap[K]}
 */
export function element(tag, attributes, text) {
  const made = document.createElement(tag);
  Object.entries(attributes || {}).forEach(([name, value]) => made.setAttribute(name, value));
  if (text !== undefined) made.textContent = text;
  return made;
}
