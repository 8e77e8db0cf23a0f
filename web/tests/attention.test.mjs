// What a fish pays attention to (issue 15, item 2): in the schooling lab a click on
// a fish selects it; its field of view, the neighbours it heeds (rings), its five
// urges as arrows and the result are drawn over the tank; the side panel explains
// them; shoal.state().metrics.attention reports them; a click on open water lets
// go. WebGL2 (SwiftShader).
import { test, describe, before, after } from "node:test";
import assert from "node:assert/strict";
import {
  serveDist,
  launch,
  openShoal,
  saveArtifact,
  clickUntil,
  waitForWidget,
} from "./harness.mjs";

const state = (page) => page.evaluate(() => window.shoal.state());
const settings = (page) => page.evaluate(() => window.shoal.settings());

/** A paused app draws only when something asks: a small mouse move over the side
 * panel asks for a frame, and this waits for it. */
let nudges = 0;
async function redraw(page) {
  nudges += 1;
  const start = await page.evaluate(() => window.shoal.state().frames);
  await page.mouse.move(60 + (nudges % 2) * 4, 600);
  await page.waitForFunction((s) => window.shoal.state().frames > s, start, { timeout: 60_000 });
}

describe("what a fish pays attention to", () => {
  let server, browser, page, errors;

  before(async () => {
    server = await serveDist();
    browser = await launch("webgl2");
    const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
    ({ page, errors } = await openShoal(context, server.url));
  });

  after(async () => {
    await browser?.close();
    await server?.close();
  });

  test("clicking a fish shows its attention and state() reports it", async () => {
    await clickUntil(page, "scene_boids", () => window.shoal.state().scene === "boids");
    // A school of 60 (Table 1's group weights) that has had time to form, held still.
    await page.evaluate(() => {
      window.shoal.set({ left: { preset: "group", fish_count: 60 } });
      window.shoal.pause();
      window.shoal.step(600);
    });
    await redraw(page);
    await waitForWidget(page, "animal_5");
    await clickUntil(page, "animal_5", () => window.shoal.settings().left.selected != null);
    const selected = (await settings(page)).left.selected;
    await redraw(page);
    const s = await state(page);
    const attention = s.metrics.attention;
    assert.ok(attention, "state().metrics.attention is reported");
    assert.equal(attention.fish, selected);
    assert.equal(attention.mode, "blended");
    assert.deepEqual(
      attention.urges.map((u) => u.urge),
      ["containment", "alignment", "cohesion", "separation", "avoidance"],
    );
    // Blended: every weighted urge is applied.
    assert.ok(attention.urges.every((u) => u.applied));
    for (const u of attention.urges) {
      assert.ok(Number.isFinite(u.strength_m_per_s2) && u.strength_m_per_s2 >= 0, u.urge);
    }
    assert.ok(attention.neighbours.length >= 1 && attention.neighbours.length <= 7);
    assert.ok(!attention.neighbours.includes(selected), "a fish does not heed itself");
    // The side panel explains it.
    await waitForWidget(page, "attention_table_left");
    await waitForWidget(page, "attention_let_go_left");
    // A step later it is still selected and its report follows the step.
    await page.evaluate(() => window.shoal.step(1));
    await redraw(page);
    const later = await state(page);
    assert.equal(later.metrics.attention.fish, selected, "the selection survives a step");
    // Closer, for the picture: the mouse wheel over the school zooms in.
    const fish = await waitForWidget(page, `animal_${selected}`).catch(() => null);
    const view = await waitForWidget(page, "view_left");
    const at = fish ?? { x: view.x + view.width / 2, y: view.y + view.height / 2, width: 0, height: 0 };
    await page.mouse.move(at.x + at.width / 2, at.y + at.height / 2);
    for (let k = 0; k < 7; k++) {
      await page.mouse.wheel(0, -120);
      await redraw(page);
    }
    await redraw(page);
    saveArtifact("attention.png", await page.screenshot());
    assert.deepEqual(errors, []);
  });

  test("Classic mode applies exactly one urge, and a click on open water lets go", async () => {
    await page.evaluate(() => {
      window.shoal.set({ left: { mode: "classic" } });
      window.shoal.step(2);
    });
    await redraw(page);
    const attention = (await state(page)).metrics.attention;
    assert.equal(attention.mode, "classic");
    assert.equal(attention.urges.filter((u) => u.applied).length, 1);
    // Open water: the bottom left corner of the view, under the tank, where no fish
    // swims (clicked again if a slow frame missed the click).
    const view = await waitForWidget(page, "view_left");
    let letGo = false;
    for (let attempt = 0; attempt < 4 && !letGo; attempt++) {
      await page.mouse.click(view.x + 20, view.y + view.height - 20, { delay: 80 });
      letGo = await page
        .waitForFunction(() => window.shoal.settings().left.selected === null, null, {
          timeout: 15_000,
        })
        .then(() => true)
        .catch(() => false);
    }
    assert.ok(letGo, "a click on open water lets the fish go");
    await redraw(page);
    assert.equal((await state(page)).metrics.attention, undefined);
    assert.deepEqual(errors, []);
  });
});
