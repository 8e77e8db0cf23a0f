// Shoal in headless Chromium, on both GPU tiers: it loads without console errors,
// draws a real aquarium, fish move, a real click pauses it, the UI changes settings
// that `shoal.state()` reports, and the automation API refuses bad input.
import { describe, test, before, after } from "node:test";
import assert from "node:assert/strict";
import {
  serveDist, launch, openShoal, decode, pixelStats, fishPixels, symmetricDifference,
  saveArtifact, clickUntil, sleep, waitFrames, sharpness, nudgeFrames,
} from "./harness.mjs";

const state = (page) => page.evaluate(() => window.shoal.state());
const widgets = (page) => page.evaluate(() => window.shoal.widgets());

// SwiftShader's WebGL2 too: what Chrome draws with when it blocks the GPU.
for (const tier of ["webgl2", "webgpu", "webgl2-swiftshader"]) {
  // The tier the app reports (the software GPU under it is the test's choice).
  const reported = tier.split("-")[0];
  describe(`aquarium on the ${tier} tier`, () => {
    let server, browser, page, errors, aquarium;

    before(async () => {
      server = await serveDist();
      browser = await launch(tier);
      ({ page, errors } = await openShoal(browser, server.url));
      // The 3D view in device pixels (the page runs at devicePixelRatio 1).
      aquarium = (await widgets(page)).aquarium;
    });

    after(async () => {
      await browser?.close();
      await server?.close();
    });

    test(`reports the ${reported} tier`, async () => {
      const s = await state(page);
      assert.equal(s.tier, reported);
      for (const key of ["time_secs", "steps", "fish_count", "tier", "fps", "paused", "seed", "scene"]) {
        assert.ok(key in s, `state() has ${key}`);
      }
      assert.equal(s.fish_count, 200);
      assert.equal(s.scene, "aquarium");
    });

    test("the canvas shows a lit, coloured aquarium, not a blank screen", async () => {
      const shot = await page.screenshot();
      saveArtifact(`${tier}-aquarium.png`, shot);
      const stats = pixelStats(decode(shot), aquarium);
      assert.ok(stats.mean > 25 && stats.mean < 230, `mean luminance ${stats.mean}`);
      assert.ok(stats.std > 12, `contrast (std of luminance) ${stats.std}`);
      assert.ok(stats.distinctColours > 150, `distinct colours ${stats.distinctColours}`);
      // Fish are the only saturated, non-blue things in the tank: the same view
      // with no fish has (almost) none of their pixels. (How many the 200 small
      // fish cover depends on where they swim at the moment of the screenshot.)
      const fish = fishPixels(decode(shot), aquarium).size;
      await page.evaluate(() => window.shoal.set({ left: { fish_count: 0 } }));
      await waitFrames(page, 2);
      const empty = fishPixels(decode(await page.screenshot()), aquarium).size;
      await page.evaluate(() => window.shoal.set({ left: { fish_count: 200 } }));
      await waitFrames(page, 2);
      assert.ok(fish > 40 && fish > 4 * empty, `fish-coloured pixels ${fish} with fish, ${empty} without`);
    });

    test("fish move between two screenshots while playing, and not while paused", async () => {
      await page.evaluate(() => window.shoal.set({ paused: false, speed: 1 }));
      const a = decode(await page.screenshot());
      const stepsA = (await state(page)).steps;
      // A second of simulated time (however slowly a software GPU draws it).
      await page.waitForFunction((n) => window.shoal.state().steps > n + 60, stepsA, { timeout: 30_000 });
      await sleep(500);
      const b = decode(await page.screenshot());
      const moved = symmetricDifference(fishPixels(a, aquarium), fishPixels(b, aquarium));
      assert.ok(moved > 0.2, `fish pixels changed by ${moved}`);

      await page.evaluate(() => window.shoal.pause());
      // Let the last frame (drawn between two steps) be replaced by the paused one.
      await sleep(2000);
      const c = decode(await page.screenshot());
      await sleep(800);
      const d = decode(await page.screenshot());
      const still = symmetricDifference(fishPixels(c, aquarium), fishPixels(d, aquarium));
      assert.equal(still, 0, "a paused aquarium is still");
      await page.evaluate(() => window.shoal.play());
    });

    test("a real click on Pause stops simulated time, and Play resumes it", async () => {
      assert.equal((await state(page)).paused, false);
      // (A toggle: clickUntil clicks again only if the first click was lost,
      // which happens on a loaded machine at one or two frames a second.)
      await clickUntil(page, "play_pause", () => window.shoal.state().paused);
      const t1 = (await state(page)).time_secs;
      await sleep(700);
      const t2 = (await state(page)).time_secs;
      assert.equal(t2, t1, "time stands still while paused");
      saveArtifact(`${tier}-paused.png`, await page.screenshot());

      await clickUntil(page, "play_pause", () => !window.shoal.state().paused);
      // Software rendering can take a few hundred milliseconds a frame: allow time.
      await page.waitForFunction((t) => window.shoal.state().time_secs > t, t2, { timeout: 15_000 });
    });

    test("dragging the speed slider changes the speed that state() reports", async () => {
      const slider = (await widgets(page)).speed;
      const y = slider.y + slider.height / 2;
      // The rail is the left part of the slider's rectangle (the number box is on the right).
      await page.mouse.move(slider.x + 4, y);
      await page.mouse.down();
      await page.mouse.move(slider.x + slider.width * 0.2, y, { steps: 5 });
      await page.mouse.up();
      await page.waitForFunction(() => window.shoal.state().speed < 1, null, { timeout: 15_000 });
      const slow = (await state(page)).speed;
      await page.mouse.move(slider.x + slider.width * 0.2, y);
      await page.mouse.down();
      await page.mouse.move(slider.x + slider.width * 0.55, y, { steps: 5 });
      await page.mouse.up();
      await page.waitForFunction((v) => window.shoal.state().speed > v, slow, { timeout: 15_000 });
      const fast = (await state(page)).speed;
      assert.ok(slow >= 0.25 && slow < 1, `dragged left: ${slow}`);
      assert.ok(fast > slow, `dragged right: ${slow} → ${fast}`);
      await page.evaluate(() => window.shoal.set({ speed: 1 }));
    });

    test("set() applies settings by name and refuses bad input without changing anything", async () => {
      await page.evaluate(() => window.shoal.set({ left: { fish_count: 120 } }));
      assert.equal((await state(page)).fish_count, 120);
      const before = await page.evaluate(() => window.shoal.settings());
      for (const [patch, expected] of [
        [{ fishcount: 5 }, "unknown setting 'fishcount'"],
        [{ speed: 100 }, "out of range"],
        [{ paused: "yes" }, "setting 'paused'"],
        [{ left: { fish_count: 50 }, seed: -1 }, "setting 'seed'"],
      ]) {
        const message = await page.evaluate((p) => {
          try {
            window.shoal.set(p);
            return null;
          } catch (e) {
            return e.message;
          }
        }, patch);
        assert.ok(message && message.includes(expected), `${JSON.stringify(patch)} → ${message}`);
      }
      assert.deepEqual(await page.evaluate(() => window.shoal.settings()), before);
      await page.evaluate(() => window.shoal.set({ left: { fish_count: 200 } }));
    });

    test("step(n) runs exactly n steps while paused and reset(seed) restarts", async () => {
      await page.evaluate(() => window.shoal.pause());
      const s0 = (await state(page)).steps;
      await page.evaluate(() => window.shoal.step(10));
      assert.equal((await state(page)).steps, s0 + 10);
      await page.evaluate(() => window.shoal.reset(42));
      const s = await state(page);
      assert.equal(s.seed, 42);
      assert.equal(s.steps, 0);
      await page.evaluate(() => window.shoal.play());
    });

    test("the page logged no errors", () => {
      assert.deepEqual(errors, []);
    });
  });
}

