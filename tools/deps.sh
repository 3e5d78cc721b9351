#!/bin/sh
# make deps: check what the build needs and install the missing Debian packages with apt-get
# (through sudo when not root), saying what it does. Quiet when nothing is missing.
set -eu
have() { command -v "$1" >/dev/null 2>&1; }
missing=""
have cc || missing="$missing gcc"
have make || missing="$missing make"
have pkg-config || missing="$missing pkg-config"
# pkg-config module:Debian package
for pair in gsl:libgsl-dev cairo:libcairo2-dev osmesa:libosmesa6-dev; do
    mod=${pair%%:*} pkg=${pair#*:}
    { have pkg-config && pkg-config --exists "$mod"; } || missing="$missing $pkg"
done
# a font the figures can name (PLOT_FONT in src/plot.h)
dpkg -s fonts-dejavu-core >/dev/null 2>&1 || missing="$missing fonts-dejavu-core"
# make paper: pdflatex with the LaTeX packages the companion uses (booktabs, listings, ...)
for pkg in texlive-latex-base texlive-latex-recommended; do
    dpkg -s "$pkg" >/dev/null 2>&1 || missing="$missing $pkg"
done
# the animation's video (optional at run time: without it the frames remain)
have ffmpeg || missing="$missing ffmpeg"
[ -z "$missing" ] && exit 0
echo "deps: installing missing Debian packages:$missing"
SUDO=""
if [ "$(id -u)" != 0 ]; then
    have sudo || { echo "deps: need root or sudo to install:$missing" >&2; exit 1; }
    SUDO=sudo
fi
$SUDO apt-get update -qq
# shellcheck disable=SC2086
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $missing
echo "deps: installed:$missing"
