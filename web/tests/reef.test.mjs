// The reef scene (issue 5) as a teacher uses it: real clicks on the scene button,
// the demo buttons, a fish and the overlay choices; the inspector shows the fish's
// mind and its fish-eye view; the event log fills; bad input is refused with a
// message. WebGL2 (SwiftShader).
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
  clickUntil,
  waitForWidget,
  changedPixels,
  scrollPanelTo,
  sleep,
} from "./harness.mjs";

const state = (page) => page.evaluate(() => window.shoal.state());
const settings = (page) => page.evaluate(() => window.shoal.settings());
const widgets = (page) => page.evaluate(() => window.shoal.widgets());

describe("reef", () => {
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

  test("the scene button opens the reef: a school, a shark, pacifists, plankton", async () => {
    await clickUntil(page, "scene_reef", () => window.shoal.state().scene === "reef");
    await waitForWidget(page, "reef_demo_courtship");
    const s = await state(page);
    assert.equal(s.reef.demo, "reef");
    assert.equal(s.reef.body, "physical");
    assert.equal(s.reef.predators, 1);
    assert.equal(s.reef.prey, 10);
    assert.equal(s.reef.pacifists, 7);
    assert.ok(s.reef.food > 20, `plankton: ${s.reef.food}`);
    const view = (await widgets(page)).view_left;
    // Software graphics draw the tank at half per side or less (Tank detail's
    // Auto, which follows a loaded machine's frame rate; a quarter of the
    // pixels in CI), which blends the small reef fish's colours into the water:
    // about 70 vivid pixels here at half size, 35 at a quarter, against 0 for
    // an empty tank, fewer in a frame where the ten fish overlap or turn
    // edge-on. The best of five frames a second apart.
    let vivid = 0;
    for (let k = 0; k < 5 && vivid <= 25; k++) {
      if (k > 0) await sleep(1000);
      const shot = await page.screenshot();
      if (k === 0) saveArtifact("reef-webgl2.png", shot);
      vivid = Math.max(vivid, fishPixels(decode(shot), view).size);
    }
    assert.ok(vivid > 25, `fish are drawn: ${vivid} vivid pixels`);
  });

  test("clicking a fish opens its mind: bars, plan, memory, fish-eye view", async () => {
    await page.evaluate(() => window.shoal.step(40));
    await page.evaluate(() => window.shoal.pause());
    // The shark swims alone: its square on screen is its own.
    await waitForWidget(page, "animal_10");
    await clickUntil(page, "animal_10", () => window.shoal.settings().reef.selected != null);
    await page.evaluate(() => window.shoal.step(30));
    await waitForWidget(page, "fish_eye");
    const s = await state(page);
    const fish = s.reef.selected;
    assert.equal(fish.index, s.reef.selected.index);
    assert.match(fish.name, /^(fish|shark|pacifist) \d+$/);
    assert.ok(["predator", "prey", "pacifist"].includes(fish.habits.kind));
    for (const v of [fish.hunger, fish.libido, fish.fear, fish.brightness]) {
      assert.ok(v >= 0 && v <= 1, `in [0, 1]: ${v}`);
    }
    assert.ok(["avoid", "escape", "school", "eat", "wander", "leave"].includes(fish.intention), fish.intention);
    const shot = await page.screenshot();
    saveArtifact("reef-selected-webgl2.png", shot);
    const png = decode(shot);
    const w = await widgets(page);
    for (const name of ["reef_inspector", "reef_bar_hunger", "reef_intention", "reef_mind_plot"]) {
      assert.ok(w[name], `${name} is on screen`);
    }
    const eye = pixelStats(png, w.fish_eye);
    assert.ok(eye.distinctColours > 20, `the fish-eye view shows a picture: ${JSON.stringify(eye)}`);
  });

  test("the water overlay and the vision fan change the picture", async () => {
    const view = await waitForWidget(page, "view_left");
    const plain = decode(await page.screenshot());
    await clickUntil(page, "reef_overlay_temperature", () => window.shoal.settings().reef.overlay === "temperature");
    const warm = decode(await page.screenshot());
    assert.ok(changedPixels(plain, warm, view) > 500, "temperature dots drawn");
    await clickUntil(page, "reef_show_vision", () => !window.shoal.settings().reef.show_vision);
    const blind = decode(await page.screenshot());
    assert.ok(changedPixels(warm, blind, view) > 100, "the vision fan disappears");
  });

  test("the demo buttons build the courtship demo; the event log fills", async () => {
    await clickUntil(page, "reef_demo_courtship", () => window.shoal.state().reef.demo === "courtship");
    await clickUntil(page, "reef_body_point", () => window.shoal.state().reef.body === "point_mass");
    let s = await state(page);
    assert.equal(s.reef.pacifists, 3);
    assert.equal(s.reef.selected, undefined, "a new demo lets go of the fish");
    await page.evaluate(() => window.shoal.step(1500));
    s = await state(page);
    assert.ok(s.reef.events.length > 0, "something happened");
    assert.ok(
      s.reef.events.some((e) => /courting|looping|circling/.test(e.text)),
      JSON.stringify(s.reef.events.map((e) => e.text)),
    );
    await page.evaluate(() => window.shoal.play());
    await page.waitForFunction((n) => window.shoal.state().steps > n + 3, s.steps, { timeout: 60_000 });
    const log = (await widgets(page)).reef_events;
    assert.ok(log, "the event log is on screen");
    const stats = pixelStats(decode(await page.screenshot()), log);
    assert.ok(stats.distinctColours > 4, "the log has text");

    // A click on the newest event selects and follows the fish it is about.
    await page.evaluate(() => window.shoal.pause());
    const newest = (await state(page)).reef.events.at(-1);
    await clickUntil(page, "reef_event_0", () => window.shoal.state().reef.selected !== undefined);
    const after = await state(page);
    const subject = newest.kind.female ?? newest.kind.fish ?? newest.kind.predator;
    assert.equal(after.reef.selected.index, subject, JSON.stringify(newest));
    assert.equal((await page.evaluate(() => window.shoal.settings())).reef.follow, true);
  });

  test("the reef's data file holds its counts, events and the selected fish's mind", async () => {
    await page.evaluate(() => window.shoal.pause());
    await page.evaluate(() => window.shoal.set({ reef: { selected: 0 } }));
    // A whole number of samples (one every 5 steps): the last counts row is now.
    await page.evaluate(() => window.shoal.step(100 + ((5 - (window.shoal.state().steps % 5)) % 5)));
    const s = await state(page);
    assert.equal(s.steps % 5, 0);
    const file = await page.evaluate(() => window.shoal.export_csv());
    const seconds = String(Math.floor(s.time_secs)).padStart(4, "0");
    assert.equal(file.name, `shoal-reef-t${seconds}s.csv`);
    const lines = file.text.trim().split("\n");
    assert.match(lines[0], /^# Shoal data: Reef \(reef\)/);
    assert.ok(lines.includes(`# seed: ${s.seed}`), lines.slice(0, 8).join("\n"));
    assert.ok(lines.some((l) => l.startsWith("# settings link: #v1.")));
    const table = lines.filter((l) => !l.startsWith("#"));
    assert.ok(table[0].startsWith("table,time_s,predators_alive,prey_alive,pacifists_alive,food,prey_eaten"), table[0]);
    const kinds = new Set(table.slice(1).map((l) => l.split(",")[0]));
    assert.ok(kinds.has("counts") && kinds.has("mind"), [...kinds].join(" "));
    assert.ok(kinds.has("event"), "the event log is in the file");
    const counts = table.filter((l) => l.startsWith("counts,"));
    const header = table[0].split(",");
    const last = counts[counts.length - 1].split(",");
    const cell = (name) => Number(last[header.indexOf(name)]);
    assert.equal(cell("food"), s.reef.food, "the last counts row is the reef now");
    assert.equal(cell("pacifists_alive"), s.reef.pacifists);
    assert.equal(cell("spawnings"), s.reef.counts.spawnings);
    assert.equal(cell("food_eaten"), s.reef.counts.food_eaten);
    await page.evaluate(() => window.shoal.set({ reef: { selected: null } }));
    await page.evaluate(() => window.shoal.play());
  });

  test("the Minds section changes every fish of a kind: sexual mania, devoted, the demo's own", async () => {
    // The courtship demo holds only pacifists, whose libido is manic already.
    // (f32 values: compare within a part in a million.)
    const near = (a, b) => Math.abs(a - b) < 1e-6 * Math.abs(b);
    await clickUntil(page, "reef_minds", () => !!window.shoal.widgets().reef_minds_pacifist);
    await clickUntil(page, "reef_minds_pacifist", () => !!window.shoal.widgets().reef_minds_libido_sexual_mania);
    await clickUntil(page, "reef_minds_libido_nominal", () =>
      Math.abs(window.shoal.settings().reef.traits.pacifist.libido_rate_per_unit - 0.0025) < 1e-9);
    await scrollPanelTo(page, "reef_minds_persistence_devoted");
    await clickUntil(page, "reef_minds_persistence_devoted", () =>
      window.shoal.settings().reef.traits.pacifist.persistence_body_lengths === 20);
    saveArtifact("reef-minds-webgl2.png", await page.screenshot());
    const pacifist = async () => {
      await page.evaluate(() => window.shoal.set({ reef: { selected: 0 } }));
      await page.evaluate(() => window.shoal.step(1));
      const fish = (await state(page)).reef.selected;
      await page.evaluate(() => window.shoal.set({ reef: { selected: null } }));
      return fish;
    };
    let fish = await pacifist();
    assert.ok(near(fish.habits.mental.libido_rate_per_unit, 0.0025), "nominal p1 applied at once");
    assert.equal(fish.habits.persistence_body_lengths, 20, "devoted");
    await scrollPanelTo(page, "reef_minds_reset");
    await clickUntil(page, "reef_minds_reset", () =>
      window.shoal.settings().reef.traits.pacifist.persistence_body_lengths == null);
    fish = await pacifist();
    assert.ok(near(fish.habits.mental.libido_rate_per_unit, 0.01), "the demo's sexual mania again");
    assert.equal(fish.habits.persistence_body_lengths, 2);
    const refused = await page.evaluate(() => {
      try {
        window.shoal.set({ reef: { traits: { prey: { fear_threshold: 0.9 } } } });
        return "no error";
      } catch (err) {
        return String(err.message);
      }
    });
    assert.match(refused, /reef\.traits\.prey\.fear_threshold/);
  });

  test("Skip to the moment: the courtship on muscles runs ahead, goes back before the spawning and follows her", async () => {
    await clickUntil(page, "reef_demo_reef", () => window.shoal.state().reef.demo === "reef");
    await clickUntil(page, "reef_demo_courtship", () => window.shoal.state().reef.demo === "courtship");
    await clickUntil(page, "reef_body_physical", () => window.shoal.state().reef.body === "physical");
    await page.evaluate(() => window.shoal.play());
    // Her choice is in the log from the start.
    await page.waitForFunction(() => window.shoal.state().reef.events.length > 0, null, { timeout: 60_000 });
    let s = await state(page);
    assert.equal(s.skip.moment, "the spawning");
    assert.equal(s.skip.last, null);
    assert.ok(
      s.reef.events.some((e) => e.kind.kind === "chose" && /prefers bigger males/.test(e.text)),
      JSON.stringify(s.reef.events.map((e) => e.text)),
    );
    await scrollPanelTo(page, "reef_skip");
    await clickUntil(page, "reef_skip", () => {
      const k = window.shoal.state().skip;
      return k.searching !== null || k.last !== null;
    });
    await page.waitForFunction(() => window.shoal.state().skip.last !== null, null, { timeout: 180_000 });
    s = await state(page);
    const last = s.skip.last;
    assert.equal(last.outcome, "found", JSON.stringify(last));
    assert.match(last.moment.text, /spawned/);
    const lead = last.moment.time_secs - last.resumed_at_secs;
    assert.ok(lead >= 12 - 1e-6 && lead <= 18.1, `resumed ${lead} s before`);
    assert.ok(s.time_secs < last.moment.time_secs, "back before the moment");
    assert.match(s.notice ?? "", /Skipped ahead to/);
    await page.waitForFunction(
      (subject) => window.shoal.state().reef.selected?.index === subject,
      last.moment.subject,
      { timeout: 30_000 },
    );
    assert.equal((await settings(page)).reef.follow, true);
    saveArtifact("reef-skip-courtship-webgl2.png", await page.screenshot());
    // Played on at 1×, the spawning comes, at the same simulated time.
    await page.waitForFunction(
      () => window.shoal.state().reef.events.some((e) => /spawned/.test(e.text)),
      null,
      { timeout: 120_000 },
    );
    s = await state(page);
    const spawned = s.reef.events.find((e) => /spawned/.test(e.text));
    assert.equal(spawned.time_secs, last.moment.time_secs);
    // The notice spoke of this run's spawning: another demo takes it away.
    assert.match((await state(page)).notice ?? "", /Skipped ahead to/);
    await clickUntil(page, "reef_demo_feeding", () => window.shoal.state().reef.demo === "feeding");
    await page.waitForFunction(() => !/Skipped ahead/.test(window.shoal.state().notice ?? ""), null, {
      timeout: 10_000,
    });
    assert.deepEqual(errors, []);
  });

  test("bad values are refused with a message and change nothing", async () => {
    const before = await settings(page);
    for (const [call, pattern] of [
      [() => window.shoal.set({ reef: { visibility_m: 99 } }), /reef\.visibility_m/],
      [() => window.shoal.set({ reef: { selected: 50 } }), /reef\.selected/],
      [() => window.shoal.set({ reef: { demo: "disco" } }), /reef\.demo|unknown variant/],
      [() => window.shoal.set({ reef: { prey_count: -3 } }), /reef\.prey_count|invalid value/],
    ]) {
      const message = await page.evaluate(async (source) => {
        try {
          // eslint-disable-next-line no-new-func
          new Function(`return (${source})()`)();
          return "no error";
        } catch (err) {
          return String(err.message);
        }
      }, call.toString());
      assert.match(message, pattern);
    }
    assert.deepEqual(await settings(page), before);
    assert.deepEqual(errors, []);
  });
});
