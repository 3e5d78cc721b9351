#!/bin/sh
# Installs Debian packages with apt-get, through sudo when not root, saying what it installs.
# Usage: apt_install.sh WHO PACKAGE... (WHO names the caller in the messages: deps, web-deps).
set -eu
who=$1
shift
echo "$who: installing missing Debian packages: $*"
SUDO=""
if [ "$(id -u)" != 0 ]; then
    command -v sudo >/dev/null 2>&1 || { echo "$who: need root or sudo to install: $*" >&2; exit 1; }
    SUDO=sudo
fi
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "$@"
echo "$who: installed: $*"
