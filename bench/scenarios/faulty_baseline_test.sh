#!/usr/bin/env bash
# A baseline that crashes or hangs is a recorded failure with its reason, and the suite goes on: RRT* is
# made to run to a 30 s cap, then (1) its child process is sent SIGSEGV from outside, (2) it is left to
# meet a 1 s --query-deadline. Each time its row says why, FAR mode's and ours' rows of the same task
# are there and solved, and ifar bench exits 2 (a planner errored) or 0 (a timeout is not an error).
#   faulty_baseline_test.sh IFAR_BENCH CONFIG_DIR
set -euo pipefail
bench=$1
config=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run_suite() {  # OUT_NAME EXTRA_ARGS...
  local name=$1
  shift
  "$bench" --config "$config" --kinds room --tasks 1 --planners rrt_star,far,ours --no-system --no-plots \
    --time-cap 30 --factor 1.0 --out "$work/$name.jsonl" --tables "$work/$name.md" "$@" > "$work/$name.out" 2>&1
}
expect_row() {  # FILE PLANNER TEXT
  grep "\"planner\": \"$2\"" "$1" | grep -qF "$3" ||
    { echo "FAIL: no $2 row with '$3' in $1:"; cat "$1"; exit 1; }
}

# (1) A crash: SIGSEGV to the child process working on RRT*.
status=0
run_suite crash &
suite=$!
child=""
for _ in $(seq 1 200); do
  # $suite is the background subshell; ifar bench is its child, the query process ifar bench's child.
  for parent in $(pgrep -P "$suite" || true); do
    child=$(pgrep -P "$parent" | head -1 || true)
    [ -z "$child" ] || break
  done
  [ -z "$child" ] || break
  sleep 0.05
done
[ -n "$child" ] || { echo "FAIL: no query process of ifar bench seen within 10 s"; exit 1; }
sleep 0.5  # RRT* (the first query) runs for 30 s
kill -SEGV "$child"
wait "$suite" || status=$?
[ "$status" = 2 ] || { echo "FAIL: exit code $status after a crashed baseline (expected 2)"; cat "$work/crash.out"; exit 1; }
expect_row "$work/crash.jsonl" rrt_star '"status": "error", "reason": "crashed: signal 11 ('
expect_row "$work/crash.jsonl" far '"status": "solved"'
expect_row "$work/crash.jsonl" ours '"status": "solved"'

# (2) A hang: RRT* still working at the deadline is killed and recorded as a timeout.
status=0
run_suite hang --query-deadline 1 || status=$?
[ "$status" = 0 ] || { echo "FAIL: exit code $status after a timed-out baseline (expected 0)"; cat "$work/hang.out"; exit 1; }
expect_row "$work/hang.jsonl" rrt_star '"status": "timeout", "reason": "killed after 1.0 s of wall time without an answer"'
expect_row "$work/hang.jsonl" far '"status": "solved"'
expect_row "$work/hang.jsonl" ours '"status": "solved"'
echo "PASS: crash and hang of RRT* recorded; FAR mode and ours solved after them"
