# Sourced by the tools that write LaTeX macros (they live beside it in tools/):
#   latex_esc        stdin to stdout, LaTeX's special characters escaped (tools/latex_esc.awk)
#   latex_def NAME TEXT   prints \newcommand{\NAME}{TEXT, escaped}
latex_esc() { awk -v filter=1 -f "$(dirname "$0")/latex_esc.awk"; }
latex_def() { printf '\\newcommand{\\%s}{%s}\n' "$1" "$(printf '%s' "$2" | latex_esc)"; }
