// @ts-check
// The studio page's service worker (served as /sw.js, so it looks after the whole page): the
// page opens again while the studio is out of reach (the school's Wi-Fi down, the teacher's
// laptop asleep), from the answers it last got, with the child's unsaved typing offered back
// from its draft. Every GET goes to the studio first, so a page is never older than its studio
// when that can be reached; only when the studio can't be reached does the last good answer
// stand in. The vendored files' addresses carry their contents' hash: those come from the
// cache first. Nothing is answered for the studio that changes anything (saves, conversions,
// runs: they wait for the studio, and the page says so). docs/studio.md, "Offline".

/** @typedef {Event & {waitUntil(work: Promise<unknown>): void}} ExtendableEvent */
/** @typedef {ExtendableEvent & {request: Request, respondWith(answer: Promise<Response>): void}} FetchEvent */

const worker = /** @type {{skipWaiting(): Promise<void>, clients: {claim(): Promise<void>},
  addEventListener(type: string, listener: (event: any) => void): void}} */ (/** @type {unknown} */ (self));
const CACHE = "rootlang-studio";
/** Answers never kept: the robots near now, a run's replay, the run's socket. */
const NEVER = ["/ws", "/api/robots", "/replay/"];

worker.addEventListener("install", () => { worker.skipWaiting(); });
worker.addEventListener("activate", (/** @type {ExtendableEvent} */ event) => {
  event.waitUntil(worker.clients.claim());   // (the page that registered it is looked after now)
});
worker.addEventListener("fetch", (/** @type {FetchEvent} */ event) => {
  const request = event.request;
  if (request.method !== "GET" || !keepable(request.url)) return;
  event.respondWith(answer(request, new URL(request.url).pathname.startsWith("/vendor/")));
});
// The page's first load came before this worker looked after it: the page sends the addresses
// it loaded then, and they are fetched again and kept, so it opens offline from the next load.
worker.addEventListener("message", (/** @type {ExtendableEvent & {data: unknown, source: {postMessage(message: unknown): void} | null}} */ event) => {
  const data = /** @type {{keep?: unknown}} */ (event.data);
  if (!Array.isArray(data.keep)) return;
  const addresses = data.keep.filter(address => typeof address === "string" && keepable(address));
  event.waitUntil(Promise.all(addresses.map(address => answer(new Request(address), true)
    .catch(() => null))).then(() => event.source?.postMessage({kept: addresses.length})));
});

/**
 * A GET the worker looks after: the studio's own, and not one of those never kept.
 * @param {string} address
 */
function keepable(address) {
  const url = new URL(address, location.href);
  return url.origin === location.origin && !NEVER.some(path => url.pathname.startsWith(path));
}

/**
 * @param {Request} request
 * @param {boolean} fixed its address names its contents (the cache's copy is as good)
 * @returns {Promise<Response>}
 */
async function answer(request, fixed) {
  const cache = await caches.open(CACHE);
  const kept = fixed ? await cache.match(request) : undefined;
  if (kept) return kept;
  try {
    const response = await fetch(request);
    if (response.ok) await cache.put(request, response.clone());
    return response;
  } catch (unreachable) {
    const last = await cache.match(request);
    if (last) return last;
    throw unreachable;
  }
}
