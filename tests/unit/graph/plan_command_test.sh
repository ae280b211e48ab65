#!/bin/sh
# ifar-plan end to end: exact lengths from a double corner (--check), a start or goal inside an obstacle
# reported with its own status and exit code (4 / 5) unless --snap, no path (1), bad input (2).
set -u
data="$IFAR_SOURCE_DIR/tests/unit/graph/data"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

# expect NAME CODE NEEDLE COMMAND...: exit code CODE and NEEDLE in stdout + stderr.
expect() {
  description="$1"; wanted="$2"; needle="$3"; shift 3
  output=$("$@" 2>&1)
  code=$?
  if [ "$code" -ne "$wanted" ]; then
    echo "FAIL $description: exit code $code, expected $wanted: $output"; failures=$((failures + 1)); return
  fi
  case "$output" in
    *"$needle"*) echo "ok   $description" ;;
    *) echo "FAIL $description: output lacks '$needle': $output"; failures=$((failures + 1)) ;;
  esac
}

map="$data/double_corner.map"
expect "double corner, every query exact" 0 "8 of 8 lengths match" \
  ifar-plan --map "$map" --scen "$map.scen" --check --tolerance 1e-9
expect "start inside an obstacle" 4 '"status": "start_in_obstacle", "length": null' \
  ifar-plan --map "$map" --start 2.5,1.5 --goal 0,0 --json
expect "start inside an obstacle, not snapped" 4 '"start_snapped": false, "goal_snapped": false' \
  ifar-plan --map "$map" --start 2.5,1.5 --goal 0,0 --json
expect "goal inside an obstacle" 5 '"status": "goal_in_obstacle"' \
  ifar-plan --map "$map" --start 0,0 --goal 1.5,2.5 --json
# Snapped to (2.5, 2), the bottom of cell (2,1) and its nearest side: then straight to (5, 5) through free cells.
expect "start snapped when asked" 0 '"status": "found", "length": 3.905124838' \
  ifar-plan --map "$map" --start 2.5,1.8 --goal 5,5 --json --snap
expect "snapped start flagged" 0 '"start_snapped": true, "goal_snapped": false' \
  ifar-plan --map "$map" --start 2.5,1.8 --goal 5,5 --json --snap
expect "start off the map" 2 '"status": "start_off_map"' \
  ifar-plan --map "$map" --start -1,0 --goal 0,0 --json

# Two blocked cells touching diagonally enclose the corner cells: no path from (0,2) to (2,0).
printf 'type octile\nheight 2\nwidth 2\nmap\n@.\n.@\n' > "$work/enclosed.map"
expect "no path" 1 '"status": "no_path"' \
  ifar-plan --map "$work/enclosed.map" --start 0,2 --goal 2,0 --json

printf 'type octile\nheight 2\nwidth 2\nmap\n@.\n' > "$work/short.map"
expect "bad map file" 2 "short.map:" ifar-plan --map "$work/short.map" --start 0,0 --goal 1,1
expect "no query" 2 "give --scen FILE or both --start X,Y and --goal X,Y" ifar-plan --map "$map"
expect "help names --snap" 0 "--snap" ifar-plan --help

if [ "$failures" -ne 0 ]; then
  echo "$failures failures"
  exit 1
fi
echo "all ifar-plan checks passed"
