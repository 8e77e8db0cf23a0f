// WCAG 2.4.3 focus order and 2.4.7 focus visible, across windows: with the
// investigation window open over the tank, Tab walks every control once, each
// stop is on the screen with the focus ring round it, and the window's
// controls come as one run, top to bottom, not interleaved with the side
// panel's.
import { describe, test, before, after } from "node:test";
import assert from "node:assert/strict";
import { serveDist, launch, openShoal, TIERS, walkOnly, waitFrames, saveArtifact } from "./harness.mjs";

/** The focused stop: the mirror's element (its name, where it is, whether the
 * focus ring is round it and which window holds it), or what else has focus. */
function read(page) {
  return page.evaluate(() => {
    const a = document.activeElement;
    if (!a || !a.closest("#shoal_a11y")) return { outside: a?.id || a?.tagName || "none" };
    const r = a.getBoundingClientRect();
    const ring = document.getElementById("shoal_focus_ring");
    const q = ring.getBoundingClientRect();
    const win = a.closest("[aria-modal]");
    return {
      name: a.getAttribute("aria-label") || a.textContent,
      node: a.dataset.node,
      x: r.x, y: r.y, w: r.width, h: r.height,
      ring: getComputedStyle(ring).display !== "none" && q.width > 0,
      ringOnIt: q.x <= r.x + r.width && q.x + q.width >= r.x && q.y <= r.y + r.height && q.y + q.height >= r.y,
      window: win ? win.getAttribute("aria-label") || "window" : null,
    };
  });
}

for (const tier of TIERS) {
  describe(`Tab order across windows (${tier})`, () => {
    let server, browser;
    before(async () => {
      server = await serveDist();
      browser = await launch(tier);
    });
    after(async () => {
      await browser?.close();
      await server?.close();
    });

    test("Tab walks the side panel and the open investigation window, every stop visible and ringed", walkOnly(tier), async () => {
      const width = 1280, height = 800;
      const { page, errors } = await openShoal(browser, `${server.url}?investigation=why-school#`, { width, height });
      await page.waitForSelector("#shoal_a11y [aria-modal]", { state: "attached", timeout: 60_000 });
      await page.focus("#shoal_canvas");
      const stops = [];
      for (let i = 0; i < 150; i++) {
        await page.keyboard.press("Tab", { delay: 100 });
        // egui scrolls its panel to the new focus on the next frames: read the
        // stop once it has settled (a few frames at most).
        let stop;
        for (let settle = 0; settle < 5; settle++) {
          await waitFrames(page, 1);
          stop = await read(page);
          if (!stop.node || (stop.y >= 0 && stop.y + stop.h <= height && stop.ringOnIt)) break;
        }
        // Once round: the walk is back at its first control.
        if (stops.length > 2 && stop.node && stop.node === stops.find((s) => s.node)?.node) break;
        stops.push(stop);
      }
      saveArtifact(`tab-order-${tier}.json`, Buffer.from(JSON.stringify(stops, null, 1)));
      const controls = stops.filter((s) => s.node);
      assert.ok(controls.length > 20, `Tab reached ${controls.length} controls`);
      // The only stop outside the mirror is the tank itself (the canvas).
      for (const s of stops.filter((s) => !s.node)) assert.equal(s.outside, "shoal_canvas", JSON.stringify(s));
      // No control twice in one round.
      const nodes = controls.map((s) => s.node);
      assert.equal(new Set(nodes).size, nodes.length, "each control once");
      // No invisible stop: on the screen, with a size, and the ring round it.
      for (const s of controls) {
        assert.ok(s.w > 0 && s.h > 0, `a stop with no size: ${JSON.stringify(s)}`);
        assert.ok(s.x + s.w > 0 && s.x < width && s.y + s.h > 0 && s.y < height, `a stop off the screen: ${JSON.stringify(s)}`);
        assert.ok(s.ring && s.ringOnIt, `the focus ring is not round ${JSON.stringify(s)}`);
      }
      // The window's controls: reached, in one run, top to bottom.
      const inWindow = controls.map((s, i) => [s, i]).filter(([s]) => s.window);
      assert.ok(inWindow.length >= 2, `the investigation window's controls are reached (${inWindow.length})`);
      const first = inWindow[0][1], last = inWindow[inWindow.length - 1][1];
      assert.equal(last - first + 1, inWindow.length, "the window's controls come as one run");
      for (let k = 1; k < inWindow.length; k++) {
        const [a] = inWindow[k - 1], [b] = inWindow[k];
        assert.ok(b.y >= a.y - 4, `the window reads top to bottom: ${a.name} then ${b.name}`);
      }
      assert.deepEqual(errors, []);
      await page.close();
    });
  });
}
