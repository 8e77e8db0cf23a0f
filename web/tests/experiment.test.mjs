// Experiments in the browser (issue 16): the schooling lab's Experiment window
// through real clicks (open, start, the page keeps drawing, cancel keeps the
// finished runs), the automation API (shoal.experiment, state().experiment,
// shoal.run_experiment), the results (plot, table, watching one run), and the
// browser's CSV against the native engine's for the same design, byte for byte
// (web/tests/fixtures/experiment-tiny.csv and experiment-physics.csv, written
// and checked by the native tests experiment::session_tests); the physics
// tank's Experiment button; Copy link, whose link runs the experiment again
// in a new page (and a damaged one, refused with a notice). WebGL2 (SwiftShader), then WebGPU.
import { test, describe, before, after } from "node:test";
import assert from "node:assert/strict";
import fs from "node:fs";
import path from "node:path";
import {
  repoRoot,
  serveDist,
  launch,
  openShoal,
  saveArtifact,
  clickWidget,
  clickUntil,
  clickInWindow,
  scrollWindowTo,
  scrollPanelTo,
  waitForWidget,
  waitFrames,
  sleep,
  TIERS,
  walkOnly,
} from "./harness.mjs";

const fixtures = path.join(repoRoot, "web", "tests", "fixtures");
const tinyDesign = JSON.parse(fs.readFileSync(path.join(fixtures, "experiment-tiny.json"), "utf8"));
const nativeCsv = fs.readFileSync(path.join(fixtures, "experiment-tiny.csv"), "utf8");
const physicsDesign = JSON.parse(fs.readFileSync(path.join(fixtures, "experiment-physics.json"), "utf8"));
const nativePhysicsCsv = fs.readFileSync(path.join(fixtures, "experiment-physics.csv"), "utf8");

const state = (page) => page.evaluate(() => window.shoal.state());
const experiment = (page) => page.evaluate(() => window.shoal.state().experiment);

/** Clicks widget `name` of the Experiment window until `predicate` holds. */
const clickInExperiment = (page, name, predicate) =>
  clickInWindow(page, name, predicate, undefined, { windowName: "experiment_window", bottomMargin: 4 });

/** The first line where two CSVs differ, or null. */
function firstDifference(a, b) {
  const la = a.split("\n");
  const lb = b.split("\n");
  for (let i = 0; i < Math.max(la.length, lb.length); i++) {
    if (la[i] !== lb[i]) return { line: i + 1, browser: la[i], native: lb[i] };
  }
  return null;
}

