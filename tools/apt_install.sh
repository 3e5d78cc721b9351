#!/bin/sh
# Installs Debian packages with apt-get, through sudo when not root: one line saying what it
# installs, apt's own output into a log (DEPS_LOG, default build/deps.log), and on a failure the
# end of that log.
# Usage: apt_install.sh WHO PACKAGE... (WHO names the caller in the messages: deps, web-deps).
set -eu
who=$1
shift
log=${DEPS_LOG:-build/deps.log}
mkdir -p "$(dirname "$log")"
echo "$who: installing missing Debian packages: $* (apt's output: $log)"
SUDO=""
if [ "$(id -u)" != 0 ]; then
    command -v sudo >/dev/null 2>&1 || { echo "$who: need root or sudo to install: $*" >&2; exit 1; }
    SUDO=sudo
fi
if ! { $SUDO apt-get update -qq &&
       DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "$@"; } \
    >"$log" 2>&1; then
    tail -20 "$log" >&2
    echo "$who: apt-get failed installing: $* (the whole output: $log)" >&2
    exit 1
fi
