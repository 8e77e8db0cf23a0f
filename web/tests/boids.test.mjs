// The schooling lab (issue 3) as a teacher uses it: real clicks and drags on the
// panel, presets and control modes, compare mode, share links, the CSV download and
// the rock tools. WebGL2 (SwiftShader); the WebGPU path is covered by aquarium tests.
// The window is tall so that the whole panel fits without scrolling.
import { test, describe, before, after } from "node:test";
import assert from "node:assert/strict";
import {
  serveDist,
  launch,
  openShoal,
  decode,
  pixelStats,
  fishPixels,
  saveArtifact,
  clickWidget,
  clickUntil,
  waitForWidget,
  waitFrames,
  scrollPanelTo,
} from "./harness.mjs";

const state = (page) => page.evaluate(() => window.shoal.state());
const settings = (page) => page.evaluate(() => window.shoal.settings());
const widget = (page, name) => page.evaluate((n) => window.shoal.widgets()[n], name);

/** Drags the handle of slider `name` to `fraction` of its width, as a person would. */
async function dragSlider(page, name, fraction) {
  await waitForWidget(page, name);
  const r = await scrollPanelTo(page, name);
  // egui puts the slider rail on the left part of the widget, the number box right.
  const railWidth = r.width - 60;
  const y = r.y + r.height / 2;
  await page.mouse.move(r.x + 8, y);
  await page.mouse.down();
  await page.mouse.move(r.x + 4 + railWidth * fraction, y, { steps: 8 });
  await page.mouse.up();
}

/** Polarization after `steps` steps from a fresh start on seed 1. */
async function polarizationAfter(page, steps) {
  await page.evaluate((n) => {
    window.shoal.reset(1);
    window.shoal.step(n);
  }, steps);
  return (await state(page)).metrics.polarization;
}

