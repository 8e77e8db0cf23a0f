// Shared helpers for Shoal's browser tests: a static server for dist/, Chromium on a
// chosen GPU tier, and pixel statistics of screenshots.
import http from "node:http";
import fs from "node:fs";
import path from "node:path";
import { fileURLToPath } from "node:url";
import { chromium } from "playwright-core";
import { PNG } from "pngjs";

const here = path.dirname(fileURLToPath(import.meta.url));
export const repoRoot = path.resolve(here, "..", "..");
export const distDir = path.join(repoRoot, "dist");
export const artifactDir = path.join(repoRoot, "web", "test-artifacts");

const MIME = {
  ".html": "text/html; charset=utf-8",
  ".js": "text/javascript; charset=utf-8",
  ".wasm": "application/wasm",
  ".css": "text/css",
  ".png": "image/png",
  ".svg": "image/svg+xml",
  ".webmanifest": "application/manifest+json",
  ".json": "application/json",
};

/**
 * Serves dist/ on a free loopback port, with `headers` on every answer (a school's
 * Content-Security-Policy, say). With `precompressed`,
 * a request that accepts brotli gets the build's `.br` copy (tools/web-finish)
 * with `Content-Encoding: br`, as nginx's `brotli_static` sends it.
 */
export async function serveDist({ headers = {}, precompressed = false } = {}) {
  if (!fs.existsSync(path.join(distDir, "index.html"))) {
    throw new Error("dist/index.html is missing: build the web app first (trunk build --release)");
  }
  const server = http.createServer((req, res) => {
    const url = new URL(req.url, "http://127.0.0.1");
    let file = path.normalize(path.join(distDir, decodeURIComponent(url.pathname)));
    if (!file.startsWith(distDir)) {
      res.writeHead(403).end();
      return;
    }
    if (fs.existsSync(file) && fs.statSync(file).isDirectory()) file = path.join(file, "index.html");
    const type = MIME[path.extname(file)] || "application/octet-stream";
    const brotli = precompressed && /\bbr\b/.test(req.headers["accept-encoding"] || "") && fs.existsSync(`${file}.br`);
    fs.readFile(brotli ? `${file}.br` : file, (err, data) => {
      if (err) {
        res.writeHead(404).end("not found");
        return;
      }
      const encoding = brotli ? { "Content-Encoding": "br", Vary: "Accept-Encoding" } : {};
      res.writeHead(200, { "Content-Type": type, ...encoding, ...headers });
      res.end(data);
    });
  });
  await new Promise((resolve) => server.listen(0, "127.0.0.1", resolve));
  const { port } = server.address();
  return {
    url: `http://127.0.0.1:${port}/`,
    close: () => new Promise((r) => server.close(r)),
    /** Drops every open connection at once, as a network that fails does. */
    closeAll: () => server.closeAllConnections(),
  };
}

const BASE_FLAGS = [
  "--no-sandbox",
  "--disable-quic",
  "--no-first-run",
  "--disable-background-networking",
  "--disable-component-update",
  "--disable-sync",
];

/** ANGLE on the system's OpenGL ES through EGL, with no display: on a machine
 * with no GPU that is Mesa's llvmpipe, a software GPU (the libgl1-mesa-dri and
 * libegl-mesa0 packages, which ./dev installs). It is the path a Linux machine or
 * a Chromebook takes with its own driver, and on this 2-core machine it draws a
 * frame in half the time SwiftShader takes (docs/benchmarks.md, *The browser
 * tests' software GPU*). */
const LLVMPIPE = ["--use-gl=angle", "--use-angle=gl-egl", "--ignore-gpu-blocklist"];

/** Chromium flags per tier. There is no GPU on CI, so every tier draws with a
 * software GPU:
 * - `webgl2`: WebGL2 on llvmpipe; no WebGPU.
 * - `webgl2-swiftshader`: WebGL2 on SwiftShader, what Chrome falls back to when
 *   it blocks a machine's GPU (the aquarium test runs on it too).
 * - `webgpu`: WebGPU on SwiftShader's Vulkan, Chrome's fallback adapter (Dawn
 *   offers no other here); the page around it is composited on llvmpipe.
 * - `none`: no WebGL and no WebGPU. */
