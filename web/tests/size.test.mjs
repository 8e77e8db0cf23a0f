// The download a school network carries (issue 36, goal 5): a size budget for the
// gzipped wasm, which fails the test command when a change outgrows it, and the
// build's finishing step (tools/web-finish): no function names in the module, a
// correct integrity hash, and brotli copies a server can send as they are.
import { test, describe } from "node:test";
import assert from "node:assert/strict";
import crypto from "node:crypto";
import fs from "node:fs";
import path from "node:path";
import zlib from "node:zlib";
import { serveDist, launch, openShoal, distDir, repoRoot } from "./harness.mjs";

const wasmName = fs.readdirSync(distDir).find((f) => f.endsWith("_bg.wasm"));
const wasmPath = path.join(distDir, wasmName);
const budget = JSON.parse(fs.readFileSync(path.join(repoRoot, "web", "size-budget.json"), "utf8"));

/** The names of a wasm module's custom sections. */
function customSections(bytes) {
  const names = [];
  let at = 8;
  const leb = () => {
    let value = 0;
    for (let shift = 0; ; shift += 7) {
      const b = bytes[at++];
      value += (b & 0x7f) * 2 ** shift;
      if (b < 0x80) return value;
    }
  };
  while (at < bytes.length) {
    const id = bytes[at++];
    const size = leb();
    const end = at + size;
    if (id === 0) {
      const len = leb();
      names.push(new TextDecoder().decode(bytes.subarray(at, at + len)));
    }
    at = end;
  }
  return names;
}

describe("download size", () => {
  test("the gzipped wasm is within the budget", () => {
    const gzip = zlib.gzipSync(fs.readFileSync(wasmPath), { level: 9 }).length;
    const mib = (n) => (n / 2 ** 20).toFixed(2);
    console.log(`wasm gzipped: ${gzip} bytes (${mib(gzip)} MiB); budget ${budget.wasm_gzip_bytes} (${mib(budget.wasm_gzip_bytes)} MiB)`);
    assert.ok(gzip <= budget.wasm_gzip_bytes, `the gzipped wasm is ${gzip} bytes, over the budget of ${budget.wasm_gzip_bytes}`);
  });

  test("the wasm carries no function names, and index.html's integrity hash matches it", () => {
    const wasm = fs.readFileSync(wasmPath);
    const sections = customSections(wasm);
    assert.ok(!sections.includes("name"), `custom sections: ${sections}`);
    const html = fs.readFileSync(path.join(distDir, "index.html"), "utf8");
    const tag = html.split("\n").find((line) => line.includes(wasmName) && line.includes("integrity="));
    assert.ok(tag, "index.html preloads the wasm with an integrity hash");
    const expected = `sha384-${crypto.createHash("sha384").update(wasm).digest("base64")}`;
    assert.ok(tag.includes(expected), `${tag} should carry ${expected}`);
  });

  test("every precompressed copy decompresses to its file", () => {
    for (const name of fs.readdirSync(distDir).filter((f) => /\.(wasm|js|html|css)$/.test(f))) {
      const file = fs.readFileSync(path.join(distDir, name));
      const br = fs.readFileSync(path.join(distDir, `${name}.br`));
      const gz = fs.readFileSync(path.join(distDir, `${name}.gz`));
      assert.ok(zlib.brotliDecompressSync(br).equals(file), `${name}.br`);
      assert.ok(zlib.gunzipSync(gz).equals(file), `${name}.gz`);
    }
  });

  test("served precompressed with brotli, the app starts, and the wasm crosses the network as the .br copy", async () => {
    const server = await serveDist({ precompressed: true });
    const browser = await launch("webgl2");
    try {
      const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
      const sent = [];
      context.on("response", async (response) => {
        if (response.url().endsWith(wasmName)) sent.push((await response.allHeaders())["content-encoding"]);
      });
      const { page, errors } = await openShoal(context, server.url);
      const bytes = await page.evaluate((name) => {
        const entry = performance.getEntriesByType("resource").find((e) => e.name.endsWith(name));
        return entry && { transfer: entry.encodedBodySize, decoded: entry.decodedBodySize };
      }, wasmName);
      const br = fs.statSync(`${wasmPath}.br`).size;
      console.log(`wasm over the network: ${bytes.transfer} bytes brotli (${(bytes.transfer / 2 ** 20).toFixed(2)} MiB), ${bytes.decoded} decoded`);
      assert.ok(sent.includes("br"), `content-encoding seen: ${sent}`);
      assert.equal(bytes.transfer, br);
      assert.equal(bytes.decoded, fs.statSync(wasmPath).size);
      assert.deepEqual(errors, []);
    } finally {
      await browser.close();
      await server.close();
    }
  });
});
