// The browser soak (issue 35): every scene driven through window.shoal for a
// given wall time or simulated time, a change every simulated 10 s (the native soak's changes,
// `shoal.soak_change`, made with the page's own shoal.set(), reset(), train()…),
// the simulation run with shoal.step(n) (as fast as the page steps), and after
// every 10 s the soak's checks on every animal (`shoal.soak_check()`: no NaN,
// no fish outside the tank or inside a rock) and state()'s numbers finite. The
// wasm memory and the JavaScript heap (after a garbage collection) are read
// after a warm-up at the scene's first settings, and at the end after the
// same warm-up at the same settings again.
//
// A manual benchmark, not a test (an hour would be too long for CI; the short
// version is soak.test.mjs):
//
//   node web/tests/soak.mjs [--minutes-per-scene 10] [--scene reef] [--seed 1]
//                           [--tier webgl2] [--count-max 20000]
//   node web/tests/soak.mjs --sim-minutes-per-scene 60   (the issue's hour a scene)
//
// --minutes-per-scene caps each scene's wall time; --sim-minutes-per-scene instead
// runs each scene's changes for that many simulated minutes (one change per 10 s),
// however long that takes.
//
// It needs the release build in dist/ (trunk build --release).
import { fileURLToPath } from "node:url";
import { serveDist, launch, openShoal } from "./harness.mjs";

/** Chromium flags for honest memory figures: precise `performance.memory`,
 * and `gc()` to collect before reading the heap. */
export const MEMORY_FLAGS = ["--enable-precise-memory-info", "--js-flags=--expose-gc"];

/** Simulated seconds of one step, by scene. */
const STEP_SECS = { aquarium: 1 / 60, boids: 1 / 60, physics: 0.055, reef: 0.055, learning: 0.055 };

export const SCENES = Object.keys(STEP_SECS);

/** The page's memory after a garbage collection: `{wasm_bytes, heap_bytes, js_heap_bytes}`. */
export async function memory(page) {
  return page.evaluate(() => {
    if (typeof window.gc === "function") window.gc();
    return window.shoal.memory();
  });
}

/** The numbers of state() that must be finite. */
function stateNumbers(s) {
  return {
    time_secs: s.time_secs,
    steps: s.steps,
    fish_count: s.fish_count,
    polarization: s.metrics?.polarization,
    milling: s.metrics?.milling,
    nnd_body_lengths: s.metrics?.nnd_body_lengths,
    mean_speed: s.metrics?.mean_speed,
  };
}

/** Runs `secs` simulated seconds of the page's scene with shoal.step. */
async function run(page, scene, secs) {
  const steps = Math.max(1, Math.round(secs / STEP_SECS[scene]));
  await page.evaluate((n) => window.shoal.step(n), steps);
  return steps;
}

/**
 * Soaks `scene` in `page` for `wallSecs` of wall time (or `maxChanges`
 * changes). Returns the figures; `failures` lists every broken rule.
 */
export async function soakScene(
  page,
  {
    scene,
    seed = 1,
    wallSecs,
    maxChanges = Infinity,
    warmUpSecs = 30,
    countMax = null,
    randomCountMax = null,
    firstExtremesSecs = null,
    log = () => {},
  },
) {
  const started = Date.now();
  // The scene's first settings (its defaults, the seed), from the start: the
  // soak's own "back to the first settings" (the last of the extremes).
  const first = async () => {
    const what = await page.evaluate(
      ([scene, seed]) => {
        const back = window.shoal.soak_change({ scene, seed, index: 6, first_extremes_secs: 0 });
        window.shoal.set(back.arg);
        window.shoal.reset(seed);
        return back.what;
      },
      [scene, seed],
    );
    if (what !== "extreme: back to the first settings") throw new Error(`not the first settings: ${what}`);
    await run(page, scene, warmUpSecs);
  };
  const figures = {
    scene,
    sim_secs: 0,
    steps: 0,
    changes: 0,
    applied: 0,
    refused: 0,
    animal_checks: 0,
    failures: [],
  };
  await first();
  figures.sim_secs += warmUpSecs;
  figures.memory_start = await memory(page);
  for (let index = 0; figures.changes < maxChanges && (Date.now() - started) / 1000 < wallSecs; index++) {
    const request = { scene, seed, index };
    if (countMax != null) request.count_max = countMax;
    if (randomCountMax != null) request.random_count_max = randomCountMax;
    if (firstExtremesSecs != null) request.first_extremes_secs = firstExtremesSecs;
    const outcome = await page.evaluate((request) => {
      const change = window.shoal.soak_change(request);
      try {
        window.shoal[change.call](change.arg === null ? undefined : change.arg);
        return { change, refused: null };
      } catch (e) {
        return { change, refused: String(e?.message ?? e) };
      }
    }, request);
    figures.changes++;
    const { change, refused } = outcome;
    if (refused === null) {
      figures.applied++;
      if (change.must_refuse) figures.failures.push(`applied, should be refused: ${change.what}`);
    } else {
      figures.refused++;
      if (!refused.trim() || /[{}]|\$/.test(refused)) {
        figures.failures.push(`${change.what}: refused without a reason: '${refused}'`);
      }
    }
    log(`${scene} ${figures.sim_secs.toFixed(0)} s ${change.what}${refused ? ` (refused: ${refused})` : ""}`);
    figures.steps += await run(page, scene, 10);
    figures.sim_secs += 10;
    const { check, state } = await page.evaluate(() => ({
      check: window.shoal.soak_check(),
      state: window.shoal.state(),
    }));
    figures.animal_checks += check.animals;
    for (const key of ["not_finite", "outside_tank", "inside_rock", "metrics_not_finite"]) {
      if (check[key] > 0) figures.failures.push(`${key} ${check[key]}: ${check.examples.join("; ")}`);
    }
    for (const [key, value] of Object.entries(stateNumbers(state))) {
      if (typeof value !== "number" || !Number.isFinite(value)) {
        figures.failures.push(`state().${key} is ${value} after ${change.what}`);
      }
    }
  }
  await first();
  figures.sim_secs += warmUpSecs;
  figures.memory_end = await memory(page);
  figures.wall_secs = (Date.now() - started) / 1000;
  return figures;
}

