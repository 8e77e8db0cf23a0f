// The teacher's studio (issue 15, item 3), on both tiers, through real clicks: the
// teacher opens the studio, hides one control (the stingrays), locks another (the
// speed), makes a third a mystery (alignment, set to 37), writes a question and
// presses Share with class (a QR code of the students' link). The link opens in a
// new page as a student: the hidden control is gone, the locked one does not move
// when dragged, the mystery number is shown nowhere (the panel, widgets(),
// settings(), state()), and the question is shown.
import { test, describe, before, after } from "node:test";
import assert from "node:assert/strict";
import zlib from "node:zlib";
import jsQR from "jsqr";
import {
  serveDist,
  launch,
  openShoal,
  saveArtifact,
  clickUntil,
  clickWidget,
  scrollPanelTo,
  waitForWidget,
  waitFrames,
  decode,
  pixelStats,
  TIERS,
  walkOnly,
  enterText,
  pressMirrored,
} from "./harness.mjs";

const QUESTION = "How strongly do these fish copy their neighbours? Guess the number.";
const MYSTERY = 37;

const settings = (page) => page.evaluate(() => window.shoal.settings());
const widgets = (page) => page.evaluate(() => window.shoal.widgets());

/** The settings a share link carries: `#v1.` + base64url of raw DEFLATE JSON. */
function linkSettings(link) {
  const fragment = link.split("#")[1];
  assert.ok(fragment.startsWith("v1."), fragment);
  const packed = Buffer.from(fragment.slice(3), "base64url");
  return JSON.parse(zlib.inflateRawSync(packed).toString("utf8"));
}

/** The text of the QR code drawn in `rect` (CSS pixels) of a screenshot,
 * read by a QR decoder as a phone would read it. */
function readQr(png, rect, scale) {
  const margin = 8;
  const x0 = Math.max(0, Math.floor((rect.x - margin) * scale));
  const y0 = Math.max(0, Math.floor((rect.y - margin) * scale));
  const w = Math.min(png.width - x0, Math.ceil((rect.width + 2 * margin) * scale));
  const h = Math.min(png.height - y0, Math.ceil((rect.height + 2 * margin) * scale));
  const data = new Uint8ClampedArray(w * h * 4);
  for (let y = 0; y < h; y++) {
    const from = ((y0 + y) * png.width + x0) * 4;
    data.set(png.data.subarray(from, from + w * 4), y * w * 4);
  }
  return jsQR(data, w, h)?.data ?? null;
}

/** A number that is the mystery value, anywhere in a JSON text. */
const holdsMystery = (text) => new RegExp(`(^|[^0-9.])${MYSTERY}(\\.0+)?([^0-9]|$)`).test(text);

