#!/usr/bin/env bash
# Seed scenes rendered by POV-Ray 3.7 with radiosity (its global
# illumination) beside camlray's mc mode -> docs/radiosity.png. POV-Ray
# gets the scene with one more global_settings block (POV-Ray merges them).
set -euo pipefail
cd "$(dirname "$0")/.."
command -v montage >/dev/null || { echo "radiosity: needs ImageMagick (apt-get install imagemagick)" >&2; exit 1; }
exe=_build/install/default/bin/camlray
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
args=()
for n in dex-cornell diagrams-snowman howard-default clojure-materials; do
  { cat "scenes/seeds/$n.scn"
    echo 'global_settings { radiosity { count 400 error_bound 0.5 recursion_limit 3 nearest_count 10 } }'
  } > "$work/$n.pov"
  povray +I"$work/$n.pov" +O"$work/$n-pov.png" +W240 +H180 +A0.3 -D +GA -GR +L/usr/share/povray-3.7/include \
    > "$work/$n.log" 2>&1 || { cat "$work/$n.log" >&2; exit 1; }
  "$exe" render "scenes/seeds/$n.scn" -W 240 -H 180 --mode mc --spp 256 -o "$work/$n-mc.png" -q
  args+=(-label "$n: POV-Ray radiosity" "$work/$n-pov.png" -label "$n: camlray mc" "$work/$n-mc.png")
done
montage "${args[@]}" -tile 4x -geometry 240x180+2+2 -pointsize 11 "$work/sheet.png"
convert "$work/sheet.png" -depth 8 -colors 256 PNG8:docs/radiosity.png
echo "wrote docs/radiosity.png"
