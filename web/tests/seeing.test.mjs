// Seeing (WCAG 2.1, README *Accessibility → Seeing*): the page lets the browser
// zoom (1.4.4); the High contrast toggle turns the panels black and the
// usual theme comes back (1.4.3, 1.4.11); a computer that asks for reduced
// motion gets it, starting paused, and so does a ?motion=reduce link
// (2.3.3); zoomed to 200 % and at 320 CSS pixels wide the drawer's controls
// fit the screen (1.4.4, 1.4.10). Screenshots of both themes, the focus ring
// and the narrow screens go to web/test-artifacts/.

import { describe, test, before, after } from "node:test";
import assert from "node:assert/strict";
import {
  TIERS,
  serveDist,
  launch,
  saveArtifact,
  clickUntil,
  waitFrames,
  nudgeFrames,
  decode,
} from "./harness.mjs";

const state = (page) => page.evaluate(() => window.shoal.state());
const widgets = (page) => page.evaluate(() => window.shoal.widgets());

/** Opens Shoal in a fresh context (`options`: Playwright's, e.g. reducedMotion)
 * at `path`, and waits until it has drawn frames (a page that starts paused
 * takes no steps). */
async function open(browser, url, { width = 1280, height = 800, path = "", ...options } = {}) {
  const context = await browser.newContext({ viewport: { width, height }, ...options });
  const page = await context.newPage();
  const errors = [];
  page.on("pageerror", (err) => errors.push(err.message));
  await page.goto(url + path);
  await page.waitForFunction(() => window.shoal && window.shoal.state().frames > 0, null, {
    timeout: 90_000,
  });
  return { context, page, errors };
}

/** The colour of the side panel's background: a pixel in its left margin,
 * halfway down, where nothing but the panel is drawn (wherever it has been
 * scrolled to). */
async function panelPixel(page) {
  const w = await widgets(page);
  assert.ok(w.hide_panel || w.view_left.x > 100, "the side panel is open");
  const png = decode(await page.screenshot());
  const x = 3;
  const y = Math.round(png.height / 2);
  const i = (y * png.width + x) * 4;
  return [png.data[i], png.data[i + 1], png.data[i + 2]];
}

