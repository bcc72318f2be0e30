#!/usr/bin/env bash
# make stress: renders the same scenes N times (default 50) with random
# domain counts (1..8) and random tile orders, and checks every image is
# bit-identical to a one-domain render. Prints the count and the result.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-50}
exe=_build/install/default/bin/camlray
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fails=0
for mode in whitted mc; do
  extra=(); [ "$mode" = mc ] && extra=(--spp 4)
  "$exe" render scenes/default.scn -W 96 -H 72 -q --mode "$mode" "${extra[@]}" --domains 1 -o "$tmp/ref.png"
  for i in $(seq 1 "$runs"); do
    d=$((RANDOM % 8 + 1)); s=$RANDOM
    "$exe" render scenes/default.scn -W 96 -H 72 -q --mode "$mode" "${extra[@]}" \
      --domains "$d" --tile-order-seed "$s" -o "$tmp/x.png"
    if ! cmp -s "$tmp/ref.png" "$tmp/x.png"; then
      echo "DIFFERENT: mode $mode, $d domains, tile order $s"
      fails=$((fails + 1))
    fi
  done
done
echo "stress: $((2 * runs)) renders with random domains and tile orders, $fails different"
[ "$fails" -eq 0 ]
