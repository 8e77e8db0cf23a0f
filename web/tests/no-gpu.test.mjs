// A browser with neither WebGPU nor WebGL2 gets a readable explanation, never a blank
// canvas or an endless "Loading…".
import { test } from "node:test";
import assert from "node:assert/strict";
import { serveDist, launch, saveArtifact } from "./harness.mjs";

test("without WebGPU and WebGL2 the page explains what is needed", async () => {
  const server = await serveDist();
  const browser = await launch("none");
  try {
    const page = await browser.newPage({ viewport: { width: 1000, height: 700 } });
    await page.goto(server.url);
    await page.waitForFunction(
      () => /needs 3D graphics/.test(document.getElementById("shoal_notice")?.textContent || ""),
      null,
      { timeout: 60_000 },
    );
    const text = await page.textContent("#shoal_notice");
    assert.match(text, /WebGPU/);
    assert.match(text, /WebGL2/);
    assert.match(text, /Chrome/);
    assert.equal(await page.isVisible("#shoal_notice button"), true, "a reload button");
    assert.equal(await page.isVisible("#shoal_canvas"), false, "no blank canvas");
    saveArtifact("no-gpu.png", await page.screenshot());
  } finally {
    await browser.close();
    await server.close();
  }
});