describe("HiDPI and resizing (WebGL2 tier)", () => {
  test("a 2× screen renders at full resolution (the tank too, with Tank detail's Auto off) and a resized window keeps drawing", async () => {
    const server = await serveDist();
    // A real 2× screen: the compositor's scale and the page's devicePixelRatio agree
    // (Playwright's deviceScaleFactor alone emulates only the latter).
    const browser = await launch("webgl2", ["--force-device-scale-factor=2"]);
    try {
      const context = await browser.newContext({ viewport: { width: 900, height: 600 }, deviceScaleFactor: 2 });
      const page = await context.newPage();
      await page.goto(server.url);
      await page.waitForFunction(() => window.shoal && window.shoal.state().steps > 30, null, { timeout: 90_000 });
      const canvas = await page.evaluate(() => {
        const c = document.getElementById("shoal_canvas");
        return { w: c.width, h: c.height, cssW: c.clientWidth };
      });
      assert.equal(canvas.w, canvas.cssW * 2, "the canvas has two device pixels per CSS pixel");
      let shot = decode(await page.screenshot());
      let rect = (await widgets(page)).aquarium;
      const scaled = { x: rect.x * 2, y: rect.y * 2, width: rect.width * 2, height: rect.height * 2 };
      assert.ok(pixelStats(shot, scaled).std > 12, "the HiDPI aquarium is not blank");
      saveArtifact("webgl2-hidpi.png", await page.screenshot());

      // Software graphics cannot draw the tank's 1800 × 1000 pixels smoothly:
      // Tank detail's Auto draws it with fewer (render/detail.rs), and unticking
      // it draws every pixel again: the same paused picture, sharper.
      await page.waitForFunction(() => window.shoal.state().scene_detail.scale < 1, null, { timeout: 60_000 });
      await page.evaluate(() => window.shoal.set({ paused: true }));
      await nudgeFrames(page, 2);
      const auto = (await state(page)).scene_detail;
      assert.ok(auto.auto && auto.scale >= 0.5, JSON.stringify(auto));
      const soft = decode(await page.screenshot());
      await clickUntil(page, "scene_detail_auto", () => window.shoal.state().scene_detail.auto === false);
      assert.equal((await state(page)).scene_detail.scale, 1, "every pixel");
      await nudgeFrames(page, 2);
      const sharp = decode(await page.screenshot());
      saveArtifact("webgl2-hidpi-every-pixel.png", await page.screenshot());
      const [before, after] = [sharpness(soft, scaled), sharpness(sharp, scaled)];
      console.log(`tank detail: ${before.toFixed(2)} at ${auto.scale} per side, ${after.toFixed(2)} at every pixel`);
      assert.ok(after > 1.15 * before, `fine detail ${after.toFixed(2)} at every pixel against ${before.toFixed(2)} at ${auto.scale}`);
      await page.evaluate(() => window.shoal.set({ paused: false }));

      await page.setViewportSize({ width: 700, height: 800 });
      await page.waitForFunction(() => window.shoal.widgets().aquarium.height > 700, null, { timeout: 30_000 });
      await page.waitForTimeout(1000);
      rect = (await widgets(page)).aquarium;
      shot = decode(await page.screenshot());
      const resized = { x: rect.x * 2, y: rect.y * 2, width: rect.width * 2, height: rect.height * 2 };
      assert.ok(pixelStats(shot, resized).std > 12, "the resized aquarium is not blank");
      saveArtifact("webgl2-resized.png", await page.screenshot());
    } finally {
      await browser.close();
      await server.close();
    }
  });
});
