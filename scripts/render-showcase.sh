#!/usr/bin/env bash
# Renders the course's culmination, the reference report's galaxy in a glass box, into
# images/NAME.png.
#
#   scripts/render-showcase.sh [SCENE] [RT_RENDER_OPTION]...
#
# Works from any directory on a fresh Debian machine: installs missing packages
# (scripts/deps.sh), configures the release preset, builds the `rt` program and renders. Without
# SCENE it renders the showcase scene, the galaxy in a glass box (1280 x 720, diffused glass), at
# its full resolution on every core (or the first scene `rt list` prints when there is no galaxy:
# a course cut before mini1_glossy). SCENE is a built-in name or a .json file; the options go to
# `rt render` (for example --width 640 --height 360, --threads 1, --accel none); -o FILE (or
# -oFILE, --output FILE, --output=FILE) writes FILE instead of images/NAME.png; a FILE that
# starts with '-' is refused in every spelling (an option where a file name was meant: `-o
# --width 64`); write such a file as ./-x. --help (or -h) anywhere among the arguments prints
# this and exits 0 before any other check. Relative paths are the caller's. Set RT_BUILD_DIR to
# build somewhere other than build/release. A checkout without stage04_camera (a handout of an
# earlier stage) has no rt: that is said at once (exit 1), before anything is installed.
set -euo pipefail
# shellcheck source-path=SCRIPTDIR source=common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

# The most advanced scene the repository has; move it forward as the stages grow.
SHOWCASE=galaxy

# The arguments are checked before anything is installed or built. Paths the caller gives (a
# scene file, -o FILE, RT_BUILD_DIR) are the caller's: made absolute before the cd below.
# --help wherever it is, first (as in render-docs-images.sh): even after -o, where a file named
# --help would be a slip.
for arg in "$@"; do
  case "$arg" in
    -h | --help) rt_usage; exit 0 ;;
  esac
done
scene=""
if (($#)) && [[ "$1" != -* ]]; then
  scene="$1"
  shift
  [[ -n "$scene" ]] || rt_bad_usage "an empty SCENE (a built-in scene's name or a .json file)"
  if [[ -f "$scene" ]]; then
    scene="$(cd "$(dirname "$scene")" && pwd)/$(basename "$scene")"
  elif [[ "$scene" == *.json ]]; then
    rt_bad_usage "no scene file '$scene'"
  fi
fi
# The caller's -o/--output replaces images/NAME.png; the other options go to `rt render` as given.
out=""
given=""
options=()
while (($#)); do
  case "$1" in
    -o | --output)
      (($# >= 2)) || rt_bad_usage "$1 needs a file name: nothing follows it"
      option="$1"
      file="$2"
      shift 2
      ;;
    -o?*) option=-o file="${1#-o}"; shift ;;
    --output=*) option=--output file="${1#--output=}"; shift ;;
    *) options+=("$1"); shift; continue ;;
  esac
  [[ -n "$file" ]] || rt_bad_usage "$option needs a file name, got ''"
  [[ "$file" != -* ]] ||
    rt_bad_usage "$option needs a file name, got '$file' (an option? a file so named: ./$file)"
  [[ -z "$out" ]] || rt_bad_usage "-o/--output given twice ('$given' and '$file')"
  given="$file"
  out="$(rt_abspath "$file")"
done
build_dir="$(rt_abspath "${RT_BUILD_DIR:-$RT_ROOT/build/release}")"
rt_needs_rt_stage

cd "$RT_ROOT"
"$RT_ROOT/scripts/deps.sh"

rt_banner "Configuring (release preset) in $build_dir"
cmake --preset release -B "$build_dir" >/dev/null
rt_banner "Building rt"
if ! cmake --build "$build_dir" --target rt --parallel "$RT_JOBS"; then
  rt_die "building rt failed (rt needs stage04_camera: is RT_LAST_STAGE set in $build_dir?)"
fi
rt="$build_dir/bin/rt"
[[ -x "$rt" ]] || rt_die "the build produced no program at $rt"

# A scene's line starts with its name; an indented line lists its parameters.
scenes="$("$rt" list | awk '!/^ / { print $1 }')"
[[ -n "$scenes" ]] || rt_die "'rt list' printed no scene"
if [[ -z "$scene" ]] && grep -qx -- "$SHOWCASE" <<<"$scenes"; then
  scene="$SHOWCASE"
elif [[ -z "$scene" ]]; then
  scene="$(head -n 1 <<<"$scenes")"
  echo "render-showcase.sh: no scene '$SHOWCASE' yet; rendering the first one, '$scene'"
fi

if [[ -z "$out" ]]; then
  mkdir -p "$RT_ROOT/images"
  out="$RT_ROOT/images/$(basename "$scene" .json).png"
fi
rt_banner "Rendering $scene"
start="$(rt_now)"
"$rt" render "$scene" -o "$out" "${options[@]+"${options[@]}"}"
echo "Rendered $scene in $(rt_elapsed "$start"): $out"
