#!/usr/bin/env bash
# Tests of the argument checks of scripts/check-course-mode.sh, scripts/check-handouts.sh,
# scripts/render-showcase.sh and scripts/grade: --help prints the usage and exits 0, bad usage
# exits 2 naming the bad value, and neither installs packages nor builds anything.
#
#   tests/scripts/usage-test.sh PATH/TO/scripts
#
# Hermetic: a stub folder first on PATH holds apt-get, sudo, cmake, ctest, make, ninja and
# dpkg-query, each of which appends its name to a log and exits 1. The scripts run
# scripts/deps.sh by its absolute path, so no PATH stub replaces it; but deps.sh asks dpkg-query
# about every package before anything else, so a log without dpkg-query means it did not run (and
# with the stubs, were it run, it finds everything missing and stops at the apt-get stub: nothing
# is installed). RT_BUILD_DIR and RT_HANDOUT_DIR name folders under a temporary directory that
# must still be absent after each case. A few cases that do go on to the work show that the stubs
# catch it (exit 1, or 3 for grade, with dpkg-query and apt-get or sudo in the log, and no
# cmake: deps.sh stopped them).
#
# Prints one line per case and exits 1 when any case fails.
set -uo pipefail

scripts="$(cd "$1" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

stubs="$work/stubs"
log="$work/ran"
mkdir "$stubs"
for tool in apt-get sudo cmake ctest make ninja dpkg-query; do
  printf '#!/bin/sh\necho "%s $*" >>"%s"\nexit 1\n' "$tool" "$log" >"$stubs/$tool"
