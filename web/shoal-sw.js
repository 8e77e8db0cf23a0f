// Shoal's service worker: after the first visit the app works with no network.
//
// On install (and again whenever the page is opened with a network) it reads
// index.html and the loader it names, fetches every file of this version of the
// app into one cache, and drops the files of older versions. Requests are then
// answered:
// - files whose names carry Trunk's content hash (the WebAssembly, its bindings,
//   the stylesheet): from the cache first, since such a file never changes;
// - everything else (the page, the loader, this script's neighbours): from the
//   network first, and from the cache when the network is down or filtered.
"use strict";

const CACHE = "shoal-app";
const HASHED = /-[0-9a-f]{16}(_bg)?\.[a-z]+$/;
// The ODD descriptions that the About windows link (made at build time from
// docs/odd-*.md by web/odd-pages.sh); index.html does not name them.
const ODD = ["odd/odd.css", "odd/schooling.html", "odd/reef.html", "odd/physics.html", "odd/learning.html"];
/** Pages of their own (the ODD pages), answered as themselves and not as the app. */
const OWN_PAGE = /\/odd\/[a-z-]+\.html$/;

/** The files this version of the app is made of, read from index.html and the
 * loader (Trunk's hashed names change with every build). */
async function appFiles() {
  const scope = new URL(self.registration.scope);
  const index = await fetch(scope.href, { cache: "no-cache" });
  if (!index.ok) throw new Error(`index.html: ${index.status}`);
  const html = await index.clone().text();
  const names = new Set([scope.href]);
  for (const [, ref] of html.matchAll(/(?:src|href)="([^"#]+)"/g)) names.add(new URL(ref, scope).href);
  for (const page of ODD) names.add(new URL(page, scope).href);
  const loader = [...names].find((n) => n.endsWith("shoal-start.js"));
  if (loader) {
    const text = await (await fetch(loader, { cache: "no-cache" })).text();
    for (const [, ref] of text.matchAll(/'([^']+\.(?:js|wasm))'/g)) names.add(new URL(ref, scope).href);
  }
  const same = [...names].filter((n) => new URL(n).origin === scope.origin);
  return { index, files: same };
}

/** Fills the cache with this version's files and forgets the others. */
async function refresh() {
  const cache = await caches.open(CACHE);
  const { index, files } = await appFiles();
  const scope = self.registration.scope;
  for (const file of files) {
    if (file === scope) continue;
    if (HASHED.test(file) && (await cache.match(file))) continue;
    const response = await fetch(file, { cache: "no-cache" });
    if (response.ok) await cache.put(file, response);
  }
  await cache.put(scope, index);
  const keep = new Set(files);
  for (const request of await cache.keys()) {
    if (!keep.has(request.url)) await cache.delete(request);
  }
}

self.addEventListener("install", (event) => {
  event.waitUntil(refresh().then(() => self.skipWaiting()));
});

self.addEventListener("activate", (event) => {
  event.waitUntil(self.clients.claim());
});

self.addEventListener("fetch", (event) => {
  const request = event.request;
  const url = new URL(request.url);
  if (request.method !== "GET" || url.origin !== self.location.origin) return;
  // The page itself, whatever its query (?lang=es, a share link's settings).
  const app = request.mode === "navigate" && !OWN_PAGE.test(url.pathname);
  const key = app ? self.registration.scope : url.origin + url.pathname;
  if (HASHED.test(url.pathname)) {
    event.respondWith(caches.match(key).then((hit) => hit || fetch(request)));
    return;
  }
  event.respondWith(
    fetch(request)
      .then((response) => {
        // A fresh page may name a new version: fetch it in the background.
        if (app && response.ok) event.waitUntil(refresh().catch(() => {}));
        return response;
      })
      .catch(() => caches.match(key).then((hit) => hit || Response.error())),
  );
});
