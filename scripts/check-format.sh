#!/usr/bin/env bash
# Checks that C++ files are laid out as the repository's .clang-format says.
#
#   scripts/check-format.sh [FILE]...
#
# Without FILE it checks every *.cpp and *.h file git tracks (or, outside a git checkout, every
# such file below the repository's root but the build trees). Prints each file that clang-format
# would change, with the first lines of the change, and how to fix it. clang-format never
# reflows the course's solution markers (// BEGIN SOLUTION..., // END SOLUTION: CommentPragmas in
# .clang-format, since a reflowed marker would cut its hint), so this script checks their rule
# itself: a marker line within the 100 columns, so that the handout's stub fits too. The layout
# depends on clang-format's version: CI checks with Debian's (clang-format 14); with another
# version a file may be reported that CI accepts. Exit codes: 0 all laid out, 1 some not, 2 no
# clang-format or a FILE not found. CLANG_FORMAT names another clang-format executable.
set -euo pipefail
# shellcheck source-path=SCRIPTDIR source=common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

case "${1:-}" in
  -h | --help) rt_usage; exit 0 ;;
esac

format="${CLANG_FORMAT:-clang-format}"
if ! command -v "$format" >/dev/null 2>&1; then
  echo "check-format.sh: error: no '$format' on PATH (Debian: sudo apt-get install clang-format)" >&2
  exit 2
fi

files=("$@")
if ((${#files[@]} == 0)); then
  cd "$RT_ROOT"
  mapfile -t files < <(
    { git ls-files --cached --others --exclude-standard -- '*.cpp' '*.h' 2>/dev/null ||
      find . \( -name '*.cpp' -o -name '*.h' \) -not -path './build*' -not -path './.git/*'; } |
      sort -u)
fi
for f in "${files[@]}"; do
  [[ -f "$f" ]] || { echo "check-format.sh: error: no file '$f'" >&2; exit 2; }
done

# One clang-format for every file (--dry-run: nothing is written; --style=file: the .clang-format
# nearest each file), which names each file it would change; then the change shown for those.
report="$(mktemp)"
formatted="$(mktemp)"
trap 'rm -f "$report" "$formatted"' EXIT
if ! "$format" --style=file --dry-run "${files[@]}" 2>"$report"; then
  cat "$report" >&2
  echo "check-format.sh: error: $format failed" >&2
  exit 2
fi
mapfile -t bad < <(sed -n 's/^\(.*\):[0-9]*:[0-9]*: warning: code should be clang-formatted.*/\1/p' \
  "$report" | sort -u)
for f in "${bad[@]}"; do
  echo "$f: not as .clang-format lays it out:"
  "$format" --style=file "$f" >"$formatted"
  diff -u --label "$f" --label "$f (formatted)" "$f" "$formatted" | sed -n '3,14p' || true
done
# FILE:LINE:TEXT of every marker line, then those whose TEXT has more than 100 characters.
mapfile -t long < <(grep -HnE '^[[:space:]]*// (BEGIN|END) SOLUTION' "${files[@]}" |
  LC_ALL=C.UTF-8 grep -E '^[^:]*:[0-9]+:.{101}' | cut -d: -f1,2 || true)
for place in "${long[@]}"; do
  echo "$place: a solution marker past the 100 columns (its hint would not fit the stub's line)"
done
if ((${#bad[@]} > 0 || ${#long[@]} > 0)); then
  ((${#bad[@]} == 0)) || echo "${#bad[@]} of ${#files[@]} files differ; fix with: $format -i FILE"
  ((${#long[@]} == 0)) || echo "${#long[@]} solution markers are too long; shorten their hints"
  exit 1
fi
echo "all ${#files[@]} files are laid out as .clang-format says ($("$format" --version))"
