#!/usr/bin/env bash
# Checks the handouts: every stage's student repository builds, fails its own stage's tests and
# passes the stages below; and the reference passes every stage's tests.
#
#   scripts/check-handouts.sh [STAGE]...
#
# First the reference: the checkout's tracked files, configured and built, run the tests of every
# stage up to the last one checked; each label must select tests and pass. Then, for each stage
# folder (stage01_primitives ... mini2_bvh) that has solution regions, in course order, or only
# the ones named (folder or label); a stage without regions is skipped and said so:
#   1. scripts/make-handout writes its student repository, and every relative link of its
#      Markdown files resolves (scripts/check-links.py: a file that is left out, an anchor);
#   2. it configures, and the test targets of its stages (<label>_tests) build;
#   3. the stage's own tests fail, at least one of them with "not implemented" in its output;
#   4. every stage below passes, so do the workflow tests (they need no stage), and no solution
#      marker is left in any stage folder.
# It prints the time of each step and a table at the end; exit 1 when a stage fails its check.
#
# Built as Debug (assertions on, no sanitizers) at -O1 without debug information, only the
# stages' test targets (not `rt`), with ccache when it is installed (scripts/deps.sh installs it
# once make-handout's listing has named the stages): the stages below a handout are the
# reference's files without their markers, the same in every later handout, and the tests are the
# reference's, so each is compiled once. -O1 rather than -O0: it takes about a quarter more CPU to
# compile, but the sampled stages' tests run ten times faster (mini1's DeterminismTests at its
# size then: 37 s at -O1, 9 minutes at -O0).
# RT_HANDOUT_OPT sets another level (RT_HANDOUT_OPT=-O0). Everything goes under RT_HANDOUT_DIR
# (default: a new temporary directory, removed when every check passed; kept, and printed, when
# one failed). RT_JOBS sets the parallelism (default: the core count), RT_CCACHE=0 builds
# without ccache.
set -euo pipefail
# shellcheck source-path=SCRIPTDIR source=common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

# The arguments and RT_HANDOUT_DIR are checked before anything is installed or created. The
# stage names against the stage folders on disk: make-handout's list, below, needs python3.
rt_operands "$@"
on_disk=()
for dir in "$RT_ROOT"/stage[0-9]*_*/ "$RT_ROOT"/mini[0-9]*_*/; do
  [[ -f "$dir/CMakeLists.txt" ]] && on_disk+=("$(basename "$dir")")
done
for name in "$@"; do
  [[ -n "$(rt_stage_named "$name" "${on_disk[@]+"${on_disk[@]}"}")" ]] ||
    rt_bad_usage "'$name' is not a stage of this checkout (present: ${on_disk[*]-none})"
done
# A relative RT_HANDOUT_DIR (or TMPDIR) is the caller's, not the repository's (the cd below).
work="${RT_HANDOUT_DIR:-}"
[[ -z "$work" ]] || work="$(realpath -m -- "$work")"
tmp_parent="$(realpath -m -- "${TMPDIR:-/tmp}")"
if [[ -n "$work" ]]; then
  place="RT_HANDOUT_DIR=$work"
else
  place="TMPDIR=$tmp_parent"
