#!/usr/bin/env bash
# Tests of scripts/check-format.sh with the repository's .clang-format on files of its own: a file
# laid out passes, one that is not is named and left as it was, a solution marker past the 100
# columns is named but not reflowed, and a missing file or clang-format is refused.
#
#   tests/scripts/format-test.sh PATH/TO/check-format.sh PATH/TO/.clang-format CLANG_FORMAT
#
# Prints one line per case and exits 1 when any case fails.
set -uo pipefail

script="$1"
style="$2"
format="$3"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cp "$style" "$work/.clang-format"

printf 'int add(int a, int b) { return a + b; }\n' >"$work/good.cpp"
printf 'int add(int a,int b){\nreturn a+b;}\n' >"$work/bad.cpp"
{
  printf 'int f() {\n'
  printf '  // BEGIN SOLUTION: hint: %s, %s\n' 'a hint that runs on past the hundredth column' \
    'as the course has some, and more than one'
  printf '  return 1;\n  // END SOLUTION\n}\n'
} >"$work/marker.cpp"
bad_before="$(cksum <"$work/bad.cpp")"

# shellcheck source-path=SCRIPTDIR source=cases.sh
source "$(dirname "${BASH_SOURCE[0]}")/cases.sh"
export CLANG_FORMAT="$format"

check "a laid-out file passes" 0 "^all 1 files are laid out as .clang-format says" \
  "$work/good.cpp"
check "a file that is not is named" 1 "^$work/bad.cpp: not as .clang-format lays it out:" \
  "$work/good.cpp" "$work/bad.cpp"
check "its change is shown" 1 "^\+int add\(int a, int b\) \{ return a \+ b; \}" "$work/bad.cpp"
check "the files counted" 1 "^1 of 2 files differ; fix with: .* -i FILE" "$work/good.cpp" \
  "$work/bad.cpp"
if [[ "$(cksum <"$work/bad.cpp")" == "$bad_before" ]]; then
  pass "the file checked is left as it was"
else
  fail "the file checked was changed"
fi
# .clang-format leaves the long marker alone; the script names it itself.
check "a long solution marker is not reflowed" 1 "^$work/marker.cpp:2: a solution marker past" \
  "$work/marker.cpp"
if grep -q "lays it out" <<<"$(bash "$script" "$work/marker.cpp" 2>&1)"; then
  fail "clang-format would reflow a solution marker (CommentPragmas)"
else
  pass ".clang-format keeps a solution marker on its line"
fi
check "and counted" 1 "^1 solution markers are too long; shorten their hints" "$work/marker.cpp"
check "a missing file" 2 "no file '$work/none.cpp'" "$work/good.cpp" "$work/none.cpp"
CLANG_FORMAT="$work/no-clang-format" check "no clang-format" 2 \
  "no '$work/no-clang-format' on PATH \(Debian: sudo apt-get install clang-format\)" \
  "$work/good.cpp"

finish
