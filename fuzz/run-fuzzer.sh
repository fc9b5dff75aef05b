#!/usr/bin/env bash
# Builds the scene loader's libFuzzer target and runs it for a bounded time.
#
#   fuzz/run-fuzzer.sh [SECONDS]      (default: $FUZZ_SECONDS, else 60)
#
# Environment: FUZZ_BUILD_DIR (default: build-fuzz at the repository root), FUZZ_JOBS (parallel
# compile jobs, default 2), FUZZ_TARGET (scene_fuzzer, the default, or model_fuzzer: the model
# reader on the model files of fuzz/models/, with a corpus of its own).
#
# The corpus starts from the repository's scene files (scenes/*.json, tests/scenefile/data/*.json,
# fuzz/scenes/*.json with what those lack, such as inline meshes, and fuzz/regressions/*, the
# inputs of past failures: none so far, so the folder is not in the repository yet) and
# grows in FUZZ_BUILD_DIR/corpus between runs. Exit status: 0 when
# the time ran out without a failure; 1 when libFuzzer found a crash, a sanitizer report, a leak
# or a timeout (the input is saved under FUZZ_BUILD_DIR/artifacts/ and printed: make it a
# regression test in tests/scenefile/FuzzRegressionTests.cpp and keep it in fuzz/regressions/).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-${FUZZ_SECONDS:-60}}"
build="${FUZZ_BUILD_DIR:-$root/build-fuzz}"
jobs="${FUZZ_JOBS:-2}"
target="${FUZZ_TARGET:-scene_fuzzer}"
[[ "$target" == scene_fuzzer || "$target" == model_fuzzer ]] || {
  echo "run-fuzzer.sh: FUZZ_TARGET must be scene_fuzzer or model_fuzzer, got '$target'" >&2
  exit 2
}
[[ "$seconds" =~ ^[0-9]+$ && "$seconds" -gt 0 ]] || {
  echo "run-fuzzer.sh: SECONDS must be a positive integer, got '$seconds'" >&2
  exit 2
}

# clang and its libFuzzer runtime (libclang-rt-N-dev, N = clang's major version).
if ! command -v clang++ >/dev/null 2>&1; then
  "$root/scripts/deps.sh" clang
fi
clang_major="$(clang++ -dumpversion | cut -d. -f1)"
runtime="libclang-rt-${clang_major}-dev"
if ! dpkg -s "$runtime" >/dev/null 2>&1; then
  echo "run-fuzzer.sh: installing $runtime (libFuzzer's runtime)"
  "$root/scripts/deps.sh" "$runtime"
fi

echo "run-fuzzer.sh: building $target in $build"
CC=clang CXX=clang++ cmake -S "$root/fuzz" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" --target "$target" --parallel "$jobs" >/dev/null

# Seeds: every scene file of the repository, and the inputs of past failures.
corpus="$build/corpus"
artifacts="$build/artifacts"
extra=(-dict="$root/fuzz/scene.dict")
shopt -s nullglob
seeds=("$root"/scenes/*.json "$root"/tests/scenefile/data/*.json "$root"/fuzz/scenes/*.json
       "$root"/fuzz/regressions/*)
if [[ "$target" == model_fuzzer ]]; then
  corpus="$build/model-corpus"
  artifacts="$build/model-artifacts"
  # Assimp 5.2 leaks on some malformed files (STL, PLY): leaks are not looked for here.
  extra=(-detect_leaks=0)
  export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
  seeds=("$root"/fuzz/models/*)
fi
shopt -u nullglob
mkdir -p "$corpus" "$artifacts"
for seed in "${seeds[@]+"${seeds[@]}"}"; do
  cp "$seed" "$corpus/seed-$(basename "$seed")"
done
echo "run-fuzzer.sh: ${#seeds[@]} seed files; running for ${seconds} s"

status=0
"$build/$target" "$corpus" \
  "${extra[@]}" \
  -max_total_time="$seconds" \
  -max_len=16384 \
  -timeout=10 \
  -rss_limit_mb=2048 \
  -artifact_prefix="$artifacts/" \
  -print_final_stats=1 2>"$build/fuzz.log" || status=$?
tail -n 25 "$build/fuzz.log"
if ((status != 0)); then
  echo "run-fuzzer.sh: the fuzzer failed (exit $status); full log: $build/fuzz.log" >&2
  ls -1 "$artifacts" >&2 || true
  exit 1
fi
echo "run-fuzzer.sh: no failure in ${seconds} s"
