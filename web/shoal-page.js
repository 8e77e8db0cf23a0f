// Page-level safety net, loaded before the WebAssembly: explains a browser without
// WebAssembly, a module that fails to load, or a start that takes too long, instead
// of an endless "Loading…". The app itself replaces this notice once it runs.
(function () {
  "use strict";
  function notice(title, text) {
    var box = document.getElementById("shoal_notice");
    // Only while still loading: never over the app or over a message it wrote.
    if (!box || !box.querySelector(".spinner")) return;
    box.className = "error";
    box.textContent = "";
    var h = document.createElement("h2");
    h.textContent = title;
    var p = document.createElement("p");
    p.textContent = text;
    var b = document.createElement("button");
    b.textContent = "Reload Shoal";
    b.onclick = function () { location.reload(); };
    box.appendChild(h); box.appendChild(p); box.appendChild(b);
  }
  if (typeof WebAssembly !== "object") {
    notice("This browser is too old for Shoal",
      "Shoal runs as WebAssembly, which this browser does not support. It works in current " +
      "Chrome, Edge, Firefox and Safari (15 or later).");
    return;
  }
  window.addEventListener("error", function (e) {
    if (e && e.message && /wasm|WebAssembly|import/i.test(e.message)) {
      notice("Shoal could not load", "Loading the simulation failed: " + e.message);
    }
  });
  window.addEventListener("unhandledrejection", function (e) {
    var reason = e && e.reason ? (e.reason.message || String(e.reason)) : "unknown error";
    notice("Shoal could not load", "Loading the simulation failed: " + reason);
  });
  setTimeout(function () {
    if (!window.shoal) {
      notice("Shoal is taking unusually long to start",
        "The aquarium has not started after 60 seconds. A slow network or a busy computer can " +
        "cause this; reloading usually helps.");
    }
  }, 60000);
})();

// Benchmark mode (?bench): measure the WebAssembly module's download size, raw and
// gzipped, and print it next to the app's own figures (see src/bench.rs).
(function () {
  "use strict";
  if (!/[?&]bench(=|&|$)/.test(location.search)) return;
  window.addEventListener("load", async function () {
    var link = document.querySelector('link[href$=".wasm"]');
    if (!link || typeof CompressionStream !== "function") return;
    var bytes = new Uint8Array(await (await fetch(link.href)).arrayBuffer());
    var gz = new Blob([bytes]).stream().pipeThrough(new CompressionStream("gzip"));
    var gzBytes = (await new Response(gz).arrayBuffer()).byteLength;
    window.shoalWasmSize = { raw_bytes: bytes.byteLength, gzip_bytes: gzBytes };
    console.log("bench: wasm " + (bytes.byteLength / 1048576).toFixed(2) + " MiB raw, " +
      (gzBytes / 1048576).toFixed(2) + " MiB gzipped");
  });
})();

// The tank's focus ring shows only to someone using the keyboard: a Tab marks the
// page as driven by keys, a pointer press unmarks it (index.html's CSS).
(function () {
  "use strict";
  document.addEventListener("keydown", function (e) {
    if (e.key === "Tab") document.documentElement.classList.add("shoal-keys");
  }, true);
  document.addEventListener("pointerdown", function () {
    document.documentElement.classList.remove("shoal-keys");
  }, true);
})();
