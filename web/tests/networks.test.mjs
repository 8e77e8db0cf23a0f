// Every classroom: Shoal starts behind a district's strict Content Security
// Policy (no inline script or style, WebAssembly allowed), and nothing on the
// page breaks that policy while it runs; it installs as an app, and after one
// visit it reloads and runs with no network at all.
import { describe, test, before, after } from "node:test";
import assert from "node:assert/strict";
import { serveDist, launch, TIERS, saveArtifact, pressMirrored, mirroredButton } from "./harness.mjs";

/** The policy a filtering district sends: only this site's own files, and
 * WebAssembly compiled from them. */
export const STRICT_CSP = "default-src 'self'; script-src 'self' 'wasm-unsafe-eval'";

for (const tier of TIERS) {
  describe(`locked-down networks (${tier})`, () => {
    let server, browser;
    before(async () => {
      server = await serveDist({ headers: { "Content-Security-Policy": STRICT_CSP } });
      browser = await launch(tier);
    });
    after(async () => {
      await browser?.close();
      await server?.close();
    });

    test("starts and runs under `default-src 'self'; script-src 'self' 'wasm-unsafe-eval'` with no violation", async () => {
      const page = await browser.newPage({ viewport: { width: 1280, height: 720 } });
      const errors = [];
      page.on("console", (m) => m.type() === "error" && errors.push(m.text()));
      page.on("pageerror", (e) => errors.push(`pageerror: ${e.message}`));
      // Every refusal the browser makes, whatever kind.
      await page.addInitScript(() => {
        window.__cspViolations = [];
        document.addEventListener("securitypolicyviolation", (e) =>
          window.__cspViolations.push(`${e.violatedDirective} ${e.blockedURI}`),
        );
      });
      const response = await page.goto(`${server.url}#`);
      assert.equal(response.headers()["content-security-policy"], STRICT_CSP, "the server sends the policy");
      await page.waitForFunction(() => window.shoal && window.shoal.state().steps > 30, null, { timeout: 120_000 });
      // The page's own stylesheet applies (the notice is hidden, the canvas fills the page).
      const layout = await page.evaluate(() => ({
        notice: getComputedStyle(document.getElementById("shoal_notice")).display,
        canvasWidth: document.getElementById("shoal_canvas").getBoundingClientRect().width,
        mirror: getComputedStyle(document.getElementById("shoal_a11y")).position,
      }));
      assert.equal(layout.notice, "none");
      assert.equal(layout.canvasWidth, 1280);
      assert.equal(layout.mirror, "fixed", "the accessible mirror's style comes from the page's CSS");
      // Work the interface a little: a control through the mirror, a language.
      await pressMirrored(page, "Español");
      await mirroredButton(page, "Reiniciar");
      saveArtifact(`networks-${tier}-strict-csp.png`, await page.screenshot());
      assert.deepEqual(await page.evaluate(() => window.__cspViolations), []);
      assert.deepEqual(errors, []);
      await page.close();
    });

    test("installable, and after one visit it reloads and runs with the network gone", async () => {
      const own = await serveDist();
      const context = await browser.newContext({ viewport: { width: 1024, height: 640 } });
      try {
        const page = await context.newPage();
        const errors = [];
        page.on("pageerror", (e) => errors.push(`pageerror: ${e.message}`));
        await page.goto(`${own.url}?lang=es#`);
        await page.waitForFunction(() => window.shoal && window.shoal.state().steps > 30, null, { timeout: 120_000 });
        // The app's manifest, as Chrome reads it (a test's private window cannot
        // install, so the manifest is checked rather than the install prompt).
        const cdp = await context.newCDPSession(page);
        const manifest = await cdp.send("Page.getAppManifest");
        assert.deepEqual(manifest.errors, [], "the manifest parses without errors");
        const parsed = JSON.parse(manifest.data);
        assert.equal(parsed.display, "standalone");
        assert.ok(["192x192", "512x512"].every((s) => parsed.icons.some((i) => i.sizes === s)), "icons Chrome needs to install");
        for (const icon of parsed.icons) {
          const response = await page.request.get(new URL(icon.src, own.url).href);
          assert.equal(response.status(), 200, icon.src);
        }
        // The service worker has kept every file of this version.
        await page.waitForFunction(
          async () => {
            const reg = await navigator.serviceWorker.getRegistration();
            if (!reg || !reg.active || !navigator.serviceWorker.controller) return false;
            const cache = await caches.open("shoal-app");
            const urls = (await cache.keys()).map((r) => new URL(r.url).pathname);
            const odd = ["/odd/odd.css", "/odd/schooling.html", "/odd/physics.html", "/odd/reef.html", "/odd/learning.html"];
            return (
              urls.some((u) => u.endsWith("_bg.wasm")) &&
              urls.includes("/") &&
              urls.includes("/shoal-start.js") &&
              odd.every((u) => urls.includes(u))
            );
          },
          null,
          { timeout: 120_000, polling: 1000 },
        );
        // The school's network fails: no server, and the browser offline.
        own.closeAll();
        await own.close();
        await context.setOffline(true);
        await page.reload();
        await page.waitForFunction(() => window.shoal && window.shoal.state().steps > 30, null, { timeout: 120_000 });
        assert.equal(await page.evaluate(() => window.shoal.state().lang), "es", "the link's language survives");
        saveArtifact(`networks-${tier}-offline.png`, await page.screenshot());
        // The About window's ODD page opens offline too, as itself (not the app).
        const odd = await context.newPage();
        await odd.goto(`${own.url}odd/reef.html`);
        assert.match(await odd.$eval("h1", (h) => h.textContent), /the reef/);
        assert.equal(await odd.$$eval("h2", (hs) => hs.length), 7);
        assert.notEqual(await odd.$eval("main", (m) => getComputedStyle(m).maxWidth), "none", "its stylesheet came from the cache");
        await odd.close();
        assert.deepEqual(errors, []);
      } finally {
        await context.close();
        own.closeAll();
        await own.close();
      }
    });
  });
}
