#!/usr/bin/env bash
# tools/render_docs_images.sh [PYRO] — renders one chosen frame of each shipped scene into
# docs/images/<name>.png (the pictures in README.md), with PYRO (default: build/pyro).
# Stereo scenes are rendered side by side (left eye on the left) and one as an anaglyph.
# Frames go through a temporary folder; only the chosen frame is copied. When Debian's
# /usr/bin/python3 has PIL (python3-matplotlib brings it), each PNG is re-encoded losslessly
# with maximum compression, to keep the pictures small in the repository.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
pyro=${1:-$root/build/pyro}
if [[ ! -x $pyro ]]; then
  echo "tools/render_docs_images.sh: no pyro executable at $pyro (build it first, or pass its path)" >&2
  exit 2
fi
out=$root/docs/images
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# shot NAME SCENE FRAME WIDTH HEIGHT [render options...]: frame FRAME of content/scenes/SCENE.json
# at WIDTH x HEIGHT (per eye) into docs/images/NAME.png.
shot() {
  local name=$1 scene=$2 frame=$3 width=$4 height=$5
  shift 5
  "$pyro" render "$root/content/scenes/$scene.json" --out "$tmp/$name" --frames "$frame:$frame" \
    --width "$width" --height "$height" "$@" >/dev/null
  cp "$tmp/$name/$(printf 'frame_%04d.png' "$frame")" "$out/$name.png"
  if /usr/bin/python3 -c 'import PIL' 2>/dev/null; then
    /usr/bin/python3 -c 'import sys; from PIL import Image; p = sys.argv[1]; Image.open(p).save(p, optimize=True)' \
      "$out/$name.png"
  fi
  echo "docs/images/$name.png: $scene.json frame $frame, $(stat -c %s "$out/$name.png") bytes"
}

shot fog fog 30 480 360
shot fog_lit fog 30 480 360 --shadows map
shot mist mist 30 480 360
shot clouds clouds 30 480 360
shot clouds_lit clouds 30 480 360 --shadows map
shot sunset sunset 30 480 360
shot cloud_vdb cloud_vdb 0 480 270
shot cloud_fitted cloud_fitted 0 480 270
shot cloud_fitted_baked cloud_fitted 0 480 270 --shadows off
shot vdb_fire vdb_fire 0 360 480
shot explosion explosion 30 384 384
shot explosion_lit explosion 30 384 384 --shadows map
shot explosion_dusk explosion_dusk 30 384 384
shot explosion_behind_tower explosion_behind_tower 30 384 384
shot flipbook_fire flipbook_fire 12 192 288
shot smoke_stacks smoke_stacks 0 480 300
shot smoke_stacks_backlit smoke_stacks 180 480 300
shot campfire campfire 20 480 360 --stereo side-by-side
shot flipbook_grid flipbook_grid 20 320 240 --stereo side-by-side
shot explosion_anaglyph explosion 30 384 384 --stereo anaglyph
