// Guided investigations (issue 15, items 1, 5, 6, 7): "Why do fish school?" end
// to end with real clicks (the side panel's Investigations button, the list, the
// intro, a prediction that must be committed before Run works and is then
// locked, the run made short with the Speed slider, the measured catches beside
// the prediction, three explanations typed in, the reveal, the sandbox open
// afterwards, the record downloaded); the other four from their links to the
// reveal, each setting up its scene, refusing Run before a prediction, running
// its measurement and showing what it measured; an unknown id in a link; the
// window on a phone. WebGL2 (SwiftShader), then WebGPU.
import { test, describe, before, after } from "node:test";
import assert from "node:assert/strict";
import fs from "node:fs";
import {
  serveDist,
  launch,
  openShoal,
  saveArtifact,
  clickWidget,
  clickUntil,
  clickInWindow,
  scrollWindowTo,
  waitForWidget,
  waitFrames,
  sleep,
  TIERS,
  walkOnly,
  enterText,
  nudgeFrames,
} from "./harness.mjs";

const inv = (page) => page.evaluate(() => window.shoal.state().investigation);
const settings = (page) => page.evaluate(() => window.shoal.settings());

/** A screenshot of what the app shows now (a paused app draws when nudged). */
async function shot(page, tier, name) {
  await nudgeFrames(page, 2);
  saveArtifact(`investigation-${tier}-${name}.png`, await page.screenshot());
}


/** The explain step: writes each answer into its prompt, one at a time, as a
 * student would (a click in the box, the text, Next), until the reveal. The
 * answer numbered `typed` is typed key by key; the others are entered as one
 * input event (`enterText`: a key costs frames on a software GPU). `onSecond`
 * runs while the second answer shows (a screenshot). */
async function explain(page, answers, { typed = -1, onSecond = null, firstPlot = false } = {}) {
  for (const [k, answer] of answers.entries()) {
    // On a loaded machine a click can land while the window still moves (the
    // plot a prompt names comes back above the box): then the box has no
    // focus and the text goes nowhere, so click and enter it again.
    for (let attempt = 0; ; attempt++) {
      await scrollWindowTo(page, "investigation_answer");
      await clickWidget(page, "investigation_answer");
      await waitFrames(page, 2);
      if (k === typed && attempt === 0) await page.keyboard.type(answer, { delay: 10 });
      else await enterText(page, answer);
      try {
        await page.waitForFunction((a) => window.shoal.state().investigation.explanations.includes(a), answer, {
          timeout: 30_000,
        });
        break;
      } catch (err) {
        if (attempt >= 2) throw err;
      }
    }
    if (k === 1 && onSecond) await onSecond();
    if (k === 0 && firstPlot) {
      // The prompt names a plot: it is back in the window beside the question.
      assert.ok((await page.evaluate(() => window.shoal.widgets())).investigation_explain_plot, "the plot the first prompt names");
    }
    await clickUntil(
      page,
      "investigation_next",
      (n) => {
        const now = window.shoal.state().investigation;
        return now.step === "reveal" || now.prompt === n;
      },
      k + 1,
    );
  }
  await page.waitForFunction(() => window.shoal.state().investigation.step === "reveal");
}

/** Drags the Speed slider to its top end, as a teacher short of time would. */
async function raiseSpeed(page) {
  const speed = await waitForWidget(page, "speed");
  await page.mouse.move(speed.x + 20, speed.y + speed.height / 2);
  await page.mouse.down();
  await page.mouse.move(speed.x + 130, speed.y + speed.height / 2, { steps: 6 });
  await page.mouse.up();
  await waitFrames(page, 2);
  const fast = (await settings(page)).speed;
  assert.ok(fast >= 6, `speed raised with the slider (${fast}×)`);
}

/** What each investigation's result must show, from its own measurement. */
async function checkResult(id, result) {
  const values = result.rows.map((r) => r.value);
  if (id === "leader") {
    const [on, off] = values;
    assert.ok(on > off, `alignment on orders the school more: ${on} vs ${off}`);
    assert.ok(result.rows.slice(2).every((r) => r.unit === "fish" && r.value <= 7), "each clicked fish heeded a few");
  } else if (id === "which-urge") {
    assert.ok(values.every((v) => v >= 0 && v <= 1), "polarizations");
    assert.ok(values.at(-1) > values[0] + 0.2, `order rises with alignment: ${values}`);
  } else if (id === "how-swim") {
    assert.equal(values.length, 7, "seven tail beats");
    assert.ok(values[4] > values[0] * 2, `faster beats swim faster: ${values}`);
  } else if (id === "learning") {
    assert.equal(values.length, 6, "six copies raced");
    assert.ok(values.at(-1) > values[0], `the 6840-try copy beats the 90-try one: ${values}`);
  }
}

