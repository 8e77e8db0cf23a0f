#!/bin/sh
# Shoal from a USB stick, on macOS, Linux or a Chromebook's Linux: serves the
# app on this computer and opens the browser. Ctrl+C stops it.
cd "$(dirname "$0")" || exit 1
if command -v python3 >/dev/null 2>&1; then
  exec python3 serve.py "$@"
fi
echo "Shoal needs Python 3 to serve itself (https://www.python.org/downloads/)."
echo "Shoal necesita Python 3 para servirse (https://www.python.org/downloads/)."
exit 1
