// The orbit camera as a person uses it: drag to turn, wheel to zoom, right-drag to
// pan, "Reset view" to come back; and on a touch screen: tap a button, pinch to zoom.
import { describe, test, before, after } from "node:test";
import assert from "node:assert/strict";
import { serveDist, launch, openShoal, clickWidget, sleep } from "./harness.mjs";

const camera = (page) => page.evaluate(() => window.shoal.state().camera);
const aquariumCentre = async (page) => {
  const r = await page.evaluate(() => window.shoal.widgets().aquarium);
  return { x: r.x + r.width / 2, y: r.y + r.height / 2 };
};

describe("orbit camera with a mouse (WebGL2 tier)", () => {
  let server, browser, page;
  before(async () => {
    server = await serveDist();
    browser = await launch("webgl2");
    ({ page } = await openShoal(browser, server.url));
  });
  after(async () => {
    await browser?.close();
    await server?.close();
  });

  test("dragging turns, the wheel zooms, right-drag pans, Reset view restores", async () => {
    const start = await camera(page);
    const c = await aquariumCentre(page);

    await page.mouse.move(c.x, c.y);
    await page.mouse.down();
    await page.mouse.move(c.x + 150, c.y + 40, { steps: 8 });
    await page.mouse.up();
    await page.waitForFunction((y) => Math.abs(window.shoal.state().camera.yaw_deg - y) > 20, start.yaw_deg, { timeout: 15_000 });
    const turned = await camera(page);
    assert.ok(Math.abs(turned.yaw_deg - start.yaw_deg) > 20, `yaw ${start.yaw_deg} → ${turned.yaw_deg}`);
    assert.notEqual(turned.pitch_deg, start.pitch_deg);

    await page.mouse.move(c.x, c.y);
    await page.mouse.wheel(0, -400);
    await page.waitForFunction((d) => window.shoal.state().camera.distance_m < d * 0.9, turned.distance_m, { timeout: 15_000 });
    await sleep(1000); // smooth scrolling settles over a few frames
    const zoomed = await camera(page);
    assert.ok(zoomed.distance_m < turned.distance_m * 0.9, `distance ${turned.distance_m} → ${zoomed.distance_m}`);

    await page.mouse.move(c.x, c.y);
    await page.mouse.down({ button: "right" });
    await page.mouse.move(c.x - 120, c.y, { steps: 8 });
    await page.mouse.up({ button: "right" });
    await page.waitForFunction(
      (t) => Math.hypot(...window.shoal.state().camera.target_m.map((v, i) => v - t[i])) > 0.3,
      zoomed.target_m,
      { timeout: 15_000 },
    );
    const panned = await camera(page);
    const moved = Math.hypot(...panned.target_m.map((v, i) => v - zoomed.target_m[i]));
    assert.ok(moved > 0.3, `target moved ${moved} m`);

    await clickWidget(page, "reset_view");
    await page.waitForFunction((d) => window.shoal.state().camera.distance_m === d, start.distance_m, { timeout: 15_000 });
    assert.deepEqual(await camera(page), start);
  });
});

