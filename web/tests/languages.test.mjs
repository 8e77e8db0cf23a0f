// Every student: Shoal in Spanish. The language comes from the link
// (`?lang=es`), the person's choice on this browser, or the browser's own
// languages; the page says which (`<html lang>`), the accessibility tree and the
// screen speak it, numbers are written its way, and every link Shoal makes
// carries it.
import { describe, test, before, after } from "node:test";
import assert from "node:assert/strict";
import { serveDist, launch, openShoal, TIERS, saveArtifact, waitFrames, axTree, axFind as find, mirroredButton, pressMirrored as press } from "./harness.mjs";

for (const tier of TIERS) {
  describe(`languages (${tier})`, () => {
    let server, browser;
    before(async () => {
      server = await serveDist();
      browser = await launch(tier);
    });
    after(async () => {
      await browser?.close();
      await server?.close();
    });

    test("?lang=es: the page, the accessibility tree and the numbers speak Spanish, and every link carries it", async () => {
      const { page, errors } = await openShoal(browser, `${server.url}?lang=es#`);
      assert.equal(await page.evaluate(() => document.documentElement.lang), "es");
      assert.equal(await page.evaluate(() => window.shoal.state().lang), "es");
      await mirroredButton(page, "Reiniciar");
      const tree = await axTree(page);
      for (const name of ["Reiniciar", "Paso", "Describir el tanque", "Teclas", "Copiar enlace"]) {
        assert.ok(find(tree, "button", name), `no button ${name}`);
      }
      for (const name of ["Reset", "Step", "Describe the tank", "Copy link"]) {
        assert.ok(!find(tree, "button", name), `an English button ${name}`);
      }
      assert.deepEqual(
        await page.evaluate(() =>
          [...document.querySelectorAll("#shoal_a11y button")]
            .filter((b) => ["English", "Español"].includes(b.textContent))
            .map((b) => [b.textContent, b.lang]),
        ),
        [["English", "en"], ["Español", "es"]],
        "each language's button speaks its own language",
      );
      const spanish = find(tree, "button", "Español");
      assert.equal(spanish?.pressed, "true", "the Español button is pressed");
      // The text size reads with a decimal comma (1,00×).
      assert.ok(
        tree.some((n) => /^\d+,\d\d×$/.test(n.name)),
        `no number with a decimal comma: ${tree.map((n) => n.name).filter((n) => /×/.test(n)).join(" | ")}`,
      );
      // Every link Shoal makes opens in Spanish.
      assert.match(await page.evaluate(() => window.shoal.share_link()), /\?lang=es#/);
      assert.match(await page.evaluate(() => window.shoal.student_link()), /\?lang=es#/);
      await page.evaluate(() => window.shoal.set({ investigation: "why-school" }));
      const link = await page.evaluate(() => window.shoal.share_link());
      assert.match(link, /[?&]investigation=why-school/);
      assert.match(link, /[?&]lang=es/);
      await waitFrames(page, 3);
      saveArtifact(`lang-es-${tier}.png`, await page.screenshot());
      assert.deepEqual(errors, []);
      await page.close();
    });

    test("the language buttons switch every word, <html lang> and the remembered choice", async () => {
      const { page, errors } = await openShoal(browser, `${server.url}#`);
      assert.equal(await page.evaluate(() => document.documentElement.lang), "en");
      await press(page, "Español");
      await page.waitForFunction(() => window.shoal.state().lang === "es", null, { timeout: 60_000 });
      await mirroredButton(page, "Reiniciar");
      assert.equal(await page.evaluate(() => document.documentElement.lang), "es");
      assert.equal(await page.evaluate(() => localStorage.getItem("shoal.lang")), "es");
      assert.match(await page.evaluate(() => window.shoal.share_link()), /\?lang=es#/);
      // Opened again without ?lang, this browser remembers.
      await page.goto(`${server.url}#`);
      await page.waitForFunction(() => window.shoal && window.shoal.state().steps > 5, null, { timeout: 90_000 });
      assert.equal(await page.evaluate(() => window.shoal.state().lang), "es");
      await press(page, "English");
      await page.waitForFunction(() => window.shoal.state().lang === "en", null, { timeout: 60_000 });
      await mirroredButton(page, "Reset");
      assert.equal(await page.evaluate(() => document.documentElement.lang), "en");
      assert.doesNotMatch(await page.evaluate(() => window.shoal.share_link()), /lang=/);
      assert.deepEqual(errors, []);
      await page.close();
    });

    test("before the WebAssembly loads, the page speaks the chosen language: a module that fails to load is explained in Spanish", async () => {
      const page = await browser.newPage({ viewport: { width: 800, height: 600 } });
      // The module never arrives: the page's own safety net must explain it.
      await page.route("**/*.wasm", (route) => route.abort());
      await page.goto(`${server.url}?lang=es#`);
      await page.waitForSelector("#shoal_notice.error h2", { timeout: 60_000 });
      const notice = await page.evaluate(() => ({
        lang: document.documentElement.lang,
        title: document.querySelector("#shoal_notice h2").textContent,
        text: document.querySelector("#shoal_notice p").textContent,
        button: document.querySelector("#shoal_notice button").textContent,
      }));
      assert.equal(notice.lang, "es");
      assert.equal(notice.title, "Shoal no pudo cargarse");
      assert.match(notice.text, /^No se pudo cargar la simulación: /);
      assert.equal(notice.button, "Volver a cargar Shoal");
      saveArtifact(`languages-${tier}-load-failed-es.png`, await page.screenshot());
      await page.close();
    });

    test("a browser set to Spanish opens in Spanish", async () => {
      const page = await browser.newPage({ viewport: { width: 1280, height: 720 }, locale: "es-MX" });
      await page.goto(`${server.url}#`);
      await page.waitForFunction(() => window.shoal && window.shoal.state().steps > 5, null, { timeout: 90_000 });
      assert.equal(await page.evaluate(() => window.shoal.state().lang), "es");
      assert.equal(await page.evaluate(() => document.documentElement.lang), "es");
      await page.close();
    });
  });
}
