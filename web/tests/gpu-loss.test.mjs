// A sim that never dies: a Chromebook that sleeps or changes screens takes the
// GPU away from the page. On WebGL2 the canvas's context is lost (and later
// given back); on WebGPU the device is destroyed. Shoal must draw again on a new
// renderer with the same fish, clock and settings, say what happened, and keep
// its controls for a screen reader.
import { describe, test, before, after } from "node:test";
import assert from "node:assert/strict";
import fs from "node:fs";
import path from "node:path";
import { serveDist, launch, openShoal, TIERS, saveArtifact, decode, fishPixels, mirroredButton, repoRoot } from "./harness.mjs";

const fixtures = path.join(repoRoot, "web", "tests", "fixtures");
const tinyDesign = JSON.parse(fs.readFileSync(path.join(fixtures, "experiment-tiny.json"), "utf8"));
const nativeCsv = fs.readFileSync(path.join(fixtures, "experiment-tiny.csv"), "utf8");

/** Takes the GPU away as the browser does when a Chromebook sleeps. */
async function loseGpu(page, tier) {
  if (tier === "webgl2") {
    await page.evaluate(() => {
      const ext = document.getElementById("shoal_canvas").getContext("webgl2").getExtension("WEBGL_lose_context");
      ext.loseContext();
      setTimeout(() => ext.restoreContext(), 1000);
    });
  } else {
    assert.equal(await page.evaluate(() => window.shoal.lose_gpu()), true);
  }
}

for (const tier of TIERS) {
  describe(`a lost graphics device (${tier})`, () => {
    let server, browser;
    before(async () => {
      server = await serveDist();
      browser = await launch(tier);
    });
    after(async () => {
      await browser?.close();
      await server?.close();
    });

    test("the tank is drawn again with the same fish, clock and settings, and the notice says why", async () => {
      const { page, errors } = await openShoal(browser, `${server.url}#`, { width: 1024, height: 640 });
      // A setting a teacher changed, to find again after the loss.
      await page.evaluate(() => window.shoal.set({ seed: 7, left: { fish_count: 400 } }));
      await page.waitForFunction(() => window.shoal.state().fish_count === 400 && window.shoal.state().time_secs > 2, null, { timeout: 60_000 });
      const before = await page.evaluate(() => window.shoal.state());
      const tankRect = (png) => ({ x: 300, y: 100, width: png.width - 300, height: png.height - 200 });
      const beforePng = decode(await page.screenshot());
      const fishBefore = fishPixels(beforePng, tankRect(beforePng)).size;
      // What the browser does when the GPU goes: on WebGL2 the context is
      // lost, then given back; on WebGPU the device is destroyed.
      await loseGpu(page, tier);
      await page.waitForFunction(
        // While the renderer restarts, the API says Shoal is not running.
        () => { try { return /graphics were lost/.test(window.shoal.state().notice || ""); } catch { return false; } },
        null,
        { timeout: 90_000 },
      );
      // It runs on: the clock goes on from where it was, not from zero.
      await page.waitForFunction(
        (t) => { try { return window.shoal.state().time_secs > t + 1; } catch { return false; } },
        before.time_secs,
        { timeout: 90_000 },
      );
      const after = await page.evaluate(() => window.shoal.state());
      assert.equal(after.fish_count, 400, "the fish count set before the loss");
      assert.equal(after.scene, before.scene);
      assert.equal(after.seed, 7);
      assert.ok(after.time_secs > before.time_secs, "the clock carried on");
      // The address holds the settings: a reload would open the same tank.
      assert.match(await page.evaluate(() => location.hash), /^#.+/);
      // Drawn again: fish on the screen.
      const shot = await page.screenshot();
      saveArtifact(`gpu-loss-${tier}.png`, shot);
      const png = decode(shot);
      const fishAfter = fishPixels(png, tankRect(png)).size;
      assert.ok(fishBefore > 30, `fish drawn before the loss (${fishBefore} pixels)`);
      assert.ok(fishAfter > fishBefore / 3, `fish are drawn again (${fishAfter} pixels, ${fishBefore} before)`);
      // The accessible controls are back, once.
      await mirroredButton(page, "Reset");
      assert.equal(await page.evaluate(() => document.querySelectorAll("#shoal_a11y").length), 1);
      assert.deepEqual(errors.filter((e) => !/lost|context/i.test(e)), []);
      await page.close();
    });

    test("an experiment under way carries on through the loss, to the same CSV as natively", async () => {
      const { page, errors } = await openShoal(browser, `${server.url}#`, { width: 1024, height: 640 });
      // Started, and the GPU taken away before its first run is done.
      const started = await page.evaluate((design) => {
        window.shoal.experiment(design);
        return window.shoal.state().experiment;
      }, tinyDesign);
      assert.equal(started.running, true);
      assert.ok(started.runs_done < started.runs_total, JSON.stringify(started));
      await loseGpu(page, tier);
      await page.waitForFunction(
        () => { try { return /graphics were lost/.test(window.shoal.state().notice || ""); } catch { return false; } },
        null,
        { timeout: 90_000 },
      );
      await page.waitForFunction(
        () => { try { const e = window.shoal.state().experiment; return e && !e.running; } catch { return false; } },
        null,
        { timeout: 180_000 },
      );
      const e = await page.evaluate(() => window.shoal.state().experiment);
      assert.equal(e.cancelled, false);
      assert.equal(e.runs_done, e.runs_total);
      assert.equal(e.csv, nativeCsv, "every run, as the native lab gives it");
      assert.deepEqual(errors.filter((e) => !/lost|context/i.test(e)), []);
      await page.close();
    });
  });
}
