#!/bin/sh
# Trunk's post-build hook (Trunk.toml). Trunk starts a stage's hooks all at once,
# and these must run in order: the last one hashes and compresses what the first
# two wrote.
#  1. external-loader.sh: Trunk's inline loader into shoal-start.js (strict CSP);
#  2. odd-pages.sh: the ODD descriptions as dist/odd/<scene>.html;
#  3. web-finish.sh: the wasm without its function names, index.html's integrity
#     hash of it, and .br / .gz copies of every file.
set -eu
here=$(dirname "$0")
sh "$here/external-loader.sh"
sh "$here/odd-pages.sh"
sh "$here/web-finish.sh"