export const TIER_FLAGS = {
  webgl2: [...BASE_FLAGS, ...LLVMPIPE],
  "webgl2-swiftshader": [...BASE_FLAGS, "--disable-gpu"],
  webgpu: [
    ...BASE_FLAGS,
    "--enable-unsafe-webgpu",
    "--enable-features=Vulkan",
    "--use-vulkan=swiftshader",
    ...LLVMPIPE,
  ],
  none: [...BASE_FLAGS, "--disable-gpu", "--disable-3d-apis", "--disable-webgl"],
};

/** The tiers a file's tests run on: SHOAL_TIERS (comma-separated), both by default. */
export const TIERS = (process.env.SHOAL_TIERS || "webgl2,webgpu").split(",");

/** The tiers that run the long walks (SHOAL_WALK_TIERS, WebGL2 by default). A
 * walk's numbers and its windows' logic are the same wasm on every tier; what a
 * tier changes is the drawing. So the other tiers run each window's drawing and
 * one short walk, and the long walks, which cost minutes a tier on a software GPU,
 * run once. */
export const WALK_TIERS = (process.env.SHOAL_WALK_TIERS || "webgl2").split(",");

/** node:test options for a long walk on `tier`: skipped, with the reason, on a tier
 * that does not walk. */
export function walkOnly(tier) {
  return WALK_TIERS.includes(tier)
    ? {}
    : { skip: `a long walk: runs on ${WALK_TIERS.join(", ")} (the same wasm computes it on every tier)` };
}

/** Launches headless Chromium for `tier` with a fresh profile. */
export async function launch(tier, extraArgs = []) {
  return chromium.launch({
    executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
    headless: true,
    args: [...TIER_FLAGS[tier], ...extraArgs],
  });
}

/** Opens the app and waits until `window.shoal` runs and has drawn frames. */
export async function openShoal(browser, url, { width = 1280, height = 720, timeout = 90_000 } = {}) {
  const page = await browser.newPage({ viewport: { width, height } });
  const errors = [];
  page.on("console", (msg) => {
    if (msg.type() === "error") errors.push(msg.text());
  });
  page.on("pageerror", (err) => errors.push(`pageerror: ${err.message}`));
  await page.goto(url);
  await page.waitForFunction(() => window.shoal && window.shoal.state().steps > 30, null, { timeout });
  return { page, errors };
}

/** Decodes a PNG buffer. */
export function decode(buffer) {
  return PNG.sync.read(buffer);
}

/** Mean and standard deviation of luminance, and the number of distinct colours
 * (quantised to 4 bits a channel), over `rect` ({x, y, width, height} in pixels). */
export function pixelStats(png, rect = { x: 0, y: 0, width: png.width, height: png.height }) {
  let sum = 0;
  let sumSq = 0;
  let n = 0;
  const colours = new Set();
  for (let y = Math.floor(rect.y); y < Math.min(png.height, rect.y + rect.height); y++) {
    for (let x = Math.floor(rect.x); x < Math.min(png.width, rect.x + rect.width); x++) {
      const i = (y * png.width + x) * 4;
      const [r, g, b] = [png.data[i], png.data[i + 1], png.data[i + 2]];
      const lum = 0.2126 * r + 0.7152 * g + 0.0722 * b;
      sum += lum;
      sumSq += lum * lum;
      n++;
      colours.add(((r >> 4) << 8) | ((g >> 4) << 4) | (b >> 4));
    }
  }
  const mean = sum / n;
  return { mean, std: Math.sqrt(Math.max(0, sumSq / n - mean * mean)), distinctColours: colours.size };
}

/** Pixels that look like fish: saturated warm, yellow, green or purple colours, which
 * neither the blue water nor the beige sand nor the grey rocks have. A Set of indices. */
