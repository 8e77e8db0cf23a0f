// Page-level safety net, loaded before the WebAssembly: explains a browser without
// WebAssembly, a module that fails to load, or a start that takes too long, instead
// of an endless "Loading…". The app itself replaces this notice once it runs.
//
// The string catalogue lives in the WebAssembly, so the few words shown before it
// loads are copied here from locales/<lang>/page.ftl; a test
// (src/i18n/tests.rs, `the_page_s_words_before_loading_match_the_catalogue`) checks
// that every copy equals its message, in every language. `{error}` stands for the
// message's `{ $error }`.
(function () {
  "use strict";
  var WORDS = /* words-begin */ {
    "en": {
      "page-loading": "Filling the aquarium…",
      "page-reload": "Reload Shoal",
      "page-too-old-title": "This browser is too old for Shoal",
      "page-too-old-why": "Shoal runs as WebAssembly, which this browser does not support. It works in current Chrome, Edge, Firefox and Safari (15 or later).",
      "page-load-failed-title": "Shoal could not load",
      "page-load-failed": "Loading the simulation failed: {error}",
      "page-unknown-error": "unknown error",
      "page-slow-title": "Shoal is taking unusually long to start",
      "page-slow-why": "The aquarium has not started after 60 seconds. A slow network or a busy computer can cause this; reloading usually helps."
    },
    "es": {
      "page-loading": "Llenando el acuario…",
      "page-reload": "Volver a cargar Shoal",
      "page-too-old-title": "Este navegador es demasiado antiguo para Shoal",
      "page-too-old-why": "Shoal funciona con WebAssembly, que este navegador no admite. Funciona en las versiones actuales de Chrome, Edge, Firefox y Safari (15 o posterior).",
      "page-load-failed-title": "Shoal no pudo cargarse",
      "page-load-failed": "No se pudo cargar la simulación: {error}",
      "page-unknown-error": "error desconocido",
      "page-slow-title": "Shoal está tardando mucho en iniciar",
      "page-slow-why": "El acuario no ha empezado después de 60 segundos. Una red lenta o una computadora ocupada pueden causarlo; volver a cargar la página suele ayudar."
    }
  } /* words-end */;

  // The same choice as the app's (src/ui/language.rs): `?lang=`, else the last
  // choice on this browser, else the browser's languages, else English.
  function language() {
    var codes = [];
    var m = /[?&]lang=([^&#]*)/.exec(location.search);
    if (m) codes.push(decodeURIComponent(m[1]));
    try {
      var stored = localStorage.getItem("shoal.lang");
      if (stored) codes.push(stored);
    } catch (e) { /* storage blocked: no remembered choice */ }
    codes = codes.concat(navigator.languages || [navigator.language || ""]);
    for (var i = 0; i < codes.length; i++) {
      var base = String(codes[i]).toLowerCase().split(/[-_]/)[0];
      if (WORDS.hasOwnProperty(base)) return base;
    }
    return "en";
  }
  var lang = language();
  var words = WORDS[lang];
  document.documentElement.lang = lang;
  var loading = document.querySelector("#shoal_notice .loading");
  if (loading) loading.textContent = words["page-loading"];

  function notice(title, text) {
    var box = document.getElementById("shoal_notice");
    // Only while still loading: never over the app (which hides the box) or over
    // a message it wrote (which replaces the spinner).
    if (!box || !box.querySelector(".spinner") || box.classList.contains("hidden")) return;
    box.className = "error";
    box.textContent = "";
    var h = document.createElement("h2");
    h.textContent = title;
    var p = document.createElement("p");
    p.textContent = text;
    var b = document.createElement("button");
    b.textContent = words["page-reload"];
    b.onclick = function () { location.reload(); };
    box.appendChild(h); box.appendChild(p); box.appendChild(b);
  }
  function failed(reason) {
    notice(words["page-load-failed-title"], words["page-load-failed"].replace("{error}", reason));
  }
  if (typeof WebAssembly !== "object") {
    notice(words["page-too-old-title"], words["page-too-old-why"]);
    return;
  }
  window.addEventListener("error", function (e) {
    // A module that fails to compile or import, or a download that breaks off
    // (Chrome says "Failed to fetch", Firefox "NetworkError").
    if (e && e.message && /wasm|WebAssembly|import|fetch|network/i.test(e.message)) failed(e.message);
  });
  window.addEventListener("unhandledrejection", function (e) {
    failed(e && e.reason ? (e.reason.message || String(e.reason)) : words["page-unknown-error"]);
  });
  setTimeout(function () {
    if (!window.shoal) notice(words["page-slow-title"], words["page-slow-why"]);
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

// Offline: after the first visit, a service worker keeps the app's files, so a
// class whose network fails (or filters) mid-lesson can reload and go on
// (web/shoal-sw.js). Not from a file:// page, where browsers allow none.
(function () {
  "use strict";
  if (!("serviceWorker" in navigator) || location.protocol === "file:") return;
  window.addEventListener("load", function () {
    navigator.serviceWorker.register("shoal-sw.js").catch(function (e) {
      console.warn("Shoal works online only here: " + e.message);
    });
  });
})();
