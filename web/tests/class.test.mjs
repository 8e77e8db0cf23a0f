// A class together (issue 37), the app's side: the class server (class/,
// built with `cargo build --release --manifest-path class/Cargo.toml`) serves
// the built dist/ over a temporary SQLite file; one teacher page starts a
// class of *How do fish swim?* from the side panel, three student pages join
// it with its code and a nickname, predict and run; the teacher's dashboard
// (read through `shoal.class()`) shows three predictions and three runs
// pooled; the reveal reaches the students; a student page holds no teacher
// token and its teacher messages are refused. WebGL2 only: the same wasm
// speaks the protocol on every tier.
import { test, describe, before, after } from "node:test";
import assert from "node:assert/strict";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";
import net from "node:net";
import { spawn } from "node:child_process";
import {
  repoRoot,
  distDir,
  launch,
  openShoal,
  saveArtifact,
  clickWidget,
  clickUntil,
  steadyWidget,
  clickInWindow,
  scrollWindowTo,
  waitForWidget,
  waitFrames,
  nudgeFrames,
  enterText,
  sleep,
  axTree,
  axFind,
} from "./harness.mjs";

/** The class server's binary: $SHOAL_CLASS_BIN, or the release build in
 * $CARGO_TARGET_DIR or class/target. */
function serverBinary() {
  if (process.env.SHOAL_CLASS_BIN) return process.env.SHOAL_CLASS_BIN;
  const target = process.env.CARGO_TARGET_DIR || path.join(repoRoot, "class", "target");
  return path.join(target, "release", "shoal-class");
}

function freePort() {
  return new Promise((resolve, reject) => {
    const s = net.createServer();
    s.listen(0, "127.0.0.1", () => {
      const { port } = s.address();
      s.close(() => resolve(port));
    });
    s.on("error", reject);
  });
}

/** Starts the class server over dist/ with a fresh SQLite file. */
async function startServer() {
  const bin = serverBinary();
  assert.ok(
    fs.existsSync(bin),
    `the class server is not built (${bin}): run cargo build --release --manifest-path class/Cargo.toml`,
  );
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), "shoal-class-browser-"));
  const port = await freePort();
  const child = spawn(
    bin,
    ["--port", String(port), "--database", `sqlite://${path.join(dir, "class.sqlite")}`, "--dist", distDir],
    { stdio: ["ignore", "inherit", "inherit"] },
  );
  const url = `http://127.0.0.1:${port}/`;
  for (let k = 0; k < 200; k++) {
    try {
      const r = await fetch(`${url}api/info`);
      if (r.ok) break;
    } catch {
      // Not listening yet.
    }
    await sleep(100);
  }
  return {
    url,
    close: async () => {
      child.kill("SIGTERM");
      await new Promise((r) => child.once("exit", r));
      fs.rmSync(dir, { recursive: true, force: true });
    },
  };
}

const cls = (page) => page.evaluate(() => window.shoal.class());


/** A student joins with the code and a nickname, from the join link. */
async function join(browser, server, code, nickname) {
  // Four pages share two cores here: give each more time to start.
  const { page, errors } = await openShoal(browser, `${server.url}?class=${code}`, {
    width: 1024,
    height: 700,
    timeout: 300_000,
  });
  await page.waitForFunction(() => window.shoal.class().server === true, null, { timeout: 60_000 });
  // The join link opens the join window with the code filled in.
  await page.waitForFunction((c) => window.shoal.class().join?.code === c, code, { timeout: 60_000 });
  // A screen reader finds the join window's fields and button by their names.
  await page.waitForSelector('#shoal_a11y input[aria-label="Nickname"]', { state: "attached", timeout: 60_000 });
  const tree = await axTree(page);
  const codeField = axFind(tree, "textbox", "Class code");
  assert.ok(codeField, "the class code field is named");
  assert.equal(codeField.value, code, "the screen reader reads the code from the link");
  assert.ok(axFind(tree, "textbox", "Nickname"), "the nickname field is named");
  assert.ok(axFind(tree, "button", "Join"), "the Join button is named");
  // On a loaded machine a click can land before the field takes the focus:
  // type until the join window holds the nickname, then press Join.
  for (let attempt = 0; ; attempt++) {
    await clickWidget(page, "class_nickname");
    await waitFrames(page, 2);
    if ((await cls(page)).join.nickname === "") await enterText(page, nickname);
    try {
      await page.waitForFunction((n) => window.shoal.class().join?.nickname === n, nickname, { timeout: 20_000 });
      break;
    } catch (e) {
      if (attempt === 3) throw new Error(`the nickname field never held ${nickname}: ${JSON.stringify(await cls(page))}`);
    }
  }
  try {
    await clickUntil(page, "class_join_go", () => window.shoal.class().role === "student");
  } catch (e) {
    saveArtifact(`class-join-${nickname.replace(/\W/g, "")}-failed.png`, await page.screenshot());
    const w = await page.evaluate(() => window.shoal.widgets());
    throw new Error(`${e.message}: ${JSON.stringify(await cls(page))}; join button ${JSON.stringify(w.class_join_go)}`);
  }
  await page.waitForFunction(() => window.shoal.class().link === "connected" && window.shoal.class().seed > 0, null, {
    timeout: 60_000,
  });
  // The class's lesson opens on the student's own seed.
  await page.waitForFunction(() => window.shoal.state().investigation?.id === "how-swim", null, { timeout: 60_000 });
  return { page, errors };
}