export function fishPixels(png, rect) {
  const out = new Set();
  for (let y = Math.floor(rect.y); y < Math.min(png.height, rect.y + rect.height); y++) {
    for (let x = Math.floor(rect.x); x < Math.min(png.width, rect.x + rect.width); x++) {
      const i = (y * png.width + x) * 4;
      const r = png.data[i] / 255, g = png.data[i + 1] / 255, b = png.data[i + 2] / 255;
      const max = Math.max(r, g, b), min = Math.min(r, g, b);
      const sat = max > 0 ? (max - min) / max : 0;
      if (max < 0.25 || sat < 0.55) continue;
      let hue;
      if (max === r) hue = (60 * ((g - b) / (max - min)) + 360) % 360;
      else if (max === g) hue = 60 * ((b - r) / (max - min)) + 120;
      else hue = 60 * ((r - g) / (max - min)) + 240;
      // Water and glass are blue-cyan (170°–250°); exclude them.
      if (hue > 165 && hue < 255) continue;
      out.add(y * png.width + x);
    }
  }
  return out;
}

/** Mean absolute luminance step between horizontally neighbouring pixels inside
 * `rect` (device pixels): how much fine detail a picture holds. */
export function sharpness(png, rect) {
  const lum = (i) => 0.2126 * png.data[i] + 0.7152 * png.data[i + 1] + 0.0722 * png.data[i + 2];
  let sum = 0, n = 0;
  for (let y = Math.floor(rect.y); y < rect.y + rect.height; y++) {
    for (let x = Math.floor(rect.x) + 1; x < rect.x + rect.width; x++) {
      const i = (y * png.width + x) * 4;
      sum += Math.abs(lum(i) - lum(i - 4));
      n++;
    }
  }
  return n ? sum / n : 0;
}

/** Fraction of the union of two pixel sets that is in only one of them. */
export function symmetricDifference(a, b) {
  let only = 0;
  for (const p of a) if (!b.has(p)) only++;
  for (const p of b) if (!a.has(p)) only++;
  const union = new Set([...a, ...b]).size;
  return union === 0 ? 0 : only / union;
}

/** Saves a screenshot buffer under web/test-artifacts/. */
export function saveArtifact(name, buffer) {
  fs.mkdirSync(artifactDir, { recursive: true });
  fs.writeFileSync(path.join(artifactDir, name), buffer);
}

/** Clicks the centre of a named widget, as a person would. Right after a reload the
 * panel may not have been laid out yet (a software-rendered frame can take seconds),
 * so it waits up to 30 s for the widget to appear. */
export async function clickWidget(page, name) {
  // One call to the page when the widget is there already: on a software GPU each
  // call waits for the frame being drawn.
  let w = await page.evaluate(() => window.shoal?.widgets() ?? {});
  let rect = w[name];
  if (!rect) {
    rect = await page
      .waitForFunction((n) => window.shoal.widgets()[n], name, { timeout: 30_000 })
      .then((handle) => handle.jsonValue())
      .catch(() => null);
    if (!rect) throw new Error(`widget ${name} is not on screen`);
    w = await page.evaluate(() => window.shoal.widgets());
  }
  // A control of the side panel below (or above) what the panel shows: scroll to it
  // first, as a person would.
  const view = w.view_left;
  if (view && rect.x + rect.width <= view.x + 1 && (rect.y < view.y || rect.y + rect.height > panelBottom(w))) {
    rect = await scrollPanelTo(page, name);
  }
  await page.mouse.click(rect.x + rect.width / 2, rect.y + rect.height / 2, { delay: 60 });
  return rect;
}

export const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

/** Enters `text` into the focused text box as one input event, as a phone's
 * keyboard, a paste or an input method does. Typing key by key costs two or three
 * frames a character on a software GPU (each key event waits for a frame), so the
 * tests type real keys in one answer (the why-school walk, with characters HTML
 * must escape) and enter longer texts this way. */
export async function enterText(page, text) {
  await page.keyboard.insertText(text);
}


/** Waits until the app has drawn `n` more frames, so that a screenshot shows what a
 * change just did (on a software GPU a frame can take a second; a fixed sleep is a
 * guess). A paused app draws only when something asks it to, so wait for one frame
 * after a command while paused. */
