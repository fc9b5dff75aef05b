#!/usr/bin/env bash
# Renders every built-in scene with two or more builds of rt and checks that they all write the
# same bytes: an image must not change with the compiler or its optimisation (the project's
# arithmetic is IEEE double without contraction, and C++ leaves some orders to the compiler, such
# as the order of a call's arguments: Clang and GCC once traced a glass's two secondary rays in
# opposite orders, and the galaxy differed in 12.8 % of its pixels).
#
# Usage: scripts/check-same-images.sh [--width W] [--keep DIR] RT RT [RT ...]
#   RT        an rt executable (a build of this repository: GCC's, Clang's, a sanitizer's)
#   --width   the images' width in pixels (default 64; each scene keeps its aspect ratio)
#   --keep    write the images into DIR (by default a temporary directory, removed at the end)
#
# The scenes are those of the first RT's `rt list`, each at its defaults, and the galaxy's other
# named views where it has the galaxy (the stages before mini project 1 have not). One line per
# image: "same" or "DIFFERENT" with `rt compare`'s figures; the exit code is 0 when every image
# is the same bytes in every build, 1 when one differs, 2 for bad usage or a build that cannot
# render a scene the first can.
#
#   scripts/check-same-images.sh build/release/bin/rt build/clang/bin/rt build/asan/bin/rt
set -euo pipefail

# shellcheck source-path=SCRIPTDIR source=common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

usage() {
  rt_usage >&2
  exit 2
}

width=64
keep=""
builds=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --width)
      [[ $# -ge 2 ]] || { echo "--width needs a positive integer" >&2; usage; }
      if [[ ! "$2" =~ ^[1-9][0-9]*$ ]]; then
        echo "--width needs a positive integer, got '$2'" >&2
        usage
      fi
      width="$2"
      shift 2
      ;;
    --keep)
      [[ $# -ge 2 ]] || { echo "--keep needs a directory" >&2; usage; }
      # An empty name would quietly fall back to a temporary directory, removed at the end.
      [[ -n "$2" ]] || { echo "--keep needs a directory, got ''" >&2; usage; }
      keep="$2"
      shift 2
      ;;
    -h | --help) rt_usage; exit 0 ;;
    -*) echo "unknown option: $1" >&2; usage ;;
    *) builds+=("$1"); shift ;;
  esac
done
[[ ${#builds[@]} -ge 2 ]] || { echo "give at least two rt executables" >&2; usage; }
for rt in "${builds[@]}"; do
  [[ -x "$rt" ]] || { echo "not an executable: $rt" >&2; exit 2; }
done

if [[ -n "$keep" ]]; then
  if [[ -e "$keep" && ! -d "$keep" ]]; then
    echo "--keep: '$keep' exists and is not a directory" >&2
    exit 2
  fi
  mkdir -p "$keep" 2>/dev/null || { echo "--keep: cannot create the directory '$keep'" >&2; exit 2; }
  out="$keep"
else
  out="$(mktemp -d)"
  trap 'rm -rf "$out"' EXIT
fi

# Each image as "NAME|ARGS": the built-in scenes, then the galaxy's other views.
images=()
while read -r scene; do
  images+=("$scene|$scene")
done < <("${builds[0]}" list | awk '/^[a-z]/ { print $1 }')
[[ ${#images[@]} -gt 0 ]] || rt_die "${builds[0]} list named no scene"
if [[ " ${images[*]} " == *" galaxy|galaxy "* ]]; then
  for view in above inside side; do images+=("galaxy-$view|galaxy --view $view"); done
fi

different=0
for image in "${images[@]}"; do
  name="${image%%|*}"
  read -r -a args <<<"${image#*|}"
  for k in "${!builds[@]}"; do
    if ! "${builds[$k]}" render "${args[@]}" --width "$width" --threads 2 \
      -o "$out/$name.$k.png" >"$out/$name.$k.log" 2>&1; then
      cat "$out/$name.$k.log" >&2
      echo "${builds[$k]} could not render $name" >&2
      exit 2
    fi
  done
  line="same"
  for ((k = 1; k < ${#builds[@]}; ++k)); do
    if ! cmp -s "$out/$name.0.png" "$out/$name.$k.png"; then
      figures="$("${builds[0]}" compare "$out/$name.0.png" "$out/$name.$k.png" 2>&1 |
        tail -n 2 | tr '\n' ' ' || true)"
      figures="${figures% }"
      [[ "$line" == same ]] && line="DIFFERENT" && different=$((different + 1))
      line+=" in ${builds[$k]}: $figures"
    fi
  done
  printf '%-34s %s\n' "$name" "$line"
done

count=${#images[@]}
if [[ $different -gt 0 ]]; then
  echo "$different of $count images differ between the builds (${builds[*]})"
  exit 1
fi
echo "all $count images are the same bytes in the ${#builds[@]} builds (${builds[*]})"
