#!/bin/sh
# The test runner. Usage: run.sh BUILD_DIR MODE [TEST_PROGRAM...]
#   test    run exactly the given unit test programs, then the CLI and build tests below
#   ledger  the claims ledger's table (whole) and checks, on what make kept in BUILD_DIR/claims.out
#   check   both
#   unit    run exactly the given programs, and nothing else
# One line per stage (unit tests, CLI tests, build checks, the ledger, the paper's checks): PASS or
# FAIL, what ran and its counts. A failure is shown in full under its stage: the FAIL lines of each
# program that failed, or all its output when it printed no summary (a crash). Every program's
# output is kept in BUILD_DIR/tests/NAME.log, its counts in BUILD_DIR/MODE-summary.txt, the skipped
# checks in BUILD_DIR/tests/skipped.txt. The last line is "N passed, N failed" over all that ran.
# The programs are independent: they run SUSLOV_JOBS at a time (else one more than the cores, as
# some of them mostly wait: on sleep, on make's look at the tree), the longest of the last run
# (BUILD_DIR/tests/durations.txt) first, and their results are read in the fixed order below, so
# that what is printed and kept is what a run of one after the other gives.
set -u
B=${1:-build}
mode=${2:-check}
shift 2 2>/dev/null || shift $#
L="$B/tests"
mkdir -p "$L"
njobs=${SUSLOV_JOBS:-$(($(nproc 2>/dev/null || echo 1) + 1))}
case $njobs in
    '' | *[!0-9]* | 0*) echo "run.sh: SUSLOV_JOBS wants a whole number of processes, at least 1," \
        "not '$njobs'" >&2; exit 2 ;;
esac
sum="$B/$mode-summary.txt"
: >"$sum"
: >"$L/skipped.txt"
status=0
# the current stage: its title, programs' names, counts and failures so far
st_names="" st_pass=0 st_fail=0 st_skip=0 st_out="" st_title="" st_n=0 st_k=0 st_t0=0
st_begin() { # st_begin TITLE N: N programs to run
    st_title=$1 st_n=$2 st_k=0 st_t0=$(date +%s)
    st_names="" st_pass=0 st_fail=0 st_skip=0 st_out=$(mktemp)
}
# On a terminal (not under NO_PROGRESS), the stage's line says how far it is and what runs until
# its result replaces it: "      CLI tests      3 of 10, 12 s; running: test_cli make_deps"; a
# terminal without escape sequences (TERM=dumb, NO_COLOR) gets spaces over it.
live=0
[ -t 1 ] && [ -z "${NO_PROGRESS:-}" ] && live=1
clear_line() {
    [ "$live" = 1 ] || return 0
    if [ "${TERM:-}" = dumb ] || [ -n "${NO_COLOR:-}" ]; then printf '\r%79s\r' ''; else printf '\r\033[K'; fi
}
# The digest of a program's log, made by its job as soon as it ends, so that the runner reads it
# in its turn with the shell's own read: "F LINE" for the stage's failures (the log's FAIL lines;
# then the whole log when it has no summary line, or when the exit status fails beside no failed
# check), "K LINE" for each SKIP line, "S LINE" the summary line "NAME: N passed, N failed", and
# "D SECONDS" the run time when the job gives its start and end (t0, t1).
# shellcheck disable=SC2016 # awk's
digest='function whole(why, i) {
        print "F " name ": " why "; its output:"
        for (i = 1; i <= NR; i++) print "F     " out[i]
    }
    { out[NR] = $0 }
    /^FAIL/ { print "F " $0 }
    /^SKIP/ { print "K " $0 }
    $0 ~ ("^" name ": [0-9]+ passed, [0-9]+ failed") { line = $0 }
    END {
        if (line == "") { whole("no summary line (crashed?)"); line = name ": 0 passed, 1 failed" }
        else if (rc != 0) {
            $0 = line
            if ($4 == 0) { whole("exit status " rc " after no failed check"); $4 = 1; line = $0 }
        }
        print "S " line
        if (t1 != "") print "D " (t1 - t0)
    }'
# took NAME: the digest $L/NAME.res of a program that ran into the stage: its failures, its SKIP
# lines into skipped.txt, its counts into the stage and the summary file, its time into durations
took() {
    st_names="$st_names $1" st_k=$((st_k + 1)) summed=0
    [ -f "$L/$1.res" ] && while IFS= read -r l; do
        case $l in
            F\ *) printf '%s\n' "${l#F }" >>"$st_out" ;;
            K\ *) printf '%s\n' "${l#K }" >>"$L/skipped.txt"; st_skip=$((st_skip + 1)) ;;
            S\ *) tally "${l#S }"; summed=1 ;;
            D\ *) durations="$durations$1 ${l#D }