for (const tier of TIERS) {
  describe(`experiments (${tier})`, () => {
    let server, browser, page, errors;

    before(async () => {
      server = await serveDist();
      browser = await launch(tier);
      ({ page, errors } = await openShoal(browser, server.url, { width: 1280, height: 900 }));
      await clickUntil(page, "scene_boids", () => window.shoal.state().scene === "boids");
      // A small school, so the runs are quick: the window's base is the tank as it is.
      await page.evaluate(() => window.shoal.set({ left: { preset: "group", fish_count: 40 } }));
    });

    after(async () => {
      await browser?.close();
      await server?.close();
    });

    test("the Experiment button opens the design window with the runs and the time", async () => {
      await scrollPanelTo(page, "experiment");
      await clickUntil(page, "experiment", () => !!window.shoal.widgets().experiment_sizing);
      const w = await page.evaluate(() => window.shoal.widgets());
      assert.ok(w.experiment_window.width <= 1280 - 24, "the window fits the screen");
      assert.ok(w.experiment_start && w.experiment_factor, "start and the factor's list");
      await waitFrames(page, 2);
      if (tier === "webgl2") saveArtifact("experiment-design.png", await page.screenshot());
    });

    test("a refused design names its field, through the API", async () => {
      const message = await page.evaluate(() => {
        try {
          window.shoal.experiment({
            settings: { scene: "boids" },
            factors: [{ key: "left.alignmnt", levels: [0, 1] }],
            replicates: { count: 2 },
            warmup_secs: 1,
            measure_secs: 1,
            measures: [{ measure: "polarization" }],
          });
          return null;
        } catch (err) {
          return err.message;
        }
      });
      assert.ok(message && message.includes("factors[0].key"), message);
      assert.equal((await state(page)).experiment, undefined, "nothing started");
    });

    test("Start runs the window's design while the tank keeps drawing; Cancel keeps the finished runs", async () => {
      // A school big enough that the nine runs last a while on a slow page too
      // (where they get half of each slow frame): there is something to cancel.
      await page.evaluate(() => window.shoal.set({ left: { fish_count: 400 } }));
      await clickInExperiment(page, "experiment_start", () => !!window.shoal.state().experiment);
      const samples = [];
      const started = Date.now();
      for (;;) {
        const t0 = Date.now();
        const s = await state(page);
        samples.push({ at: t0, frames: s.frames, waited: Date.now() - t0, e: s.experiment });
        // At least one run done, and long enough to count frames: a loaded CI
        // machine draws SwiftShader frames slowly, and a 40-fish run is quick.
        const drawn = s.frames - samples[0].frames;
        if (s.experiment.runs_done >= 1 && (drawn > 5 || !s.experiment.running)) break;
        assert.ok(Date.now() - started < 240_000, "a run finishes and frames are drawn within 4 minutes");
        await sleep(250);
      }
      const first = samples[0];
      const last = samples.at(-1);
      assert.ok(last.e.running, "still running after one run");
      assert.ok(last.e.steps_done > first.e.steps_done, "steps advance");
      // The page answered every poll and kept drawing: frames grew between polls.
      const secs = (last.at - first.at) / 1000;
      const fps = (last.frames - first.frames) / Math.max(secs, 1e-3);
      assert.ok(samples.every((s) => s.waited < 3000), "no poll waited 3 s for the page");
      assert.ok(last.frames > first.frames + 5, `frames ${first.frames} → ${last.frames}`);
      console.log(`${tier}: ${fps.toFixed(1)} frames/s during the experiment, ${samples.length} polls`);
      await waitFrames(page, 2);
      if (tier === "webgl2") saveArtifact("experiment-running.png", await page.screenshot());
      await clickInExperiment(page, "experiment_cancel", () => window.shoal.state().experiment.cancelled);
      const e = await experiment(page);
      assert.equal(e.running, false);
      assert.ok(e.runs_done >= 1 && e.runs_done < e.runs_total, `${e.runs_done} of ${e.runs_total}`);
      assert.ok(e.csv.includes(`# completed: ${e.runs_done} of ${e.runs_total} runs`), "the CSV says it is partial");
      assert.ok(e.summary.length >= 1, "the completed runs are summarised");
      await waitForWidget(page, "experiment_results");
      await page.evaluate(() => window.shoal.set({ left: { fish_count: 40 } }));
    });

    test("shoal.run_experiment gives the summary and the native engine's CSV", async () => {
      const polls = [];
      const poller = setInterval(async () => {
        try {
          polls.push(await page.evaluate(() => window.shoal.state().frames));
        } catch {}
      }, 100);
      const result = await page.evaluate((d) => window.shoal.run_experiment(d), tinyDesign);
      clearInterval(poller);
      assert.ok(polls.length >= 1 && polls.at(-1) >= polls[0], "frames during the run");
      // Both levels, each measure, two seeds.
      const levels = [...new Set(result.summary.map((r) => r.levels[0]))].sort((a, b) => a - b);
      assert.deepEqual(levels, [0, 80]);
      assert.equal(result.summary.length, 4);
      for (const row of result.summary) {
        assert.equal(row.n, 2);
        assert.ok(row.ci95_low <= row.mean && row.mean <= row.ci95_high, JSON.stringify(row));
        assert.ok(["polarization", "nnd_body_lengths"].includes(row.measure));
      }
      saveArtifact(`experiment-tiny-${tier}.csv`, Buffer.from(result.csv));
      // The browser's CSV against the native engine's (docs/experiments.md,
      // "Browser and native give the same CSV"): the same bytes, every number.
      const diff = firstDifference(result.csv, nativeCsv);
      assert.equal(diff, null, diff && `line ${diff.line}:\n  browser ${diff.browser}\n  native  ${diff.native}`);
      assert.equal(result.csv, nativeCsv);
      const e = await experiment(page);
      assert.equal(e.running, false);
      assert.equal(e.cancelled, false);
      assert.equal(e.runs_done, 4);
      assert.equal(e.steps_done, e.steps_total);
      assert.equal(e.csv, result.csv);
    });

    test("Copy link: the experiment's link opens a page that runs it again, to the same CSV", walkOnly(tier), async () => {
      await clickInExperiment(page, "experiment_link", () => (window.shoal.state().notice || "").includes("Link copied"));
      const link = await page.evaluate(() => window.shoal.experiment_link());
      assert.ok(link.startsWith(`${server.url}?experiment=v1.`), link);
      // The first page waits paused (it then draws only when asked), so that the
      // machine's two cores run the reopened page's experiment.
      await page.evaluate(() => window.shoal.set({ paused: true }));
      const opened = await openShoal(browser, link, { width: 1280, height: 900 });
      const other = opened.page;
      await other.waitForFunction(() => window.shoal.state().experiment && !window.shoal.state().experiment.running, null, {
        timeout: 300_000,
        polling: 500,
      });
      const s = await other.evaluate(() => window.shoal.state());
      assert.equal(s.scene, "boids", "the experiment's scene");
      assert.ok(s.notice.includes("reopened the experiment 'tiny'"), s.notice);
      assert.equal(s.experiment.csv, nativeCsv, "the same runs, the same numbers");
      await waitForWidget(other, "experiment_results");
      if (tier === "webgl2") saveArtifact("experiment-link.png", await other.screenshot());
      assert.deepEqual(opened.errors, []);
      await other.close();

      // Cut off when copied: a notice says so, and the rest of the page works.
      const cut = link.slice(0, Math.floor(link.length * 0.6));
      const damaged = await openShoal(browser, cut, { width: 1280, height: 900 });
      const d = await damaged.page.evaluate(() => window.shoal.state());
      assert.ok(d.notice && d.notice.includes("could not open its experiment") && d.notice.includes("damaged"), d.notice);
      assert.equal(d.experiment, undefined, "nothing runs");
      await damaged.page.evaluate(() => window.shoal.step(5));
      await damaged.page.close();
      await page.evaluate(() => window.shoal.set({ paused: false }));
    });

    test("the results: a plot per measure, the table, and watching one run", async () => {
      await waitForWidget(page, "experiment_plot_0");
      await waitForWidget(page, "experiment_plot_1");
      await waitFrames(page, 3);
      if (tier === "webgl2") saveArtifact("experiment-results.png", await page.screenshot());
      // Row 1 is alignment 80; its first seed is 1.
      await clickInExperiment(
        page,
        "experiment_watch_1_0",
        () => window.shoal.settings().left.alignment === 80 && window.shoal.settings().seed === 1
      );
      const s = await state(page);
      assert.ok(s.time_secs < 5, `the run restarts from its start (${s.time_secs} s)`);
      assert.equal((await page.evaluate(() => window.shoal.settings())).left.fish_count, 40);
      assert.deepEqual(errors, []);
    });

    if (tier === "webgl2") {
      test("a readable dose-response for the docs: alignment 0 to 100, three seeds", async () => {
        await clickInExperiment(page, "experiment_clear", () => !window.shoal.widgets().experiment_results);
        const result = await page.evaluate(
          (d) => window.shoal.run_experiment(d),
          {
            ...tinyDesign,
            name: "alignment-sweep",
            factors: [{ key: "left.alignment", levels: { from: 0, to: 100, steps: 5 } }],
            replicates: { count: 3, first_seed: 1 },
            warmup_secs: 5,
            measure_secs: 10,
            measures: [{ measure: "polarization", summary: "mean" }, { measure: "nnd_body_lengths", summary: "mean" }],
          }
        );
        assert.equal(result.summary.length, 5 * 2);
        await waitForWidget(page, "experiment_plot_1");
        await scrollWindowTo(page, "experiment_plot_0", { windowName: "experiment_window", bottomMargin: 4 });
        await waitFrames(page, 3);
        saveArtifact("experiment-results-docs.png", await page.screenshot());
      });
    }
  });
}

