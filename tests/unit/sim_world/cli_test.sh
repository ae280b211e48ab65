#!/bin/sh
# ifar-worldgen, ifar-import and ifar-render end to end: exit codes, files written, errors on bad input.
set -eu
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

ifar-worldgen --kind room_objects --seed 9 --out "$work/room.yaml"
ifar-render "$work/room.yaml" --out "$work/room.png" --resolution 0.1
# 32 m + 2 m margin at 0.1 m per pixel is 340 pixels wide: PNG IHDR width at bytes 16..19.
width=$(od -An -tu1 -j16 -N4 "$work/room.png" | awk '{print $1*16777216 + $2*65536 + $3*256 + $4}')
[ "$width" -eq 340 ] || { echo "room.png is $width pixels wide, expected 340"; exit 1; }

if ifar-worldgen --kind castle --out "$work/x.yaml" 2>"$work/err"; then echo "unknown kind accepted"; exit 1; fi
grep -q "unknown kind 'castle'" "$work/err"

printf 'name: bad\nunits: furlong\nstart: {x: 0, y: 0}\n' > "$work/bad.yaml"
status=0; ifar-render "$work/bad.yaml" 2>"$work/err" || status=$?
[ "$status" -eq 2 ] || { echo "bad world: exit code $status, expected 2"; exit 1; }
grep -q "bad.yaml: key 'units': unknown units 'furlong'" "$work/err"

svg="$IFAR_SHARED_DATA/namosim/minimal_stilman_2005.svg"
if [ -f "$svg" ]; then
  ifar-import "$svg" --out "$work/stilman.yaml"
  ifar-render "$work/stilman.yaml" --out "$work/stilman.png"
  [ -s "$work/stilman.png" ]
else
  echo "skipping SVG import: $svg is absent"
fi
printf '<svg viewBox="0 0 10 10"><path id="robot_0" d="M 1 1 h 1 v 1 z"/><path id="w" type="wall" d="M 0 0 L 5"/></svg>' > "$work/bad.svg"
status=0; ifar-import "$work/bad.svg" 2>"$work/err" || status=$?
[ "$status" -eq 2 ] || { echo "malformed SVG: exit code $status, expected 2"; exit 1; }
grep -q "element <path> 'w' (line 1): path data at character 9: command 'L' expects 2 numbers" "$work/err"
echo "sim_world_cli: all checks passed"