const mib = (b) => (b == null ? "-" : (b / 1048576).toFixed(1));

/** One line of figures. */
export function line(f) {
  return (
    `${f.scene.padEnd(9)} wall ${f.wall_secs.toFixed(0)} s, sim ${f.sim_secs.toFixed(0)} s, ` +
    `steps ${f.steps}, changes ${f.changes} (applied ${f.applied}, refused ${f.refused}), ` +
    `animal-checks ${f.animal_checks}, failures ${f.failures.length}; ` +
    `wasm MiB ${mib(f.memory_start.wasm_bytes)} -> ${mib(f.memory_end.wasm_bytes)}, ` +
    `heap in use MiB ${mib(f.memory_start.heap_bytes)} -> ${mib(f.memory_end.heap_bytes)}, ` +
    `JS heap MiB ${mib(f.memory_start.js_heap_bytes)} -> ${mib(f.memory_end.js_heap_bytes)}`
  );
}

async function main() {
  const args = process.argv.slice(2);
  const option = (name, otherwise) => {
    const i = args.indexOf(name);
    return i >= 0 && i + 1 < args.length ? args[i + 1] : otherwise;
  };
  const minutes = Number(option("--minutes-per-scene", "10"));
  const simMinutes = option("--sim-minutes-per-scene", null);
  if (simMinutes != null && !(Number(simMinutes) > 0)) throw new Error(`--sim-minutes-per-scene: not a positive number: ${simMinutes}`);
  const seed = Number(option("--seed", "1"));
  const tier = option("--tier", "webgl2");
  const countMax = option("--count-max", null);
  const scenes = option("--scene", null) ? [option("--scene")] : SCENES;
  const server = await serveDist();
  const browser = await launch(tier, MEMORY_FLAGS);
  let failed = false;
  try {
    const { page, errors } = await openShoal(browser, server.url);
    const opened = await memory(page);
    const per = simMinutes == null ? `${minutes} min (wall)` : `${simMinutes} simulated min`;
    console.log(`browser soak, ${tier} tier, ${per} per scene, seed ${seed}`);
    console.log(`page opened: wasm MiB ${mib(opened.wasm_bytes)}, heap in use MiB ${mib(opened.heap_bytes)}, JS heap MiB ${mib(opened.js_heap_bytes)}`);
    for (const scene of scenes) {
      const f = await soakScene(page, {
        scene,
        seed,
        wallSecs: simMinutes == null ? minutes * 60 : Infinity,
        // One change per simulated 10 s.
        maxChanges: simMinutes == null ? Infinity : Math.round((Number(simMinutes) * 60) / 10),
        countMax: countMax == null ? null : Number(countMax),
        log: process.env.SOAK_VERBOSE ? (t) => console.error(t) : () => {},
      });
      console.log(line(f));
      for (const failure of f.failures.slice(0, 10)) console.log(`  ${failure}`);
      failed ||= f.failures.length > 0;
    }
    const closing = await memory(page);
    console.log(`at the end: wasm MiB ${mib(closing.wasm_bytes)}, heap in use MiB ${mib(closing.heap_bytes)}, JS heap MiB ${mib(closing.js_heap_bytes)}`);
    if (errors.length) {
      console.log(`console errors: ${errors.slice(0, 5).join(" | ")}`);
      failed = true;
    }
  } finally {
    await browser.close();
    await server.close();
  }
  process.exitCode = failed ? 1 : 0;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  await main();
}