done
chmod +x "$stubs"/*
# The python3 that PATH finds, called directly: a version manager's shim (pyenv's) takes half a
# second a run, most of this test's time.
python="$(python3 -c 'import sys; print(sys.executable)' 2>/dev/null)"
if [[ -n "$python" && -x "$python" ]]; then
  ln -s "$python" "$stubs/python3"
fi
export PATH="$stubs:$PATH"
export RT_BUILD_DIR="$work/build" RT_HANDOUT_DIR="$work/handouts"
unset RT_JOBS  # grade.py's parser checks it; the caller's value is no concern here
export PYTHONDONTWRITEBYTECODE=1  # grade.py is imported: no __pycache__ in the checkout

# shellcheck source-path=SCRIPTDIR source=cases.sh
source "$(dirname "${BASH_SOURCE[0]}")/cases.sh"

# What a case left behind: the stubs it ran, and the work folders it made (then removed).
left() {
  [[ -s "$log" ]] && printf 'it ran: %s; ' "$(cut -d ' ' -f 1 "$log" | uniq | paste -sd ' ')"
  local dir
  for dir in "$RT_BUILD_DIR" "$RT_HANDOUT_DIR"; do
    [[ -e "$dir" ]] && printf 'it made %s; ' "$dir"
  done
  rm -rf "$RT_BUILD_DIR" "$RT_HANDOUT_DIR"
}

# usage NAME EXPECTED_EXIT PATTERN ARG...: `check`, then that the script ran no stub (no deps.sh,
# no build) and made no work folder.
cases=0
dirty=0
usage() {
  rm -f "$log"
  check "$@"
  local what
  what="$(left)"
  if [[ -n "$what" ]]; then
    fail "$1: it must install and build nothing" "$what"
    dirty=$((dirty + 1))
  fi
  cases=$((cases + 1))
}

# reaches_deps NAME EXPECTED_EXIT PATTERN ARG...: `check` of a command that goes on to the work;
# the stubs must show that deps.sh ran (dpkg-query, then the installer) and stopped it before
# cmake.
reaches_deps() {
  rm -f "$log"
  check "$@"
  if grep -q '^dpkg-query ' "$log" 2>/dev/null && grep -qE '^(apt-get|sudo) ' "$log" &&
      ! grep -q '^cmake ' "$log"; then
    pass "$1: the stubs caught deps.sh"
  else
    fail "$1: the stubs caught deps.sh" "$(cat "$log" 2>/dev/null || echo 'no stub ran')"
  fi
  rm -rf "$RT_BUILD_DIR" "$RT_HANDOUT_DIR"
}

# ---- scripts/check-course-mode.sh: stage folder names only ----------------------------------
script="$scripts/check-course-mode.sh"
e='^check-course-mode\.sh: error:'
present='\(present: stage01_primitives( [a-z0-9_]+)*\)$'
usage "course: --help" 0 '^  scripts/check-course-mode\.sh \[STAGE\]\.\.\.$' --help
usage "course: -h after a stage folder" 0 '^  scripts/check-course-mode\.sh \[STAGE\]' \
  stage01_primitives -h
usage "course: an unknown option is named" 2 "$e unknown option '--bogus' \(see --help\)$" --bogus
usage "course: an unknown option after a stage folder" 2 "$e unknown option '-x' \(see --help\)$" \
  stage01_primitives -x
usage "course: an unknown stage folder is named, with those present" 2 \
  "$e 'stage99_nosuch' is not a stage folder with a CMakeLists\.txt, nor its label $present" \
  stage99_nosuch
usage "course: a folder's name with more after it is not its label" 2 \
  "$e 'stage01_primitivesX' is not a stage folder" stage01_primitivesX
usage "course: every name is checked before any work" 2 \
  "$e 'stage99_nosuch' is not a stage folder" stage01_primitives stage99_nosuch
usage "course: an empty name" 2 "$e '' is not a stage folder" ""
reaches_deps "course: a good stage folder goes on to deps.sh" 1 '^deps\.sh: installing missing' \
  stage01_primitives
reaches_deps "course: a label names its folder" 1 '^deps\.sh: installing missing' stage01
reaches_deps "course: a folder with a trailing slash (a shell's completion)" 1 \
  '^deps\.sh: installing missing' stage01_primitives/

# ---- scripts/check-handouts.sh: stage folders or labels -------------------------------------
script="$scripts/check-handouts.sh"
e='^check-handouts\.sh: error:'
usage "handouts: --help" 0 '^  scripts/check-handouts\.sh \[STAGE\]\.\.\.$' --help
usage "handouts: --help wins over a bad stage" 0 '^  scripts/check-handouts\.sh \[STAGE\]' \
  stage99 --help
usage "handouts: an unknown option is named" 2 "$e unknown option '--bogus' \(see --help\)$" --bogus
usage "handouts: an unknown option after a stage" 2 "$e unknown option '--keep' \(see --help\)$" \
  stage01 --keep
usage "handouts: an unknown stage is named, with those present" 2 \
  "$e 'stage99' is not a stage of this checkout $present" \
  stage99
usage "handouts: a label is accepted, the bad name after it named" 2 \
  "$e 'stage99' is not a stage of this checkout" stage01 stage99
usage "handouts: a folder is accepted, the bad name after it named" 2 \
  "$e 'nosuch' is not a stage of this checkout" stage01_primitives nosuch
usage "handouts: an empty name" 2 "$e '' is not a stage of this checkout" ""
repo="$(cd "$scripts/.." && pwd)"
RT_HANDOUT_DIR="$repo/build/usage-test-handouts" usage \
  "handouts: RT_HANDOUT_DIR inside the repository" 1 \
  "$e RT_HANDOUT_DIR=$repo/build/usage-test-handouts lies inside the repository" stage01
reaches_deps "handouts: a good label goes on to deps.sh" 1 '^deps\.sh: installing missing' stage01
reaches_deps "handouts: a folder with a trailing slash (a shell's completion)" 1 \
  '^deps\.sh: installing missing' stage01_primitives//

# ---- scripts/render-showcase.sh: SCENE, its -o, the rest for `rt render` --------------------
script="$scripts/render-showcase.sh"
e='^render-showcase\.sh: error:'
usage "showcase: --help" 0 '^  scripts/render-showcase\.sh \[SCENE\] \[RT_RENDER_OPTION\]\.\.\.$' \
  --help
usage "showcase: --help after a scene and rt options" 0 '^  scripts/render-showcase\.sh \[SCENE\]' \
  galaxy --width 64 --help
usage "showcase: an empty scene" 2 "$e an empty SCENE" ""
usage "showcase: a missing scene file is named" 2 "$e no scene file 'nosuch\.json'$" nosuch.json
usage "showcase: -o without a file" 2 "$e -o needs a file name$" galaxy -o
usage "showcase: --output without a file" 2 "$e --output needs a file name$" galaxy --output
usage "showcase: -o takes a file, not the next option" 2 \
  "$e -o needs a file name, got '--width'$" -o --width 64
usage "showcase: -o with an empty file" 2 "$e -o/--output needs a file name, got ''$" galaxy -o ""
usage "showcase: --output= with an empty file" 2 "$e -o/--output needs a file name, got ''$" \
  --output=
usage "showcase: -o given twice, both named" 2 \
  "$e -o/--output given twice \('a\.png' and 'b\.png'\)$" -o a.png --width 64 --output b.png
usage "showcase: -oFILE and --output=FILE given together" 2 \
  "$e -o/--output given twice \('a\.png' and 'b\.png'\)$" -oa.png --output=b.png
: >"$work/scene.json"
usage "showcase: a scene file, then a bad -o" 2 "$e -o needs a file name, got '-'$" \
  "$work/scene.json" -o -
# An option the script does not know is `rt render`'s to judge, once rt is built: passed on.
reaches_deps "showcase: an unknown option goes on to rt render (deps.sh first)" 1 \
  '^deps\.sh: installing missing' --bogus-option

# ---- scripts/grade: grade.py's parser decides, before deps.sh --------------------------------
script="$scripts/grade"
if command -v python3 >/dev/null 2>&1; then
  usage "grade: --help" 0 '^usage: scripts/grade ' --help
  usage "grade: an unknown option is named" 2 \
    '^scripts/grade: error: unrecognized arguments: --bogus$' --bogus
  usage "grade: an unknown stage is named" 2 \
    "^grade: error: --stage: 'stage99' is no stage of this checkout" --stage stage99
  usage "grade: a bad --jobs is named" 2 \
    "^scripts/grade: error: argument -j/--jobs: expected a positive integer, got '0'$" --jobs 0
  usage "grade: a missing --source-dir is named" 2 \
    "^grade: error: --source-dir: '$work/none' is not a directory$" --source-dir "$work/none"
  : >"$work/file"
  usage "grade: an --output-dir that is a file" 2 \
    "^grade: error: --output-dir: cannot write '$work/file': it is not a directory$" \
    --output-dir "$work/file"
  # The parser takes abbreviations: --no-d is --no-deps (not an unknown option), --no- is either.
  usage "grade: --no-d (--no-deps) with --help" 0 '^usage: scripts/grade ' --no-d --help
  usage "grade: --no-d is --no-deps: the bad stage after it is named" 2 \
    "^grade: error: --stage: 'stage99' is no stage of this checkout" --no-d --stage stage99
  usage "grade: --no- is ambiguous" 2 \
    '^scripts/grade: error: ambiguous option: --no- could match --no-build, --no-deps$' --no-
  reaches_deps "grade: good arguments go on to deps.sh" 3 \
    '^grade: error: scripts/deps\.sh could not install the packages$' \
    --stage stage01 --build-dir "$work/grade-build"
else
  # Without python3 the wrapper reads --help itself; its parser's cases need python3.
  usage "grade: --help without python3" 0 '^  scripts/grade \[--stage STAGE\]\.\.\.' --help
  echo "note grade: the parser's cases need python3 on PATH: not run"
fi

echo "$((cases - dirty)) of $cases cases installed and built nothing"
finish
