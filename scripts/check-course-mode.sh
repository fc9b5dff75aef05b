#!/usr/bin/env bash
# Checks course mode: a repository cut after any stage builds and passes its tests.
#
#   scripts/check-course-mode.sh [STAGE]...
#
# For each stage folder present (stage01_primitives ... stage07_reflections, mini1_glossy,
# mini2_bvh), in order, or only the ones named (folder or label, as check-handouts.sh takes
# them): configure one reused build tree (build/course,
# or RT_BUILD_DIR) with -DRT_LAST_STAGE=<folder>, build everything, then for every stage built so
# far check that `ctest -L <label>` selects at least one test and passes, and that no test of a
# later stage exists in that configuration (and, before mini2_bvh, no rt-mpi target). The label
# of a folder is its name up to the first underscore (stage04_camera -> stage04, mini1_glossy ->
# mini1). Reusing one build tree keeps the
# object files of the lower stages from step to step, so each step builds only the new stage.
# Stops at the first failure, naming the stage.
set -euo pipefail
# shellcheck source-path=SCRIPTDIR source=common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

ALL_STAGES=(stage01_primitives stage02_geometries stage03_intersections stage04_camera
            stage05_lighting stage06_shadows stage07_reflections mini1_glossy mini2_bvh)

# The arguments are checked before anything is installed or created.
rt_operands "$@"
# A relative RT_BUILD_DIR is the caller's, not the repository's (the cd below).
build_dir="$(rt_abspath "${RT_BUILD_DIR:-$RT_ROOT/build/course}")"
log="$build_dir/course-mode.log"

present=()
for stage in "${ALL_STAGES[@]}"; do
  [[ -f "$RT_ROOT/$stage/CMakeLists.txt" ]] && present+=("$stage")
done
((${#present[@]})) || rt_die "no stage folder with a CMakeLists.txt under $RT_ROOT"
wanted=()
for name in "$@"; do
  stage="$(rt_stage_named "$name" "${present[@]}")"
  [[ -n "$stage" ]] || rt_bad_usage "'$name' is not a stage folder with a CMakeLists.txt, nor" \
    "its label (present: ${present[*]})"
  wanted+=("$stage")
done
((${#wanted[@]})) || wanted=("${present[@]}")

cd "$RT_ROOT"
"$RT_ROOT/scripts/deps.sh"
mkdir -p "$build_dir"

fail() {
  printf '\nCOURSE MODE FAILED for RT_LAST_STAGE=%s: %s\n' "$1" "$2" >&2
  if [[ -n "${3:-}" && -f "$3" ]]; then
    printf -- '---- last lines of %s ----\n' "$3" >&2
    tail -n 80 "$3" >&2
  fi
  exit 1
}

# Number of tests `ctest -L ^label$` selects in the configured tree.
count_tests() {
  ctest --test-dir "$build_dir" -N -L "^$1\$" | sed -n 's/^Total Tests: *//p'
}

total_start="$(rt_now)"
for stage in "${wanted[@]}"; do
  step_start="$(rt_now)"
  rt_banner "Course mode: RT_LAST_STAGE=$stage"

  if ! cmake -S "$RT_ROOT" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DRT_BUILD_TESTS=ON \
      -DRT_LAST_STAGE="$stage" >"$log" 2>&1; then
    fail "$stage" "configure failed" "$log"
  fi
  if ! cmake --build "$build_dir" --parallel "$RT_JOBS" >>"$log" 2>&1; then
    fail "$stage" "build failed" "$log"
  fi

  # rt-mpi deals mini2's tiles: a cut before mini2_bvh has no such program (nor its model).
  if [[ "$stage" != mini2_bvh ]] &&
      cmake --build "$build_dir" --target help | grep -Eq '^\.\.\. (rt-mpi|mpi_deal_model)$'; then
    fail "$stage" "the cut has rt-mpi or mpi_deal_model, which need mini2_bvh's tile pool"
  fi
  # Labels of this configuration: those of the stages up to $stage, plus any label that is not a
  # stage's (cross-stage tests, for example). A stage label beyond $stage is a leak.
  allowed=()
  for s in "${present[@]}"; do
    allowed+=("$(rt_label_of "$s")")
    [[ "$s" == "$stage" ]] && break
  done
  later=()
  past=0
  for s in "${ALL_STAGES[@]}"; do
    ((past)) && later+=("$(rt_label_of "$s")")
    [[ "$s" == "$stage" ]] && past=1
  done
  labels="$(ctest --test-dir "$build_dir" -N --print-labels | sed -n 's/^ \{1,\}//p')"
  for l in "${later[@]+"${later[@]}"}"; do
    if grep -qx -- "$l" <<<"$labels"; then
      fail "$stage" "tests labelled $l (a later stage) exist in this configuration"
    fi
  done

  for l in "${allowed[@]}"; do
    n="$(count_tests "$l")"
    if [[ -z "$n" || "$n" -lt 1 ]]; then
      fail "$stage" "no test carries the label $l"
    fi
    if ! ctest --test-dir "$build_dir" -L "^$l\$" --no-tests=error --output-on-failure \
        --parallel "$RT_JOBS" >"$build_dir/ctest-$l.log" 2>&1; then
      fail "$stage" "tests labelled $l failed" "$build_dir/ctest-$l.log"
    fi
    printf '  %-8s %4d tests passed\n' "$l" "$n"
  done
  others=()
  while read -r l; do
    [[ -z "$l" || " ${allowed[*]} " == *" $l "* ]] || others+=("$l")
  done <<<"$labels"
  ((${#others[@]} == 0)) || echo "  other labels (not checked here): ${others[*]}"
  all="$(ctest --test-dir "$build_dir" -N | sed -n 's/^Total Tests: *//p')"
  labelled="$(ctest --test-dir "$build_dir" -N -L . | sed -n 's/^Total Tests: *//p')"
  ((all == labelled)) || echo "  warning: $((all - labelled)) test(s) carry no label"
  echo "  $stage: ok ($(rt_elapsed "$step_start"))"
done
echo
echo "Course mode: ${#wanted[@]} stage(s) ok in $(rt_elapsed "$total_start")"
