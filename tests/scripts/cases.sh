# shellcheck shell=bash
# The case runner of the tests of scripts/ (sourced): `script` names the script under test.
#
#   check NAME EXPECTED_EXIT PATTERN ARG...   runs `bash "$script" ARG...`; the case passes when
#                                             it exits EXPECTED_EXIT and a line of its output
#                                             (stdout and stderr) matches PATTERN (grep -E)
#   pass NAME / fail NAME [DETAIL]            a case decided by the caller
#   finish                                    the summary line; exit 1 when any case failed
#
# Variables set before `check` (VAR=value check ...) reach the script.
failures=0

pass() { echo "ok   $1"; }

fail() {
  echo "FAIL $1${2:+: $2}"
  failures=$((failures + 1))
}

check() {
  local name="$1" want_code="$2" pattern="$3"
  shift 3
  local out code
  # shellcheck disable=SC2154  # script: set by the test that sources this file
  out="$(bash "$script" "$@" 2>&1)"
  code=$?
  if [[ $code -eq $want_code ]] && grep -qE -- "$pattern" <<<"$out"; then
    pass "$name"
  else
    fail "$name" "exit $code (expected $want_code), output:"
    printf '%s\n' "$out" | tail -n 15
  fi
}

finish() {
  [[ $failures -eq 0 ]] || { echo "$failures case(s) failed"; exit 1; }
  echo "all cases passed"
}
