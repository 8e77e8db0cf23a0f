// Investigations a class can follow (issue 35, item 3): the investigation
// window docks beside the tanks and never covers what its prompt asks the
// student to watch (Why do fish school?'s two tanks, during the run, at
// 1280×800; at 1920×1080 and on a phone too); an explain prompt that names a
// plot shows it again; the record names the student (asked once, remembered by
// this browser only), the date, the seed and a link that opens the same run
// again, in a file named by the investigation, the name and the date.
// Each tier (WebGL2, then WebGPU) draws the window beside the tanks; the record
// and the remembered name, the same wasm on every tier, are walked on WebGL2.
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
  nudgeFrames,
  enterText,
  TIERS,
  walkOnly,
} from "./harness.mjs";

const widgets = (page) => page.evaluate(() => window.shoal.widgets());

async function shot(page, tier, name) {
  await nudgeFrames(page, 2);
  saveArtifact(`investigation-class-${tier}-${name}.png`, await page.screenshot());
}

/** Do two rectangles overlap (by more than a rounding's width)? */
function overlap(a, b) {
  const w = Math.min(a.x + a.width, b.x + b.width) - Math.max(a.x, b.x);
  const h = Math.min(a.y + a.height, b.y + b.height) - Math.max(a.y, b.y);
  return w > 0.5 && h > 0.5;
}

/** The window and each tank on screen: none covered. */
async function assertTanksVisible(page, what) {
  await waitFrames(page, 2);
  const w = await widgets(page);
  const win = w.investigation_window;
  assert.ok(win, `${what}: the window is open`);
  const tanks = ["view_left", "view_right"].filter((t) => w[t]);
  assert.ok(tanks.length >= 1, `${what}: a tank is drawn`);
  for (const t of tanks) {
    assert.ok(!overlap(win, w[t]), `${what}: the window ${JSON.stringify(win)} covers ${t} ${JSON.stringify(w[t])}`);
    assert.ok(w[t].width >= 150 && w[t].height >= 100, `${what}: ${t} keeps a useful size ${JSON.stringify(w[t])}`);
  }
  const vw = await page.evaluate(() => window.innerWidth);
  const vh = await page.evaluate(() => window.innerHeight);
  assert.ok(win.x >= 0 && win.x + win.width <= vw + 1 && win.y >= 0 && win.y + win.height <= vh + 1, `${what}: the window on screen ${JSON.stringify(win)}`);
  return { win, tanks: tanks.map((t) => w[t]) };
}


/** From the intro to a committed prediction `choice`. */
async function predict(page, choice) {
  await clickInWindow(page, "investigation_next", () => window.shoal.state().investigation.step === "predict");
  await clickInWindow(page, `investigation_choice_${choice}`, (k) => window.shoal.state().investigation.chosen === k, choice);
  await clickInWindow(page, "investigation_commit", () => window.shoal.state().investigation.step === "run");
}

