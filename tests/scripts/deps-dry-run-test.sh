#!/usr/bin/env bash
# Tests of scripts/deps.sh's decisions, without touching the machine: dpkg-query, apt-get and
# sudo are replaced by stubs on PATH. dpkg-query reports every package installed except those
# listed in STUB_MISSING; apt-get and sudo record that they were run, which a dry run must never
# do.
#
#   tests/scripts/deps-dry-run-test.sh PATH/TO/deps.sh
#
# Prints one line per case and exits 1 when any case fails.
set -uo pipefail

deps="$1"
stubs="$(mktemp -d)"
trap 'rm -rf "$stubs"' EXIT

cat >"$stubs/dpkg-query" <<'STUB'
#!/usr/bin/env bash
# dpkg-query -W -f=FORMAT PACKAGE: "installed" unless PACKAGE is in STUB_MISSING.
for p in ${STUB_MISSING:-}; do [[ "$p" == "${!#}" ]] && exit 1; done
printf installed
STUB
for tool in apt-get sudo; do
  printf '#!/usr/bin/env bash\necho "%s $*" >>"%s/ran"\n' "$tool" "$stubs" >"$stubs/$tool"
done
chmod +x "$stubs"/*

failures=0
# compare FIRST|ALL NAME EXPECTED_EXIT EXPECTED ARG...: runs deps.sh, compares its exit code and
# its whole first line (FIRST) or its whole output (ALL) with EXPECTED (empty: no output at all),
# and that it ran no installer.
compare() {
  local what="$1" name="$2" want_code="$3" want_out="$4"
  shift 4
  rm -f "$stubs/ran"
  local out code got
  out="$(PATH="$stubs:$PATH" "$deps" "$@" 2>&1)"
  code=$?
  got="$out"
  [[ "$what" == ALL ]] || got="${out%%$'\n'*}"
  if [[ "$code" != "$want_code" || "$got" != "$want_out" || \
        ( -z "$want_out" && -n "$out" ) || -e "$stubs/ran" ]]; then
    echo "FAIL $name: exit $code (want $want_code), output:"
    echo "$out"
    [[ "$got" == "$want_out" ]] || printf 'wanted %s:\n%s\n' \
      "$([[ "$what" == ALL ]] && echo "the output" || echo "as its first line")" "$want_out"
    [[ -e "$stubs/ran" ]] && echo "and it ran: $(cat "$stubs/ran")"
    failures=$((failures + 1))
  else
    echo "ok   $name"
  fi
}
# check NAME EXPECTED_EXIT EXPECTED_FIRST_LINE ARG...
check() { compare FIRST "$@"; }
# check_all NAME EXPECTED_EXIT EXPECTED_OUTPUT ARG...: every line of the output, in order.
check_all() { compare ALL "$@"; }

all="cmake g++ make libgtest-dev libgmock-dev libstb-dev nlohmann-json3-dev libcli11-dev libassimp-dev"
# TC01: a dry run with nothing missing says so, naming what it checked (once it printed nothing)
STUB_MISSING="" check "TC01 dry run, nothing missing" 0 \
  "deps.sh: dry run: nothing missing ($all)" --dry-run
# TC02: without --dry-run, nothing missing: silent, for the scripts that call it
STUB_MISSING="" check "TC02 nothing missing is silent" 0 ""
# TC03: a dry run with a package missing names it and runs nothing
STUB_MISSING="libcli11-dev" check "TC03 dry run, one missing" 0 \
  "deps.sh: dry run: missing: libcli11-dev" --dry-run
# TC04: an extra package is checked too
STUB_MISSING="" check "TC04 dry run with an extra package" 0 \
  "deps.sh: dry run: nothing missing ($all clang)" --dry-run clang
# TC05: --pretend-missing makes an installed package missing
STUB_MISSING="" check "TC05 dry run, pretend missing" 0 \
  "deps.sh: dry run: missing: make" --dry-run --pretend-missing make
# TC06: the test command's extras (scripts/test-all.sh): matplotlib missing is named alone
STUB_MISSING="python3-matplotlib" check "TC06 dry run, the test command's extras" 0 \
  "deps.sh: dry run: missing: python3-matplotlib" --dry-run python3 python3-matplotlib
# TC07: the model files' library (Assimp) is checked too, and named when missing
STUB_MISSING="libassimp-dev" check "TC07 dry run, Assimp missing" 0 \
  "deps.sh: dry run: missing: libassimp-dev" --dry-run
# TC08: --embree adds Embree 3 to the packages checked
STUB_MISSING="" check "TC08 dry run, --embree checks Embree" 0 \
  "deps.sh: dry run: nothing missing ($all libembree-dev)" --dry-run --embree
# TC09: --embree with Embree missing names it alone, and runs nothing
STUB_MISSING="libembree-dev" check "TC09 dry run, Embree missing" 0 \
  "deps.sh: dry run: missing: libembree-dev" --embree --dry-run
# TC10: without --embree, a missing Embree is not asked for
STUB_MISSING="libembree-dev" check "TC10 Embree missing, not asked for" 0 \
  "deps.sh: dry run: nothing missing ($all)" --dry-run
# TC11: --mpi adds OpenMPI (the program and the headers), --video ffmpeg
STUB_MISSING="" check "TC11 dry run, --mpi and --video" 0 \
  "deps.sh: dry run: nothing missing ($all openmpi-bin libopenmpi-dev ffmpeg)" --dry-run --mpi --video
# TC12: the test command's packages (scripts/test-all.sh) with OpenMPI's headers missing
STUB_MISSING="libopenmpi-dev" check "TC12 dry run, OpenMPI missing" 0 \
  "deps.sh: dry run: missing: libopenmpi-dev" --dry-run --mpi --video python3 python3-matplotlib
# TC13: --pretend-missing takes a package name, not the next option: the dry run stays on (with
# make missing, a lost --dry-run would run apt-get)
STUB_MISSING="make" check "TC13 --pretend-missing refuses an option as its package" 2 \
  "deps.sh: --pretend-missing needs a package name, got '--dry-run'" --pretend-missing --dry-run
# TC14: nor an empty name
STUB_MISSING="" check "TC14 --pretend-missing refuses an empty package" 2 \
  "deps.sh: --pretend-missing needs a package name, got ''" --dry-run --pretend-missing ""
# TC15: an empty extra package is refused, not checked
STUB_MISSING="" check "TC15 an empty package name" 2 \
  "deps.sh: an empty package name (see --help)" --dry-run ""
# What a dry run says it would run: through sudo (the stub) unless this test runs as root.
sudo=""
((EUID == 0)) || sudo="sudo "
install="env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends"
# TC16: --only checks the packages named, not the build's (missing ones here): scripts/grade
# --list on a machine without a compiler asks for python3 alone
STUB_MISSING="cmake g++ libgtest-dev" check_all "TC16 --only leaves the build's packages out" 0 \
  "deps.sh: dry run: nothing missing (python3)" --dry-run --only python3
# TC17: and installs only those of them that are missing, the build's missing ones not
STUB_MISSING="cmake g++ python3 python3-matplotlib" check_all "TC17 --only installs the named" 0 \
  "deps.sh: dry run: missing: python3
deps.sh: dry run: would run: ${sudo}apt-get update -qq
deps.sh: dry run: would run: ${sudo}$install python3" --only python3 --dry-run
# TC18: --only wherever it is; --video and --embree add their packages, in the order given
STUB_MISSING="make" check_all "TC18 --only last, with the optional components" 0 \
  "deps.sh: dry run: nothing missing (python3 ffmpeg libembree-dev)" \
  --dry-run python3 --video --embree --only
# TC19: --only with nothing named is refused: it would check nothing
STUB_MISSING="" check_all "TC19 --only without a package" 2 \
  "deps.sh: --only needs a package to install (EXTRA_PKG, --embree, --mpi or --video)" \
  --dry-run --only
# TC20: --pretend-missing's PKG is not a package to install
STUB_MISSING="" check_all "TC20 --only with only --pretend-missing's package" 2 \
  "deps.sh: --only needs a package to install (EXTRA_PKG, --embree, --mpi or --video)" \
  --dry-run --only --pretend-missing python3
# TC21: without --dry-run, the named packages all installed: silent, and nothing installed, though
# a build package is missing
STUB_MISSING="cmake" check_all "TC21 --only, nothing missing, silent" 0 "" --only python3

((failures == 0))
