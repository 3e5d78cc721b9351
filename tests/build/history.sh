#!/bin/sh
# The product speaks of itself alone: no tracked file names a tracker's numbers ("issue 12"), a
# review's items, working sessions, work logs or who did what when. Those belong to the history
# of the development (git log), which a reader of the code cannot look up. One check per pattern,
# over the files git tracks; each hit is printed as FILE:LINE: TEXT.
# Left out: this file (it spells the patterns). A pattern git grep cannot read fails the check.
# Usage: history.sh. Last line: "history: N passed, N failed" (a SKIP outside a git checkout).
set -u
pass=0 fail=0
if ! git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    echo "SKIP history: not a git checkout"
    echo "history: 0 passed, 0 failed"
    exit 0
fi
# pattern (extended regular expression, case-insensitive) | what it catches
# (split at the last '|': a pattern may hold alternatives)
patterns=$(cat <<'EOF'
\bissues? #?[0-9]+|a tracker's numbers
\b(pull request|PR|ticket) #?[0-9]+|a pull request's or ticket's number
\bthe( [a-z-]+)? issue('s)?\b|a tracker's issue named as "the issue"
\breview items?\b|a review's items
\breviewers?\b|the reviewers of the development
\bsessions?\b|working sessions
\bwork ?logs?\b|work logs
\b(helpers?|agents?) (task|branch|worktree)s?\b|who did what
EOF
)
# All patterns in one search first: none found anywhere (status 1) passes each; otherwise (a hit,
# or a pattern git grep cannot read) each is searched alone, to say which.
set --
while IFS= read -r line; do set -- "$@" -e "${line%|*}"; done <<EOF
$patterns
EOF
if git grep -q -I -i -E "$@" -- . ':!tests/build/history.sh' 2>/dev/null; then found=0; else found=$?; fi
while IFS= read -r line; do
    pattern=${line%|*} what=${line##*|}
    hits=""
    [ "$found" = 1 ] ||
        hits=$(git grep -n -I -i -E "$pattern" -- . ':!tests/build/history.sh' 2>&1 | cut -c1-160)
    if [ -z "$hits" ]; then
        pass=$((pass + 1))
    else
        fail=$((fail + 1))
        echo "FAIL history: $what:"
        echo "$hits" | sed 's/^/    /'
    fi
done <<EOF
$patterns
EOF
echo "history: $pass passed, $fail failed"
[ "$fail" = 0 ]
