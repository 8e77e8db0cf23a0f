// In-browser benchmark on both tiers: opens Shoal with ?bench, waits for the app's
// table (simulation steps/s, fish-steps/s, frame time) and the page's wasm size, and
// prints them. Not a test: it asserts nothing. Run with `./dev bench`.
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

const server = await serveDist();
try {
  for (const tier of ["webgl2", "webgpu"]) {
    const browser = await launch(tier);
    try {
      const page = await browser.newPage({ viewport: { width: 1280, height: 720 } });
      await page.goto(server.url + "?bench");
      await page.waitForFunction(() => window.shoal?.state().bench?.done, null, { timeout: 900_000 });
      const { tier: reported, bench } = await page.evaluate(() => window.shoal.state());
      const size = await page.evaluate(() => window.shoalWasmSize);
      console.log(`\nbrowser benchmark, ${reported} tier (headless Chromium, SwiftShader: software GPU)`);
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
