// The ODD model descriptions (issue 32, item 8): each scene's About window links
// its model's ODD page, which the build makes from docs/odd-*.md (web/odd-pages.sh)
// and serves with the app. Served here under a school's strict Content Security
// Policy, as the app itself must run.
import { test, describe, before, after } from "node:test";
import assert from "node:assert/strict";
import fs from "node:fs";
import path from "node:path";
import { serveDist, launch, openShoal, clickUntil, axTree, axFind, saveArtifact, distDir, repoRoot } from "./harness.mjs";

const CSP = "default-src 'self'; script-src 'self' 'wasm-unsafe-eval'";
const SECTIONS = [
  "1. Purpose and patterns",
  "2. Entities, state variables and scales",
  "3. Process overview and scheduling",
  "4. Design concepts",
  "5. Initialisation",
  "6. Input data",
  "7. Submodels",
];
const LINK = "Model description (ODD)";

describe("ODD pages", () => {
  let server, browser, context, page, errors;

  before(async () => {
    server = await serveDist({ headers: { "Content-Security-Policy": CSP } });
    browser = await launch("webgl2");
    context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
    ({ page, errors } = await openShoal(context, server.url));
  });

  after(async () => {
    await browser?.close();
    await server?.close();
  });

  test("the build made one page per docs/odd-*.md", () => {
    const odds = fs.readdirSync(path.join(repoRoot, "docs")).filter((f) => /^odd-.+\.md$/.test(f));
    assert.ok(odds.length >= 4, odds.join());
    for (const md of odds) {
      const html = md.replace(/^odd-/, "").replace(/\.md$/, ".html");
      assert.ok(fs.existsSync(path.join(distDir, "odd", html)), `dist/odd/${html} is missing`);
    }
    assert.ok(fs.existsSync(path.join(distDir, "odd", "odd.css")));
  });

  test("the physics tank's About links its ODD, which opens in a new tab with its sections", async () => {
    await clickUntil(page, "scene_physics", () => window.shoal.state().scene === "physics");
    await clickUntil(page, "about", () => !!window.shoal.widgets().about_window);
    // The accessibility mirror of egui's controls has the link, by its catalogue name.
    await page.waitForFunction(
      (name) => [...document.querySelectorAll("#shoal_a11y a")].some((a) => (a.getAttribute("aria-label") || a.textContent) === name),
      LINK,
      { timeout: 60_000 },
    );
    const tree = await axTree(page);
    assert.ok(axFind(tree, "link", LINK), "a screen reader finds the link");
    saveArtifact("odd-about-physics.png", await page.screenshot());

    // Followed through the mirror, as a screen reader does: a new tab with the page.
    const opened = context.waitForEvent("page", { timeout: 60_000 });
    await page.evaluate((name) => {
      const a = [...document.querySelectorAll("#shoal_a11y a")].find((a) => (a.getAttribute("aria-label") || a.textContent) === name);
      a.click();
    }, LINK);
    const odd = await opened;
    await odd.waitForLoadState("load");
    assert.equal(new URL(odd.url()).pathname, "/odd/physics.html");
    const headings = await odd.$$eval("h2", (hs) => hs.map((h) => h.textContent.trim()));
    assert.deepEqual(headings, SECTIONS);
    assert.match(await odd.title(), /physics tank/);
    await odd.close();
    assert.deepEqual(errors, []);
  });

  test("each page is served readable under the strict policy, with no dead links", async () => {
    for (const name of ["schooling", "reef", "physics", "learning"]) {
      const response = await fetch(`${server.url}odd/${name}.html`);
      assert.equal(response.status, 200, name);
      const html = await response.text();
      for (const section of SECTIONS) assert.ok(html.includes(`<h2>${section}</h2>`), `${name}: ${section}`);
      assert.ok(!/<script|style=/.test(html), `${name}: no script and no inline style`);
      // Every link leads to a page that is served, or out of the app.
      for (const [, href] of html.matchAll(/href="([^"]+)"/g)) {
        if (/^https?:/.test(href)) continue;
        const target = new URL(href, `${server.url}odd/${name}.html`);
        assert.equal((await fetch(target)).status, 200, `${name}: ${href}`);
      }
    }
    const reader = await context.newPage();
    const violations = [];
    reader.on("console", (m) => m.type() === "error" && violations.push(m.text()));
    await reader.goto(`${server.url}odd/reef.html`);
    // The stylesheet applied: the text column is narrow, not the browser's default.
    const width = await reader.$eval("main", (m) => getComputedStyle(m).maxWidth);
    assert.notEqual(width, "none");
    saveArtifact("odd-reef.png", await reader.screenshot());
    assert.deepEqual(violations, []);
    await reader.close();
  });
});