/** The student predicts (the first sketch) and runs. */
async function predictAndRun(page) {
  await clickInWindow(page, "investigation_next", () => window.shoal.state().investigation.step === "predict");
  await clickInWindow(page, "investigation_choice_0", () => window.shoal.state().investigation.chosen === 0);
  await clickInWindow(page, "investigation_commit", () => window.shoal.state().investigation.step === "run");
  await clickInWindow(page, "investigation_run", () => window.shoal.state().investigation.running);
}

describe("a class together (webgl2)", () => {
  let server, browser;

  before(async () => {
    server = await startServer();
    browser = await launch("webgl2");
  });

  after(async () => {
    await browser?.close();
    await server?.close();
  });

  test("a teacher starts a class, three students join, predict and run, the dashboard pools their runs", async () => {
    const info = await (await fetch(`${server.url}api/info`)).json();
    assert.deepEqual(info, { server: "shoal-class", protocol: 1 });

    // The teacher: Start a class, How do fish swim? (the fourth investigation).
    const { page: teacher, errors: teacherErrors } = await openShoal(browser, server.url, { width: 1280, height: 800 });
    await teacher.waitForFunction(() => window.shoal.class().server === true, null, { timeout: 60_000 });
    await clickUntil(teacher, "class_start", () => !!window.shoal.widgets().class_start_go);
    // The radio button is chosen when the screen reader's copy of it is checked
    // (clicked once the new window has sized itself).
    await steadyWidget(teacher, "class_lesson_3");
    await clickUntil(teacher, "class_lesson_3", () =>
      [...document.querySelectorAll('#shoal_a11y input[type="radio"]')].some(
        (r) => r.getAttribute("aria-label") === "How does a fish swim?" && r.checked,
      ),
    );
    await clickUntil(teacher, "class_start_go", () => window.shoal.class().role === "teacher");
    await teacher.waitForFunction(() => window.shoal.class().view?.code, null, { timeout: 60_000 });
    const code = (await cls(teacher)).code;
    assert.match(code, /^[A-HJ-NP-Z2-9]{6}$/);
    assert.deepEqual((await cls(teacher)).view.setup, { investigation: "how-swim" });
    await waitForWidget(teacher, "class_qr");
    // The projector shows the dashboard; the teacher's own tank waits (the
    // students' pages need the machine's two cores).
    await teacher.evaluate(() => window.shoal.set({ paused: true }));
    // The teacher link's token is kept by this browser only.
    const kept = await teacher.evaluate(() => localStorage.getItem("shoal.class.teacher"));
    assert.ok(kept && JSON.parse(kept).who.token.length === 64, "the teacher's token is kept in this browser");

    const students = [];
    for (const name of ["Ana", "Bo <b>", "Chen"]) students.push(await join(browser, server, code, name));
    await teacher.waitForFunction(() => window.shoal.class().view?.roster.length === 3, null, { timeout: 60_000 });
    const seeds = [];
    for (const s of students) seeds.push((await cls(s.page)).seed);
    const classSeed = (await cls(teacher)).view.seed;
    assert.deepEqual(seeds, [classSeed + 1, classSeed + 2, classSeed + 3], "seed = class seed + join order");
    for (const [k, s] of students.entries()) {
      assert.equal((await s.page.evaluate(() => window.shoal.settings())).seed, seeds[k], "the tank runs the student's seed");
    }

    for (const s of students) await predictAndRun(s.page);
    for (const s of students) {
      await s.page.waitForFunction(() => window.shoal.state().investigation.result, null, { timeout: 900_000, polling: 1000 });
    }
    // Every student's messages reach the server (nothing waits).
    for (const s of students) {
      await s.page.waitForFunction(() => window.shoal.class().waiting === 0, null, { timeout: 60_000 });
    }

    // The dashboard: three predictions, and three runs pooled in each measure.
    await teacher.waitForFunction(
      () => {
        const c = window.shoal.class();
        const n = Object.values(c.view?.histogram ?? {}).reduce((a, b) => a + b, 0);
        return n === 3 && c.pooled?.length > 0 && c.pooled.every((p) => p.n === 3 && p.students === 3);
      },
      null,
      { timeout: 120_000, polling: 1000 },
    );
    const dash = await cls(teacher);
    for (const p of dash.pooled) {
      assert.ok(p.low <= p.mean && p.mean <= p.high && p.low >= p.min && p.high <= p.max, JSON.stringify(p));
    }
    assert.ok(dash.view.roster.every((r) => r.prediction && r.results.length > 0));
    // One run each (the Runs column), however many measures a run reports.
    assert.ok(dash.view.roster.every((r) => r.runs === 1), JSON.stringify(dash.view.roster.map((r) => r.runs)));
    assert.ok(dash.view.roster.some((r) => r.nickname === "Bo <b>"), "nicknames as typed");
    await nudgeFrames(teacher, 2);
    await waitForWidget(teacher, "class_pooled");
    saveArtifact("class-teacher-dashboard.png", await teacher.screenshot());

    // Before the reveal the students see no counts.
    for (const s of students) assert.equal((await cls(s.page)).view.histogram, null);
    await clickUntil(teacher, "class_reveal", () => window.shoal.class().view.state.revealed === true);
    for (const s of students) {
      await s.page.waitForFunction(
        () => {
          const h = window.shoal.class().view?.histogram;
          return h && Object.values(h).reduce((a, b) => a + b, 0) === 3;
        },
        null,
        { timeout: 60_000 },
      );
    }
    await nudgeFrames(students[0].page, 2);
    saveArtifact("class-student.png", await students[0].page.screenshot());

    // A student page cannot reach the dashboard: no teacher token in its
    // storage, and a teacher's message from its connection is refused.
    const s0 = students[0].page;
    assert.equal(await s0.evaluate(() => localStorage.getItem("shoal.class.teacher")), null);
    const stored = await s0.evaluate(() => JSON.stringify(localStorage));
    assert.ok(!stored.includes(JSON.parse(kept).who.token), "the teacher token is nowhere in a student's storage");
    const refused = await s0.evaluate(async (c) => {
      const ws = new WebSocket(`ws://${location.host}/ws`);
      const got = [];
      await new Promise((r) => (ws.onopen = r));
      ws.onmessage = (e) => got.push(JSON.parse(e.data));
      const token = JSON.parse(localStorage.getItem("shoal.class.student")).who.token;
      ws.send(JSON.stringify({ v: 1, id: "x1", type: "resume", code: c, student_token: token }));
      ws.send(JSON.stringify({ v: 1, id: "x2", type: "reveal", revealed: false }));
      ws.send(JSON.stringify({ v: 1, id: "x3", type: "teacher", code: c, teacher_token: "0".repeat(64) }));
      for (let k = 0; k < 100 && got.filter((m) => m.re === "x2" || m.re === "x3").length < 2; k++) {
        await new Promise((r) => setTimeout(r, 100));
      }
      ws.close();
      return got.filter((m) => m.re === "x2" || m.re === "x3");
    }, code);
    assert.deepEqual(
      refused.map((m) => [m.re, m.type]),
      [
        ["x2", "error"],
        ["x3", "error"],
      ],
    );
    assert.equal(refused[0].code, "forbidden");
    assert.equal((await cls(teacher)).view.state.revealed, true, "the forged message changed nothing");

    assert.deepEqual(teacherErrors, []);
    for (const s of students) assert.deepEqual(s.errors, []);
  });
});