export async function waitFrames(page, n = 1) {
  const start = await page.evaluate(() => window.shoal.state().frames);
  await page.waitForFunction(([s, k]) => window.shoal.state().frames >= s + k, [start, n], {
    timeout: 60_000,
  });
}

/** Makes a paused app draw `n` more frames: it draws only when something asks,
 * and a small mouse move (over the top of the window) asks. */
let nudges = 0;
export async function nudgeFrames(page, n = 1) {
  nudges += 1;
  const start = await page.evaluate(() => window.shoal.state().frames);
  for (let k = 0; k < n; k++) {
    await page.mouse.move(page.viewportSize().width * 0.45 + ((nudges + k) % 2) * 3, 40);
    await page.waitForFunction((s) => window.shoal.state().frames > s, start + k, { timeout: 60_000 });
  }
}

/** Where the side panel's visible part ends: the bottom of the tank views (the
 * bottom panels begin there), or null before the first layout. */
function panelBottom(w) {
  const views = [w.view_left, w.view_right].filter(Boolean);
  return views.length ? Math.max(...views.map((v) => v.y + v.height)) : null;
}

/** Scrolls the side panel with the mouse wheel, as a person would, until the named
 * widget lies within the visible part of the panel (above the bottom panels), and
 * returns its rectangle. */
export async function scrollPanelTo(page, name) {
  for (let attempt = 0; attempt < 40; attempt++) {
    const w = await page.evaluate(() => window.shoal.widgets());
    const r = w[name];
    const bottom = panelBottom(w);
    if (r && bottom !== null && r.y >= 0 && r.y + r.height <= bottom) return attempt ? steady(page, name, r) : r;
    await page.mouse.move(120, 300);
    await page.mouse.wheel(0, r && r.y < 0 ? -100 : 100);
    await waitFrames(page, 2);
  }
  throw new Error(`${name} cannot be scrolled into view`);
}

/** Widget `name`'s rectangle once it has stopped moving: egui scrolls smoothly
 * and a window resizes to new content over several frames, and on a quick
 * software GPU a rectangle read meanwhile is not where the click would land.
 * Waits for the next frame until two frames agree. */
async function steady(page, name, rect) {
  for (let k = 0; k < 20; k++) {
    const { frames, paused } = await page.evaluate(() => {
      const s = window.shoal.state();
      return { frames: s.frames, paused: s.paused };
    });
    // A running tank draws on: its next frame comes, however slowly a loaded
    // machine draws it. A paused one draws only while something moves.
    const drew = await page
      .waitForFunction((f) => window.shoal.state().frames > f, frames, { timeout: paused ? 500 : 15_000 })
      .then(() => true)
      .catch(() => false);
    const now = (await page.evaluate(() => window.shoal.widgets()))[name];
    if (!now) return rect;
    const same = Math.abs(now.x - rect.x) < 0.5 && Math.abs(now.y - rect.y) < 0.5;
    rect = now;
    if (same || !drew) return rect;
  }
  return rect;
}

/** Waits until widget `name` is on screen and has stopped moving (a window that
 * has just opened sizes itself over a few frames), and returns its rectangle. */
export async function steadyWidget(page, name) {
  return steady(page, name, await waitForWidget(page, name));
}

/** Scrolls the window whose rectangle `shoal.widgets()` names `windowName` (the open
 * investigation's, by default) with the mouse wheel until widget `name` lies
 * inside it, below its title bar and `bottomMargin` pixels above its bottom, and
 * returns the widget's rectangle once it has stopped moving. */
export async function scrollWindowTo(page, name, { windowName = "investigation_window", bottomMargin = 2 } = {}) {
  for (let attempt = 0; attempt < 40; attempt++) {
    const w = await page.evaluate(() => window.shoal.widgets());
    const r = w[name];
    const win = w[windowName];
    if (r && win && r.y >= win.y + 20 && r.y + r.height <= win.y + win.height - bottomMargin) {
      // Scrolled, or not: a window also moves while it resizes to new content.
      return steady(page, name, r);
    }
    if (!win) {
      await waitFrames(page, 1);
      continue;
    }
    await page.mouse.move(win.x + win.width / 2, win.y + win.height / 2);
    await page.mouse.wheel(0, r && r.y < win.y + 20 ? -120 : 120);
    await waitFrames(page, 2);
  }
  throw new Error(`${name} cannot be scrolled into the window`);
}

