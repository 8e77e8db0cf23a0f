// In-browser benchmark on both tiers: opens Shoal with ?bench, waits for the app's
// table (simulation steps/s, fish-steps/s, frame time) and the page's wasm size, and
// prints them, with the time from navigation to the first drawn frame (cold and
// cached). Not a test: it asserts nothing. Run with `./dev bench`.
import fs from "node:fs";
import path from "node:path";
import zlib from "node:zlib";
import { serveDist, launch, distDir } from "./harness.mjs";

const wasm = fs.readdirSync(distDir).find((f) => f.endsWith(".wasm"));
if (wasm) {
  const bytes = fs.readFileSync(path.join(distDir, wasm));
  const gz = zlib.gzipSync(bytes, { level: 9 }).length;
  console.log(`wasm (dist/${wasm}): ${(bytes.length / 1048576).toFixed(2)} MiB raw, ${(gz / 1048576).toFixed(2)} MiB gzipped`);
}

/**
 * Milliseconds from navigation to the app's first drawn frame (the page's
 * `shoal-first-frame` performance mark), on a fresh page in `context`.
 */
async function firstFrameMs(context, url) {
  const page = await context.newPage();
  try {
    await page.goto(url);
    await page.waitForFunction(() => performance.getEntriesByName("shoal-first-frame").length > 0, null, {
      timeout: 120_000,
    });
    return await page.evaluate(() => performance.getEntriesByName("shoal-first-frame")[0].startTime);
  } finally {
    await page.close();
  }
}

// `node web/tests/bench.mjs --first-frame`: only the first-frame figures.
const firstFrameOnly = process.argv.includes("--first-frame");
const server = await serveDist();
try {
  // SwiftShader's WebGL2 first: the software GPU every earlier figure in
  // docs/benchmarks.md was measured on. Then the tiers the browser tests use.
  const GPU = {
    "webgl2-swiftshader": "SwiftShader",
    webgl2: "Mesa llvmpipe",
    webgpu: "SwiftShader's Vulkan, the page composited on Mesa llvmpipe",
  };
  for (const tier of (process.env.SHOAL_BENCH_TIERS || "webgl2-swiftshader,webgl2,webgpu").split(",")) {
    const browser = await launch(tier);
    try {
      // First frame at 1280 × 800: a cold cache (a new browser profile), then the
      // same page again with the files cached (the service worker's second visit).
      const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
      const cold = await firstFrameMs(context, server.url);
      const warm = await firstFrameMs(context, server.url);
      await context.close();
      console.log(`\nfirst frame, ${tier} (navigation → first drawn frame, 1280 × 800): ${cold.toFixed(0)} ms cold cache, ${warm.toFixed(0)} ms cached (goal: ≤ 2,000 ms)`);
      if (firstFrameOnly) continue;
      const page = await browser.newPage({ viewport: { width: 1280, height: 720 } });
      await page.goto(server.url + "?bench");
      await page.waitForFunction(() => window.shoal?.state().bench?.done, null, { timeout: 900_000 });
      const { tier: reported, bench } = await page.evaluate(() => window.shoal.state());
      const size = await page.evaluate(() => window.shoalWasmSize);
      console.log(`\nbrowser benchmark, ${reported} tier (headless Chromium; software GPU: ${GPU[tier] ?? tier})`);
      if (size) console.log(`  wasm in the page: ${(size.raw_bytes / 1048576).toFixed(2)} MiB raw, ${(size.gzip_bytes / 1048576).toFixed(2)} MiB gzipped`);
      console.log("     scene |   fish |    steps/s |  fish-steps/s | frame ms | cpu ms");
      for (const r of bench.rows) {
        console.log(`  ${r.scene.padStart(8)} | ${String(r.fish).padStart(6)} | ${r.sim_steps_per_sec.toFixed(0).padStart(10)} | ${r.fish_steps_per_sec.toFixed(0).padStart(13)} | ${r.frame_ms.toFixed(2).padStart(8)} | ${r.cpu_frame_ms.toFixed(2).padStart(6)}`);
      }
      if (bench.annealing_evaluations_per_sec != null) {
        console.log(`  learning lab: ${bench.annealing_evaluations_per_sec.toFixed(1)} annealing evaluations/s`);
      }
      if (bench.experiment) {
        const e = bench.experiment;
        console.log(`  experiment ${e.name}: ${e.runs} runs of ${e.steps_per_run} steps on one thread: ${e.runs_per_sec.toFixed(3)} runs/s, ${e.steps_per_sec.toFixed(0)} steps/s`);
      }
    } finally {
      await browser.close();
    }
  }
} finally {
  await server.close();
}
