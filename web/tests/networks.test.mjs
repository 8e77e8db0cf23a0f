// Every classroom: Shoal starts behind a district's strict Content Security
// Policy (no inline script or style, WebAssembly allowed), and nothing on the
// page breaks that policy while it runs.
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
  });
}
