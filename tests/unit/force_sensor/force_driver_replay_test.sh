#!/bin/sh
# ifar-force-driver replays a candump log (30 frames at 100 Hz, a 2-byte frame, a motor frame, a
# 190 ms gap, one more frame) over in-process LCM: it must report the bad frame and the silent
# sensor, recover, and exit cleanly at the end of the log.
set -eu
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/can.yaml" <<CONFIG
bus:
  kind: candump
  candump_input: $IFAR_SOURCE_DIR/tests/unit/force_sensor/data/force_replay.log
force_sensor:
  frame_id: 400
CONFIG
status=0
timeout 20 ifar-force-driver --config "$work/can.yaml" --lcm-url memq:// --log-dir "" > "$work/out.txt" 2>&1 || status=$?
cat "$work/out.txt"
[ "$status" -eq 0 ] || { echo "FAIL: exit status $status"; exit 1; }
for expected in "bad force sensor frame (dlc 2)" "force sensor silent" "status 4 -> 0" "end of log"; do
  grep -qF "$expected" "$work/out.txt" || { echo "FAIL: missing '$expected'"; exit 1; }
done
# A config error names the key.
printf 'bus:\n  kind: serial\nforce_sensor:\n  frame_id: 400\n' > "$work/bad.yaml"
status=0
ifar-force-driver --config "$work/bad.yaml" --lcm-url memq:// --log-dir "" > "$work/bad.txt" 2>&1 || status=$?
cat "$work/bad.txt"
[ "$status" -eq 2 ] || { echo "FAIL: bad config exit status $status, expected 2"; exit 1; }
grep -q "kind" "$work/bad.txt" || { echo "FAIL: bad config message does not name the key"; exit 1; }
echo PASS
