#!/usr/bin/env bash
# ifar bench reads the interaction settings of the planned rows from --config's planner.yaml: a bad value
# there stops the suite before any work, naming the file and the key.
#   bad_planner_config_test.sh IFAR_BENCH CONFIG_DIR
set -euo pipefail
bench=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$2"/*.yaml "$work/"
sed -i -E 's/^(  search_radius_m:) *[0-9.]+/\1 -4.0/' "$work/planner.yaml"
grep -q '^  search_radius_m: -4.0' "$work/planner.yaml" || { echo "FAIL: could not break planner.yaml"; exit 1; }
status=0
"$bench" --config "$work" --kinds room --tasks 1 --no-system --no-plots --out "$work/rows.jsonl" \
  --tables "$work/tables.md" > "$work/out" 2>&1 || status=$?
if [ "$status" != 1 ] || ! grep -qF "$work/planner.yaml" "$work/out" ||
   ! grep -qF "key 'interaction.search_radius_m'" "$work/out"; then
  echo "FAIL: exit code $status (expected 1) or the message does not name the file and key:"; cat "$work/out"
  exit 1
fi
[ ! -e "$work/rows.jsonl" ] || { echo "FAIL: rows written despite the bad config"; exit 1; }
echo "PASS: $(head -1 "$work/out")"
