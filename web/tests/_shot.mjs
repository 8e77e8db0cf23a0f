import { serveDist, launch, openShoal, clickWidget, sleep } from "./harness.mjs";
const [,, name, patchJson, steps, clickName, trainN] = process.argv;
const server = await serveDist();
const browser = await launch(process.env.TIER || "webgl2");
const { page, errors } = await openShoal(browser, server.url, { width: 1366, height: 900 });
await page.evaluate((p) => window.shoal.set(JSON.parse(p)), patchJson);
if (trainN) await page.evaluate((n) => window.shoal.train(n), Number(trainN));
await page.evaluate((n) => window.shoal.step(n), Number(steps || 0));
await sleep(1500);
if (clickName) { await clickWidget(page, clickName); await sleep(2500); }
await page.screenshot({ path: `/tmp/shots/${name}.png` });
const s = await page.evaluate(() => window.shoal.state());
console.log(JSON.stringify({ learning: s.learning, fps: s.fps }).slice(0, 2000));
console.log("errors", errors);
await browser.close(); await server.close();
