#!/bin/sh
# make deps: check what the build needs and install the missing Debian packages with apt-get
# (through sudo when not root), saying what it does. Quiet when nothing is missing.
# Usage: deps.sh [PROFILE], PROFILE one of
#   check    the C compiler $CC (gcc, or clang for CC=clang), a C++ compiler (the install test
#            builds a C++ program against the library), make, pkg-config, GSL, Cairo, OSMesa,
#            a font, clang-format 14 (make check)
#   figures  check + ffmpeg (make figures: the animation's video)
#   paper    figures + TeX Live (make paper; the default). make paper quotes the recorded
#            bench run (data/bench-recorded/) and runs no bench
#   bench    check + g++ and Boost.Odeint headers (make bench: the Boost peers; never make check)
#   mutants  check + python3 (make mutants-ops: tools/mutants_ops.py)
set -eu
profile=${1:-paper}
case $profile in
    check|figures|paper|bench|mutants) ;;
    *) echo "deps: unknown profile '$profile' (check, figures, paper, bench or mutants)" >&2; exit 2 ;;
esac
have() { command -v "$1" >/dev/null 2>&1; }
missing=""
# The C compiler make uses ($CC, its first word; cc by default), by its Debian package: clang-14
# is Debian 12's clang.
cc=$(echo "${CC:-cc}" | awk '{ print $1 }')
if ! have "$cc"; then
    case $(basename "$cc") in
        clang | clang-[0-9]*) missing="$missing $(basename "$cc")" ;;
        cc | gcc | gcc-[0-9]*) missing="$missing gcc" ;;
        *) echo "deps: CC=$cc is not installed, and not a compiler this script knows the package of" >&2
           exit 2 ;;
    esac
fi
cxx=$(echo "${CXX:-c++}" | awk '{ print $1 }')
if ! have "$cxx"; then
    case $(basename "$cxx") in clang++*) missing="$missing clang" ;; *) missing="$missing g++" ;; esac
fi
have make || missing="$missing make"
# make test's format check runs Debian 12's clang-format (tests/build/format.sh)
have clang-format-14 || missing="$missing clang-format-14"
have pkg-config || missing="$missing pkg-config"
# pkg-config module:Debian package
for pair in gsl:libgsl-dev cairo:libcairo2-dev osmesa:libosmesa6-dev libpng:libpng-dev; do
    mod=${pair%%:*} pkg=${pair#*:}
    { have pkg-config && pkg-config --exists "$mod"; } || missing="$missing $pkg"
done
# a font the figures can name (SUS_PLOT_FONT in src/render/plot.h)
dpkg -s fonts-dejavu-core >/dev/null 2>&1 || missing="$missing fonts-dejavu-core"
# make paper: pdflatex with the LaTeX packages the companion uses (booktabs, listings, ...)
if [ "$profile" = paper ]; then
    # lmodern: Type 1 fonts in T1 encoding (no Type 3 bitmaps; make paper checks with pdffonts)
    for pkg in texlive-latex-base texlive-latex-recommended lmodern; do
        dpkg -s "$pkg" >/dev/null 2>&1 || missing="$missing $pkg"
    done
    # pdftotext, pdfinfo: tools/paper.sh finds where to split the tall stability figure
    have pdftotext || missing="$missing poppler-utils"
    # gs: tools/paper_layout.sh measures the printed size of figure text (make paper fails < 7 pt)
    have gs || missing="$missing ghostscript"
fi
# make bench: Boost.Odeint (header-only, in libboost1.74-dev) and a C++ compiler for the peers
if [ "$profile" = bench ]; then
    have g++ || missing="$missing g++"
    [ -f /usr/include/boost/numeric/odeint.hpp ] || missing="$missing libboost1.74-dev"
fi
# make mutants-ops: the generator and runner of the operator mutants
if [ "$profile" = mutants ]; then
    have python3 || missing="$missing python3"
fi
# the animation's video (optional at run time: without it the frames remain)
if [ "$profile" != check ] && [ "$profile" != bench ] && [ "$profile" != mutants ]; then
    have ffmpeg || missing="$missing ffmpeg"
fi
[ -z "$missing" ] && exit 0
# shellcheck disable=SC2086
exec sh "$(dirname "$0")/apt_install.sh" deps $missing
