#!/usr/bin/env bash
# Installs the Debian packages this project builds with, when they are missing.
#
#   scripts/deps.sh [--dry-run] [--only] [--embree] [--mpi] [--video]
#                   [--pretend-missing PKG]... [EXTRA_PKG]...
#
# Silent, and touches nothing, when every package is already installed (a dry run then says
# "nothing missing" and lists the packages it checked). Otherwise it runs
# `apt-get update` once and installs only the missing packages (through sudo when not root).
# EXTRA_PKG names packages that a caller needs beyond the build's own (CI adds clang for the
# fuzzer). --dry-run prints what would be installed and exits 0 without changing anything;
# --pretend-missing treats PKG as not installed (to try the install path on a complete machine).
# --embree adds Intel's Embree 3 (libembree-dev), optional: with it, `rt bench` gains its row
# "Embree 3" (reconfigure after installing). --mpi adds OpenMPI (openmpi-bin, libopenmpi-dev):
# with it, rt-mpi is built and its tests (label mpi) run. --video adds ffmpeg, which
# `rt animate --video` encodes with. The README's test command and CI ask for both.
# --only (anywhere among the arguments) leaves the build's own packages out: only the packages
# named (EXTRA_PKG, --embree, --mpi, --video; at least one, else exit 2) are checked and
# installed. `scripts/deps.sh --only python3` installs python3 alone, as scripts/grade does when
# it builds nothing (--list, --no-build).
set -euo pipefail
# shellcheck source-path=SCRIPTDIR source=common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"  # rt_usage

# What the build needs: compiler and build tool, CMake, GoogleTest and GoogleMock, stb (PNG
# output), nlohmann-json (scene files), CLI11 (rt's command line) and Assimp (model files; the
# build works without it, and then cannot read them). The CMake files name the same packages
# when one is missing.
build_packages=(cmake g++ make libgtest-dev libgmock-dev libstb-dev nlohmann-json3-dev
                libcli11-dev libassimp-dev)

dry_run=0
only=0
named=()  # the packages asked for beyond the build's, in the order given
pretend=()
while (($#)); do
  case "$1" in
    --dry-run) dry_run=1 ;;
    --only) only=1 ;;
    --embree) named+=(libembree-dev) ;;
    --mpi) named+=(openmpi-bin libopenmpi-dev) ;;
    --video) named+=(ffmpeg) ;;
    --pretend-missing)
      (($# >= 2)) || { echo "deps.sh: --pretend-missing needs a package name" >&2; exit 2; }
      # A package name, not the next option: `--pretend-missing --dry-run` must not lose the dry
      # run (and then really install).
      if [[ -z "$2" || "$2" == -* ]]; then
        echo "deps.sh: --pretend-missing needs a package name, got '$2'" >&2
        exit 2
      fi
      pretend+=("$2")
      shift
      ;;
    -h | --help)
      rt_usage
      exit 0
      ;;
    -*) echo "deps.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
    '') echo "deps.sh: an empty package name (see --help)" >&2; exit 2 ;;
    *) named+=("$1") ;;
  esac
  shift
done
if ((only)); then
  ((${#named[@]})) || {
    echo "deps.sh: --only needs a package to install (EXTRA_PKG, --embree, --mpi or --video)" >&2
    exit 2
  }
  packages=("${named[@]}")
else
  packages=("${build_packages[@]}" "${named[@]+"${named[@]}"}")
fi

installed() {
  local p
  for p in "${pretend[@]+"${pretend[@]}"}"; do
    [[ "$p" == "$1" ]] && return 1
  done
  [[ "$(dpkg-query -W -f='${db:Status-Status}' "$1" 2>/dev/null)" == installed ]]
}

if ! command -v dpkg-query >/dev/null 2>&1 || ! command -v apt-get >/dev/null 2>&1; then
  echo "deps.sh: not a Debian-like system (no dpkg-query/apt-get); install these yourself:" \
       "${packages[*]}" >&2
  exit 0  # CMake names any package it still cannot find.
fi

missing=()
for p in "${packages[@]}"; do
  installed "$p" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  # Silent for the scripts that call it; a dry run is asked for by a person, who gets an answer.
  ((dry_run)) && echo "deps.sh: dry run: nothing missing (${packages[*]})"
  exit 0
fi

if ((EUID == 0)); then
  sudo=()
elif command -v sudo >/dev/null 2>&1; then
  sudo=(sudo)
else
  echo "deps.sh: missing packages: ${missing[*]}" >&2
  echo "deps.sh: not root and no sudo; as root, run:" \
       "apt-get update && apt-get install ${missing[*]}" >&2
  exit 1
fi

apt_update=("${sudo[@]+"${sudo[@]}"}" apt-get update -qq)
apt_install=("${sudo[@]+"${sudo[@]}"}" env DEBIAN_FRONTEND=noninteractive
             apt-get install -y -qq --no-install-recommends "${missing[@]}")
if ((dry_run)); then
  echo "deps.sh: dry run: missing: ${missing[*]}"
  echo "deps.sh: dry run: would run: ${apt_update[*]}"
  echo "deps.sh: dry run: would run: ${apt_install[*]}"
  exit 0
fi
echo "deps.sh: installing missing Debian packages: ${missing[*]}"
"${apt_update[@]}"
"${apt_install[@]}" >/dev/null
echo "deps.sh: installed ${missing[*]}"