/** *Is there a leader?*: click a fish to see what it heeds, let the school
 * swim with alignment on, then turn it off with the window's button. */
async function leaderRun(page, tier) {
  await waitForWidget(page, "animal_5");
  await clickUntil(page, "animal_5", () => window.shoal.settings().left.selected != null);
  await shot(page, tier, "leader-attention");
  await raiseSpeed(page);
  const start = await page.evaluate(() => window.shoal.state().time_secs);
  await page.waitForFunction((t) => window.shoal.state().time_secs > t + 16, start, { timeout: 300_000, polling: 500 });
  await clickInWindow(page, "investigation_alignment_off", () => window.shoal.settings().left.alignment === 0);
}

/** *Learning to swim*: Run starts the practice, a little every frame; the
 * test lets it practise, then fast-forwards the rest of the 6,840 tries with
 * shoal.train (the same annealing steps the frames would run, each from the
 * same state), so the race starts. */
async function learningRun(page) {
  await page.waitForFunction(() => window.shoal.state().learning.evaluations > 0, null, { timeout: 120_000 });
  for (let k = 0; k < 10; k++) {
    const l = await page.evaluate(() => window.shoal.state().learning);
    if (l.drill !== 0) break;
    await page.evaluate(() => window.shoal.train(1000));
  }
  assert.notEqual((await page.evaluate(() => window.shoal.state().learning)).drill, 0, "the first drill learned");
}

