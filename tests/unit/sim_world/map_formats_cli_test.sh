#!/bin/sh
# Every map format through ifar-import, ifar-render and ifar-run: a namosim SVG, a MovingAI .map and a
# map_server .yaml (told from a world file by its keys); import's exit codes (0 complete, 1 incomplete, 2 bad
# input); --robot; errors of one short line, never a copy of the file.
set -u
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
config="$IFAR_SOURCE_DIR/config"
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
ok() { echo "ok   $*"; }

# A 6 m x 6 m room at namosim's centimetre: walls, a box, two robots with a goal each (robot_N_goal_M).
cat > "$work/room.svg" <<'SVG'
<svg viewBox="0 0 600 600">
<path id="south" type="wall" d="M 0 580 H 600 V 600 H 0 Z"/>
<path id="north" type="wall" d="M 0 0 H 600 V 20 H 0 Z"/>
<path id="west" type="wall" d="M 0 20 H 20 V 580 H 0 Z"/>
<path id="east" type="wall" d="M 580 20 H 600 V 580 H 580 Z"/>
<rect id="box" type="movable" x="280" y="280" width="40" height="40"/>
<circle id="robot_0" cx="100" cy="500" r="20"/>
<circle id="robot_1" cx="500" cy="500" r="20"/>
<path id="robot_0_goal_0" d="M 90 90 h 20 v 20 h -20 z"/>
<path id="robot_1_goal_0" d="M 490 90 h 20 v 20 h -20 z"/>
</svg>
SVG

# Complete: exit 0, the other robot named in a warning.
status=0; ifar-import "$work/room.svg" --scale 0.01 --out "$work/room.yaml" 2>"$work/err" || status=$?
if [ "$status" -eq 0 ] && grep -q "warning: robot 'robot_1' (1 goal: robot_1_goal_0) not simulated" "$work/err" &&
   grep -q '{name: "robot_0_goal_0", x: 1, y: 5}' "$work/room.yaml"; then
  ok "complete SVG: exit 0, robot_1 named"
else
  fail "complete SVG: exit $status: $(cat "$work/err")"
fi
# --robot by index: robot_1's start and goal.
ifar-import "$work/room.svg" --scale 0.01 --robot 1 --out "$work/room1.yaml" 2>/dev/null
start_ok=$(awk -F'[{}:,]+' '/^start:/ { dx = $4 - 5; dy = $6 - 1; print (dx * dx + dy * dy < 1e-18) ? "yes" : "no" }' "$work/room1.yaml")
if [ "$start_ok" = yes ] && grep -q '"robot_1_goal_0", x: 5, y: 5' "$work/room1.yaml"; then
  ok "--robot 1 picks robot_1"
else
  fail "--robot 1: $(cat "$work/room1.yaml")"
fi
status=0; ifar-import "$work/room.svg" --robot robot_9 2>"$work/err" >/dev/null || status=$?
[ "$status" -eq 2 ] && grep -q "no robot 'robot_9' (by id or index) in the file; its robots: robot_0, robot_1" "$work/err" &&
  ok "unknown --robot: exit 2" || fail "unknown --robot: exit $status: $(cat "$work/err")"

# No walls: written, exit 1, the warning says why.
grep -v 'type="wall"' "$work/room.svg" > "$work/nowalls.svg"
status=0; ifar-import "$work/nowalls.svg" --out "$work/nowalls.yaml" 2>"$work/err" || status=$?
if [ "$status" -eq 1 ] && [ -s "$work/nowalls.yaml" ] && grep -q 'warning: no walls: no drawing element has type="wall"' "$work/err"; then
  ok "no walls: exit 1, world written"
else
  fail "no walls: exit $status: $(cat "$work/err")"
fi

# ifar-render takes the SVG itself, with the importer's options.
status=0; ifar-render "$work/room.svg" --scale 0.01 --resolution 0.1 --out "$work/room.png" 2>"$work/err" || status=$?
width=$(od -An -tu1 -j16 -N4 "$work/room.png" 2>/dev/null | awk '{print $1*16777216 + $2*65536 + $3*256 + $4}')
# 6 m, the 0.2 m edge walls either side and 2 m margin at 0.1 m per pixel.
[ "$status" -eq 0 ] && [ "${width:-0}" -eq 84 ] && ok "render SVG: 84 pixels wide" ||
  fail "render SVG: exit $status, width ${width:-none}: $(cat "$work/err")"

# A MovingAI map and a map_server map (a .yaml told from a world file by its image and resolution keys).
printf 'type octile\nheight 4\nwidth 6\nmap\n......\n.@@...\n......\n......\n' > "$work/tiny.map"
printf 'P2\n6 4\n255\n255 255 255 255 255 255\n255 0 0 255 255 255\n255 255 255 255 255 255\n255 255 255 255 255 255\n' > "$work/tiny.pgm"
printf 'image: tiny.pgm\nresolution: 0.5\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n' > "$work/tiny.yaml"
for map in tiny.map tiny.yaml; do
  status=0; ifar-render "$work/$map" --out "$work/$map.png" 2>"$work/err" || status=$?
  [ "$status" -eq 0 ] && [ -s "$work/$map.png" ] && ok "render $map" || fail "render $map: exit $status: $(cat "$work/err")"
done

# ifar-run drives an SVG, a .map and a map_server .yaml (a short run: exit 0 or 1, never bad input).
for input in "room.svg --scale 0.01" "tiny.map --start 0.5,0.5 --goal 5.5,3.5" "tiny.yaml --goal 2.75,1.75"; do
  set -- $input
  file=$1; shift
  status=0; ifar-run "$work/$file" "$@" --max-time 1 --config-dir "$config" >/dev/null 2>"$work/err" || status=$?
  if [ "$status" -le 1 ] && grep -q "from $work/$file" "$work/err"; then
    ok "run $file: exit $status"
  else
    fail "run $file: exit $status: $(head -c 400 "$work/err")"
  fi
done

# Errors are one short line: a broken SVG, and an SVG (or any large non-YAML file) read as a world file.
expect_short_error() {
  description="$1"; needle="$2"; shift 2
  status=0; "$@" >/dev/null 2>"$work/err" || status=$?
  lines=$(grep -c . "$work/err")
  size=$(wc -c < "$work/err")
  if [ "$status" -eq 2 ] && [ "$lines" -eq 1 ] && [ "$size" -le 400 ] && grep -q -- "$needle" "$work/err"; then
    ok "$description: $(cat "$work/err")"
  else
    fail "$description: exit $status, $lines lines, $size bytes: $(head -c 400 "$work/err")"
  fi
}
sed 's/d="M 90 90 h 20 v 20 h -20 z"/d="M 90 90 h 20 v"/' "$work/room.svg" > "$work/broken.svg"
expect_short_error "run broken SVG" "element <path> 'robot_0_goal_0' (line 9): path data at character 14: command 'v' expects 1 numbers" \
  ifar-run "$work/broken.svg" --config-dir "$config"
awk 'BEGIN { for (i = 0; i < 4000; ++i) printf "<path d=\"M 0 0 L 10 10\" id=\"p%d\"/> ", i; print "" }' > "$work/big.txt"
expect_short_error "run non-YAML file" "the top level must be a map of settings, found '<path" \
  ifar-run "$work/big.txt" --config-dir "$config"
expect_short_error "render non-YAML file" "the top level must be a map of settings" ifar-render "$work/big.txt"

if [ "$failures" -ne 0 ]; then
  echo "sim_world_map_formats_cli: $failures failures"
  exit 1
fi
echo "sim_world_map_formats_cli: all checks passed"
