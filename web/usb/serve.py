#!/usr/bin/env python3
"""Shoal from a USB stick: serves the app in the folder `shoal/` beside this
file on http://127.0.0.1:8080 (the next free port if that one is taken) and
opens it in the browser. Nothing leaves this computer: the server answers
only this computer, and the app needs no network.

    python3 serve.py              # then Ctrl+C to stop
    python3 serve.py --port 9000 --no-browser

Only Python 3's standard library is used.
"""

import argparse
import functools
import http.server
import os
import sys
import webbrowser

HERE = os.path.dirname(os.path.abspath(__file__))
APP = os.path.join(HERE, "shoal")

# The same strict policy a district's filter may send: the app needs no more.
HEADERS = {
    "Content-Security-Policy": "default-src 'self'; script-src 'self' 'wasm-unsafe-eval'",
    "X-Content-Type-Options": "nosniff",
    # The service worker decides what is cached (it keeps the app offline).
    "Cache-Control": "no-cache",
}
TYPES = {
    ".wasm": "application/wasm",
    ".js": "text/javascript",
    ".mjs": "text/javascript",
    ".webmanifest": "application/manifest+json",
    ".json": "application/json",
    ".svg": "image/svg+xml",
    ".css": "text/css",
    ".html": "text/html; charset=utf-8",
}


class Handler(http.server.SimpleHTTPRequestHandler):
    extensions_map = {**http.server.SimpleHTTPRequestHandler.extensions_map, **TYPES}

    def end_headers(self):
        for name, value in HEADERS.items():
            self.send_header(name, value)
        super().end_headers()

    def log_message(self, format, *args):
        pass


def main():
    parser = argparse.ArgumentParser(description="Serve Shoal on this computer only.")
    parser.add_argument("--port", type=int, default=8080, help="first port to try (default 8080)")
    parser.add_argument("--no-browser", action="store_true", help="do not open a browser")
    args = parser.parse_args()
    if not os.path.isfile(os.path.join(APP, "index.html")):
        sys.exit(f"Shoal's files are missing: expected {APP}/index.html next to this script.")
    handler = functools.partial(Handler, directory=APP)
    server = None
    for port in range(args.port, args.port + 20):
        try:
            server = http.server.ThreadingHTTPServer(("127.0.0.1", port), handler)
            break
        except OSError:
            continue
    if server is None:
        sys.exit(f"Ports {args.port} to {args.port + 19} are all taken: try --port 9000.")
    url = f"http://127.0.0.1:{server.server_address[1]}/"
    print(f"Shoal is at {url}  (Ctrl+C to stop)", flush=True)
    print(f"Shoal está en {url}  (Ctrl+C para detener)", flush=True)
    if not args.no_browser:
        webbrowser.open(url)
    try:
        server.serve_forever()
    except KeyboardInterrupt:
        pass


if __name__ == "__main__":
    main()