for (const tier of TIERS) describe(`investigations a class can follow (${tier})`, () => {
  let server, browser;

  before(async () => {
    server = await serveDist();
    browser = await launch(tier);
  });

  after(async () => {
    await browser?.close();
    await server?.close();
  });

  test("Why do fish school?: the window covers neither tank, before and during the run (1280×800)", async () => {
    const { page, errors } = await openShoal(browser, `${server.url}?investigation=why-school`, { width: 1280, height: 800 });
    await waitForWidget(page, "investigation_window");
    await waitForWidget(page, "view_right");
    const intro = await assertTanksVisible(page, "intro");
    assert.equal(intro.tanks.length, 2, "both tanks");
    // Beside the tanks: at the screen's right, the tanks left of it.
    assert.ok(intro.tanks.every((t) => t.x + t.width <= intro.win.x), JSON.stringify(intro));
    await predict(page, 1);
    await clickInWindow(page, "investigation_run", () => window.shoal.state().investigation.running);
    await page.waitForFunction(() => window.shoal.state().time_secs > 2, null, { timeout: 60_000 });
    await assertTanksVisible(page, "during the run");
    await shot(page, tier, "1280-running");
    assert.deepEqual(errors, []);
    await page.close();
  });

  for (const [width, height] of [
    [1920, 1080],
    [390, 844],
  ]) {
    test(`Why do fish school? at ${width}×${height}: the window covers neither tank`, async () => {
      const { page, errors } = await openShoal(browser, `${server.url}?investigation=why-school`, { width, height });
      await waitForWidget(page, "investigation_window");
      await waitForWidget(page, "view_right");
      await assertTanksVisible(page, `${width}×${height} intro`);
      await clickInWindow(page, "investigation_next", () => window.shoal.state().investigation.step === "predict");
      await assertTanksVisible(page, `${width}×${height} predict`);
      await shot(page, tier, `${width}x${height}`);
      assert.deepEqual(errors, []);
      await page.close();
    });
  }

  // The record and the remembered name are the same wasm on every tier: a walk.
  test("How does a fish swim?: the plot comes back with its prompt; the record is ready to hand in and its link reruns", walkOnly(tier), async () => {
    const { page, errors } = await openShoal(browser, `${server.url}?investigation=how-swim`, { width: 1280, height: 800 });
    await page.waitForFunction(() => window.shoal.state().investigation?.id === "how-swim");
    // Another seed than the investigation's own: the record's link must carry it.
    await page.evaluate(() => window.shoal.set({ seed: 5 }));
    await predict(page, 0);
    await clickInWindow(page, "investigation_run", () => window.shoal.state().investigation.running);
    await page.waitForFunction(() => window.shoal.state().investigation.result, null, { timeout: 600_000, polling: 1000 });
    const ran = await page.evaluate(() => window.shoal.settings());
    await assertTanksVisible(page, "how-swim result");
    await clickInWindow(page, "investigation_next", () => window.shoal.state().investigation.step === "explain");
    // Prompt 1 asks about the measured curve: it is there with the question.
    await waitForWidget(page, "investigation_explain_plot");
    await shot(page, tier, "explain-plot");
    for (let k = 0; k < 3; k++) {
      await scrollWindowTo(page, "investigation_answer");
      await clickWidget(page, "investigation_answer");
      await enterText(page, `answer ${k + 1}`);
      await page.waitForFunction((a) => window.shoal.state().investigation.explanations.includes(a), `answer ${k + 1}`);
      await clickUntil(
        page,
        "investigation_next",
        (n) => {
          const now = window.shoal.state().investigation;
          return now.step === "reveal" || now.prompt === n;
        },
        k + 1,
      );
      await waitFrames(page, 2);
      const now = await page.evaluate(() => window.shoal.state().investigation);
      if (now.step === "explain" && now.prompt === 2) {
        // "Why can't a fish go faster and faster…": words only, no plot.
        assert.equal((await widgets(page)).investigation_explain_plot, undefined, "no plot for a prompt that names none");
      }
    }
    await page.waitForFunction(() => window.shoal.state().investigation.step === "reveal");

    // The name, typed once into its field (reached and named for a screen reader).
    await scrollWindowTo(page, "investigation_student");
    await clickWidget(page, "investigation_student");
    await enterText(page, "Ana <b>Pérez</b>");
    await page.waitForFunction(() => localStorage.getItem("shoal.student") === "Ana <b>Pérez</b>");
    const tree = await page.evaluate(() =>
      [...document.querySelectorAll("input, textarea, [role=textbox]")].map((e) => e.getAttribute("aria-label") || e.labels?.[0]?.textContent || ""),
    );
    assert.ok(tree.some((n) => n.includes("Your name")), `the name field is named: ${JSON.stringify(tree)}`);
    await shot(page, tier, "name");

    const download = page.waitForEvent("download", { timeout: 30_000 });
    await scrollWindowTo(page, "investigation_record");
    await clickWidget(page, "investigation_record");
    const file = await download;
    const today = await page.evaluate(() => {
      const d = new Date();
      return `${d.getFullYear()}-${String(d.getMonth() + 1).padStart(2, "0")}-${String(d.getDate()).padStart(2, "0")}`;
    });
    assert.equal(file.suggestedFilename(), `shoal-how-swim-ana-b-perez-b-${today}.html`);
    const html = fs.readFileSync(await file.path(), "utf8");
    saveArtifact(`investigation-class-${tier}-record.html`, html);
    assert.ok(html.includes(`Ana &lt;b&gt;Pérez&lt;/b&gt;, ${today} at `), "the name, escaped, and the date");
    assert.ok(!html.includes("<b>Pérez"), "no markup from the name");
    assert.ok(html.includes("Seed: 5."), "the seed");
    const href = html.match(/<a href="([^"]+)"/)[1].replaceAll("&amp;", "&");
    assert.ok(href.startsWith(`${server.url}`) && href.includes("?investigation=how-swim#v1."), href);
    assert.deepEqual(errors, []);
    await page.close();

    // The link opens the same investigation on the run's settings.
    const again = await openShoal(browser, href, { width: 1280, height: 800 });
    await again.page.waitForFunction(() => window.shoal.state().investigation?.id === "how-swim");
    const reopened = await again.page.evaluate(() => window.shoal.settings());
    assert.equal(reopened.seed, 5, "the run's seed, not the investigation's own");
    assert.deepEqual(reopened.physics, ran.physics);
    assert.equal((await again.page.evaluate(() => window.shoal.state().investigation)).step, "intro");
    assert.deepEqual(again.errors, []);
    await again.page.close();
  });

  test("the name is asked once: this browser remembers it", walkOnly(tier), async () => {
    const { page } = await openShoal(browser, server.url, { width: 1280, height: 800 });
    assert.ok(!(await page.evaluate(() => window.shoal.investigation_record().html)).includes("Luis"));
    await page.evaluate(() => localStorage.setItem("shoal.student", "Luis"));
    await page.reload();
    await page.waitForFunction(() => window.shoal && window.shoal.state().steps > 30, null, { timeout: 90_000 });
    assert.ok((await page.evaluate(() => window.shoal.investigation_record().html)).includes("Luis, "));
    await page.close();
  });
});
