# The page outside the canvas: its notices and the names a screen reader
# hears (src/web/page.rs, src/web/mod.rs, src/web/a11y_dom.rs).

page-could-not-start = Shoal could not start
page-no-canvas = The page has no canvas named shoal_canvas.
page-link-error = This link could not be opened: { $error }. Shoal started with its usual settings instead.
page-no-gpu-title = Shoal needs 3D graphics, and this browser did not provide them
page-no-gpu-why = Shoal draws the aquarium with WebGPU or, where that is missing, WebGL2. This browser offered neither, or they are switched off.
page-no-gpu-where = It works in current Chrome, Edge, Firefox and Safari (version 15 or later) on Windows, macOS, Linux, ChromeOS, Android and iPadOS. Check that hardware acceleration is on (in Chrome: Settings → System → "Use graphics acceleration when available"), then reload.
page-details = Details: { $detail }
page-reload = Reload Shoal
page-panic-title = Shoal stopped because of an internal error
page-panic-sorry = Sorry: something went wrong inside Shoal. Reloading the page starts it again.
page-panic-details = Details for the developers: { $detail }
page-canvas = The tank. Arrow keys turn the camera, plus and minus zoom, N selects a fish, D describes the tank, question mark lists every key.
page-text-agent = Text you type into the field being edited
page-file-not-text = the file is not text
page-file-unreadable = the file could not be read: { $error }

# Before the WebAssembly has loaded (web/shoal-page.js keeps a copy of these,
# checked against this file by a test).
page-loading = Filling the aquarium…
page-too-old-title = This browser is too old for Shoal
page-too-old-why = Shoal runs as WebAssembly, which this browser does not support. It works in current Chrome, Edge, Firefox and Safari (15 or later).
page-load-failed-title = Shoal could not load
page-load-failed = Loading the simulation failed: { $error }
page-unknown-error = unknown error
page-slow-title = Shoal is taking unusually long to start
page-slow-why = The aquarium has not started after 60 seconds. A slow network or a busy computer can cause this; reloading usually helps.