for (const tier of TIERS) {
  describe(`investigations (${tier})`, () => {
    let server, browser;

    before(async () => {
      server = await serveDist();
      browser = await launch(tier);
    });

    after(async () => {
      await browser?.close();
      await server?.close();
    });

    test("Why do fish school? from the first screen to the reveal, with real clicks", walkOnly(tier), async () => {
      const { page, errors } = await openShoal(browser, server.url, { width: 1024, height: 700 });
      assert.equal(await inv(page), null, "no investigation at first");
      const list = await page.evaluate(() => window.shoal.investigations());
      assert.deepEqual(
        list.map((i) => i.id),
        ["why-school", "leader", "which-urge", "how-swim", "learning"],
      );
      assert.ok(list.every((i) => i.title && i.minutes >= 5 && i.minutes <= 15));

      // The button is on the first screen, at the top of the side panel.
      const button = await waitForWidget(page, "investigations");
      assert.ok(button.y < 120, `the Investigations button is at the top (y ${button.y})`);
      await clickUntil(page, "investigations", () => !!window.shoal.widgets()["investigation_why-school"]);
      await shot(page, tier, "1-list");

      await clickUntil(page, "investigation_why-school", () => window.shoal.state().investigation?.id === "why-school");
      const s = await settings(page);
      assert.equal(s.scene, "boids");
      assert.ok(s.compare, "two tanks");
      assert.equal(s.left.preset, "individual");
      assert.equal(s.right.preset, "group");
      assert.equal(s.left.fish_count, s.right.fish_count);
      assert.equal(s.left.sharks, 1);
      assert.equal(s.right.sharks, 1);
      await shot(page, tier, "2-intro");

      await clickInWindow(page, "investigation_next", () => window.shoal.state().investigation.step === "predict");
      // Run is there but refuses before a prediction.
      await scrollWindowTo(page, "investigation_run");
      await clickWidget(page, "investigation_run");
      await waitFrames(page, 3);
      let i = await inv(page);
      assert.equal(i.step, "predict");
      assert.equal(i.prediction, null);
      assert.equal(i.running, false);
      await clickInWindow(page, "investigation_choice_1", () => window.shoal.state().investigation.chosen === 1);
      await shot(page, tier, "3-predict");
      await clickInWindow(page, "investigation_commit", () => window.shoal.state().investigation.step === "run");
      i = await inv(page);
      assert.equal(i.prediction.choice, 1);
      assert.equal(i.prediction.text, "The school (Group tank)");
      // Locked: the choices are gone (once the next frame is drawn).
      await waitFrames(page, 2);
      assert.equal((await page.evaluate(() => window.shoal.widgets())).investigation_choice_0, undefined);

      // The Speed slider, dragged to its top end, makes the 3 minutes short.
      await raiseSpeed(page);

      await clickInWindow(page, "investigation_run", () => window.shoal.state().investigation.running);
      assert.equal((await settings(page)).paused, false, "the run plays the tanks");
      const started = Date.now();
      await sleep(5000);
      await shot(page, tier, "4-running");
      await page.waitForFunction(() => window.shoal.state().investigation.result, null, {
        timeout: 600_000,
        polling: 1000,
      });
      const secs = (Date.now() - started) / 1000;
      const st = await page.evaluate(() => window.shoal.state());
      i = st.investigation;
      console.log(`why-school (${tier}): 180 simulated seconds in ${secs.toFixed(0)} s: ${i.result.summary}`);
      assert.ok(st.time_secs >= 180, `the run lasted 3 simulated minutes (${st.time_secs})`);
      assert.ok(st.paused, "paused at the end");
      const [loners, school] = i.result.rows.map((r) => r.value);
      // Measured from the run: at most what the tanks' counters hold now.
      assert.ok(Number.isInteger(loners) && loners <= st.metrics.catches, `${loners} vs ${st.metrics.catches}`);
      assert.ok(Number.isInteger(school) && school <= st.metrics_right.catches);
      assert.ok(i.result.summary.includes(`${loners} loners`) && i.result.summary.includes(`${school} fish`));
      assert.ok(i.result.verdict.includes("The school (Group tank)"), "the prediction beside the result");
      // The investigation's seed shows what it is about (docs/investigations.md).
      assert.ok(school < loners, `the school lost fewer: ${school} against ${loners}`);
      await waitForWidget(page, "investigation_result");
      await shot(page, tier, "5-result");

      // Explain: three prompts, one at a time, answers typed in.
      await clickInWindow(page, "investigation_next", () => window.shoal.state().investigation.step === "explain");
      await explain(page, ["Steadily on the left", "It <switched>", "Too many targets"], {
        typed: 1,
        firstPlot: true,
        onSecond: () => shot(page, tier, "6-explain"),
      });
      await waitForWidget(page, "investigation_reveal");
      await shot(page, tier, "7-reveal");

      // The sandbox stays open: the controls work.
      await clickUntil(page, "play_pause", () => !window.shoal.settings().paused);
      assert.equal((await inv(page)).prediction.choice, 1, "still locked");

      // The record: one self-contained HTML file and the CSV.
      const download = page.waitForEvent("download", { timeout: 30_000 });
      await scrollWindowTo(page, "investigation_record");
      await clickWidget(page, "investigation_record");
      const file = await download;
      // Named by the investigation and the date (no name typed: none in it).
      assert.match(file.suggestedFilename(), /^shoal-why-school-\d{4}-\d\d-\d\d\.html$/);
      const html = fs.readFileSync(await file.path(), "utf8");
      saveArtifact(`investigation-${tier}-record.html`, html);
      assert.ok(html.includes("The school (Group tank) (locked before the run)"));
      assert.ok(html.includes(`<td class="n">${loners}</td>`) && html.includes(`<td class="n">${school}</td>`));
      assert.ok(html.includes("It &lt;switched&gt;"), "student text, typed key by key, escaped");
      assert.ok(html.includes("<svg") && !html.includes("<script"), "inline plot, no script");
      assert.ok(html.includes("What scientists found"));
      const record = await page.evaluate(() => window.shoal.investigation_record());
      assert.ok(record.csv.includes(`why-school,"fish caught, loners (Individual tank)",${loners},fish`), record.csv);
      assert.deepEqual(errors, []);
      await page.close();
    });

    // The other four, each from its link to the reveal with real clicks: the
    // prediction committed (Run refused before), the run, what the student does
    // during it (click fish and turn alignment off; watch; practise), the
    // result beside the prediction, the explanations typed, the reveal.
    const walks = [
      // The student clicks a fish in the tank: a window wide enough that the
      // investigation window does not cover the school.
      { id: "leader", scene: "boids", choice: 1, prompts: 3, during: leaderRun, long: true, size: [1180, 780] },
      { id: "which-urge", scene: "boids", choice: 0, prompts: 3, long: true },
      // Its run takes seconds: every tier walks it, window, chart and reveal.
      { id: "how-swim", scene: "physics", choice: 0, prompts: 3, long: false },
      { id: "learning", scene: "learning", choice: 0, prompts: 2, during: learningRun, long: true },
    ];
    for (const walk of walks) {
      test(`?investigation=${walk.id}: from the link to the reveal with real clicks`, walk.long ? walkOnly(tier) : {}, async () => {
        const { page, errors } = await openShoal(browser, `${server.url}?investigation=${walk.id}`, {
          width: walk.size?.[0] ?? 960,
          height: walk.size?.[1] ?? 660,
        });
        await page.waitForFunction((x) => window.shoal.state().investigation?.id === x, walk.id);
        assert.equal((await settings(page)).scene, walk.scene);
        await clickInWindow(page, "investigation_next", () => window.shoal.state().investigation.step === "predict");
        // Run refuses before a prediction.
        await scrollWindowTo(page, "investigation_run");
        await clickWidget(page, "investigation_run");
        await waitFrames(page, 3);
        let i = await inv(page);
        assert.equal(i.step, "predict");
        assert.equal(i.prediction, null);
        assert.equal(i.running, false);
        await clickInWindow(page, `investigation_choice_${walk.choice}`, (k) => window.shoal.state().investigation.chosen === k, walk.choice);
        assert.ok((await page.evaluate(() => window.shoal.share_link())).includes(`?investigation=${walk.id}#v1.`));
        await clickInWindow(page, "investigation_commit", () => window.shoal.state().investigation.step === "run");
        await clickInWindow(page, "investigation_run", () => window.shoal.state().investigation.running);
        const started = Date.now();
        if (walk.during) await walk.during(page, tier);
        await page.waitForFunction(() => window.shoal.state().investigation.result, null, {
          timeout: 900_000,
          polling: 1000,
        });
        i = await inv(page);
        console.log(`${walk.id} (${tier}): run in ${((Date.now() - started) / 1000).toFixed(0)} s: ${i.result.summary}`);
        assert.equal(i.prediction.choice, walk.choice, "the prediction stays locked");
        assert.ok(i.result.rows.length >= 2 && i.result.rows.every((r) => Number.isFinite(r.value)), JSON.stringify(i.result.rows));
        assert.ok(i.result.verdict.length > 0);
        await checkResult(walk.id, i.result);
        await waitForWidget(page, "investigation_result");
        await shot(page, tier, `${walk.id}-1-result`);

        await clickInWindow(page, "investigation_next", () => window.shoal.state().investigation.step === "explain");
        await explain(
          page,
          Array.from({ length: walk.prompts }, (_, k) => `A${k + 1} ${walk.id}`),
        );
        await waitForWidget(page, "investigation_reveal");
        await shot(page, tier, `${walk.id}-2-reveal`);
        const record = await page.evaluate(() => window.shoal.investigation_record());
        assert.ok(record.html.includes(`A${walk.prompts} ${walk.id}`), "the answers in the record");
        assert.ok(record.csv.split("\n").some((line) => line.startsWith(`${walk.id},`)), record.csv);
        assert.deepEqual(errors, []);
        await page.close();
      });
    }

    test("a link with an unknown investigation names the known ones and opens the rest", async () => {
      const { page } = await openShoal(browser, `${server.url}?investigation=nope`);
      const s = await page.evaluate(() => window.shoal.state());
      assert.equal(s.investigation, null);
      assert.ok(s.notice.includes("'nope'") && s.notice.includes("why-school, leader"), s.notice);
      const refused = await page.evaluate(() => {
        try {
          window.shoal.set({ investigation: "nope", speed: 2 });
          return null;
        } catch (err) {
          return err.message;
        }
      });
      assert.ok(refused.includes("which-urge"), refused);
      assert.equal((await settings(page)).speed, 1, "nothing changed");
      await page.evaluate(() => window.shoal.set({ investigation: "how-swim" }));
      assert.equal((await inv(page)).step, "intro");
      await page.close();
    });

    test("on a phone the investigation window fits the screen", async () => {
      const { page } = await openShoal(browser, `${server.url}?investigation=why-school`, {
        width: 390,
        height: 844,
      });
      await clickInWindow(page, "investigation_next", () => window.shoal.state().investigation.step === "predict");
      const w = await waitForWidget(page, "investigation_window");
      assert.ok(w.x >= 0 && w.x + w.width <= 390, `x ${w.x} width ${w.width}`);
      assert.ok(w.y >= 0 && w.y + w.height <= 844, `y ${w.y} height ${w.height}`);
      await shot(page, tier, "phone");
      await page.close();
    });
  });
}