" ;;
        esac
    done <"$L/$1.res"
    rm -f "$L/$1.res"
    [ "$summed" = 1 ] && return
    echo "$1: no digest of its output in $L/$1.res" >>"$st_out"
    tally "$1: 0 passed, 1 failed"
}
# tally "NAME: N passed, N failed": into the summary file and the stage's counts
tally() {
    echo "$1" >>"$sum"
    set -- $1
    st_pass=$((st_pass + $2)) st_fail=$((st_fail + $4))
}
# st_end TITLE WHAT: the stage's line, then its failures
st_end() {
    clear_line
    skipped=""
    [ "$st_skip" = 0 ] || skipped=", $st_skip skipped (see $L/skipped.txt)"
    [ "$st_fail" = 0 ] && verdict=PASS || { verdict=FAIL; status=1; }
    printf '%s  %-14s %s: %d passed, %d failed%s\n' "$verdict" "$1" "$2" "$st_pass" "$st_fail" \
        "$skipped"
    sed 's/^/      /' "$st_out"
    rm -f "$st_out"
}
# what a stage's line says it ran
what_programs() { echo "$st_k programs"; }
what_scripts() { echo "$(echo $st_names | wc -w) scripts"; }
what_names() { echo $st_names | tr ' ' ',' | sed 's/,/, /g'; }

# The queue, in the order of the results: entry K is q_kind_K, one of
#   B  a stage begins: q_title_K, with q_count_K programs
#   P  a program: q_name_K, run as q_cmd_K (quoted for eval), its output into $L/NAME.log
#   E  the stage ends: its line says what q_what_K (a function) says it ran
#   F  the function q_fn_K, run in its turn (it prints its own stage)
q_n=0 q_b=0
q_add() { q_n=$((q_n + 1)); eval "q_kind_$q_n=\$1 q_started_$q_n=0 q_done_$q_n=0"; }
stage() { q_add B; eval "q_title_$q_n=\$1"; q_b=$q_n; eval "q_count_$q_b=0"; }
end_stage() { q_add E; eval "q_what_$q_n=\$1 q_title_$q_n=\$q_title_$q_b"; }
fn() { q_add F; eval "q_fn_$q_n=\$1"; }
prog() { # prog NAME COMMAND...
    q_add P
    eval "q_name_$q_n=\$1 q_count_$q_b=\$((q_count_$q_b + 1))"
    shift
    c=""
    for a in "$@"; do
        case $a in *\'*) a=$(printf '%s\n' "$a" | sed "s/'/'\\\\''/g") ;; esac
        c="$c '$a'"
    done
    eval "q_cmd_$q_n=\$c"
}

if [ "$mode" != ledger ]; then
    stage "unit tests"
    for t in "$@"; do prog "${t##*/}" "$t"; done
    end_stage what_programs