for (const tier of TIERS) {
  describe(`teacher's studio (${tier})`, () => {
    let server, browser, page, errors, link;

    before(async () => {
      server = await serveDist();
      browser = await launch(tier);
      ({ page, errors } = await openShoal(browser, server.url, { width: 1280, height: 800 }));
      await clickUntil(page, "scene_boids", () => window.shoal.state().scene === "boids");
      // The starting state the students get: a school of 60, alignment 37.
      await page.evaluate(
        (a) => window.shoal.set({ left: { fish_count: 60, sharks: 1, alignment: a } }),
        MYSTERY,
      );
    });

    after(async () => {
      await browser?.close();
      await server?.close();
    });

    test("the teacher hides, locks, makes a mystery, asks a question and shares a QR code", async () => {
      await clickUntil(page, "studio_open", () => !!window.shoal.widgets().studio_window);
      // The toggles beside the controls.
      await scrollPanelTo(page, "studio_hide_left_stingrays");
      await clickUntil(
        page,
        "studio_hide_left_stingrays",
        () => window.shoal.settings().studio.rules["left.stingrays"]?.hidden === true,
      );
      await scrollPanelTo(page, "studio_mystery_left_alignment");
      await clickUntil(
        page,
        "studio_mystery_left_alignment",
        () => window.shoal.settings().studio.rules["left.alignment"]?.mystery === true,
      );
      // Far down the panel, Speed's lock is reached as a screen reader or the
      // keyboard reaches it: by its name in the accessible mirror, which says
      // which rule on which control.
      await pressMirrored(page, "Lock Speed");
      await page.waitForFunction(() => window.shoal.settings().studio.rules.speed?.locked === true, null, {
        timeout: 60_000,
      });
      // Every toggle on screen is a target of at least 24 px (WCAG 2.5.8).
      const toggles = Object.entries(await widgets(page)).filter(([n]) =>
        /^studio_(hide|lock|mystery)_/.test(n),
      );
      assert.ok(toggles.length >= 9, `${toggles.length} toggles`);
      for (const [n, r] of toggles) {
        assert.ok(r.width >= 24 && r.height >= 24, `${n}: ${r.width}x${r.height}`);
      }
      // The question, typed into the studio window.
      await clickWidget(page, "studio_question");
      await enterText(page, QUESTION);
      await page.waitForFunction(
        (q) => window.shoal.settings().studio.question === q,
        QUESTION,
        { timeout: 60_000 },
      );
      const s = await settings(page);
      assert.deepEqual(s.studio.rules, {
        "left.alignment": { mystery: true },
        "left.stingrays": { hidden: true },
        speed: { locked: true },
      });
      assert.equal(s.studio.student_view, false, "the teacher's page is not the student view");
      assert.equal(s.left.alignment, MYSTERY, "the teacher sees the value");
      await waitForWidget(page, "studio_question_card");
      await waitFrames(page, 2);
      saveArtifact(`studio-${tier}.png`, await page.screenshot());

      // Share with class: the QR code, big enough to project.
      await clickUntil(page, "studio_share", () => !!window.shoal.widgets().studio_qr);
      await waitFrames(page, 2);
      const w = await widgets(page);
      const qr = w.studio_qr;
      assert.ok(qr.width >= 160, `QR code ${qr.width} px wide`);
      assert.ok(Math.abs(qr.width - qr.height) < 1, "square");
      assert.ok(w.studio_copy_link, "a Copy link button");
      const shot = await page.screenshot();
      saveArtifact(`studio-share-${tier}.png`, shot);
      // Black modules on white: high contrast inside the code's square.
      const stats = pixelStats(decode(shot), qr);
      assert.ok(stats.std > 80, `QR contrast ${stats.std}`);
      assert.ok(stats.mean > 60 && stats.mean < 230, `QR mean ${stats.mean}`);

      link = await page.evaluate(() => window.shoal.student_link());
      const carried = linkSettings(link);
      assert.equal(carried.studio.student_view, true);
      assert.equal(carried.studio.question, QUESTION);
      assert.deepEqual(carried.studio.rules, s.studio.rules);
      // Decoded as far as its JSON, the link shows no mystery number: the value
      // travels scrambled in "sealed".
      assert.equal(carried.left?.alignment, undefined, "no alignment in the clear");
      assert.equal(typeof carried.sealed, "string");
      assert.ok(!holdsMystery(JSON.stringify(carried)), JSON.stringify(carried));
      // The QR code on screen, read by a decoder, is exactly the link.
      const png = decode(shot);
      const read = readQr(png, qr, png.width / 1280);
      assert.equal(read, link, "the QR code reads as the students' link");
      assert.deepEqual(errors, []);
    });

    test("the link opens the student view with the rules in force", walkOnly(tier), async () => {
      assert.ok(link, "the first test made the link");
      // The teacher's page has handed over its link; closed, it no longer shares
      // the software GPU with the student's page (half the frames otherwise).
      await page.close();
      const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
      const { page: pupil, errors: pupilErrors } = await openShoal(context, link, {
        width: 1280,
        height: 800,
      });
      const state = await pupil.evaluate(() => window.shoal.state());
      assert.equal(state.student_view, true);
      // The hidden value is applied exactly: the student's page holds settings
      // whose own link, mystery value sealed in it, is the teacher's link.
      assert.equal(await pupil.evaluate(() => window.shoal.student_link()), link);
      assert.equal(state.scene, "boids");
      assert.equal(state.notice, undefined, "the link opened without complaint");
      // The question, and no studio.
      await waitForWidget(pupil, "studio_question_card");
      let w = await pupil.evaluate(() => window.shoal.widgets());
      assert.equal(w.studio_open, undefined, "no Teacher's studio button for students");
      assert.equal(w.studio_hide_speed, undefined, "no toggles");
      // Hidden: the stingrays' count is gone, the sharks' (free) is there.
      assert.ok(w.sharks_count, "the free count is drawn");
      assert.equal(w.stingrays_count, undefined, "the hidden count is not");
      // Mystery: alignment's slider is replaced, so is the preset that would name it.
      assert.ok(w["mystery_left.alignment"], "the mystery label");
      assert.ok(w["mystery_left.preset"], "the preset is a mystery with it");
      assert.equal(w.weight_alignment, undefined, "no alignment slider");
      assert.ok(w.weight_cohesion, "the free sliders are there");
      const pupilSettings = await pupil.evaluate(() => window.shoal.settings());
      assert.equal(pupilSettings.left.alignment, "mystery");
      assert.ok(!holdsMystery(JSON.stringify(pupilSettings)), "settings() never holds 37");
      assert.ok(!holdsMystery(JSON.stringify(w)), "widgets() never names 37");
      // Selected fish: its attention gives no weight away.
      await pupil.evaluate(() => {
        window.shoal.set({ left: { selected: 4 } });
        window.shoal.step(3);
      });
      const attention = (await pupil.evaluate(() => window.shoal.state())).metrics.attention;
      assert.equal(attention.urges[1].urge, "alignment");
      assert.equal(attention.urges[1].weight, "mystery");
      assert.ok(Number.isFinite(attention.urges[2].weight), "a free urge's weight shows");
      const csv = await pupil.evaluate(() => window.shoal.export_csv().text);
      assert.ok(csv.includes("# settings link: withheld"), "the CSV withholds the link");
      assert.ok(!csv.includes("#v1."));
      // set() refuses what the teacher keeps.
      const refused = await pupil.evaluate(() => {
        try {
          window.shoal.set({ left: { alignment: 80 } });
          return null;
        } catch (err) {
          return err.message;
        }
      });
      assert.ok(refused && refused.includes("left.alignment"), refused);

      // Locked: the speed slider is drawn greyed and a real drag does not move it.
      await scrollPanelTo(pupil, "speed");
      w = await pupil.evaluate(() => window.shoal.widgets());
      assert.ok(w.locked_speed, "marked locked");
      const r = w.speed;
      await pupil.mouse.move(r.x + 10, r.y + r.height / 2);
      await pupil.mouse.down();
      await pupil.mouse.move(r.x + r.width - 5, r.y + r.height / 2, { steps: 8 });
      await pupil.mouse.up();
      await pupil.mouse.click(r.x + r.width - 5, r.y + r.height / 2);
      await waitFrames(pupil, 3);
      assert.equal((await pupil.evaluate(() => window.shoal.settings())).speed, 1);
      // A free slider still moves: the drag itself works.
      const c = (await scrollPanelTo(pupil, "weight_cohesion"));
      const before = (await pupil.evaluate(() => window.shoal.settings())).left.cohesion;
      await pupil.mouse.click(c.x + c.width * 0.1, c.y + c.height / 2);
      await pupil.waitForFunction(
        (b) => window.shoal.settings().left.cohesion !== b,
        before,
        { timeout: 30_000 },
      );
      await scrollPanelTo(pupil, "mystery_left.alignment");
      await waitFrames(pupil, 2);
      saveArtifact(`studio-student-${tier}.png`, await pupil.screenshot());
      // The question card at the top of the side panel.
      const card = await scrollPanelTo(pupil, "studio_question_card");
      assert.ok(card.height > 30, "the card holds the question");
      await waitFrames(pupil, 2);
      saveArtifact(`studio-student-question-${tier}.png`, await pupil.screenshot());
      assert.deepEqual(pupilErrors, []);
      await context.close();
    });
  });
}

