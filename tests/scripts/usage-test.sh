#!/usr/bin/env bash
# Tests of the argument checks of scripts/check-course-mode.sh, scripts/check-handouts.sh,
# scripts/render-showcase.sh and scripts/grade: --help prints the usage and exits 0, bad usage
# exits 2 naming the bad value, and neither installs packages nor builds anything. And of a
# checkout without stage04_camera (a handout of stage01, faked: a copy of scripts/ and grading/,
# no git): render-showcase.sh and scripts/render-docs-images.sh say that rt comes with stage 4,
# check-handouts.sh that a handout cannot cut handouts, each exit 1 before anything is installed.
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
# cmake: deps.sh stopped them). grade's cases of its parser need python3; its cases without
# python3 run on a PATH of the stubs and links to a few programs (bash, awk, grep, ...) that
# holds no python3, and check which packages deps.sh asked dpkg-query about.
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
help='^  scripts/render-showcase\.sh \[SCENE\] \[RT_RENDER_OPTION\]\.\.\.$'
usage "showcase: --help" 0 "$help" --help
usage "showcase: --help after a scene and rt options" 0 "$help" galaxy --width 64 --help
usage "showcase: an empty scene" 2 "$e an empty SCENE" ""
usage "showcase: a missing scene file is named" 2 "$e no scene file 'nosuch\.json'$" nosuch.json
# --help (or -h) wherever it is wins over every check, even where it would be -o's file.
usage "showcase: --help after an empty scene" 0 "$help" "" --help
usage "showcase: -h after a missing scene file" 0 "$help" nosuch.json -h
usage "showcase: --help after an empty -o file" 0 "$help" galaxy -o "" --help
usage "showcase: --help after -o" 0 "$help" -o --help
usage "showcase: -h after --output=" 0 "$help" --output= -h
# -o at the end, or with an empty file: refused, naming the option as given.
usage "showcase: -o without a file" 2 "$e -o needs a file name: nothing follows it$" galaxy -o
usage "showcase: --output without a file" 2 "$e --output needs a file name: nothing follows it$" \
  galaxy --output
usage "showcase: -o with an empty file" 2 "$e -o needs a file name, got ''$" galaxy -o ""
usage "showcase: --output with an empty file" 2 "$e --output needs a file name, got ''$" \
  --output ""
usage "showcase: --output= with an empty file" 2 "$e --output needs a file name, got ''$" \
  --output=
# A file name that starts with '-' is refused in every spelling (an option where the file was
# meant), naming the option as typed and the way to write such a file; nothing is installed.
hint() {
  printf "%s" "$e $1 needs a file name, got '$2' \\(an option\\? a file so named: \\./$2\\)\$"
}
usage "showcase: -o -x refused" 2 "$(hint -o -x)" -o -x
usage "showcase: --output -x refused" 2 "$(hint --output -x)" galaxy --output -x
usage "showcase: -o-x refused" 2 "$(hint -o -x)" -o-x
usage "showcase: --output=-x refused" 2 "$(hint --output -x)" --output=-x --width 64
usage "showcase: -o takes no option's name as its file" 2 "$(hint -o --width)" -o --width 64
: >"$work/scene.json"
usage "showcase: a scene file, then -o -" 2 "$(hint -o -)" "$work/scene.json" -o -
usage "showcase: -o given twice, both named" 2 \
  "$e -o/--output given twice \('a\.png' and 'b\.png'\)$" -o a.png --width 64 --output b.png
usage "showcase: -oFILE and --output=FILE given together" 2 \
  "$e -o/--output given twice \('a\.png' and 'b\.png'\)$" -oa.png --output=b.png
reaches_deps "showcase: -o ./-x goes on to deps.sh" 1 '^deps\.sh: installing missing' \
  galaxy -o ./-x --width 64
# An option the script does not know is `rt render`'s to judge, once rt is built: passed on.
reaches_deps "showcase: an unknown option goes on to rt render (deps.sh first)" 1 \
  '^deps\.sh: installing missing' --bogus-option

# ---- A checkout without stage04_camera: a handout of stage01, faked -------------------------
# A copy of scripts/ and grading/ beside stage01_primitives alone, its README with the section a
# handout has, and no git (GIT_CEILING_DIRECTORIES: nor a checkout above the temporary folder).
# render-showcase.sh and render-docs-images.sh, which build rt, say at once that rt comes with
# stage 4; check-handouts.sh asks make-handout first, which says why a handout cannot cut
# handouts; neither installs anything first.
cut="$work/cut"
mkdir -p "$cut/stage01_primitives"
cp -R "$scripts" "$cut/scripts"
cp -R "$scripts/../grading" "$cut/grading"
: >"$cut/stage01_primitives/CMakeLists.txt"
cat >"$cut/README.md" <<'README'
# The course

## This handout: `stage01_primitives`

Text.
README
export GIT_CEILING_DIRECTORIES="$work"
no_rt='this checkout has no stage04_camera \(a student handout of an earlier stage\?\): rt, which'
no_rt+=' renders, comes with stage 4$'
script="$cut/scripts/render-showcase.sh"
e='^render-showcase\.sh: error:'
usage "showcase without stage04_camera: says so before deps.sh" 1 "$e $no_rt"
usage "showcase without stage04_camera: a scene and options, the same" 1 "$e $no_rt" \
  galaxy -o x.png --width 64
