#!/bin/sh
# make web-deps: what the web edition (make web, make check-web) needs, and nothing that
# make check needs. Installs the missing Debian packages with apt-get (through sudo when not
# root) and the pinned npm packages of tools/web/package-lock.json (KaTeX, playwright-core)
# into tools/web/node_modules, saying what it installs. Quiet when nothing is missing.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
have() { command -v "$1" >/dev/null 2>&1; }
missing=""
# Debian's own python3 (the generator's markdown and pygments are Debian packages)
[ -x /usr/bin/python3 ] || missing="$missing python3"
for pkg in python3-markdown python3-pygments universal-ctags chromium fonts-dejavu-core \
           clang lld llvm wasi-libc libclang-rt-14-dev-wasm32; do
    dpkg -s "$pkg" >/dev/null 2>&1 || missing="$missing $pkg"
done
have node || missing="$missing nodejs"
have npm || missing="$missing npm"
# shellcheck disable=SC2086
[ -z "$missing" ] || sh "$here/../apt_install.sh" web-deps $missing
# npm packages at the versions pinned in package-lock.json; reinstalled when the lock changes
stamp="$here/node_modules/.installed-lock"
if ! cmp -s "$here/package-lock.json" "$stamp" 2>/dev/null; then
    echo "web-deps: installing npm packages (package-lock.json): katex, playwright-core"
    (cd "$here" && npm ci --no-audit --no-fund --loglevel=error)
    cp "$here/package-lock.json" "$stamp"
fi