describe("framing (WebGL2 tier)", () => {
  test("V puts the camera back, and a new scene or demo opens framed on its subject (issue 14)", async () => {
    const server = await serveDist();
    const browser = await launch("webgl2");
    try {
      const { page } = await openShoal(browser, server.url);
      const start = await camera(page);
      const c = await aquariumCentre(page);
      await page.mouse.move(c.x, c.y);
      await page.mouse.wheel(0, -400);
      await page.waitForFunction((d) => window.shoal.state().camera.distance_m < d * 0.9, start.distance_m, { timeout: 15_000 });
      await sleep(1000);
      await page.keyboard.press("v", { delay: 100 });
      await page.waitForFunction((d) => window.shoal.state().camera.distance_m === d, start.distance_m, { timeout: 15_000 });
      assert.deepEqual(await camera(page), start, "V frames the tank again");

      // The courtship demo opens on the trio, closer than the whole tank.
      await page.evaluate(() => window.shoal.set({ scene: "reef", reef: { demo: "courtship" } }));
      await page.waitForFunction((d) => window.shoal.state().camera.distance_m < d * 0.8, start.distance_m, { timeout: 30_000 });
      // School meets obstacle looks down on the pillar.
      await page.evaluate(() => window.shoal.set({ reef: { demo: "school_meets_obstacle" } }));
      await page.waitForFunction(() => window.shoal.state().camera.pitch_deg > 60, null, { timeout: 30_000 });
      // Following a fish brings the camera close; the next scene opens on its whole tank.
      // (The feeding demo's fish are small: following one comes within a few metres.)
      await page.evaluate(() => window.shoal.set({ reef: { demo: "feeding", selected: 0, follow: true } }));
      await page.waitForFunction((d) => window.shoal.state().camera.distance_m < d * 0.7, start.distance_m, { timeout: 30_000 });
      const close = await camera(page);
      await page.evaluate(() => window.shoal.set({ scene: "boids" }));
      await page.waitForFunction((d) => window.shoal.state().camera.distance_m > d * 2, close.distance_m, { timeout: 30_000 });
      await sleep(1000);
      const opened = await camera(page);
      await page.keyboard.press("v", { delay: 100 });
      await sleep(1000);
      assert.deepEqual(await camera(page), opened, "the schooling lab opened on its whole tank, as V frames it");
      const button = await page.evaluate(() => window.shoal.widgets().reset_view);
      const view = await page.evaluate(() => window.shoal.widgets().view_left);
      assert.ok(button.y + button.height <= view.y + view.height, "Reset view is on the tank, in sight");
    } finally {
      await browser.close();
      await server.close();
    }
  });
});

describe("keyboard (WebGL2 tier)", () => {
  test("Space pauses and plays, S steps once", async () => {
    const server = await serveDist();
    const browser = await launch("webgl2");
    try {
      const { page } = await openShoal(browser, server.url);
      await page.click("#shoal_canvas", { position: { x: 700, y: 650 } });
      await page.keyboard.press("Space", { delay: 100 });
      await page.waitForFunction(() => window.shoal.state().paused, null, { timeout: 10_000 });
      const steps = await page.evaluate(() => window.shoal.state().steps);
      await page.keyboard.press("s", { delay: 100 });
      await page.waitForFunction((n) => window.shoal.state().steps === n + 1, steps, { timeout: 10_000 });
      await page.keyboard.press("Space", { delay: 100 });
      await page.waitForFunction(() => !window.shoal.state().paused, null, { timeout: 10_000 });
    } finally {
      await browser.close();
      await server.close();
    }
  });
});

describe("touch screen (WebGL2 tier)", () => {
  test("a tap presses Pause and a pinch zooms", async () => {
    const server = await serveDist();
    const browser = await launch("webgl2");
    try {
      const context = await browser.newContext({ viewport: { width: 1024, height: 700 }, hasTouch: true });
      const page = await context.newPage();
      await page.goto(server.url);
      await page.waitForFunction(() => window.shoal && window.shoal.state().steps > 30, null, { timeout: 90_000 });

      const button = await page.evaluate(() => window.shoal.widgets().play_pause);
      await page.touchscreen.tap(button.x + button.width / 2, button.y + button.height / 2);
      await page.waitForFunction(() => window.shoal.state().paused, null, { timeout: 10_000 });

      const before = await camera(page);
      const c = await aquariumCentre(page);
      const cdp = await context.newCDPSession(page);
      const touch = (type, spread) =>
        cdp.send("Input.dispatchTouchEvent", {
          type,
          touchPoints: type === "touchEnd" ? [] : [
            { x: c.x - spread, y: c.y, id: 1 },
            { x: c.x + spread, y: c.y, id: 2 },
          ],
        });
      await touch("touchStart", 40);
      for (let spread = 50; spread <= 200; spread += 15) {
        await touch("touchMove", spread);
        await sleep(120);
      }
      await sleep(1000);
      await touch("touchEnd", 0);
      await page.waitForFunction((d) => window.shoal.state().camera.distance_m < d * 0.8, before.distance_m, { timeout: 15_000 });
      const after = await camera(page);
      assert.ok(after.distance_m < before.distance_m * 0.8, `pinch: distance ${before.distance_m} → ${after.distance_m}`);
    } finally {
      await browser.close();
      await server.close();
    }
  });
});