usage "showcase without stage04_camera: bad usage is still bad usage" 2 \
  "$e -o needs a file name: nothing follows it$" galaxy -o
script="$cut/scripts/render-docs-images.sh"
e='^render-docs-images\.sh: error:'
usage "docs images without stage04_camera: says so before deps.sh" 1 "$e $no_rt"
usage "docs images without stage04_camera: --list, the same" 1 "$e $no_rt" --list
usage "docs images without stage04_camera: --help still prints the usage" 0 \
  '^  scripts/render-docs-images\.sh \[--list\] \[RT_RENDER_OPTION\]\.\.\.$' --help
if command -v python3 >/dev/null 2>&1; then
  script="$cut/scripts/check-handouts.sh"
  e='^check-handouts\.sh: error:'
  why="^make-handout: error: $cut is a handout of stage01_primitives, not a git checkout:"
  why+=" handouts are cut from the course's repository, a git checkout, and a handout cannot cut"
  why+=" handouts \(git ls-files -z --cached: fatal: not a git repository"
  usage "handouts in a handout: make-handout says why, before deps.sh" 1 "$why" stage01
  usage "handouts in a handout: the listing failed, before deps.sh" 1 \
    "$e scripts/make-handout --list failed$" stage01
else
  echo "note handouts in a handout: make-handout needs python3 on PATH: not run"
fi
# With the folder there, the scripts go on to deps.sh (which the stubs stop).
mkdir "$cut/stage04_camera"
: >"$cut/stage04_camera/CMakeLists.txt"
script="$cut/scripts/render-showcase.sh"
reaches_deps "showcase with stage04_camera: goes on to deps.sh" 1 '^deps\.sh: installing missing'
script="$cut/scripts/render-docs-images.sh"
reaches_deps "docs images with stage04_camera: goes on to deps.sh" 1 \
  '^deps\.sh: installing missing' --list
unset GIT_CEILING_DIRECTORIES

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
  # With python3 there and nothing to build, deps.sh is not run at all.
  usage "grade: --list with python3 installs nothing" 0 '^stage01 +stage01_primitives +[0-9]' \
    --list
else
  echo "note grade: the parser's cases need python3 on PATH: not run"
fi

# Without python3 (a PATH of the stubs and links to the programs the scripts and `check` call,
# none of them python3): the wrapper reads --help, --list, --no-build and --no-deps itself, and
# asks deps.sh for python3 alone when nothing is built, for the build's packages too when it is.
bare="$work/bare"
mkdir "$bare"
for tool in "$stubs"/*; do
  [[ "${tool##*/}" == python3 ]] || cp "$tool" "$bare/"
done
for tool in bash basename dirname nproc awk grep tail; do
  found="$(command -v "$tool")" && [[ "$found" == /* ]] && ln -s "$found" "$bare/$tool"
done
# without_python NAME EXPECTED_EXIT PATTERN ASKED ARG...: `check` of scripts/grade on that PATH,
# then that deps.sh asked dpkg-query about the packages ASKED, in that order, and nothing was
# built (no cmake); with ASKED empty, that no stub ran at all (deps.sh did not run).
without_python() {
  local name="$1" want_code="$2" pattern="$3" want_asked="$4"
  shift 4
  rm -f "$log"
  PATH="$bare" check "$name" "$want_code" "$pattern" "$@"
  local asked
  asked="$(awk '$1 == "dpkg-query" { print $NF }' "$log" 2>/dev/null | paste -sd ' ')"
  if [[ "$asked" == "$want_asked" ]] && ! grep -q '^cmake ' "$log" 2>/dev/null &&
      [[ -n "$want_asked" || ! -e "$log" ]]; then
    pass "$name: deps.sh asked for ${want_asked:-nothing}"
  else
    fail "$name: deps.sh asked for ${want_asked:-nothing}" \
      "it asked for ${asked:-nothing}; $(left)"
  fi
  rm -rf "$RT_BUILD_DIR" "$RT_HANDOUT_DIR"
}
if found="$(PATH="$bare" command -v python3)"; then
  fail "grade without python3: the PATH made without python3 has one" "$found"
fi
built="cmake g++ make libgtest-dev libgmock-dev libstb-dev nlohmann-json3-dev libcli11-dev"
built+=" libassimp-dev"
without_python "grade without python3: --help" 0 '^  scripts/grade \[--stage STAGE\]\.\.\.' "" \
  --help
without_python "grade without python3: --list installs python3 alone" 3 \
  '^deps\.sh: installing missing Debian packages: python3$' python3 --list
without_python "grade without python3: --no-build installs python3 alone" 3 \
  '^deps\.sh: installing missing Debian packages: python3$' python3 --stage stage01 --no-build
without_python "grade without python3: a build installs its packages and python3" 3 \
  "^deps\.sh: installing missing Debian packages: ${built//+/\\+} python3$" "$built python3" \
  --stage stage01
without_python "grade without python3: --list --no-deps installs nothing" 3 \
  '^grade: error: python3 not found \(scripts/deps\.sh --only python3 installs it\)$' "" \
  --list --no-deps

echo "$((cases - dirty)) of $cases cases installed and built nothing"
finish
