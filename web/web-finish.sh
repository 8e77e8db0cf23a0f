#!/bin/sh
# Trunk post-build hook (run by web/post-build.sh): tools/web-finish drops the wasm's function
# names (a tenth of the download), fixes index.html's integrity hash of it, and
# writes brotli and gzip copies of the files for servers that send them
# precompressed (see the tool). A small native program in a package of its own;
# cargo builds it here the first time, so a fresh clone needs nothing more.
set -eu
dir="${TRUNK_STAGING_DIR:?this hook is run by trunk build}"
cargo run --quiet --release --manifest-path tools/web-finish/Cargo.toml \
  --target-dir "${CARGO_TARGET_DIR:-target}" -- "$dir"
