// @ts-check
// The page itself: its elements, the state the browser tests read, its words in the page's
// language, and the status line.

/** @typedef {import("./messages").SetupReply} SetupReply */

/**
 * The element with this id (the page's own, always there).
 * @param {string} id
 * @returns {any}
 */
export const $ = id => document.getElementById(id);

/** What the page shows, for the browser tests: `<output id="state">`'s data attributes. */
export const state = /** @type {HTMLElement} */ (document.getElementById("state")).dataset;

/** The open program, its version on disk when opened or last saved (a Save sends it back), and
 * whether a run goes on (one page, one program). */
export const session = {current: "", version: "", running: false, folder: ""};

// The page's sentences in its language (the studio's strings; the keys until they are known).
/** @type {Record<string, string>} */
let pageWords = {};

/** @param {Record<string, string>} strings */
export function setWords(strings) { pageWords = strings; }

/** @param {string} key */
export function hasWords(key) { return key in pageWords; }

/**
 * A sentence of the page's, with its {name}s filled in.
 * @param {string} key
 * @param {Record<string, string | number>} [values]
 */
export function words(key, values) {
  let text = pageWords[plural(key, values)] || pageWords[key] || key;
  // (a function: a value's own "$&" or "$1" stays as it is)
  for (const [name, value] of Object.entries(values || {})) text = text.replace("{" + name + "}", () => String(value));
  return text;
}

/**
 * A sentence's key for its {count}: ``key_one`` where the page's language says "one" of it
 * (1 in English, Dutch, Spanish and German; 0 and 1 in French) and the studio has that form,
 * else ``key`` (the other form: "2 mistakes").
 * @param {string} key
 * @param {Record<string, string | number>} [values]
 */
function plural(key, values) {
  const count = values ? Number(values.count) : NaN;
  if (!Number.isFinite(count)) return key;
  const language = document.documentElement.lang || pageLanguage || "en";
  let form = count === 1 ? "one" : "other";
  try { form = new Intl.PluralRules(language).select(count); } catch { /* an unknown language: as English */ }
  return form === "one" ? key + "_one" : key;
}

/** The problem the status line reports now ("" when it reports none): see `fixed`. */
let statusAbout = "";

/**
 * The status line.
 * @param {string} text
 * @param {boolean} [isError]
 * @param {string} [about] the problem it reports ("mistakes", "out_of_step", "run" ...), so
 *   that the line goes as soon as that is fixed (`fixed(about)`)
 */
export function say(text, isError, about) {
  $("status").textContent = text;
  $("status").className = isError ? "error" : "";
  statusAbout = isError ? about || "" : "";
  state.statusAbout = statusAbout;
}

/**
 * What the status line reported is fixed: it says so no more (a line about something else stays).
 * @param {string} about
 */
export function fixed(about) {
  if (statusAbout && statusAbout === about) say(words("ready"));
}

// --- the page's language ----------------------------------------------------------------------

// Chosen in the page (kept in this browser), or ?language=xx, else ("") the studio's own default;
// once the setup has come, the one it is in.
let pageLanguage = new URLSearchParams(location.search).get("language")
  || localStorage.getItem("rootlang.language") || "";

/**
 * An address of the studio's, asked in the page's language.
 * @param {string} path
 */
export function inPageLanguage(path) {
  if (!pageLanguage) return path;
  const address = new URL(path, location.href);
  address.searchParams.set("language", pageLanguage);
  return address.pathname + address.search;
}

/**
 * Words without the signs around them (◤, ▶): what a screen reader says of a button is its words,
 * which its name contains (WCAG 2.5.3), not "black up-pointing triangle".
 * @param {string} text
 */
export const withoutSigns = text => text.replace(/^[^\p{L}\p{N}]+|[^\p{L}\p{N})]+$/gu, "");

/**
 * The page's words in its language: the Language menu lists the studio's languages (each named
 * in itself); each [data-i18n] element's English words are replaced, so the signs around them
 * (◤, ▶) stay; its accessible name follows.
 * @param {SetupReply} setup
 */
export function translatePage(setup) {
  pageLanguage = setup.language;
  document.documentElement.lang = setup.language;
  $("language").replaceChildren(...Object.entries(setup.languages).map(([code, name]) => new Option(name, code)));
  $("language").value = setup.language;
  if (setup.language === "en") return;
  document.querySelectorAll("[data-i18n]").forEach(element => {
    const key = /** @type {HTMLElement} */ (element).dataset.i18n || "";
    const english = setup.english[key], local = setup.strings[key];
    if (!english || !local) return;
    element.textContent = (element.textContent || "").replace(english, local);
    // (a pictured button's words are a part of it: the button's name follows them)
    const named = element.classList.contains("words") ? element.parentElement : element;
    if (!named || !named.hasAttribute("aria-label")) return;
    named.setAttribute("aria-label", withoutSigns(element.textContent));
    if (named.hasAttribute("title")) named.setAttribute("title", withoutSigns(element.textContent));
  });
}

export function chooseLanguage() {
  localStorage.setItem("rootlang.language", $("language").value);
  const address = new URL(location.href);
  address.searchParams.set("language", $("language").value);
  location.href = address.toString();
}
