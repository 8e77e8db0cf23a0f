#!/usr/bin/env bash
# Runs the class server's tests against SQLite and a throwaway PostgreSQL
# (class/with-postgres.sh: installs the Debian `postgresql` package if missing,
# starts a cluster in a temporary directory on a free port, stops and removes it
# whatever happens).
# Usage: class/test-postgres.sh [extra cargo test arguments]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
exec "$here/with-postgres.sh" cargo test --manifest-path "$here/Cargo.toml" "$@"
