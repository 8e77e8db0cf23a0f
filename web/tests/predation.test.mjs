// The confusion effect and joint flight switches (issue 32 item 7), as a teacher
// uses them: real clicks in the schooling lab's panel and the reef's, the Paper
// only button, and the same switches through shoal.set. WebGL2 (SwiftShader).
import { test, describe, before, after } from "node:test";
import assert from "node:assert/strict";
import { serveDist, launch, openShoal, saveArtifact, clickUntil, scrollPanelTo } from "./harness.mjs";

const settings = (page) => page.evaluate(() => window.shoal.settings());

describe("predation switches", () => {
  let server, browser, page;

  before(async () => {
    server = await serveDist();
    browser = await launch("webgl2");
    const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
    ({ page } = await openShoal(context, server.url));
  });

  after(async () => {
    await browser?.close();
    await server?.close();
  });

  test("schooling lab: both on by default; Paper only turns both off; a click turns confusion back on", async () => {
    await clickUntil(page, "scene_boids", () => window.shoal.state().scene === "boids");
    let s = await settings(page);
    assert.deepEqual(s.predation, { confusion: true, joint_flight: true });
    await clickUntil(page, "predation_paper_only", () => {
      const p = window.shoal.settings().predation;
      return !p.confusion && !p.joint_flight;
    });
    await scrollPanelTo(page, "predation_paper_only");
    saveArtifact("predation-boids.png", await page.screenshot());
    await clickUntil(page, "predation_confusion", () => window.shoal.settings().predation.confusion);
    s = await settings(page);
    assert.deepEqual(s.predation, { confusion: true, joint_flight: false });
  });

  test("reef: the same switches, shared with the schooling lab", async () => {
    await clickUntil(page, "scene_reef", () => window.shoal.state().scene === "reef");
    await clickUntil(page, "predation_joint_flight", () => window.shoal.settings().predation.joint_flight);
    await scrollPanelTo(page, "predation_joint_flight");
    saveArtifact("predation-reef.png", await page.screenshot());
    const ok = await page.evaluate(() => window.shoal.set({ predation: { confusion: false } }));
    assert.ok(ok === undefined || ok === true || ok?.ok !== false, JSON.stringify(ok));
    const s = await settings(page);
    assert.deepEqual(s.predation, { confusion: false, joint_flight: true });
  });
});
