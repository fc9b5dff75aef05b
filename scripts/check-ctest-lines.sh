#!/usr/bin/env bash
# Checks that every ctest command line the repository documents or runs fails when it selects
# no test.
#
#   scripts/check-ctest-lines.sh [FILE]...
#
# Plain ctest exits 0 when a mistyped label selects nothing ("No tests were found!!!"), which
# reads as a pass. So each ctest command in the Markdown files (code spans and code blocks) and
# in the scripts must carry --no-tests=error, or use a test preset (--preset NAME: the test
# presets of CMakePresets.json set noTestsAction=error). Listings (-N, --show-only,
# --print-labels) run no test and are exempt; so are comment lines of scripts. A command is
# "ctest" followed by an option, up to the end of its code span or shell command; lines ending
# in a backslash are joined first.
#
# Without FILE it checks every *.md file of the repository, scripts/* and .ci/run. Prints each
# offending command as FILE:LINE: COMMAND. Exit codes: 0 none, 1 some, 2 a FILE not found.
set -euo pipefail
# shellcheck source-path=SCRIPTDIR source=common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

case "${1:-}" in
  -h | --help) rt_usage; exit 0 ;;
esac

files=("$@")
if ((${#files[@]} == 0)); then
  cd "$RT_ROOT"
  mapfile -t files < <(
    { git ls-files --cached --others --exclude-standard -- '*.md' 2>/dev/null ||
      find . -name '*.md' -not -path './build*' -not -path './.git/*'; } | sort -u)
  files+=(scripts/* .ci/run)
fi
for f in "${files[@]}"; do
  [[ -f "$f" ]] || { echo "check-ctest-lines.sh: error: no file '$f'" >&2; exit 2; }
done

status=0
for f in "${files[@]}"; do
  markdown=0
  [[ "$f" == *.md ]] && markdown=1
  awk -v file="$f" -v markdown="$markdown" '
    # Reports each ctest command of text (which starts on line lineno) lacking the option.
    function check(text, lineno,   m, cmd, end) {
      while (match(text, /(^|[^[:alnum:]_.\/-])ctest +-/)) {
        m = substr(text, RSTART, RLENGTH)
        text = substr(text, RSTART + index(m, "ctest") - 1)
        end = match(text, /`|&&|;|\||\)/)
        cmd = end ? substr(text, 1, end - 1) : text
        sub(/ +$/, "", cmd)
        if (cmd !~ /--no-tests=error/ && cmd !~ /--preset[ =]/ &&
            cmd !~ / (-N|--show-only|--print-labels)( |=|$)/) {
          printf "%s:%d: %s\n", file, lineno, cmd
          bad = 1
        }
        text = substr(text, 6)
      }
    }
    !markdown && /^[[:space:]]*#/ { next }
    {
      if (joined == "") start = FNR
      line = $0
      if (sub(/\\$/, " ", line)) { joined = joined line; next }
      check(joined line, start)
      joined = ""
    }
    END { if (joined != "") check(joined, start); exit bad }
  ' "$f" || status=1
done
if ((status)); then
  echo "check-ctest-lines.sh: the ctest commands above select nothing silently: add" \
       "--no-tests=error (or use --preset release)" >&2
fi
exit "$status"
