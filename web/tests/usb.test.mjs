// Every classroom: Shoal from a USB stick (issue 35). `./dev usb` packs the
// release app (dist/) with a one-command server (web/usb/serve.py); unpacked
// anywhere, `python3 serve.py` serves it on this computer only, under the
// strict policy a district's filter sends, and the app runs.
import { describe, test, before, after } from "node:test";
import assert from "node:assert/strict";
import { spawn, execFileSync } from "node:child_process";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";
import { repoRoot, distDir, launch, saveArtifact } from "./harness.mjs";
import { STRICT_CSP } from "./networks.test.mjs";

const python = "python3";

/** The zip's entries with their Unix permissions. */
function entries(zip) {
  const out = execFileSync(python, [
    "-c",
    "import sys, zipfile\nfor i in zipfile.ZipFile(sys.argv[1]).infolist(): print(oct(i.external_attr >> 16), i.filename)",
    zip,
  ]);
  return Object.fromEntries(
    out
      .toString()
      .trim()
      .split("\n")
      .map((line) => line.split(" ").reverse()),
  );
}

describe("Shoal from a USB stick", () => {
  let dir, server, browser, url;
  before(async () => {
    dir = fs.mkdtempSync(path.join(os.tmpdir(), "shoal-usb-"));
    const zip = path.join(dir, "shoal-usb.zip");
    execFileSync(python, [path.join(repoRoot, "web/usb/pack.py"), distDir, zip]);
    execFileSync(python, ["-m", "zipfile", "-e", zip, dir]);
    browser = await launch("webgl2");
  });
  after(async () => {
    await browser?.close();
    server?.kill();
    if (dir) fs.rmSync(dir, { recursive: true, force: true });
  });

  test("the zip holds the app, the server and the start scripts, runnable after unzip", () => {
    const zip = entries(path.join(dir, "shoal-usb.zip"));
    for (const name of ["serve.py", "start.sh", "start.cmd", "README.txt", "shoal/index.html", "shoal/shoal-sw.js", "shoal/odd/reef.html", "shoal/odd/odd.css"]) {
      assert.ok(zip[`shoal-usb/${name}`], `${name} is in the zip`);
    }
    assert.ok(Object.keys(zip).some((n) => n.endsWith(".wasm")), "the WebAssembly module is in the zip");
    assert.equal(zip["shoal-usb/start.sh"], "0o100755", "start.sh is executable once unzipped");
    assert.equal(zip["shoal-usb/serve.py"], "0o100755");
    const readme = fs.readFileSync(path.join(dir, "shoal-usb/README.txt"), "utf8");
    assert.match(readme, /start\.cmd/);
    assert.match(readme, /sin conexión/, "the instructions are in Spanish too");
  });

  test("one command serves it on this computer only, under a strict policy, and it runs", async () => {
    // A port away from the other tests' servers; serve.py moves on if taken.
    server = spawn(python, [path.join(dir, "shoal-usb/serve.py"), "--port", "18480", "--no-browser"], {
      stdio: ["ignore", "pipe", "inherit"],
    });
    url = await new Promise((resolve, reject) => {
      let out = "";
      server.stdout.on("data", (d) => {
        out += d;
        const m = out.match(/Shoal is at (http:\/\/127\.0\.0\.1:\d+\/)/);
        if (m) resolve(m[1]);
      });
      server.on("exit", (code) => reject(new Error(`serve.py stopped (${code}): ${out}`)));
    });
    const page = await browser.newPage({ viewport: { width: 1280, height: 720 } });
    const errors = [];
    page.on("pageerror", (e) => errors.push(e.message));
    const response = await page.goto(url);
    assert.equal(response.headers()["content-security-policy"], STRICT_CSP);
    await page.waitForFunction(() => window.shoal && window.shoal.state().steps > 30, null, { timeout: 120_000 });
    const wasm = await page.evaluate(async () => {
      const name = [...performance.getEntriesByType("resource")].map((r) => r.name).find((n) => n.endsWith(".wasm"));
      return name && (await fetch(name, { method: "HEAD" })).headers.get("content-type");
    });
    assert.equal(wasm, "application/wasm", "streaming compilation needs the WebAssembly type");
    saveArtifact("usb-served.png", await page.screenshot());
    assert.deepEqual(errors, []);
    await page.close();
  });
});
