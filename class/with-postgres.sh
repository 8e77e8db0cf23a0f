#!/usr/bin/env bash
# Runs a command with a throwaway PostgreSQL cluster: installs the Debian
# `postgresql` package if missing, starts a cluster in a temporary directory on a
# free port (as the `postgres` user when run as root), exports its URL as
# SHOAL_CLASS_TEST_POSTGRES, runs the command, and stops and removes the cluster
# whatever happens. The cluster runs with fsync=off (fast tests) unless
# SHOAL_PG_FSYNC=on (the load harness's figures).
# Usage: class/with-postgres.sh COMMAND [ARGUMENTS...]
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: $0 COMMAND [ARGUMENTS...]" >&2; exit 2; }

pgbin="$(ls -d /usr/lib/postgresql/*/bin 2>/dev/null | sort -V | tail -1 || true)"
if [ -z "$pgbin" ] || [ ! -x "$pgbin/initdb" ]; then
    echo "with-postgres: installing postgresql (Debian package)" >&2
    if [ "$(id -u)" = 0 ]; then sudo=""; else sudo="sudo"; fi
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq postgresql >/dev/null
    pgbin="$(ls -d /usr/lib/postgresql/*/bin | sort -V | tail -1)"
fi

if [ "$(id -u)" = 0 ]; then
    as_pg() { runuser -u postgres -- "$@"; }
else
    as_pg() { "$@"; }
fi

dir="$(mktemp -d /tmp/shoal-class-pg.XXXXXX)"
[ "$(id -u)" = 0 ] && chown postgres "$dir"
port="$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])')"
user="$(if [ "$(id -u)" = 0 ]; then echo postgres; else id -un; fi)"

cleanup() {
    as_pg "$pgbin/pg_ctl" -D "$dir/data" -m immediate stop >/dev/null 2>&1 || true
    rm -rf "$dir"
}
trap cleanup EXIT

as_pg "$pgbin/initdb" -D "$dir/data" -U "$user" --auth=trust -E UTF8 >/dev/null
as_pg "$pgbin/pg_ctl" -D "$dir/data" -l "$dir/log" -w \
    -o "-p $port -k $dir -c listen_addresses=127.0.0.1 -c fsync=${SHOAL_PG_FSYNC:-off}" start >/dev/null

export SHOAL_CLASS_TEST_POSTGRES="postgres://$user@127.0.0.1:$port/postgres"
echo "with-postgres: PostgreSQL $("$pgbin/postgres" --version | awk '{print $3}') on port $port (fsync=${SHOAL_PG_FSYNC:-off})" >&2
"$@"
