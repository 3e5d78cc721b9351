#!/bin/sh
# Prints the function FUNC of FILE with the comment right above it, down to the closing brace in
# column 0. Used by make paper to show the code beside the equations. Usage: snippet.sh FILE FUNC
set -eu
awk -v fn="$2" '
    start { print; if (/^}/) { found = 1; exit } next }
    /^\/\*/ { buf = ""; incomment = 1 }
    incomment { buf = buf $0 "\n"; if (/\*\//) incomment = 0; next }
    $0 ~ ("[ *]" fn "\\(") { start = 1; printf "%s", buf; print; next }
    { buf = "" }
    END { if (!found) { print "snippet.sh: no function " fn > "/dev/stderr"; exit 1 } }
' "$1"
