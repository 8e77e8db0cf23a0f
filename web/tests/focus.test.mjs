// WCAG 2.4.7: when the tank itself (the canvas) has the keyboard's focus, a ring
// shows round it; a mouse user, who did not press Tab, sees none.
import { test } from "node:test";
import assert from "node:assert/strict";
import { serveDist, launch, openShoal, TIERS } from "./harness.mjs";

test("the tank's focus ring shows after Tab and goes with a pointer press", async () => {
  const server = await serveDist();
  const browser = await launch(TIERS[0]);
  try {
    const { page, errors } = await openShoal(browser, `${server.url}#`);
    const outline = () =>
      page.evaluate(() => getComputedStyle(document.getElementById("shoal_canvas")).outlineStyle);
    await page.evaluate(() => document.getElementById("shoal_canvas").focus());
    assert.equal(await outline(), "none", "no ring for a page nobody has tabbed in");
    await page.evaluate(() => {
      document.dispatchEvent(new KeyboardEvent("keydown", { key: "Tab" }));
      document.getElementById("shoal_canvas").focus();
    });
    assert.equal(await outline(), "solid", "a ring once the keyboard is in use");
    await page.mouse.click(700, 300);
    assert.equal(await outline(), "none", "no ring after a pointer press");
    assert.deepEqual(errors, []);
  } finally {
    await browser.close();
    await server.close();
  }
});
