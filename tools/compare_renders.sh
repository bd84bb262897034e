#!/usr/bin/env bash
# tools/compare_renders.sh OTHER_CHECKOUT [FRAMES] [RENDER OPTIONS...] — renders every shipped
# scene (content/scenes/*.json) with this checkout's build/pyro and with OTHER_CHECKOUT's (each
# with its own content folder), frames FRAMES (default 12:14) and the given options (for example
# `--shadows off`), and says for every frame whether the two PNGs are byte-identical. A scene the
# other checkout cannot render (newer than it) is reported as such. Scenes that pick settings from
# timings (a `quality` target) may differ from run to run.
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
other=${1:?usage: tools/compare_renders.sh OTHER_CHECKOUT [FRAMES] [RENDER OPTIONS...]}
frames=${2:-12:14}
shift $(( $# >= 2 ? 2 : 1 ))
for pyro in "$root/build/pyro" "$other/build/pyro"; do
  [[ -x $pyro ]] || { echo "tools/compare_renders.sh: no pyro executable at $pyro (build it first)" >&2; exit 2; }
done
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
status=0
for scene in "$root"/content/scenes/*.json; do
  name=$(basename "$scene" .json)
  (cd "$root" && ./build/pyro render "content/scenes/$name.json" --out "$tmp/new/$name" --frames "$frames" "$@" >/dev/null 2>&1)
  if ! (cd "$other" && ./build/pyro render "content/scenes/$name.json" --out "$tmp/old/$name" --frames "$frames" "$@" >/dev/null 2>&1); then
    echo "$name: the other checkout cannot render it"
    continue
  fi
  for png in "$tmp/new/$name"/*.png; do
    if cmp -s "$png" "$tmp/old/$name/$(basename "$png")"; then echo "$name $(basename "$png"): same bytes"
    else echo "$name $(basename "$png"): DIFFERENT"; status=1; fi
  done
done
exit $status