fi
if [ "$mode" != ledger ] && [ "$mode" != unit ]; then
    # every CLI test script, found by name (tools/mutants.sh finds them the same way)
    stage "CLI tests"
    for c in tests/cli/test_*.sh; do n=${c##*/}; prog "${n%.sh}" sh "$c" "$B"; done
    end_stage what_scripts
    stage "build checks"
    prog make_deps sh tests/build/make_deps.sh "$B"
    prog layers sh tests/build/layers.sh
    prog style sh tests/build/style.sh
    prog format sh tests/build/format.sh
    prog mutants_fresh sh tests/build/mutants_fresh.sh
    prog history sh tests/build/history.sh
    prog eqmap sh tools/eqmap.sh check
    prog doc_links sh tests/build/doc_links.sh
    prog doc_facts sh tests/build/doc_facts.sh
    # the steps of docs/howto/add-a-method.md, taken in a scratch copy of the tree and build
    prog scaffold_method sh tests/build/scaffold_method.sh "$B"
    end_stage what_names
fi
ledger_stage() {
    st_begin "claims ledger" 0
    # claims.out (make ran the ledger only if the claims program changed) holds the table, then
    # under "checks that failed:" each failing line again, then the findings. The table is printed
    # whole by make ledger and with V=1; a failing line always, in full, under the stage's line.
    cp "$B/claims.out" "$L/claims.log"
    if [ "$mode" = ledger ] || [ "${V:-0}" = 1 ]; then
        awk '/^checks that failed:$/ || /^findings of / { exit } { print }' "$B/claims.out"
    fi
    awk '/^checks that failed:$/ { on = 1; next } /^findings of / { exit } on && NF' \
        "$B/claims.out" >>"$st_out"
    awk -v name=claims -v rc=0 "$digest" "$B/claims.out" >"$L/claims.res"
    took claims
    # claims.tsv is the TSV (its header first), not the printed table
    want='^id	paper_ref	quantity	measured	expected	tolerance	verdict'
    if head -1 "$B/claims.tsv" | grep -q "$want"; then
        tally "claims_tsv: 1 passed, 0 failed"
    else
        echo "FAIL claims.tsv does not start with its header" >>"$st_out"
        tally "claims_tsv: 0 passed, 1 failed"
    fi
    # every id once: the companion makes a macro of each
    dup=$(cut -f1 "$B/claims.tsv" | sort | uniq -d | head -3 | tr '\n' ' ')
    if [ -z "$dup" ]; then
        tally "claims_ids: 1 passed, 0 failed"
    else
        echo "FAIL claims.tsv repeats ids: $dup" >>"$st_out"
        tally "claims_ids: 0 passed, 1 failed"
    fi
    # No field of the ledger may read nan: a measurement that did not happen is a failure that
    # says so.
    if grep -iqw nan "$B/claims.tsv" 2>/dev/null; then
        grep -iw nan "$B/claims.tsv" | cut -f1 | sed 's/^/FAIL claims.tsv has nan: /' >>"$st_out"
        tally "claims_no_nan: 0 passed, 1 failed"
    else
        tally "claims_no_nan: 1 passed, 0 failed"
    fi
    lines=$(awk 'END { print NR - 1 }' "$B/claims.tsv")
    st_end "claims ledger" "$lines lines, table in $B/claims.out"
}
# The findings, last: the tally by verdict and each line that contradicts the paper, by its
# published number; then where the whole ledger is.
findings() {
    awk '/^findings of / { on = 1 } /^claims: [0-9]+ passed/ { exit } on' "$B/claims.out"
    echo "the whole ledger: $B/claims.out (each line's check and finding) and $B/claims.tsv;" \
        "make ledger, or make check V=1, prints it"
}
if [ "$mode" != test ] && [ "$mode" != unit ]; then
    fn ledger_stage
    stage "paper checks"
    # Every numbered statement of the paper is in the ledger or in paper/not_tested.tsv.
    prog paper_coverage sh tools/paper_coverage.sh "$B/claims.tsv"
    # Every tolerance of the ledger has a rule with its reason in paper/tolerances.tsv.
    prog paper_tolerances sh tools/paper_tolerances.sh "$B/claims.tsv" paper/tolerances.tsv \
        "$B/tolerances.tex"
    # The committed PDFs print the numbers this ledger gives (make paper writes them).
    prog paper_fresh sh tools/paper_fresh.sh "$B"
    end_stage what_names
    fn findings
fi

# The programs' start order: the longest of the last run first (a new one counts as short), so
# that no long one is left to run alone at the end; the queue's order among equals.
order=$(k=1; while [ $k -le $q_n ]; do
            eval "[ \$q_kind_$k = P ] && echo \"\$k \$q_name_$k\""; k=$((k + 1))
        done | awk -v f="$L/durations.txt" '
            BEGIN { while ((getline l <f) > 0) { split(l, a, " "); d[a[1]] = a[2] } }
            { print $1, ($2 in d) ? d[$2] : 0 }' | sort -s -k2,2nr | cut -d' ' -f1 | tr '\n' ' ')
durations=""
# A program runs in a process group of its own (setsid), so that an interrupt can end it whole: a
# background job of a script ignores SIGINT, and its children would outlive it. It writes
# the digest of its log, $L/NAME.res (its times from /proc/uptime when there is one), then its
# number into the pool's pipe (fd 3), which the runner reads to learn that a slot is free. A TERM
# to the group ends the program (the trap leaves it the default action) but not its job until it
# has reaped it: an orphan would be left to init, which may reap it late, while the runner waits
# for the group to be gone.
# shellcheck disable=SC2016 # expanded by the job's shell
job='trap : TERM; L=$1 name=$2 k=$3 digest=$4; shift 4
read -r t0 x </proc/uptime 2>/dev/null || t0=0
"$@" </dev/null >"$L/$name.log" 2>&1 3>&-; rc=$?
read -r t1 x </proc/uptime 2>/dev/null || t1=0
awk -v name="$name" -v rc=$rc -v t0=$t0 -v t1=$t1 "$digest" "$L/$name.log" >"$L/$name.res"
echo "$k" >&3'
setsid=""
command -v setsid >/dev/null 2>&1 && setsid=setsid
active=0
start_next() {
    set -- $order
    k=$1; shift; order=$*
    eval "name=\$q_name_$k c=\$q_cmd_$k"
    eval "$setsid sh -c \"\$job\" job \"\$L\" \"\$name\" $k \"\$digest\" $c &"
    eval "q_pid_$k=\$! q_started_$k=1"
    active=$((active + 1))
}
# On an interrupt, the programs still running are ended whole (the process group of each), and
# waited for until the last process of each is gone (a test script cleans up its scratch files on
# TERM), for at most 5 s. $! too: the trap may come between a start and its bookkeeping. A program
# just started may not have its group yet (setsid has not run): its group is asked again until it
# has one or is gone.
stop_all() {
    pids="" last=${!:-} k=1
    while [ $k -le $q_n ]; do
        eval "s=\$q_started_$k d=\$q_done_$k p=\${q_pid_$k:-}"
        [ "$s" = 1 ] && [ "$d" = 0 ] && pids="$pids $p"
        [ "$d" = 1 ] && [ "$p" = "$last" ] && last="" # ended and waited for: the pid may be reused
        k=$((k + 1))
    done
    case " $pids " in *" $last "*) ;; *) pids="$pids $last" ;; esac # each group asked once
    for p in $pids; do
        if [ -z "$setsid" ]; then kill -TERM "$p" 2>/dev/null; continue; fi
        i=0
        until kill -TERM "-$p" 2>/dev/null || ! kill -0 "$p" 2>/dev/null || [ $i -ge 100 ]; do
            sleep 0.01; i=$((i + 1))
        done
    done
    for p in $pids; do wait "$p" 2>/dev/null; done # the jobs' own shells, which TERM ends at once
    i=0
    while [ $i -lt 100 ] && alive $pids; do sleep 0.05; i=$((i + 1)); done
}
# alive PID...: one of these processes, or of their groups, is still there
alive() {
    for p in "$@"; do
        kill -0 "$p" 2>/dev/null && return 0
        [ -n "$setsid" ] && kill -0 "-$p" 2>/dev/null && return 0
    done
    return 1
}
# dash runs no EXIT trap when a signal ends it: end the programs, remove the stage's file, then die
# of the same signal, so that make (or the terminal) sees the interrupt; deaf to further signals
# meanwhile, which would end the cleanup half done
trap 'rm -f "$st_out"' EXIT
for sig in INT TERM HUP; do
    # shellcheck disable=SC2064 # $sig now, the rest at the signal
    trap "trap '' INT TERM HUP; trap - EXIT; stop_all; rm -f \"\$st_out\"; trap - $sig; kill -$sig \$\$" $sig
