#!/usr/bin/env bash
# make messages-coverage: how many of the parser's error states have a
# hand-written message in parser/parser.messages (never fails the build:
# other grammar work keeps adding states).
set -uo pipefail
cd "$(dirname "$0")/../parser"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
grammars="grammar_lang.mly grammar_scene.mly grammar_objects.mly grammar_texture.mly"
menhir --table --unused-tokens --base "$tmp/parser" $grammars --list-errors > "$tmp/all.messages" 2>/dev/null
total=$(grep -c '^## Ends in an error in state' "$tmp/all.messages")
menhir --table --unused-tokens --base "$tmp/parser" $grammars \
  --compare-errors "$tmp/all.messages" --compare-errors parser.messages > "$tmp/cmp" 2>&1
missing=$(grep -c 'No sentence that leads to this state exists' "$tmp/cmp")
stale=$(menhir --table --unused-tokens --base "$tmp/parser" $grammars \
  --compile-errors parser.messages 2>&1 >/dev/null | grep -c 'Error')
covered=$((total - missing))
printf 'messages-coverage: %d of %d error states have a hand-written message (%d%%)\n' \
  "$covered" "$total" $((100 * covered / (total > 0 ? total : 1)))
[ "$stale" -gt 0 ] && echo "warning: parser.messages has $stale entries that no longer compile"
exit 0
