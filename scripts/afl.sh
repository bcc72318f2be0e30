#!/usr/bin/env bash
# make afl: AFL++ on an instrumented build of the scene parser. Installs
# afl++ (Debian) when missing, builds test/afl/afl_parse.exe under the afl
# profile in _build_afl, seeds a corpus from the repository's small scenes,
# runs afl-fuzz for AFL_SECONDS (default 600) and reports from its
# fuzzer_stats; exits 1 when a crash or a hang was found.
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_TO_RUN=${AFL_SECONDS:-600}
if ! command -v afl-fuzz >/dev/null; then
  if [ "$(id -u)" -eq 0 ]; then DEBIAN_FRONTEND=noninteractive apt-get install -y afl++ >/dev/null
  else echo "afl: needs afl++ (apt-get install afl++)" >&2; exit 1; fi
fi
dune build --build-dir _build_afl --profile afl test/afl/afl_parse.exe 2>&1 | grep -v '^Read ' || true
exe=_build_afl/default/test/afl/afl_parse.exe
[ -x "$exe" ] || { echo "afl: the harness did not build" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/in"
find scenes test/golden test/errors -type f \( -name '*.scn' -o -name '*.pov' -o -name '*.inc' \) -size -4k \
  | head -200 | while read -r f; do cp "$f" "$work/in/$(echo "$f" | tr / _)"; done
"$exe" --dict > "$work/dict"
export AFL_SKIP_CPUFREQ=1 AFL_I_DONT_CARE_ABOUT_MISSING_CRASHES=1 AFL_NO_UI=1 AFL_NO_AFFINITY=1
echo "afl: $(ls "$work/in" | wc -l) seeds, $SECONDS_TO_RUN s"
afl-fuzz -i "$work/in" -o "$work/out" -x "$work/dict" -t 1000 -V "$SECONDS_TO_RUN" -- "$exe" @@ \
  > "$work/afl.log" 2>&1 || { tail -20 "$work/afl.log" >&2; exit 1; }
stats=$work/out/default/fuzzer_stats
get() { sed -n "s/^$1 *: *//p" "$stats"; }
echo "afl: $(get run_time) s, $(get execs_done) inputs ($(get execs_per_sec) per s), corpus $(get corpus_count), crashes $(get saved_crashes), hangs $(get saved_hangs)"
if [ "$(get saved_crashes)" != 0 ] || [ "$(get saved_hangs)" != 0 ]; then
  mkdir -p fuzz-out/afl
  find "$work/out/default/crashes" "$work/out/default/hangs" -type f ! -name README.txt \
    -exec cp {} fuzz-out/afl/ \;
  echo "afl: the inputs are in fuzz-out/afl/" >&2
  exit 1
fi
