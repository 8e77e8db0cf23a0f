#!/bin/sh
# Trunk post-build hook (run by web/post-build.sh): moves the loader that Trunk writes inline
# into index.html (`<script type="module">import init … </script>`) into a file of
# its own, shoal-start.js, loaded with `src`. A school's Content Security Policy
# (`script-src 'self' 'wasm-unsafe-eval'`) refuses inline scripts, and Trunk 0.21
# has no setting for this (trunk-rs/trunk issue 288).
set -eu
dir="${TRUNK_STAGING_DIR:?this hook is run by trunk build}"
url="${TRUNK_PUBLIC_URL:-/}"
html="$dir/index.html"
awk -v js="$dir/shoal-start.js" -v src="${url}shoal-start.js" '
  inside && /<\/script>/ { inside = 0; moved = 1; print "<script type=\"module\" src=\"" src "\"></script>"; next }
  inside { print > js; next }
  !moved && /^[ \t]*<script type="module">[ \t]*$/ { inside = 1; next }
  { print }
  END { if (!moved) { print "external-loader.sh: no inline loader found in index.html" > "/dev/stderr"; exit 1 } }
' "$html" > "$html.new"
mv "$html.new" "$html"
