# shellcheck shell=bash disable=SC2034  # sourced: RT_ROOT and RT_JOBS are for the caller
# Shared by the scripts in this folder; sourced, not run.
#
# Sets RT_ROOT (the repository root, whatever directory the caller ran from) and RT_JOBS (parallel
# build and test jobs: the number of cores unless RT_JOBS is already set), and defines
#   rt_banner TEXT      a banner line on stdout
#   rt_die TEXT         an error line on stderr, then exit 1
#   rt_bad_usage TEXT   an error line on stderr, then exit 2 (bad usage: an option or argument)
#   rt_operands ARG...  for a script that takes no options: --help (anywhere) prints its header
#                       and exits 0; any other argument that starts with - is bad usage (exit 2)
#   rt_label_of FOLDER  a stage folder's label: its name up to the first underscore
#                       (stage04_camera -> stage04, mini1_glossy -> mini1)
#   rt_stage_named NAME FOLDER...
#                       the FOLDER that NAME names, by its folder name or its label (a trailing
#                       slash, as a shell's completion leaves it, is allowed); nothing when none
#   rt_needs_rt_stage   for a script that builds rt: exit 1 (rt_die) at once when the checkout has
#                       no stage04_camera, the stage rt comes with (a student handout of an
#                       earlier stage), before anything is installed or built
#   rt_abspath PATH     PATH made absolute against the current directory (it need not exist):
#                       a path the caller gave (an argument, RT_BUILD_DIR) read before a cd
#   rt_now              seconds since the epoch, with a fraction
#   rt_elapsed START    the time since START (from rt_now) as "12.3 s" or "4 min 05 s"

RT_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
RT_JOBS="${RT_JOBS:-$(nproc 2>/dev/null || echo 2)}"

rt_banner() { printf '\n==== %s ====\n' "$*"; }

rt_die() {
  printf '%s: error: %s\n' "$(basename "$0")" "$*" >&2
  exit 1
}

rt_bad_usage() {
  printf '%s: error: %s\n' "$(basename "$0")" "$*" >&2
  exit 2
}

rt_operands() {
  local arg
  for arg in "$@"; do
    case "$arg" in
      -h | --help) rt_usage; exit 0 ;;
      -*) rt_bad_usage "unknown option '$arg' (see --help)" ;;
    esac
  done
}

rt_label_of() { echo "${1%%_*}"; }

rt_stage_named() {
  local name="$1" s
  shift
  while [[ "$name" == */ ]]; do name="${name%/}"; done
  [[ -n "$name" ]] || return 0
  for s in "$@"; do
    if [[ "$name" == "$s" || "$name" == "$(rt_label_of "$s")" ]]; then
      echo "$s"
    fi
  done
}

rt_needs_rt_stage() {
  [[ -f "$RT_ROOT/stage04_camera/CMakeLists.txt" ]] ||
    rt_die "this checkout has no stage04_camera (a student handout of an earlier stage?): rt," \
      "which renders, comes with stage 4"
}

rt_abspath() {
  if [[ "$1" == /* ]]; then
    printf '%s\n' "$1"
  else
    printf '%s\n' "$PWD/$1"
  fi
}

rt_now() { date +%s.%N; }

rt_elapsed() {
  awk -v a="$1" -v b="$(rt_now)" 'BEGIN {
    s = b - a
    if (s < 60) printf "%.1f s", s
    else printf "%d min %02d s", int(s / 60), int(s) % 60
  }'
}

# Prints the comment block at the top of the running script (its usage), without the '#'.
rt_usage() { awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; }
