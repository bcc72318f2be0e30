#!/usr/bin/env bash
# Builds and runs every test suite and ends with the one line CI reads:
# "N passed, N failed".
set -uo pipefail
cd "$(dirname "$0")/.."
log=$(mktemp)
trap 'rm -f "$log"' EXIT
dune build @install test/main.exe bench/whole/whole.exe 2>&1 | grep -v "^Read " | head -200
if [ "${PIPESTATUS[0]}" -ne 0 ]; then
  echo "build failed"
  echo "0 passed, 1 failed"
  exit 1
fi
export CAMLRAY_EXE="$PWD/_build/install/default/bin/camlray"
export CAMLRAY_SCENES="$PWD/scenes"
( cd _build/default/test && ./main.exe --color=never "$@" ) 2>&1 | tee "$log"
status=${PIPESTATUS[0]}
total=$(grep -Eo '[0-9]+ tests? run' "$log" | tail -1 | grep -Eo '^[0-9]+')
failed=$(grep -Eo '[0-9]+ failures?!' "$log" | tail -1 | grep -Eo '^[0-9]+')
total=${total:-0}
failed=${failed:-0}
if [ "$status" -ne 0 ] && [ "$failed" -eq 0 ]; then failed=1; fi
echo "$((total - failed)) passed, $failed failed"
[ "$status" -eq 0 ] && [ "$failed" -eq 0 ]
