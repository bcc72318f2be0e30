#!/usr/bin/env bash
# Contact sheets for the README (needs ImageMagick):
#   sheets.sh gallery    every seed scene in both modes (240x180; whitted
#                        with +A0.3, mc with 64 spp) -> docs/gallery.png
#   sheets.sh radiosity  four seeds by POV-Ray 3.7 with radiosity (its
#                        global illumination; the scene gets one more
#                        global_settings block, which POV-Ray merges) beside
#                        camlray's mc mode (256 spp) -> docs/radiosity.png
set -euo pipefail
cd "$(dirname "$0")/.."
command -v montage >/dev/null || { echo "$1: needs ImageMagick (apt-get install imagemagick)" >&2; exit 1; }
exe=_build/install/default/bin/camlray
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
args=()
case "$1" in
  gallery)
    tile=200x150 cols=6
    for f in scenes/seeds/*.scn; do
      n=$(basename "$f" .scn)
      "$exe" render "$f" -W 240 -H 180 --aa 0.3 -o "$work/$n-whitted.png" -q
      "$exe" render "$f" -W 240 -H 180 --mode mc --spp 64 -o "$work/$n-mc.png" -q
      args+=(-label "$n whitted" "$work/$n-whitted.png" -label "$n mc" "$work/$n-mc.png")
    done ;;
  radiosity)
    tile=240x180 cols=4
    for n in dex-cornell diagrams-snowman howard-default clojure-materials; do
      { cat "scenes/seeds/$n.scn"
        echo 'global_settings { radiosity { count 400 error_bound 0.5 recursion_limit 3 nearest_count 10 } }'
      } > "$work/$n.pov"
      povray +I"$work/$n.pov" +O"$work/$n-pov.png" +W240 +H180 +A0.3 -D +GA -GR \
        +L/usr/share/povray-3.7/include > "$work/$n.log" 2>&1 || { cat "$work/$n.log" >&2; exit 1; }
      "$exe" render "scenes/seeds/$n.scn" -W 240 -H 180 --mode mc --spp 256 -o "$work/$n-mc.png" -q
      args+=(-label "$n: POV-Ray radiosity" "$work/$n-pov.png" -label "$n: camlray mc" "$work/$n-mc.png")
    done ;;
  *) echo "usage: sheets.sh gallery|radiosity" >&2; exit 2 ;;
esac
montage "${args[@]}" -tile "${cols}x" -geometry "$tile+2+2" -pointsize 11 "$work/sheet.png"
convert "$work/sheet.png" -depth 8 -colors 256 "PNG8:docs/$1.png"
echo "wrote docs/$1.png"
