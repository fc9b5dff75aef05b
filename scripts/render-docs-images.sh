#!/usr/bin/env bash
# Renders the reference images into docs/images/ (which is committed).
#
#   scripts/render-docs-images.sh [--list] [RT_RENDER_OPTION]...
#
# 1. The course's stages: docs/images/NAME.png is `rt render NAME --width 500`, for every built-in
#    scene of stages 4 to 7 (the scenes of `rt list` that the ambient, phong, shadow or whitted
#    tracer renders, or one of stage 4's debugging views: rays, normals, hits; the `shapes` scene
#    is stage 2's image). The READMEs show them, and a student checks a render against them
#    exactly:
#
#      rt render NAME --width 500 -o mine.png && rt compare mine.png docs/images/NAME.png
#
#    The cli tests (ReferenceImageTests) render every one the same way and compare. Options given
#    replace --width 500 (the committed images are rendered without any).
# 2. The images with options of their own, listed in docs/images/render-options.txt (a line
#    `IMAGE SCENE [RT_RENDER_OPTION]...`): the mini projects' scenes at their own sizes, an image
#    with a --param, the galaxy with and without diffused glass. docs/images/IMAGE.png is
#    `rt render SCENE` with that line's options only.
# 3. The pictures of mini2_bvh's trees (bvh-top.png, bvh-leaves.png, bvh-wide-root.png), drawn by
#    mini2_bvh_picture, when the build has mini2_bvh.
# A README link to an image of docs/images/ that does not exist is reported. --list (anywhere
# among the arguments) prints what would be rendered and renders nothing; it still builds rt,
# whose `rt list` and `rt export` name the scenes. Set RT_BUILD_DIR to build somewhere other than
# build/release (a relative path is the caller's). A checkout without stage04_camera (a handout
# of an earlier stage) has no rt: that is said at once (exit 1), before anything is installed.
set -euo pipefail
# shellcheck source-path=SCRIPTDIR source=common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

# --list and --help wherever they are; every other argument is an option of `rt render`.
list_only=0
options=()
for arg in "$@"; do
  case "$arg" in
    -h | --help) rt_usage; exit 0 ;;
    --list) list_only=1 ;;
    *) options+=("$arg") ;;
  esac
done
((${#options[@]})) || options=(--width 500)
# A relative RT_BUILD_DIR is the caller's, not the repository's (the cd below).
build_dir="$(rt_abspath "${RT_BUILD_DIR:-$RT_ROOT/build/release}")"
rt_needs_rt_stage

cd "$RT_ROOT"
"$RT_ROOT/scripts/deps.sh"
cmake --preset release -B "$build_dir" >/dev/null
cmake --build "$build_dir" --target rt --parallel "$RT_JOBS" >/dev/null ||
  rt_die "building rt failed (run: cmake --build $build_dir --target rt)"
rt="$build_dir/bin/rt"
[[ -x "$rt" ]] || rt_die "no rt program at $rt"

# Renders docs/images/$1.png as rt render $2 with the options after them (or lists it).
render() {
  local image="$1" scene="$2"
  shift 2
  if ((list_only)); then
    echo "would render: docs/images/$image.png (rt render $scene $*)"
  else
    local start
    start="$(rt_now)"
    "$rt" render "$scene" -o "docs/images/$image.png" --silent "$@"
    echo "rendered docs/images/$image.png (rt render $scene $*) in $(rt_elapsed "$start")"
  fi
}

# 1. The course's scenes: those whose tracer (as their export records it) is one of stages 4-7.
# (The debugging views are stage 4's.)
# A scene's line of rt list starts with its name; an indented line lists its parameters.
scenes="$("$rt" list | awk '/^[^ ]/ { print $1 }')"
course_tracer='"tracer": "(rays|normals|hits|ambient|phong|shadow|whitted)"'
names=()
while read -r name; do
  scene="$("$rt" export "$name")"
  [[ "$scene" =~ $course_tracer ]] && names+=("$name")
done <<<"$scenes"
((${#names[@]})) || rt_die "rt list shows no scene of the course's stages"

((list_only)) || mkdir -p docs/images
for name in "${names[@]}"; do
  render "$name" "$name" "${options[@]}"
done

# 2. The images with options of their own: IMAGE SCENE OPTION... (# starts a comment). A scene
# this build does not have (a course cut) is skipped, saying so.
options_file=docs/images/render-options.txt
if [[ -f "$options_file" ]]; then
  while read -r image scene rest; do
    [[ -z "$image" || "$image" == \#* ]] && continue
    [[ -n "$scene" ]] || rt_die "$options_file: the image $image names no scene"
    # A scene file of scenes/ (a path ending in .json) is rendered as it is.
    if [[ "$scene" == *.json ]]; then
      [[ -f "$scene" ]] || rt_die "$options_file: the image $image names $scene, which does not exist"
    elif ! grep -qx -- "$scene" <<<"$scenes"; then
      echo "skipped: docs/images/$image.png ($scene is not a built-in scene of this build)"
      continue
    fi
    read -r -a own <<<"$rest"
    render "$image" "$scene" "${own[@]}"
  done <"$options_file"
fi

# 3. The BVH's boxes over the galaxy.
if cmake --build "$build_dir" --target mini2_bvh_picture --parallel "$RT_JOBS" >/dev/null 2>&1; then
  if ((list_only)); then
    echo "would draw: docs/images/bvh-top.png, docs/images/bvh-leaves.png," \
         "docs/images/bvh-wide-root.png (mini2_bvh_picture)"
  else
    "$build_dir/bin/mini2_bvh_picture" docs/images/bvh-top.png --depth 3
    "$build_dir/bin/mini2_bvh_picture" docs/images/bvh-leaves.png
    "$build_dir/bin/mini2_bvh_picture" docs/images/bvh-wide-root.png --wide --depth 0
  fi
fi

linked="$(git ls-files --cached --others --exclude-standard -- '*README.md' 2>/dev/null ||
          find . -name README.md -not -path './build*')"
while read -r image; do
  [[ -z "$image" || -f "$image" ]] || echo "missing: $image (a README links it)"
done < <(xargs grep -ohE '(\]\(|src=")(\.\./)?docs/images/[A-Za-z0-9_.-]+\.png' <<<"$linked" |
           sed -E 's#^.*(docs/images/)#\1#' | sort -u)
