#!/usr/bin/env bash
# Builds everything and runs every test.
#
#   scripts/test-all.sh [CTEST_OPTION]...
#
# Works from any directory on a fresh Debian machine: installs missing packages
# (scripts/deps.sh, python3 with matplotlib for the workflow tests, Chromium for the gallery's
# test in a headless browser, OpenMPI for rt-mpi and its tests, ffmpeg for rt animate --video,
# Embree 3 for rt bench's row and its tests, clang-format for the layout check), configures the release preset, builds all targets and runs ctest with
# output on failure. Options go to ctest (for example -L stage03,
# or -R Sphere); a selection that matches no test is an error (--no-tests=error), not a pass. The
# last line printed is ctest's summary ("100% tests passed, 0 tests failed out of N"); the exit
# code is ctest's. Set RT_BUILD_DIR to build somewhere other than build/release, RT_JOBS to change
# the parallelism.
set -euo pipefail
# shellcheck source-path=SCRIPTDIR source=common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

case "${1:-}" in
  -h | --help) rt_usage; exit 0 ;;
esac

# A relative RT_BUILD_DIR is the caller's, not the repository's (the cd below).
build_dir="$(rt_abspath "${RT_BUILD_DIR:-$RT_ROOT/build/release}")"

cd "$RT_ROOT"
# python3: scripts/grade and the workflow tests; python3-matplotlib: the gallery's charts;
# chromium: the gallery in a headless browser (workflow.gallery_browser, skipped without it); the
# optional components too (Embree, OpenMPI, ffmpeg, clang-format), so that every test runs here
# as in CI.
"$RT_ROOT/scripts/deps.sh" --embree --mpi --video python3 python3-matplotlib chromium \
  clang-format

rt_banner "Configuring (release preset) in $build_dir"
cmake --preset release -B "$build_dir" >/dev/null
rt_banner "Building"
start="$(rt_now)"
cmake --build "$build_dir" --parallel "$RT_JOBS"
echo "Built in $(rt_elapsed "$start")"

rt_banner "Testing"
log="$build_dir/test-all.log"
set +e
ctest --test-dir "$build_dir" --no-tests=error --output-on-failure --parallel "$RT_JOBS" "$@" 2>&1 |
  tee "$log"
status="${PIPESTATUS[0]}"
set -e
# ctest prints its summary line before the label times and the list of failures; repeat it so
# that it is the last line, where a reader (or CI) looks.
summary="$(grep -E '^[0-9]+% tests passed' "$log" | tail -n 1 || true)"
if [[ -n "$summary" ]]; then
  echo
  echo "$summary"
fi
exit "$status"
