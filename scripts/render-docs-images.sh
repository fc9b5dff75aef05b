#!/usr/bin/env bash
# Renders the reference images into docs/images/ (which is committed).
#
#   scripts/render-docs-images.sh [--list] [RT_RENDER_OPTION]...
#
# docs/images/NAME.png is `rt render NAME --width 500`, for every built-in scene of the course's
# stages 4 to 7 (the scenes of `rt list` that the ambient, phong, shadow or whitted tracer
# renders). The READMEs show them, and a student checks a render against them exactly:
#
#   rt render NAME --width 500 -o mine.png && rt compare mine.png docs/images/NAME.png
#
# The cli tests (ReferenceImageTests) render every one the same way and compare. Options given
# replace --width 500 (the committed images are rendered without any). The mini projects' images
# (the galaxy: sampled, and long to render) are made by the commands their READMEs give.
# A README link to an image of docs/images/ that does not exist is reported. --list prints what
# would be rendered and renders nothing. Set RT_BUILD_DIR to build somewhere other than
# build/release.
set -euo pipefail
# shellcheck source-path=SCRIPTDIR source=common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

list_only=0
case "${1:-}" in
  -h | --help) rt_usage; exit 0 ;;
  --list) list_only=1; shift ;;
esac
options=("$@")
((${#options[@]})) || options=(--width 500)

cd "$RT_ROOT"
"$RT_ROOT/scripts/deps.sh"
build_dir="${RT_BUILD_DIR:-$RT_ROOT/build/release}"
cmake --preset release -B "$build_dir" >/dev/null
cmake --build "$build_dir" --target rt --parallel "$RT_JOBS" >/dev/null ||
  rt_die "building rt failed (run: cmake --build $build_dir --target rt)"
rt="$build_dir/bin/rt"
[[ -x "$rt" ]] || rt_die "no rt program at $rt"

# The course's scenes: those whose tracer (as their export records it) is one of stages 4-7. A
# scene's line of rt list starts with its name; an indented line lists its parameters.
names=()
while read -r name; do
  scene="$("$rt" export "$name")"
  [[ "$scene" =~ \"tracer\":\ \"(ambient|phong|shadow|whitted)\" ]] && names+=("$name")
done < <("$rt" list | awk '/^[^ ]/ { print $1 }')
((${#names[@]})) || rt_die "rt list shows no scene of the course's stages"

((list_only)) || mkdir -p docs/images
for name in "${names[@]}"; do
  if ((list_only)); then
    echo "would render: docs/images/$name.png (rt render $name ${options[*]})"
  else
    start="$(rt_now)"
    "$rt" render "$name" -o "docs/images/$name.png" --silent "${options[@]}"
    echo "rendered docs/images/$name.png (rt render $name ${options[*]}) in $(rt_elapsed "$start")"
  fi
done

linked="$(git ls-files --cached --others --exclude-standard -- '*README.md' 2>/dev/null ||
          find . -name README.md -not -path './build*')"
while read -r image; do
  [[ -z "$image" || -f "$image" ]] || echo "missing: $image (a README links it)"
done < <(xargs grep -ohE 'docs/images/[A-Za-z0-9_.-]+\.png' <<<"$linked" | sort -u)
