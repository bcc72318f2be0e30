#!/usr/bin/env bash
# make conformance-parse: run `camlray check` over every POV-Ray example
# scene (.pov, or .pov.gz decompressed to a temporary folder; a scene with
# an INI file of the same name read as its first frame), two at a
# time, in a scratch copy of the examples, classify the outcome (accepted / unsupported feature / error) and
# write the table to docs/conformance-parse.md.
set -uo pipefail
cd "$(dirname "$0")/.."
EXAMPLES=${EXAMPLES:-/usr/share/doc/povray/examples}
EXE=${CAMLRAY_EXE:-$PWD/_build/install/default/bin/camlray}
OUT=${OUT:-docs/conformance-parse.md}
JOBS=${JOBS:-2}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Scenes run in a scratch copy of the examples: some #write files into
# their own folder, and nothing may be written next to the originals.
cp -r "$EXAMPLES" "$tmp/ex"
SRC=$EXAMPLES
EXAMPLES=$tmp/ex
# the scene list; gzip-compressed scenes (and their folder's compressed
# include files) are decompressed in the copy
: > "$tmp/list"
while IFS= read -r f; do
  case "$f" in
    *.pov.gz)
      d=$(dirname "$f")
      for g in "$d"/*.inc.gz; do [ -e "$g" ] && gzip -dc "$g" > "${g%.gz}"; done
      gzip -dc "$f" > "${f%.gz}"
      echo "${f%.gz}" >> "$tmp/list" ;;
    *) echo "$f" >> "$tmp/list" ;;
  esac
done < <(find "$EXAMPLES" -type f \( -name '*.pov' -o -name '*.pov.gz' \) | sort)

# one scene -> "name<TAB>class<TAB>detail"
check_one() {
  f=$1
  name=${f#"$EXAMPLES"/}
  # a scene made to run from its INI file (same name) as an animation is
  # read as POV-Ray reads its first frame
  extra=()
  ini=${f%.pov}.ini
  if [ -f "$ini" ]; then
    fr=$(sed -n 's/^[[:space:]]*Initial_Frame[[:space:]]*=[[:space:]]*\([0-9]*\).*/\1/Ip' "$ini" | head -1)
    ck=$(sed -n 's/^[[:space:]]*Initial_Clock[[:space:]]*=[[:space:]]*\([-0-9.]*\).*/\1/Ip' "$ini" | head -1)
    [ -n "$fr" ] && extra+=(--frame "$fr")
    [ -n "$ck" ] && extra+=(--clock "$ck")
  fi
  err=$(cd "$(dirname "$f")" && timeout 60 "$EXE" check "$(basename "$f")" "${extra[@]}" 2>&1 >/dev/null)
  rc=$?
  first=$(printf '%s\n' "$err" | grep -m1 ': error: ' | sed 's/^.*: error: //')
  if [ $rc -eq 0 ]; then printf '%s\taccepted\t\n' "$name"
  elif [ $rc -eq 124 ]; then printf '%s\terror\ttimeout (60 s)\n' "$name"
  elif [[ $first =~ ^(.*)\ is\ not\ supported\ by\ camlray ]]; then
    printf '%s\tunsupported\t%s\n' "$name" "${BASH_REMATCH[1]}"
  elif [[ $first =~ uses\ ([^ ,]*),\ which\ camlray\ does\ not\ support ]]; then
    printf '%s\tunsupported\t%s\n' "$name" "${BASH_REMATCH[1]}"
  else
    [ -z "$first" ] && first="exit code $rc: $(printf '%s' "$err" | head -1)"
    printf '%s\terror\t%s\n' "$name" "$first"
  fi
}
export -f check_one
export EXAMPLES EXE
xargs -a "$tmp/list" -d '\n' -P "$JOBS" -I{} bash -c 'check_one "$1"' _ {} | sort > "$tmp/results"

total=$(wc -l < "$tmp/results")
acc=$(awk -F'\t' '$2=="accepted"' "$tmp/results" | wc -l)
uns=$(awk -F'\t' '$2=="unsupported"' "$tmp/results" | wc -l)
errs=$(awk -F'\t' '$2=="error"' "$tmp/results" | wc -l)
{
  echo "# Parse conformance over POV-Ray's example scenes"
  echo
  echo "\`make conformance-parse\` runs \`camlray check\` (parse and compile, no render) on every"
  echo "example scene in $SRC (run in a scratch copy, so that scenes that #write"
  echo "leave nothing behind). Generated $(date -u +%Y-%m-%d)."
  echo
  echo "| outcome | scenes |"
  echo "|---|---|"
  echo "| accepted | $acc |"
  echo "| unsupported feature (named) | $uns |"
  echo "| error | $errs |"
  echo "| **total** | **$total** |"
  echo
  echo "## Unsupported features, by number of scenes stopped"
  echo
  echo "| feature | scenes |"
  echo "|---|---|"
  awk -F'\t' '$2=="unsupported"{print $3}' "$tmp/results" | sort | uniq -c | sort -rn \
    | awk '{printf "| %s | %d |\n", $2, $1}'
  echo
  echo "## Errors"
  echo
  echo "| message (numbers and names folded) | scenes |"
  echo "|---|---|"
  awk -F'\t' '$2=="error"{print $3}' "$tmp/results" | sed -E 's/[0-9.]+/N/g; s/identifier [A-Za-z_0-9]+/identifier X/; s/\|/\\|/g' \
    | sort | uniq -c | sort -rn | awk '{c=$1; $1=""; printf "| %s | %d |\n", substr($0,2), c}'
  echo
  echo "## Every scene"
  echo
  echo "| scene | outcome | detail |"
  echo "|---|---|---|"
  awk -F'\t' '{d=$3; gsub(/\|/,"\\|",d); printf "| %s | %s | %s |\n", $1, $2, d}' "$tmp/results"
} > "$OUT"
printf 'conformance-parse: %d scenes: %d accepted, %d unsupported feature (named), %d error\n' \
  "$total" "$acc" "$uns" "$errs"
echo "top unsupported features:"
awk -F'\t' '$2=="unsupported"{print $3}' "$tmp/results" | sort | uniq -c | sort -rn | head -15
echo "errors:"
awk -F'\t' '$2=="error"{print $3}' "$tmp/results" | sed -E 's/[0-9.]+/N/g' | sort | uniq -c | sort -rn | head -15
echo "table written to $OUT"
