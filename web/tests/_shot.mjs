import { serveDist, launch, openShoal, clickWidget, sleep } from "./harness.mjs";
const [,, name, patchJson, steps, clickAnimal] = process.argv;
const server = await serveDist();
const browser = await launch(process.env.TIER || "webgl2");
const { page, errors } = await openShoal(browser, server.url, { width: 1366, height: 800 });
await page.evaluate((p) => window.shoal.set(JSON.parse(p)), patchJson);
await page.evaluate((n) => window.shoal.step(n), Number(steps || 0));
await sleep(1500);
if (clickAnimal) { await clickWidget(page, clickAnimal); await sleep(1500); }
await page.screenshot({ path: `/tmp/shots/${name}.png` });
const s = await page.evaluate(() => window.shoal.state());
console.log(JSON.stringify({ reef: s.reef && { ...s.reef, events: s.reef.events.slice(-5) }, fps: s.fps, sps: s.steps_per_sec }).slice(0, 3000));
console.log("errors", errors);
await browser.close(); await server.close();
