// Every student: what a screen reader and a keyboard get. The browser's own
// accessibility tree (CDP Accessibility.getFullAXTree) must show every control
// with its name, role, value and range; acting on those elements, as a screen
// reader does, must change the settings; the keys must work; and the live
// region must say what the tank does.
import { describe, test, before, after } from "node:test";
import assert from "node:assert/strict";
import { serveDist, launch, openShoal, TIERS, walkOnly, saveArtifact, sleep, axTree, axFind as find } from "./harness.mjs";

/** Waits until the mirror shows an element matching `selector`. */
async function mirrored(page, selector) {
  await page.waitForSelector(`#shoal_a11y ${selector}`, { state: "attached", timeout: 60_000 });
  return page.locator(`#shoal_a11y ${selector}`).first();
}

for (const tier of TIERS) {
  describe(`screen reader and keyboard (${tier})`, () => {
    let server, browser, page, errors;
    before(async () => {
      server = await serveDist();
      browser = await launch(tier);
      ({ page, errors } = await openShoal(browser, `${server.url}#`));
    });
    after(async () => {
      await browser?.close();
      await server?.close();
    });

    test("the accessibility tree shows every control with its name, role, value and range", async () => {
      await page.evaluate(() => window.shoal.set({ scene: "boids" }));
      await mirrored(page, 'input[type=range][aria-label="Alignment"]');
      const tree = await axTree(page);
      // The scene tabs, each saying whether it is the one shown.
      for (const name of ["Aquarium", "Schooling lab", "Physics fish", "Reef", "Learning lab"]) {
        const tab = find(tree, "button", name);
        assert.ok(tab, `no button ${name}`);
        assert.equal(tab.pressed, name === "Schooling lab" ? "true" : "false", `${name} pressed`);
      }
      for (const name of ["Pause", "Reset", "Step", "Describe the tank", "Keys"]) {
        assert.ok(find(tree, "button", name), `no button ${name}`);
      }
      // Each urge's slider: named as on screen, with its value, range and help.
      const settings = await page.evaluate(() => window.shoal.settings());
      for (const [name, key] of [["Alignment", "alignment"], ["Cohesion", "cohesion"], ["Separation", "separation"]]) {
        const slider = find(tree, "slider", name);
        assert.ok(slider, `no slider ${name}`);
        assert.equal(Number(slider.valuemin), 0, `${name} min`);
        assert.equal(Number(slider.valuemax), 100, `${name} max`);
        assert.equal(Number(slider.value ?? slider.valuetext), settings.left[key], `${name} value`);
        assert.ok((slider.description || "").length > 20, `${name} has no help: ${JSON.stringify(slider)}`);
      }
      const radio = find(tree, "radio", "Blended (direct)");
      assert.ok(radio, "no control-mode radio");
      assert.ok(find(tree, "checkbox", "Compare two tanks"), "no Compare check box");
      // No nameless control.
      const controls = tree.filter((n) => ["button", "slider", "checkbox", "radio", "textbox", "spinbutton", "combobox"].includes(n.role));
      const nameless = controls.filter((n) => !n.name.trim());
      assert.deepEqual(nameless, [], "controls without a name");
      assert.ok(controls.length > 40, `only ${controls.length} controls`);
      // The live region.
      assert.ok(tree.some((n) => n.role === "status"), "no live region");
    });

    test("a screen reader's actions move the egui controls and the settings", async () => {
      await page.evaluate(() => window.shoal.set({ scene: "boids", paused: false }));
      // Moving the mirrored slider (a screen reader's arrow keys on it).
      const before = (await page.evaluate(() => window.shoal.settings())).left.alignment;
      const slider = await mirrored(page, 'input[type=range][aria-label="Alignment"]');
      await slider.focus();
      for (let i = 0; i < 3; i++) await page.keyboard.press("ArrowRight", { delay: 100 });
      await page.waitForFunction((b) => window.shoal.settings().left.alignment > b, before, { timeout: 30_000 });
      // The ring shows where the focus is, over the slider egui drew.
      const ring = await page.evaluate(() => {
        const r = document.getElementById("shoal_focus_ring");
        const s = getComputedStyle(r);
        return { display: s.display, w: r.getBoundingClientRect().width };
      });
      assert.equal(ring.display, "block");
      assert.ok(ring.w > 20, `ring ${JSON.stringify(ring)}`);
      // Pressing a button (a screen reader's default action is a click).
      const pause = await mirrored(page, 'button:text-is("Pause")');
      await pause.evaluate((b) => b.click());
      await page.waitForFunction(() => window.shoal.state().paused, null, { timeout: 30_000 });
      const play = await mirrored(page, 'button:text-is("Play")');
      await play.evaluate((b) => b.click());
      await page.waitForFunction(() => !window.shoal.state().paused, null, { timeout: 30_000 });
      // Ticking a check box.
      const compare = await mirrored(page, 'input[type=checkbox][aria-label="Compare two tanks"]');
      await compare.evaluate((c) => c.click());
      await page.waitForFunction(() => window.shoal.state().compare, null, { timeout: 30_000 });
      await compare.evaluate((c) => c.click());
      await page.waitForFunction(() => !window.shoal.state().compare, null, { timeout: 30_000 });
      // A scene tab.
      const reef = await mirrored(page, 'button:text-is("Reef")');
      await reef.evaluate((b) => b.click());
      await page.waitForFunction(() => window.shoal.state().scene === "reef", null, { timeout: 60_000 });
      await page.evaluate(() => window.shoal.set({ scene: "boids" }));
      assert.deepEqual(errors, []);
    });

    test("keys: Tab reaches the controls, ? lists the keys, D describes the tank, P pauses", async () => {
      await page.evaluate(() => window.shoal.set({ scene: "boids", paused: false }));
      // A student who clicked the tank presses Tab: egui moves its focus to
      // the first control, and the page's focus follows it into the mirror.
      await page.focus("#shoal_canvas");
      await page.keyboard.press("Tab", { delay: 100 });
      await page
        .waitForFunction(() => !!document.activeElement?.closest("#shoal_a11y"), null, { timeout: 30_000 })
        .catch(() => {});
      const first = await page.evaluate(() => ({
        inMirror: !!document.activeElement?.closest("#shoal_a11y"),
        text: document.activeElement?.textContent || document.activeElement?.getAttribute("aria-label"),
      }));
      assert.ok(first.inMirror, `Tab went to ${JSON.stringify(first)}`);
      await page.keyboard.press("Tab", { delay: 100 });
      const second = await page.evaluate(() => ({
        inMirror: !!document.activeElement?.closest("#shoal_a11y"),
        text: document.activeElement?.textContent || document.activeElement?.getAttribute("aria-label"),
      }));
      assert.ok(second.inMirror && second.text !== first.text, `the next Tab: ${JSON.stringify([first, second])}`);
      // The keys reach egui from a focused control.
      await page.keyboard.press("p", { delay: 100 });
      await page.waitForFunction(() => window.shoal.state().paused, null, { timeout: 30_000 });
      await page.keyboard.press("p", { delay: 100 });
      await page.waitForFunction(() => !window.shoal.state().paused, null, { timeout: 30_000 });
      await page.keyboard.press("?", { delay: 100 });
      await page.waitForFunction(() => !!window.shoal.widgets().keys_close, null, { timeout: 30_000 });
      const shot = await page.screenshot();
      saveArtifact(`a11y-keys-window-${tier}.png`, shot);
      await page.keyboard.press("?", { delay: 100 });
      await page.waitForFunction(() => !window.shoal.widgets().keys_close, null, { timeout: 30_000 });
      await page.keyboard.press("d", { delay: 100 });
      await page.waitForFunction(() => (window.shoal.state().said || "").includes("Plots:"), null, { timeout: 30_000 });
      const said = await page.evaluate(() => window.shoal.state().said);
      assert.match(said, /fish/);
      assert.match(said, /polarization \d\.\d\d/);
      const live = await page.evaluate(() => document.getElementById("shoal_live").textContent);
      assert.equal(live, said, "the live region says what the app said");
      assert.deepEqual(errors, []);
    });

    test("Why do fish school? from prediction to reveal with the screen reader's elements only", walkOnly(tier), async () => {
      // Every step through the mirror, as a screen reader does it: a click is
      // the element's default action, typing fills the mirrored text box.
      const press = async (text) => {
        const button = await mirrored(page, `button:text-is(${JSON.stringify(text)})`);
        await button.evaluate((b) => b.click());
      };
      const inv = () => page.evaluate(() => window.shoal.state().investigation);
      await press("Investigations: predict, run, explain");
      await press("Why do fish school?");
      await page.waitForFunction(() => window.shoal.state().investigation?.id === "why-school", null, { timeout: 60_000 });
      await press("Next: predict »");
      await page.waitForFunction(() => window.shoal.state().investigation.step === "predict", null, { timeout: 30_000 });
      // The choices are buttons that say which one is chosen.
      await press("The school (Group tank)");
      await page.waitForFunction(() => window.shoal.state().investigation.chosen === 1, null, { timeout: 30_000 });
      // The mirror follows on the next frame it draws.
      await page.waitForFunction(
        () =>
          [...document.querySelectorAll("#shoal_a11y button")].some(
            (b) => b.textContent === "The school (Group tank)" && b.getAttribute("aria-pressed") === "true",
          ),
        null,
        { timeout: 30_000 },
      );
      await press("Commit my prediction (it locks)");
      await page.waitForFunction(() => window.shoal.state().investigation.step === "run", null, { timeout: 30_000 });
      // Faster with the ] key, from a focused control.
      const run = await mirrored(page, 'button:text-is("Run »")');
      await run.focus();
      for (let k = 0; k < 3; k++) await page.keyboard.press("]", { delay: 100 });
      await page.waitForFunction(() => window.shoal.settings().speed >= 8, null, { timeout: 30_000 });
      await press("Run »");
      await page.waitForFunction(() => window.shoal.state().investigation.running, null, { timeout: 30_000 });
      await page.waitForFunction(() => window.shoal.state().investigation.result, null, { timeout: 900_000, polling: 1000 });
      // The result is words in the page.
      const summary = (await inv()).result.summary;
      await page.waitForFunction(
        (s) => [...document.querySelectorAll("#shoal_a11y p")].some((p) => p.textContent.includes(s)),
        summary,
        { timeout: 30_000 },
      );
      await press("Next: explain »");
      await page.waitForFunction(() => window.shoal.state().investigation.step === "explain", null, { timeout: 30_000 });
      const answers = ["The loners were caught one by one", "The shark switched targets", "Too many fish to follow"];
      let question = null;
      for (const [k, answer] of answers.entries()) {
        // The mirror shows the next question's box a frame after the state moves on.
        await page.waitForFunction(
          (q) => {
            const box = document.querySelector("#shoal_a11y textarea");
            return box && box.getAttribute("aria-label") !== q;
          },
          question,
          { timeout: 30_000 },
        );
        const box = await mirrored(page, "textarea");
        question = await box.getAttribute("aria-label");
        assert.ok(question.length > 10, "the answer box is named by its question");
        await box.fill(answer);
        await page.waitForFunction((a) => window.shoal.state().investigation.explanations.includes(a), answer, { timeout: 30_000 });
        await press(k + 1 === answers.length ? "What did scientists find? »" : "Next question »");
        await page.waitForFunction((n) => {
          const i = window.shoal.state().investigation;
          return i.step === "reveal" || i.prompt === n;
        }, k + 1, { timeout: 30_000 });
      }
      await page.waitForFunction(() => window.shoal.state().investigation.step === "reveal", null, { timeout: 30_000 });
      await page.waitForFunction(
        () => [...document.querySelectorAll("#shoal_a11y p")].some((p) => p.textContent === "What scientists found"),
        null,
        { timeout: 30_000 },
      );
      saveArtifact(`a11y-why-school-reveal-${tier}.png`, await page.screenshot());
      await page.evaluate(() => window.shoal.set({ speed: 1 }));
      assert.deepEqual(errors, []);
    });

    test("the live region tells a shark's catch", walkOnly(tier), async () => {
      await page.evaluate(() => window.shoal.set({ scene: "boids", speed: 4, left: { sharks: 4 } }));
      await page.waitForFunction(
        () => /caught/.test(document.getElementById("shoal_live").textContent || ""),
        null,
        { timeout: 180_000 },
      );
      await page.evaluate(() => window.shoal.set({ speed: 1, left: { sharks: 0 } }));
      await sleep(100);
    });
  });
}
