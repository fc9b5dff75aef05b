#!/usr/bin/env bash
# Renders the images the READMEs show into docs/images/ (which is committed).
#
#   scripts/render-docs-images.sh [--list] [RT_RENDER_OPTION]...
#
# Every README.md of the repository that links docs/images/NAME.png, where NAME is a built-in
# scene of `rt list`, gets that scene rendered with `rt render NAME` at its full resolution (or
# with the options given). An image listed in docs/images/render-options.txt (a line
# `NAME SCENE [RT_RENDER_OPTION]...`) is `rt render SCENE` with that line's options instead, and
# only those: a comparison pair of one scene, an image with --param or a size of its own. Links
# to other images are listed and left alone. --list prints what would be rendered and renders
# nothing. Set RT_BUILD_DIR to build somewhere other than build/release.
set -euo pipefail
# shellcheck source-path=SCRIPTDIR source=common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

list_only=0
case "${1:-}" in
  -h | --help) rt_usage; exit 0 ;;
  --list) list_only=1; shift ;;
esac

cd "$RT_ROOT"
"$RT_ROOT/scripts/deps.sh"
build_dir="${RT_BUILD_DIR:-$RT_ROOT/build/release}"
cmake --preset release -B "$build_dir" >/dev/null
cmake --build "$build_dir" --target rt --parallel "$RT_JOBS" >/dev/null ||
  rt_die "building rt failed (run: cmake --build $build_dir --target rt)"
rt="$build_dir/bin/rt"
[[ -x "$rt" ]] || rt_die "no rt program at $rt"

# A scene's line starts with its name; an indented line lists its parameters.
scenes="$("$rt" list | awk '!/^ / { print $1 }')"
linked="$(git ls-files --cached --others --exclude-standard -- '*README.md' 2>/dev/null ||
          find . -name README.md -not -path './build*')"
names="$(xargs grep -ohE 'docs/images/[A-Za-z0-9_.-]+\.png' <<<"$linked" |
         sed 's|docs/images/||; s|\.png$||' | sort -u)"
[[ -n "$names" ]] || { echo "No README links an image under docs/images/."; exit 0; }

# The images with options of their own: NAME SCENE OPTION... (# starts a comment).
declare -A own=()
options_file=docs/images/render-options.txt
if [[ -f "$options_file" ]]; then
  while read -r image rest; do
    [[ -z "$image" || "$image" == \#* ]] && continue
    [[ -n "$rest" ]] || rt_die "$options_file: the image $image names no scene"
    own["$image"]="$rest"
  done <"$options_file"
fi

((list_only)) || mkdir -p docs/images
while read -r name; do
  scene="$name"
  args=("$@")
  if [[ -v "own[$name]" ]]; then
    read -r -a args <<<"${own[$name]}"
    scene="${args[0]}"
    args=("${args[@]:1}")
  fi
  if ! grep -qx -- "$scene" <<<"$scenes"; then
    echo "skipped: docs/images/$name.png ($scene is not a built-in scene)"
  elif ((list_only)); then
    echo "would render: docs/images/$name.png (rt render $scene${args[*]:+ ${args[*]}})"
  else
    start="$(rt_now)"
    "$rt" render "$scene" -o "docs/images/$name.png" --quiet "${args[@]}"
    echo "rendered docs/images/$name.png in $(rt_elapsed "$start")"
  fi
done <<<"$names"
