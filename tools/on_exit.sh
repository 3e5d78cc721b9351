# Sourced by the scripts that make scratch files: on_exit COMMAND runs COMMAND when the script
# ends, normally or by INT, TERM or HUP. dash runs no EXIT trap when a signal ends it, so each
# signal gets its own: COMMAND, deaf to further signals meanwhile (a second one, which a terminal
# or tests/run.sh may send, would end it half done, and the rm it runs), then death by the same
# signal, so that the caller (make, run.sh, a terminal) sees the interrupt. COMMAND is expanded
# when it runs: on_exit 'rm -rf "$tmp"'.
on_exit() {
    trap "$1" EXIT
    for on_exit_sig in INT TERM HUP; do
        # shellcheck disable=SC2064 # the signal now, the rest when it comes
        trap "trap '' INT TERM HUP; trap - EXIT; $1; trap - $on_exit_sig; kill -$on_exit_sig \$\$" \
            $on_exit_sig
    done
}
