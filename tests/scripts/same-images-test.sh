#!/usr/bin/env bash
# Tests of scripts/check-same-images.sh against a real rt: the same build twice agrees, a build
# whose sampled renders take another seed is caught, bad usage is refused.
#
#   tests/scripts/same-images-test.sh PATH/TO/check-same-images.sh PATH/TO/rt
#
# Prints one line per case and exits 1 when any case fails.
set -uo pipefail

script="$1"
rt="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# The same rt under another name, and one whose renders draw other random numbers.
printf '#!/usr/bin/env bash\nexec "%s" "$@"\n' "$rt" >"$work/same"
{
  echo '#!/usr/bin/env bash'
  # shellcheck disable=SC2016  # the $ are the stub's own
  printf 'if [[ "$1" == render ]]; then exec "%s" "$@" --seed 7; fi\n' "$rt"
  printf 'exec "%s" "$@"\n' "$rt"
} >"$work/seeded"
chmod +x "$work/same" "$work/seeded"
scenes="$("$rt" list | grep -c '^[a-z]')"
images=$((scenes + 3))  # and the galaxy's three other views

# shellcheck source-path=SCRIPTDIR source=cases.sh
source "$(dirname "${BASH_SOURCE[0]}")/cases.sh"

check "the same build twice: every image the same" 0 \
  "^all $images images are the same bytes in the 2 builds" --width 16 "$rt" "$work/same"
check "another seed: the sampled scenes differ, named" 1 \
  "^galaxy +DIFFERENT in $work/seeded: pixels differing" --width 16 "$rt" "$work/seeded"
check "another seed: the count of differing images" 1 \
  "^[0-9]+ of $images images differ between the builds" --width 16 "$rt" "$work/seeded"
check "a scene without sampling stays the same" 1 "^two-color +same$" \
  --width 16 "$rt" "$work/seeded"
check "one build is not a comparison" 2 "give at least two rt executables" "$rt"
check "a missing executable" 2 "not an executable: $work/none" "$rt" "$work/none"
check "a bad width" 2 "--width needs a positive integer" --width 0 "$rt" "$rt"
check "a bad width is named" 2 "^--width needs a positive integer, got 'abc'$" \
  --width abc "$rt" "$rt"
check "an empty --keep is refused, not a temporary directory" 2 \
  "^--keep needs a directory, got ''$" --keep "" "$rt" "$rt"
touch "$work/file"
check "--keep naming a file" 2 "^--keep: '$work/file' exists and is not a directory$" \
  --keep "$work/file" "$rt" "$rt"

finish