describe("teacher's studio on a phone (WebGL2)", () => {
  let server, browser;
  before(async () => {
    server = await serveDist();
    browser = await launch("webgl2");
  });
  after(async () => {
    await browser?.close();
    await server?.close();
  });

  test("the studio window sits at the bottom and every toggle above it can be scrolled to and pressed", async () => {
    const { page, errors } = await openShoal(browser, server.url, { width: 390, height: 844 });
    await page.evaluate(() => window.shoal.set({ scene: "boids" }));
    await clickUntil(page, "show_panel", () => !!window.shoal.widgets().hide_panel);
    await clickUntil(page, "studio_open", () => !!window.shoal.widgets().studio_window);
    await waitFrames(page, 3);
    let w = await page.evaluate(() => window.shoal.widgets());
    const win = w.studio_window;
    assert.ok(win.y >= 844 * 0.5, `the window keeps to the lower half: ${JSON.stringify(win)}`);
    assert.ok(win.y + win.height <= 844 && win.x >= 0 && win.x + win.width <= 390, JSON.stringify(win));
    // A toggle far down the panel: scrolled until it is above the window,
    // then pressed by its effect.
    const name = "studio_lock_left_separation";
    let r;
    for (let attempt = 0; attempt < 60; attempt++) {
      w = await page.evaluate(() => window.shoal.widgets());
      r = w[name];
      if (r && r.y >= 0 && r.y + r.height <= w.studio_window.y - 4) break;
      await page.mouse.move(120, 200);
      await page.mouse.wheel(0, r && r.y < 0 ? -80 : 80);
      await waitFrames(page, 2);
    }
    assert.ok(r && r.y + r.height <= w.studio_window.y - 4, `${name} reached above the window: ${JSON.stringify(r)}`);
    assert.ok(r.width >= 24 && r.height >= 24, JSON.stringify(r));
    await clickUntil(page, name, () => window.shoal.settings().studio.rules["left.separation"]?.locked === true);
    saveArtifact("studio-phone.png", await page.screenshot());
    assert.deepEqual(errors, []);
    await page.close();
  });
});
