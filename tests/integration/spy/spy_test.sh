#!/usr/bin/env bash
# `ifar spy` under a virtual X server finds every project LCM type in the types jar (lcm-spy prints
# "Found N LCM types" once it has scanned its class path).
set -euo pipefail
type_list=$1
expected=$(grep -c . "$type_list")
out=$(mktemp)
trap 'rm -f "$out"' EXIT
command -v xvfb-run > /dev/null || { echo "FAIL: xvfb-run missing (install xvfb; scripts/setup does)"; exit 1; }
# timeout inside xvfb-run ends lcm-spy itself (ifar execs into java) after the check.
setsid xvfb-run -a timeout 40 ifar spy > "$out" 2>&1 &
runner=$!
found=""
for _ in $(seq 300); do
  found=$(sed -n 's/^Found \([0-9]*\) LCM types$/\1/p' "$out" | head -1)
  [ -n "$found" ] && break
  sleep 0.1
done
# Stop lcm-spy through its timeout so xvfb-run ends on its own and removes its /tmp/xvfb-run.* folder;
# the whole process group (our own only) goes if it has not within 10 s.
pkill -TERM -s "$runner" -x timeout 2>/dev/null || true
for _ in $(seq 100); do
  kill -0 "$runner" 2>/dev/null || break
  sleep 0.1
done
kill -- -"$runner" 2>/dev/null || true
wait "$runner" 2>/dev/null || true
cat "$out"
[ -n "$found" ] || { echo "FAIL: lcm-spy did not report its types"; exit 1; }
[ "$found" = "$expected" ] || { echo "FAIL: lcm-spy found $found types, the project has $expected"; exit 1; }
echo "PASS: lcm-spy found all $found project types"
