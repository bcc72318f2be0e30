#!/usr/bin/env bash
# Renders every seed scene in both modes (240x180; whitted with +A0.3,
# mc with 64 samples per pixel) and assembles docs/gallery.png.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v montage >/dev/null || { echo "gallery: needs ImageMagick (apt-get install imagemagick)" >&2; exit 1; }
exe=_build/install/default/bin/camlray
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
args=()
for f in scenes/seeds/*.scn; do
  n=$(basename "$f" .scn)
  "$exe" render "$f" -W 240 -H 180 --aa 0.3 -o "$work/$n-whitted.png" -q
  "$exe" render "$f" -W 240 -H 180 --mode mc --spp 64 -o "$work/$n-mc.png" -q
  args+=(-label "$n whitted" "$work/$n-whitted.png" -label "$n mc" "$work/$n-mc.png")
done
montage "${args[@]}" -tile 6x -geometry 200x150+2+2 -pointsize 11 "$work/sheet.png"
convert "$work/sheet.png" -depth 8 -colors 256 PNG8:docs/gallery.png
echo "wrote docs/gallery.png"