/** Clicks widget `name` of a window (see [`scrollWindowTo`] for `options`) until
 * `predicate(arg)` holds in the page, scrolling it into the window first. */
export async function clickInWindow(page, name, predicate, arg, options = {}) {
  for (let attempt = 0; attempt < 4; attempt++) {
    await scrollWindowTo(page, name, options);
    try {
      await clickUntil(page, name, predicate, arg);
      return;
    } catch {
      console.error(`clicking ${name} in the window: no effect, scrolling to it again`);
    }
  }
  throw new Error(`clicking ${name} in the window had no effect`);
}

/** Waits until a named widget is on screen (the panel may still be laying out) and
 * returns its rectangle. */
export async function waitForWidget(page, name) {
  await page.waitForFunction((n) => !!window.shoal.widgets()[n], name, { timeout: 60_000 });
  return page.evaluate((n) => window.shoal.widgets()[n], name);
}

/** Clicks an idempotent widget (a radio, a check box, a preset button) until
 * `predicate` holds: on a software-rendered, loaded machine a frame can take
 * seconds, and a click that lands while egui is still laying out the previous frame
 * may be missed. */
export async function clickUntil(page, name, predicate, arg) {
  for (let attempt = 0; attempt < 4; attempt++) {
    await clickWidget(page, name);
    try {
      await page.waitForFunction(predicate, arg, { timeout: 20_000 });
      return;
    } catch {
      // Not applied yet: click again (said, so that a slow run shows why).
      console.error(`clicking ${name}: no effect in 20 s, clicking again`);
    }
  }
  throw new Error(`clicking ${name} had no effect`);
}

/** Pixels that differ by more than a little (summed RGB difference over 60)
 * between two decoded screenshots, inside `rect`. */
export function changedPixels(a, b, rect) {
  let changed = 0;
  for (let y = Math.floor(rect.y); y < rect.y + rect.height; y++) {
    for (let x = Math.floor(rect.x); x < rect.x + rect.width; x++) {
      const i = (y * a.width + x) * 4;
      const d = Math.abs(a.data[i] - b.data[i]) + Math.abs(a.data[i + 1] - b.data[i + 1]) + Math.abs(a.data[i + 2] - b.data[i + 2]);
      if (d > 60) changed++;
    }
  }
  return changed;
}

/** The browser's accessibility tree, as a screen reader gets it (CDP
 * `Accessibility.getFullAXTree`): the nodes not ignored, each with role, name,
 * value, description and properties. */
export async function axTree(page) {
  const cdp = await page.context().newCDPSession(page);
  await cdp.send("Accessibility.enable");
  const { nodes } = await cdp.send("Accessibility.getFullAXTree");
  await cdp.detach();
  return nodes
    .filter((n) => !n.ignored)
    .map((n) => {
      const props = Object.fromEntries((n.properties || []).map((p) => [p.name, p.value?.value]));
      return {
        role: n.role?.value,
        name: n.name?.value ?? "",
        value: n.value?.value,
        description: n.description?.value,
        ...props,
      };
    });
}

/** The node of `tree` with `role` and `name`. */
export const axFind = (tree, role, name) => tree.find((n) => n.role === role && n.name === name);

/** Waits until the accessible mirror has a button named `name`. */
export async function mirroredButton(page, name) {
  await page.waitForFunction(
    (n) => [...document.querySelectorAll("#shoal_a11y button")].some((b) => (b.getAttribute("aria-label") || b.textContent) === n),
    name,
    { timeout: 60_000 },
  );
}

/** Presses the mirror's button named `name`, as a screen reader does. */
export async function pressMirrored(page, name) {
  await mirroredButton(page, name);
  await page.evaluate((n) => {
    const b = [...document.querySelectorAll("#shoal_a11y button")].find((b) => (b.getAttribute("aria-label") || b.textContent) === n);
    b.click();
  }, name);
}