for (const tier of TIERS) {
  describe(`experiments in the physics tank (${tier})`, () => {
    let server, browser, page, errors;

    before(async () => {
      server = await serveDist();
      browser = await launch(tier);
      ({ page, errors } = await openShoal(browser, server.url, { width: 1280, height: 900 }));
      await clickUntil(page, "scene_physics", () => window.shoal.state().scene === "physics");
    });

    after(async () => {
      await browser?.close();
      await server?.close();
    });

    test("the physics tank's Experiment button opens the window with its own factors", async () => {
      await scrollPanelTo(page, "experiment");
      await clickUntil(page, "experiment", () => !!window.shoal.widgets().experiment_sizing);
      const w = await page.evaluate(() => window.shoal.widgets());
      assert.ok(w.experiment_start && w.experiment_factor, "start and the factor's list");
      await waitFrames(page, 2);
      if (tier === "webgl2") saveArtifact("experiment-physics-design.png", await page.screenshot());
    });

    test("muscle fish in a current: the browser's CSV is the native engine's", walkOnly(tier), async () => {
      const result = await page.evaluate((d) => window.shoal.run_experiment(d), physicsDesign);
      saveArtifact(`experiment-physics-${tier}.csv`, Buffer.from(result.csv));
      const distance = result.summary.filter((r) => r.measure === "distance_swum_m");
      assert.equal(distance.length, 2, "one distance per current");
      assert.ok(distance.every((r) => r.mean > 0), JSON.stringify(distance));
      const diff = firstDifference(result.csv, nativePhysicsCsv);
      assert.equal(diff, null, diff && `line ${diff.line}:\n  browser ${diff.browser}\n  native  ${diff.native}`);
      assert.deepEqual(errors, []);
    });
  });
}