done
# the pool's pipe: open for reading and writing (so that neither end waits for the other), and
# removed at once; the open descriptor is all the jobs need
fifo="$L/.pool.$$"
rm -f "$fifo"
mkfifo "$fifo" && exec 3<>"$fifo" && rm -f "$fifo" || exit 2
# the stage's line while it waits: which of its programs is next, and the programs running
show_wait() {
    [ "$live" = 1 ] || return 0
    clear_line
    names="" k=1
    while [ $k -le $q_n ]; do
        eval "[ \$q_started_$k = 1 ] && [ \$q_done_$k = 0 ] && names=\"\$names \$q_name_$k\""
        k=$((k + 1))
    done
    printf '      %-14s %d of %d, %d s; running:%s' "$st_title" $((st_k + 1)) "$st_n" \
        $(($(date +%s) - st_t0)) "$names" | cut -c1-79 | tr -d '\n'
}
# entry K of the queue, in its turn; 1 when it is a program that has not ended yet
take() {
    eval "kind=\$q_kind_$1"
    case $kind in
        B) eval "st_begin \"\$q_title_$1\" \$q_count_$1" ;;
        E) eval "st_end \"\$q_title_$1\" \"\$(\$q_what_$1)\"" ;;
        F) eval "\$q_fn_$1" ;;
        P) eval "d=\$q_done_$1 name=\$q_name_$1"
           [ "$d" = 1 ] || return 1
           took "$name" ;;
    esac
    return 0
}
head=1
while [ $head -le $q_n ]; do
    if take $head; then head=$((head + 1)); continue; fi
    while [ $active -lt "$njobs" ] && [ -n "$order" ]; do start_next; done
    [ $active -gt 0 ] || { echo "run.sh: entry $head of the queue never started" >&2; exit 2; }
    show_wait
    read -r k <&3 || continue # a signal: its trap ends the run
    eval "wait \$q_pid_$k; q_done_$k=1"
    active=$((active - 1))
done
exec 3>&-
# the durations for the next run's order: written whole (a run that was cut keeps the last)
printf '%s' "$durations" >"$L/durations.txt.tmp" && mv "$L/durations.txt.tmp" "$L/durations.txt"
awk '{ p += $2; f += $4 } END { printf "%d passed, %d failed\n", p, f; exit f > 0 }' "$sum" || status=1
exit $status
