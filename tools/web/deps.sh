#!/bin/sh
# make web-deps: what the web edition (make web, make check-web) needs, and nothing that
# make check needs. Installs the missing Debian packages with apt-get (through sudo when not
# root) and the pinned npm packages of tools/web/package-lock.json (KaTeX, playwright-core)
# into tools/web/node_modules. Quiet when nothing is missing; otherwise one line saying what it
# installs, the installers' output going to LOG (shown, its end, only when an install fails).
# Usage: deps.sh LOG
set -eu
here=$(cd "$(dirname "$0")" && pwd)
log=${1:-/dev/null}
mkdir -p "$(dirname "$log")"
have() { command -v "$1" >/dev/null 2>&1; }
# run CMD... with its output appended to the log; on failure, show the log's end and stop
logged() {
    if ! "$@" >>"$log" 2>&1; then
        echo "web-deps: failed: $*; the end of $log:" >&2
        tail -n 20 "$log" >&2
        exit 1
    fi
}
missing=""
# Debian's own python3 (the generator's markdown and pygments are Debian packages)
[ -x /usr/bin/python3 ] || missing="$missing python3"
for pkg in python3-markdown python3-pygments universal-ctags chromium fonts-dejavu-core \
           clang lld llvm wasi-libc libclang-rt-14-dev-wasm32; do
    dpkg -s "$pkg" >/dev/null 2>&1 || missing="$missing $pkg"
done
have node || missing="$missing nodejs"
have npm || missing="$missing npm"
if [ -n "$missing" ]; then
    echo "web-deps: installing Debian packages:$missing (log: $log)"
    # shellcheck disable=SC2086
    logged sh "$here/../apt_install.sh" web-deps $missing
fi
# npm packages at the versions pinned in package-lock.json; reinstalled when the lock changes
stamp="$here/node_modules/.installed-lock"
if ! cmp -s "$here/package-lock.json" "$stamp" 2>/dev/null; then
    echo "web-deps: installing npm packages katex, playwright-core (package-lock.json; log: $log)"
    logged sh -c 'cd "$1" && npm ci --no-audit --no-fund --loglevel=error' sh "$here"
    cp "$here/package-lock.json" "$stamp"
fi
