// What the class's pages share (the pupil's name page, the class bar on the studio page, the
// teacher's page): requests in the page's language, its words, the class's WebSockets.

// The page's language: ?language=xx, else the one chosen in this browser, else the studio's.
export const pageLanguage = new URLSearchParams(location.search).get("language")
  || localStorage.getItem("rootlang.language") || "";

export function inPageLanguage(path) {
  if (!pageLanguage) return path;
  const address = new URL(path, location.href);
  address.searchParams.set("language", pageLanguage);
  return address.pathname + address.search;
}

// A JSON request; a refusal throws its message (in the page's language).
export async function api(method, path, body) {
  const response = await fetch(inPageLanguage(path), {
    method: method, headers: body ? {"Content-Type": "application/json"} : {},
    body: body ? JSON.stringify(body) : undefined,
  });
  const data = await response.json().catch(() => ({}));
  if (!response.ok) {
    const error = new Error((data.errors || []).map(e => e.message).join("\n") || response.statusText);
    error.status = response.status;
    throw error;
  }
  return data;
}

// The page's words: `words(key, {name: ...})`; English until the studio's strings have come.
let known = {};
export function setWords(strings) { known = strings || {}; }
export function words(key, values) {
  let text = known[key] || key;
  for (const [name, value] of Object.entries(values || {})) text = text.replace("{" + name + "}", () => String(value));
  return text;
}

// Each [data-i18n] element's text in the page's language (its accessible name follows).
export function translate(root) {
  root.querySelectorAll("[data-i18n]").forEach(element => {
    const local = known[element.dataset.i18n];
    if (!local) return;
    element.textContent = local;
    if (element.hasAttribute("aria-label")) element.setAttribute("aria-label", local);
  });
  root.querySelectorAll("[data-i18n-placeholder]").forEach(element => {
    const local = known[element.dataset.i18nPlaceholder];
    if (local) { element.placeholder = local; element.setAttribute("aria-label", local); }
  });
}

// A WebSocket to the studio that comes back after a lost link (the studio restarted, Wi-Fi).
export function keepOpen(path, onMessage, onState) {
  const open = () => {
    const socket = new WebSocket((location.protocol === "https:" ? "wss://" : "ws://") + location.host + inPageLanguage(path));
    socket.onmessage = event => onMessage(JSON.parse(event.data));
    socket.onopen = () => onState && onState(true);
    socket.onclose = () => { if (onState) onState(false); setTimeout(open, 2000); };
  };
  open();
}
