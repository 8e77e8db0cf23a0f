// The learning lab (issue 6) as a teacher uses it: real clicks on the scene
// button, Start/Pause training, the controller switch and the race; training runs
// across frames without freezing the page and survives a visit to another scene;
// the plots fill; a bad controllers file is refused with a message. WebGL2.
import { test, describe, before, after } from "node:test";
import assert from "node:assert/strict";
import {
  serveDist,
  launch,
  openShoal,
  decode,
  pixelStats,
  saveArtifact,
  clickUntil,
  waitForWidget,
  changedPixels,
  waitFrames,
} from "./harness.mjs";

const state = (page) => page.evaluate(() => window.shoal.state());

describe("learning lab", () => {
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

  test("the scene button opens the lab; Start training trains across frames", async () => {
    await clickUntil(page, "scene_learning", () => window.shoal.state().scene === "learning");
    await page.evaluate(() => window.shoal.set({ learning: { annealing_steps: 200 } }));
    await waitForWidget(page, "learning_train");
    let s = await state(page);
    assert.equal(s.learning.evaluations, 0);
    assert.equal(s.learning.drills, 7);
    await clickUntil(page, "learning_train", () => window.shoal.settings().learning.training);
    // The page keeps drawing while it trains: frames and tries both advance.
    const frames = s.steps;
    await page.waitForFunction(() => window.shoal.state().learning.evaluations >= 40, null, { timeout: 120_000 });
    s = await state(page);
    assert.ok(s.steps > frames, "the swimmer kept swimming while training ran");
    await clickUntil(page, "learning_train", () => !window.shoal.settings().learning.training);
    const paused = (await state(page)).learning.evaluations;
    await page.waitForFunction((n) => window.shoal.state().steps > n + 20, s.steps, { timeout: 60_000 });
    assert.equal((await state(page)).learning.evaluations, paused, "paused training stays put");
  });

  test("training lowers the objective and leaving the scene keeps the progress", async () => {
    const before = (await state(page)).learning;
    await page.evaluate(() => window.shoal.train(150));
    let s = await state(page);
    // The tries across frames may have brought the drill near its end, so the 150
    // can finish it and start the next: then the finished drill's objective
    // is the one that fell.
    if (s.learning.drill === before.drill) {
      assert.ok(s.learning.best_objective < s.learning.start_objective, JSON.stringify(s.learning));
    } else {
      assert.ok(s.learning.finished.length > before.finished.length, JSON.stringify(s.learning));
      const [objective] = s.learning.finished[before.drill];
      assert.ok(objective < before.start_objective, `${objective} vs ${before.start_objective}`);
    }
    const progress = s.learning.progress;
    await clickUntil(page, "scene_reef", () => window.shoal.state().scene === "reef");
    await clickUntil(page, "scene_learning", () => window.shoal.state().scene === "learning");
    s = await state(page);
    assert.equal(s.learning.progress, progress, "progress kept across scenes");
    for (const name of ["learning_objective_plot", "learning_raw_plot", "learning_modes_plot", "learning_abstract_plot"]) {
      await waitForWidget(page, name);
    }
    await waitFrames(page, 3);
    const shot = await page.screenshot();
    saveArtifact("learning-webgl2.png", shot);
    const png = decode(shot);
    const w = await page.evaluate(() => window.shoal.widgets());
    for (const name of ["learning_objective_plot", "learning_raw_plot", "learning_modes_plot", "learning_abstract_plot"]) {
      assert.ok(w[name], `${name} is on screen`);
      assert.ok(pixelStats(png, w[name]).distinctColours > 6, `${name} has lines`);
    }
    // The swimmer moves: the view changes between two moments.
    await page.evaluate(() => window.shoal.pause());
    // Paused, the app draws only when asked: pause() and step() each ask once.
    await waitFrames(page, 1);
    const a = decode(await page.screenshot());
    await page.evaluate(() => window.shoal.step(40));
    await waitFrames(page, 1);
    const b = decode(await page.screenshot());
    await page.evaluate(() => window.shoal.play());
    const changed = changedPixels(a, b, w.view_left);
    assert.ok(changed > 40, `the swimmer moved on screen: ${changed} pixels changed`);
  });

  test("the race: sharks trained longer swim farther; the controller switch restarts the swimmer", async () => {
    // Finish the first drill (200 tries) so the race has its entrants.
    await page.evaluate(() => window.shoal.train(200));
    await clickUntil(page, "learning_race", () => window.shoal.state().learning.race !== undefined);
    await page.evaluate(() => window.shoal.step(60));
    const race = (await state(page)).learning.race;
    assert.equal(race.length, 6);
    const distances = race.map(([, d]) => d);
    assert.ok(distances[5] > distances[0], `the best-trained beats the least: ${distances}`);
    await clickUntil(page, "learning_hand_tuned", () => window.shoal.state().learning.controller === "hand_tuned");
    const s = await state(page);
    assert.ok(s.steps < 40 && s.learning.buoy_times_secs.length === 0, `the swimmer started again: ${s.steps}`);
    saveArtifact("learning-race-webgl2.png", await page.screenshot());
  });

  test("saved controllers load back; a bad file is refused and changes nothing", async () => {
    const text = await page.evaluate(() => window.shoal.save_controllers());
    assert.match(text, /"version": 1/);
    const refused = await page.evaluate(() => {
      try {
        window.shoal.load_controllers('{"version": 9, "species": "fish", "drills": []}');
        return "no error";
      } catch (err) {
        return String(err.message);
      }
    });
    assert.match(refused, /load_controllers/);
    assert.equal((await state(page)).learning.source, "shipped");
    await page.evaluate((t) => window.shoal.load_controllers(t), text);
    assert.equal((await state(page)).learning.source, "loaded");
    assert.deepEqual(errors, []);
  });
});
