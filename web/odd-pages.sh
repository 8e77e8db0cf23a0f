#!/bin/sh
# Trunk post-build hook (run by web/post-build.sh): the ODD descriptions docs/odd-*.md become
# static pages dist/odd/<scene>.html with web/odd-page.css, linked from each
# scene's About window. tools/odd-pages is a small native program (pulldown-cmark)
# in a package of its own; cargo builds it here the first time (seconds), so a
# fresh clone needs nothing more. It builds into the app's own target folder,
# which `trunk serve` does not watch.
set -eu
dir="${TRUNK_STAGING_DIR:?this hook is run by trunk build}"
cargo run --quiet --release --manifest-path tools/odd-pages/Cargo.toml \
  --target-dir "${CARGO_TARGET_DIR:-target}" -- \
  docs web/odd-page.css "$dir/odd"