fi
case "${work:-$tmp_parent}/" in
  "$(realpath -- "$RT_ROOT")"/*) rt_die "$place lies inside the repository; a handout goes outside" ;;
esac

cd "$RT_ROOT"
# make-handout's listing first, with python3 alone (installed when missing): a checkout that cannot
# cut handouts (a handout itself, which is no git checkout) says so before anything else is
# installed. The build's packages and ccache come once the stages to check are known.
command -v python3 >/dev/null 2>&1 || "$RT_ROOT/scripts/deps.sh" --only python3

# Each stage folder (in course order) and its number of solution regions, from the lines
# "stage03_intersections (stage03): 11 region(s)" of make-handout --list.
listing="$(scripts/make-handout --no-deps --list)" || rt_die "scripts/make-handout --list failed"
present=()
declare -A regions=()
while read -r folder _ count _; do
  present+=("$folder")
  regions[$folder]="$count"
done < <(grep -E '^[a-z]+[0-9]+_[A-Za-z0-9_]+ \([a-z]+[0-9]+\): [0-9]+ region' <<<"$listing")
((${#present[@]})) || rt_die "no stage folder with a CMakeLists.txt under $RT_ROOT"
named=" "
for name in "$@"; do
  found="$(rt_stage_named "$name" "${present[@]}")"
  [[ -n "$found" ]] || rt_bad_usage "'$name' is not a stage of this checkout (present: ${present[*]})"
  named+="$found "
done
wanted=()  # in course order; without names, the stages that have solution regions
skipped=()
for s in "${present[@]}"; do
  if (($# == 0)) && ((regions[$s] == 0)); then
    skipped+=("$s")
  elif [[ $# -eq 0 || "$named" == *" $s "* ]]; then
    wanted+=("$s")
  fi
done
((${#wanted[@]})) || rt_die "no stage to check: none has solution regions"
last="${wanted[-1]}"  # the reference is checked up to the last stage handed out
"$RT_ROOT/scripts/deps.sh" python3 ccache

if [[ -z "$work" ]]; then
  work="$(mktemp -d "$tmp_parent/rt-handouts.XXXXXX")"
  remove_work=1
else
  mkdir -p "$work"
  remove_work=0
fi

cmake_args=(-DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=${RT_HANDOUT_OPT:--O1}"
            -DRT_BUILD_TESTS=ON)
if [[ "${RT_CCACHE:-1}" != 0 ]] && command -v ccache >/dev/null 2>&1; then
  cmake_args+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  # Paths under $work are hashed relative to the build directory, so that the same file at the
  # same place of two handouts is compiled once.
  export CCACHE_BASEDIR="$work"
  echo "ccache: $(ccache --version | head -n 1), cache $(ccache --get-config cache_dir)"
fi
ulimit -c 0  # a stub in a noexcept function ends its test with std::terminate: no core files

failures=()  # the stages (or "reference") whose check failed
summary=()   # the final table's rows
own_failed=""  # set by check_labels: "failed/total" of the stage handed out
fail() {  # fail STAGE WHAT [LOG]
  [[ " ${failures[*]-} " == *" $1 "* ]] || failures+=("$1")
  printf '  FAILED: %s\n' "$2" >&2
  if [[ -n "${3:-}" && -f "$3" ]]; then
    printf -- '  ---- last lines of %s ----\n' "$3" >&2
    tail -n 40 "$3" | sed 's/^/  /' >&2
  fi
}

# Configures DIR/build and builds the test targets of the stages up to STAGE; logs in DIR.
build_tests() {  # build_tests DIR STAGE
  local dir="$1" last="$2" targets=() s
  for s in "${present[@]}"; do
    targets+=("$(rt_label_of "$s")_tests")
    [[ "$s" == "$last" ]] && break
  done
  cmake -S "$dir" -B "$dir/build" "${cmake_args[@]}" >"$dir/configure.log" 2>&1 || return 1
  cmake --build "$dir/build" --parallel "$RT_JOBS" --target "${targets[@]}" >"$dir/build.log" 2>&1
}

# Runs the tests of one label in DIR/build; the log is DIR/ctest-LABEL.log. Prints "passed
# total" (what ctest's summary says), or nothing when it has no summary.
run_label() {  # run_label DIR LABEL
  local dir="$1" label="$2" log="$1/ctest-$2.log"
  ctest --test-dir "$dir/build" -L "^$label\$" --no-tests=error --output-on-failure \
    --timeout 120 --parallel "$RT_JOBS" >"$log" 2>&1 || true
  sed -n 's/^[0-9]*% tests passed, \([0-9]*\) tests* failed out of \([0-9]*\)$/\1 \2/p' "$log" |
    awk '{ print $2 - $1, $2 }'
}

# The checks of one built tree: every label of the stages below STAGE passes; STAGE's own label
# passes (the reference) or fails with a stub's message (a handout: own_failed says how many).
# Prints a line per label.
check_labels() {  # check_labels DIR STAGE MODE (reference|handout)
  local dir="$1" last="$2" mode="$3" s label result passed total ok=0
  for s in "${present[@]}"; do
    label="$(rt_label_of "$s")"
    result="$(run_label "$dir" "$label")"
    read -r passed total <<<"${result:-0 0}"
    if ((total == 0)); then
      fail "$last" "$label: no test ran" "$dir/ctest-$label.log"
      ok=1
    elif [[ "$s" != "$last" || "$mode" == reference ]]; then
      if ((passed == total)); then
        printf '  %-8s %4d/%-4d passed\n' "$label" "$passed" "$total"
      else
        fail "$last" "$label: $((total - passed)) of $total tests failed" "$dir/ctest-$label.log"
        ok=1
      fi
    elif ((passed == total)); then
      fail "$last" "$label: every test passes in the handout: its stubs are not tested"
      ok=1
    elif ! grep -q 'not implemented' "$dir/ctest-$label.log"; then
      fail "$last" "$label: its tests fail, but none with a stub's 'not implemented'" \
        "$dir/ctest-$label.log"
      ok=1
    else
      printf '  %-8s %4d/%-4d passed, %d fail as they should (not implemented)\n' "$label" \
        "$passed" "$total" "$((total - passed))"
      own_failed="$((total - passed))/$total"
    fi
    [[ "$s" == "$last" ]] && break
  done
  return "$ok"
}

total_start="$(rt_now)"

rt_banner "Reference: the tests of every stage up to $last"
start="$(rt_now)"
reference="$work/reference"
rm -rf "$reference"
mkdir -p "$reference"
git ls-files -z | xargs -0 cp -P --parents -t "$reference"
if ! build_tests "$reference" "$last"; then
  fail reference "the reference does not build" "$reference/build.log"
  rt_die "the reference must build and pass before its handouts are checked (kept: $work)"
fi
built="$(rt_elapsed "$start")"
start="$(rt_now)"
check_labels "$reference" "$last" reference ||
  rt_die "the reference must pass before its handouts are checked (kept: $work)"
echo "  reference: built in $built, tested in $(rt_elapsed "$start")"
summary+=("$(printf '%-10s %-22s %-12s %s' reference "build $built" "" "every stage passes")")

for stage in "${wanted[@]}"; do
  label="$(rt_label_of "$stage")"
  rt_banner "Handout of $stage"
  dir="$work/$label"
  rm -rf "$dir"
  start="$(rt_now)"
  log="$work/make-handout-$label.log"
  if ! scripts/make-handout --no-deps --stage "$stage" --out "$dir" >"$log" 2>&1; then
    fail "$stage" "scripts/make-handout failed" "$log"
    continue
  fi
  sed 's/^/  /' "$log"
  links="$work/check-links-$label.log"
  if ! python3 scripts/check-links.py "$dir" >"$links" 2>&1; then
    fail "$stage" "broken links in the handout's Markdown files" "$links"
    continue
  fi
  sed 's/^/  /' "$links"
  if ! build_tests "$dir" "$stage"; then
    fail "$stage" "the handout does not build" "$dir/build.log"
    continue
  fi
  built="$(rt_elapsed "$start")"
  start="$(rt_now)"
  own_failed="?"
  check_labels "$dir" "$stage" handout || continue
  # The course workflow's own tests (the grader, make-handout, documented ctest lines) need no
  # stage: they pass in every handout.
  read -r passed total <<<"$(run_label "$dir" workflow)"
  if [[ -z "$total" || "$passed" != "$total" ]]; then
    fail "$stage" "the workflow tests fail in the handout" "$dir/ctest-workflow.log"
    continue
  fi
  printf '  %-8s %4d/%-4d passed\n' workflow "$passed" "$total"
  tested="$(rt_elapsed "$start")"
  leaks="$(grep -rlE --exclude-dir=tests '(BEGIN|END) SOLUTION' "$dir"/stage* "$dir"/mini* \
             2>/dev/null || true)"
  if [[ -n "$leaks" ]]; then
    fail "$stage" "solution markers left in: $(echo "$leaks" | tr '\n' ' ')"
    continue
  fi
  echo "  $stage: ok (make-handout and build $built, tests $tested)"
  summary+=("$(printf '%-10s %-22s %-12s %s' "$label" "build $built" "tests $tested" \
                "$own_failed of $label fail, the stages below pass")")
  rm -rf "$dir/build"  # the object files live on in ccache
done

rt_banner "Handouts"
printf '%s\n' "${summary[@]}"
for s in "${skipped[@]+"${skipped[@]}"}"; do
  printf '%-10s not handed out: %s has no solution region yet\n' "$(rt_label_of "$s")" "$s"
done
if ((${#failures[@]})); then
  echo "Handouts: FAILED for ${failures[*]} (kept for inspection: $work)" >&2
  exit 1
fi
((remove_work)) && rm -rf "$work"
echo "Handouts: the reference and ${#wanted[@]} handout(s) ok in $(rt_elapsed "$total_start")"
