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
# `rt render` (for example --width 640 --height 360, --threads 1, --accel none). Set
# RT_BUILD_DIR to build somewhere other than build/release.
set -euo pipefail
# shellcheck source-path=SCRIPTDIR source=common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

# The most advanced scene the repository has; move it forward as the stages grow.
SHOWCASE=galaxy

case "${1:-}" in
  -h | --help) rt_usage; exit 0 ;;
esac

# A scene file named relative to the caller's directory keeps working after the cd below.
if (($#)) && [[ -f "$1" ]]; then
  set -- "$(cd "$(dirname "$1")" && pwd)/$(basename "$1")" "${@:2}"
fi
cd "$RT_ROOT"
"$RT_ROOT/scripts/deps.sh"

build_dir="${RT_BUILD_DIR:-$RT_ROOT/build/release}"
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
if (($#)) && [[ "$1" != -* ]]; then
  scene="$1"
  shift
elif grep -qx -- "$SHOWCASE" <<<"$scenes"; then
  scene="$SHOWCASE"
else
  scene="$(head -n 1 <<<"$scenes")"
  echo "render-showcase.sh: no scene '$SHOWCASE' yet; rendering the first one, '$scene'"
fi

mkdir -p "$RT_ROOT/images"
out="$RT_ROOT/images/$(basename "$scene" .json).png"
rt_banner "Rendering $scene"
start="$(rt_now)"
"$rt" render "$scene" -o "$out" "$@"
echo "Rendered $scene in $(rt_elapsed "$start"): $out"