describe("schooling lab", () => {
  let server, browser, page, errors;

  before(async () => {
    server = await serveDist();
    browser = await launch("webgl2");
    const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
    await context.grantPermissions(["clipboard-read", "clipboard-write"], { origin: server.url });
    ({ page, errors } = await openShoal(context, server.url));
  });

  after(async () => {
    await browser?.close();
    await server?.close();
  });

  test("clicking the scene button opens the schooling lab with its controls and metrics", async () => {
    await clickUntil(page, "scene_boids", () => window.shoal.state().scene === "boids");
    await waitForWidget(page, "weight_cohesion");
    await waitForWidget(page, "plot_0");
    const s = await state(page);
    for (const key of ["polarization", "milling", "nnd_body_lengths", "groups", "mean_speed", "force_frequencies"]) {
      assert.ok(key in s.metrics, `metrics.${key}`);
    }
    assert.equal((await settings(page)).left.preset, "individual");
  });

  test("dragging the alignment, cohesion and wander sliders with the mouse lines the fish up", async () => {
    await page.evaluate(() => window.shoal.pause());
    const solitary = await polarizationAfter(page, 2400);
    await dragSlider(page, "weight_alignment", 1.0);
    await dragSlider(page, "weight_cohesion", 0.3);
    await dragSlider(page, "wander", 0.0);
    const s = await settings(page);
    assert.ok(s.left.alignment > 90, `alignment ${s.left.alignment}`);
    assert.ok(s.left.cohesion > 20 && s.left.cohesion < 40, `cohesion ${s.left.cohesion}`);
    assert.ok(s.left.wander < 5, `wander ${s.left.wander}`);
    assert.equal(s.left.preset, "custom");
    const social = await polarizationAfter(page, 2400);
    assert.ok(social > solitary + 0.4, `polarization ${solitary} → ${social}`);
  });

  test("clear sight, distant fish and slowest speed are sliders of the tank, and clear sight feeds alignment", async () => {
    await page.evaluate(() => window.shoal.set({ left: { preset: "group" }, paused: true }));
    for (const name of ["clear_sight_m", "distant_pull", "min_speed_m_per_s"]) await waitForWidget(page, name);
    const r = await scrollPanelTo(page, "min_speed_m_per_s");
    await page.mouse.move(700, 400);
    await waitFrames(page, 2);
    saveArtifact("boids-senses.png", await page.screenshot({ clip: { x: 0, y: Math.max(0, r.y - 300), width: 420, height: 340 } }));
    // Dragging clear sight to its left end: the fish read no heading.
    await dragSlider(page, "clear_sight_m", 0.0);
    await page.waitForFunction(() => window.shoal.settings().left.clear_sight_m < 0.3, null, { timeout: 30_000 });
    const blind = await polarizationAfter(page, 2400);
    await page.evaluate(() => window.shoal.set({ left: { clear_sight_m: 0.3 } }));
    const sighted = await polarizationAfter(page, 2400);
    assert.ok(sighted > blind + 0.2, `polarization with clear sight ${sighted}, without ${blind}`);
    // The screen reader's view: named, with range and help.
    const slider = page.locator('#shoal_a11y input[type=range][aria-label="Distant fish"]').first();
    await slider.waitFor({ state: "attached", timeout: 60_000 });
    assert.equal(await slider.getAttribute("max"), "100");
    await page.evaluate(() => window.shoal.set({ left: { preset: "individual", distant_pull: 50, min_speed_m_per_s: 0.15 }, paused: false }));
    assert.deepEqual(errors, []);
  });

  test("preset and control-mode buttons switch what the fish do", async () => {
    await clickUntil(page, "preset_group", () => window.shoal.settings().left.preset === "group");
    const group = await settings(page);
    assert.deepEqual(
      [group.left.containment, group.left.alignment, group.left.cohesion, group.left.separation, group.left.avoidance],
      [26, 26, 29, 26, 98],
      "Table 1, group"
    );
    const grouped = await polarizationAfter(page, 3600);
    assert.ok(grouped > 0.8, `group preset polarises: ${grouped}`);

    await clickUntil(page, "mode_monte_carlo", () => window.shoal.settings().left.mode === "monte_carlo");
    await polarizationAfter(page, 600);
    const shares = (await state(page)).metrics.force_frequencies;
    const total = 26 + 26 + 29 + 26 + 98;
    for (const [name, w] of Object.entries({ containment: 26, alignment: 26, cohesion: 29, separation: 26, avoidance: 98 })) {
      assert.ok(Math.abs(shares[name] - w / total) < 0.03, `${name}: ${shares[name]} vs ${w / total}`);
    }
    await clickUntil(page, "preset_monte_carlo_paper", () => window.shoal.settings().left.preset === "monte_carlo_paper");
    await clickUntil(page, "mode_blended", () => window.shoal.settings().left.mode === "blended");
    assert.equal((await settings(page)).left.preset, "custom");
  });

  test("compare mode: a teacher picks Individual and Group, and only the weights differ", async () => {
    // A teacher's fresh page: the earlier tests' slider drags are gone.
    await page.reload();
    await page.waitForFunction(() => window.shoal && window.shoal.state().tier, null, { timeout: 90_000 });
    await clickUntil(page, "scene_boids", () => window.shoal.state().scene === "boids");
    await clickUntil(page, "compare", () => window.shoal.state().compare);
    await page.waitForFunction(() => window.shoal.state().compare && window.shoal.widgets().edit_left, null, {
      timeout: 30_000,
    });
    // A frame after choosing the tank, so a slow software GPU does not fold the
    // two clicks into one frame (egui takes one click per widget per frame).
    // Each click is checked by its effect (`editing_*` marks the tank the
    // controls change): a click lost on a loaded machine once sent the Group
    // preset to the left tank.
    await clickUntil(page, "edit_left", () => !!window.shoal.widgets().editing_left);
    await waitFrames(page, 2);
    await clickUntil(page, "preset_individual", () => window.shoal.settings().left.preset === "individual");
    await clickUntil(page, "edit_right", () => !!window.shoal.widgets().editing_right);
    await waitFrames(page, 2);
    await clickUntil(page, "preset_group", () => window.shoal.settings().right.preset === "group");
    const chosen = await settings(page);
    const withoutWeights = (tank) => {
      const rest = { ...tank };
      for (const key of ["preset", "containment", "alignment", "cohesion", "separation", "avoidance"]) delete rest[key];
      return rest;
    };
    assert.deepEqual(withoutWeights(chosen.left), withoutWeights(chosen.right), "the two tanks differ only in the five weights");
    assert.notDeepEqual(chosen.left.cohesion, chosen.right.cohesion);
    await page.waitForFunction(() => window.shoal.state().compare && window.shoal.widgets().view_right, null, {
      timeout: 30_000,
    });
    await page.evaluate(() => {
      window.shoal.pause();
      window.shoal.step(3600);
    });
    const s = await state(page);
    assert.ok(s.metrics_right, "the right tank has metrics");
    assert.ok(
      s.metrics_right.polarization > s.metrics.polarization + 0.3,
      `group (right) ${s.metrics_right.polarization} vs individual (left) ${s.metrics.polarization}`
    );
    await page.evaluate(() => window.shoal.play());
    const stepsBefore = (await state(page)).steps;
    await page.waitForFunction((n) => window.shoal.state().steps > n + 20, stepsBefore, { timeout: 60_000 });
    const left = await widget(page, "view_left");
    const right = await widget(page, "view_right");
    const shot = await page.screenshot();
    saveArtifact("compare-webgl2.png", shot);
    const png = decode(shot);
    for (const [name, r] of [["left", left], ["right", right]]) {
      const stats = pixelStats(png, r);
      assert.ok(stats.std > 10 && stats.distinctColours > 50, `${name} tank is drawn: ${JSON.stringify(stats)}`);
    }
    // The loners are spread through the left tank; the school may sit behind glass.
    const fish = fishPixels(png, left).size;
    assert.ok(fish > 40, `the left tank shows fish (${fish} fish pixels)`);
    await page.evaluate(() => window.shoal.pause());
  });

  test("a copied link reopens exactly the same setting, and a damaged one falls back with a notice", async () => {
    await page.evaluate(() =>
      window.shoal.set({ seed: 77, right: { cohesion: 55, sharks: 1 }, left: { vision_angle_deg: 270 } })
    );
    await clickWidget(page, "copy_link");
    await page.waitForFunction(() => /copied/i.test(window.shoal.state().notice || ""), null, { timeout: 60_000 });
    const link = await page.evaluate(() => navigator.clipboard.readText());
    assert.equal(link, await page.evaluate(() => window.shoal.share_link()));
    assert.ok(link.includes("#v1."), link);
    const expected = await settings(page);

    const other = await page.context().newPage();
    await other.goto(link);
    await other.waitForFunction(() => window.shoal && window.shoal.state().tier, null, { timeout: 90_000 });
    assert.deepEqual(await other.evaluate(() => window.shoal.settings()), expected);
    assert.equal((await other.evaluate(() => window.shoal.state())).compare, true);

    const broken = link.slice(0, link.length - 12) + "!!tampered!!";
    await other.goto("about:blank");
    await other.goto(broken);
    await other.waitForFunction(() => window.shoal && window.shoal.state().tier, null, { timeout: 90_000 });
    const s = await other.evaluate(() => window.shoal.state());
    assert.match(s.notice || "", /could not be opened/);
    assert.equal(s.scene, "aquarium", "falls back to the defaults");
    saveArtifact("bad-link-notice.png", await other.screenshot());
    await other.close();
  });

  test("the CSV button downloads the metrics table, named after the scene and the time, with the run's header", async () => {
    await page.evaluate(() => window.shoal.step(600));
    const s = await state(page);
    assert.equal(s.paused, true, "paused: the time in the name is the time now");
    const expected = await page.evaluate(() => window.shoal.export_csv());
    // Click again if a slow frame lost the click (as clickUntil does).
    let file = null;
    for (let attempt = 0; attempt < 3 && !file; attempt++) {
      const download = page.waitForEvent("download", { timeout: 20_000 }).catch(() => null);
      await clickWidget(page, "export_csv");
      file = await download;
    }
    assert.ok(file, "the button starts a download");
    const seconds = String(Math.floor(s.time_secs)).padStart(4, "0");
    assert.equal(file.suggestedFilename(), `shoal-boids-t${seconds}s.csv`);
    assert.equal(file.suggestedFilename(), expected.name);
    const stream = await file.createReadStream();
    let text = "";
    for await (const chunk of stream) text += chunk;
    assert.equal(text, expected.text, "the button saves what shoal.export_csv() gives");
    const lines = text.trim().split("\n");
    const comments = lines.filter((l) => l.startsWith("# "));
    assert.match(comments[0], /^# Shoal data: Schooling lab \(boids\)/);
    assert.ok(comments.includes(`# seed: ${s.seed}`), comments.join("\n"));
    assert.ok(comments.some((l) => l.startsWith(`# simulated time: ${s.time_secs.toFixed(3)} s`)), comments.join("\n"));
    const link = comments.find((l) => l.startsWith("# settings link: #v1."));
    assert.ok(link, comments.join("\n"));
    const fragment = link.split(" ")[3];
    assert.ok((await page.evaluate(() => window.shoal.share_link())).endsWith(fragment), fragment);
    const table = lines.filter((l) => !l.startsWith("#"));
    assert.ok(table[0].startsWith("tank,time_s,polarization,milling"), table[0]);
    assert.ok(table.length > 10, `${table.length} rows`);
    assert.ok(table.some((l) => l.startsWith("right,")), "both tanks are in the table");
    // shoal.metrics_csv() still gives the bare table.
    const metrics = await page.evaluate(() => window.shoal.metrics_csv());
    assert.ok(metrics.startsWith("tank,time_s,polarization"), metrics.slice(0, 80));
    assert.ok(text.endsWith(metrics));
  });

  test("a teacher adds and removes a rock by clicking in the tank", async () => {
    await page.evaluate(() => window.shoal.set({ compare: false }));
    await waitForWidget(page, "tool_add_rock");
    const before = (await settings(page)).left.obstacles;
    assert.equal(before, null, "the seed's rocks until edited");
    // The tool is chosen when its button says so to a screen reader (a click
    // while the panel scrolls can miss).
    await clickUntil(page, "tool_add_rock", () =>
      [...document.querySelectorAll("#shoal_a11y button")].some(
        (b) => b.textContent === "Add rock" && b.getAttribute("aria-pressed") === "true",
      ),
    );
    const view = await waitForWidget(page, "view_left");
    // Walk down the view, column by column, until a click lands on free sand
    // (clicks beyond the glass, or too close to another rock or pillar, are
    // refused with a notice and change nothing).
    let at = null;
    let x = 0.5;
    for (const column of [0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8, 0.25, 0.75, 0.15, 0.85]) {
      for (let y = 0.5; y < 0.95 && !at; y += 0.025) {
        await page.mouse.click(view.x + view.width * column, view.y + view.height * y, { delay: 60 });
        await page.waitForTimeout(400);
        if ((await settings(page)).left.obstacles !== null) at = y;
      }
      if (at) {
        x = column;
        break;
      }
    }
    if (!at) saveArtifact("boids-rock-refused.png", await page.screenshot());
    assert.ok(at, `a click on the sand adds a rock (${(await page.evaluate(() => window.shoal.state())).notice})`);
    const added = (await settings(page)).left.obstacles;
    const world = added.length;
    assert.ok(world >= 1);
    // The tool, then the rock; again if a slow frame lost a click (the tool is
    // not in state(), so the rock's removal is what tells).
    for (let attempt = 0; attempt < 4; attempt++) {
      await clickWidget(page, "tool_remove_rock");
      await waitFrames(page, 2);
      await page.mouse.click(view.x + view.width * x, view.y + view.height * at, { delay: 60 });
      const removed = await page
        .waitForFunction((n) => window.shoal.settings().left.obstacles.length < n, world, { timeout: 20_000 })
        .then(() => true)
        .catch(() => false);
      if (removed) break;
    }
    assert.equal((await settings(page)).left.obstacles.length, world - 1, "one rock removed");
    await clickUntil(page, "restore_rocks", () => window.shoal.settings().left.obstacles === null);
    await clickWidget(page, "tool_look");
  });

  test("show vision draws the fish's view over the tank", async () => {
    await page.evaluate(() => window.shoal.set({ show_vision: false }));
    const view = await widget(page, "view_left");
    await page.waitForTimeout(300);
    const plain = decode(await page.screenshot({ clip: view }));
    await clickWidget(page, "show_vision");
    await page.waitForFunction(() => window.shoal.settings().show_vision, null, { timeout: 60_000 });
    await page.waitForTimeout(600);
    const shot = await page.screenshot({ clip: view });
    saveArtifact("show-vision-webgl2.png", shot);
    const withVision = decode(shot);
    let changed = 0;
    for (let i = 0; i < plain.data.length; i += 4) {
      if (Math.abs(plain.data[i] - withVision.data[i]) + Math.abs(plain.data[i + 1] - withVision.data[i + 1]) > 40) changed++;
    }
    assert.ok(changed > 2000, `vision lines change ${changed} pixels`);
    assert.deepEqual(errors, [], "no console errors");
  });
});
