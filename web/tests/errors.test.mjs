// A Rust panic is explained on the page, and the Reload button brings Shoal back.
import { test } from "node:test";
import assert from "node:assert/strict";
import { serveDist, launch, openShoal, saveArtifact } from "./harness.mjs";

test("a panic shows a readable message, and Reload restarts a working Shoal", async () => {
  const server = await serveDist();
  const browser = await launch("webgl2");
  try {
    const { page } = await openShoal(browser, server.url);
    await page.evaluate(() => window.shoal.crash_test());
    await page.waitForFunction(
      () => /internal error/.test(document.getElementById("shoal_notice")?.textContent || ""),
      null,
      { timeout: 30_000 },
    );
    const text = await page.textContent("#shoal_notice");
    assert.match(text, /crash test requested/);
    assert.match(text, /Reloading the page starts it/);
    saveArtifact("panic.png", await page.screenshot());

    await page.click("#shoal_notice button");
    await page.waitForFunction(() => window.shoal && window.shoal.state().steps > 10, null, {
      timeout: 90_000,
    });
    assert.equal(await page.isVisible("#shoal_notice"), false);
  } finally {
    await browser.close();
    await server.close();
  }
});