for (const tier of TIERS) {
  describe(`seeing (${tier})`, () => {
    let server, browser;
    before(async () => {
      server = await serveDist();
      browser = await launch(tier);
    });
    after(async () => {
      await browser?.close();
      await server?.close();
    });

    test("the page lets the browser zoom", async () => {
      const { context, page } = await open(browser, server.url);
      try {
        const content = await page.evaluate(
          () => document.querySelector('meta[name="viewport"]').content,
        );
        assert.ok(!/user-scalable\s*=\s*(no|0)/i.test(content), content);
        assert.ok(!/maximum-scale\s*=\s*1(\.0*)?\b/i.test(content), content);
        assert.match(content, /width=device-width/);
      } finally {
        await context.close();
      }
    });

    test("High contrast turns the panels black, and the usual theme comes back", async () => {
      const { context, page, errors } = await open(browser, server.url);
      try {
        // The schooling lab comparing two tanks: both plots' lines show.
        await page.evaluate(() => window.shoal.set({ scene: "boids", compare: true }));
        await page.waitForFunction(() => window.shoal.widgets().plot_0, null, { timeout: 60_000 });
        await page.waitForFunction(() => window.shoal.state().time_secs > 8, null, { timeout: 120_000 });
        let s = await state(page);
        assert.deepEqual(s.seeing, { high_contrast: false, reduce_motion: false });
        const usual = await panelPixel(page);
        assert.ok(usual.every((c) => c >= 20 && c <= 34), `the usual panel is grey 27: ${usual}`);
        saveArtifact(`seeing-default-${tier}.png`, await page.screenshot());

        await clickUntil(page, "high_contrast", () => window.shoal.state().seeing.high_contrast);
        await waitFrames(page, 2);
        const contrast = await panelPixel(page);
        assert.ok(contrast.every((c) => c <= 6), `the high-contrast panel is black: ${contrast}`);
        // The keyboard's focus ring: Tab to the first control.
        await page.keyboard.press("Tab", { delay: 100 });
        await waitFrames(page, 2);
        saveArtifact(`seeing-high-contrast-${tier}.png`, await page.screenshot());

        await clickUntil(page, "high_contrast", () => !window.shoal.state().seeing.high_contrast);
        await waitFrames(page, 2);
        const back = await panelPixel(page);
        assert.deepEqual(back, usual, "the usual theme is back");
        assert.deepEqual(errors, []);
      } finally {
        await context.close();
      }
    });

    test("a computer that asks for reduced motion gets it, paused, and the toggle turns it off", async () => {
      const { context, page } = await open(browser, server.url, { reducedMotion: "reduce" });
      try {
        let s = await state(page);
        assert.deepEqual(s.seeing, { high_contrast: false, reduce_motion: true });
        assert.equal(s.paused, true, "it starts paused");
        assert.match(s.notice ?? "", /Reduced motion/);
        assert.equal(s.steps, 0, "no step was taken");
        await clickUntil(page, "notice_ok", () => !window.shoal.state().notice);
        await nudgeFrames(page, 1);
        await clickUntil(page, "reduce_motion", () => !window.shoal.state().seeing.reduce_motion);
        s = await state(page);
        assert.equal(s.paused, true, "turning it off does not start the fish");
      } finally {
        await context.close();
      }
    });

    test("?contrast=high&motion=reduce opens high contrast and calm, whatever the computer says", async () => {
      const { context, page } = await open(browser, server.url, { path: "?contrast=high&motion=reduce" });
      try {
        const s = await state(page);
        assert.deepEqual(s.seeing, { high_contrast: true, reduce_motion: true });
        assert.equal(s.paused, true);
        const pixel = await panelPixel(page).catch(() => null);
        // The panel may start closed on a small screen; here it is open.
        assert.ok(pixel && pixel.every((c) => c <= 6), `black panel: ${pixel}`);
        // The keyboard's focus ring, thick and yellow: Tab to the first control.
        await page.keyboard.press("Tab", { delay: 100 });
        await nudgeFrames(page, 2);
        saveArtifact(`seeing-focus-ring-${tier}.png`, await page.screenshot());
      } finally {
        await context.close();
      }
    });

    test("zoomed to 200 % (a 1280-pixel window seen as 640 CSS pixels) nothing shrinks it back", async () => {
      const { context, page } = await open(browser, server.url, { width: 640, height: 400, deviceScaleFactor: 2 });
      try {
        const s = await state(page);
        assert.equal(s.ui_scale, 1, "Shoal adds no scale of its own: the browser's zoom stands");
        await clickUntil(page, "show_panel", () => !!window.shoal.widgets().hide_panel);
        await waitFrames(page, 2);
        const w = await widgets(page);
        for (const name of ["hide_panel", "scene_learning", "reset", "new_seed"]) {
          assert.ok(w[name] && w[name].x + w[name].width <= 640, `${name} fits: ${JSON.stringify(w[name])}`);
        }
        saveArtifact(`seeing-zoom-200-${tier}.png`, await page.screenshot());
      } finally {
        await context.close();
      }
    });

    test("at 320 CSS pixels wide the drawer's controls fit the screen", async () => {
      const { context, page } = await open(browser, server.url, { width: 320, height: 640, hasTouch: true, isMobile: true });
      try {
        await clickUntil(page, "show_panel", () => !!window.shoal.widgets().hide_panel);
        await waitFrames(page, 2);
        const w = await widgets(page);
        const names = [
          "hide_panel",
          "scene_aquarium",
          "scene_boids",
          "scene_physics",
          "scene_reef",
          "scene_learning",
          "play_pause",
          "step",
          "reset",
          "new_seed",
        ];
        for (const name of names) {
          assert.ok(w[name], `${name} is drawn`);
          assert.ok(w[name].x >= 0 && w[name].x + w[name].width <= 320, `${name} fits: ${JSON.stringify(w[name])}`);
        }
        saveArtifact(`seeing-320px-${tier}.png`, await page.screenshot());
        // The schooling lab's longer panel: its rows fit too.
        await page.evaluate(() => window.shoal.set({ scene: "boids" }));
        await page.waitForFunction(() => window.shoal.widgets().compare, null, { timeout: 60_000 });
        await waitFrames(page, 2);
        const b = await widgets(page);
        for (const name of ["compare", "scene_boids", "play_pause"]) {
          assert.ok(b[name].x >= 0 && b[name].x + b[name].width <= 320, `${name} fits: ${JSON.stringify(b[name])}`);
        }
        saveArtifact(`seeing-320px-boids-${tier}.png`, await page.screenshot());
      } finally {
        await context.close();
      }
    });
  });
}
