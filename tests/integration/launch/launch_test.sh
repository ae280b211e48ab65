#!/usr/bin/env bash
# ifar launch as a real process: prefixed output, respawn with back-off, SIGINT then SIGKILL on stop in
# the reverse of the file's order, a required process that fails ends the launch with exit code 1, a
# readiness summary after start and on change, a process listed `after` the recorder starts once it records
# (its first message is in the log) or after the start wait, a bad launch file exits 2.
set -euo pipefail
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; cat "$work/out" 2>/dev/null || true; exit 1; }

cat > "$work/respawn.yaml" <<'YAML'
stop_timeout_s: 1
processes:
  - name: ticker
    command: [bash, -c, 'for i in $(seq 1 30); do echo tick $i; sleep 0.2; done']
  - name: crasher
    command: [bash, -c, 'echo crashing; exit 3']
    respawn: true
    respawn_delay_s: 0.2
  - name: stubborn
    command: [bash, -c, 'trap "" INT; echo ignoring INT; while true; do sleep 0.1; done']
YAML
# Started with SIGINT ignored, as a shell starts background jobs: the children must still get it.
status=0
(trap '' INT; exec ifar launch "$work/respawn.yaml" --duration 1.5 --no-colour) > "$work/out" 2>&1 || status=$?
[ $status = 0 ] || fail "respawn launch exited $status"
grep -q '^ticker   | tick 1$' "$work/out" || fail "ticker output is not prefixed"
grep -q '^crasher  | crashing$' "$work/out" || fail "crasher output is not prefixed"
[ "$(grep -c 'crasher exited with code 3' "$work/out")" -ge 3 ] || fail "crasher was not restarted"
grep -q 'restarting crasher in 0.40 s' "$work/out" || fail "no back-off on repeated crashes"
grep -q 'ticker killed by signal 2' "$work/out" || fail "ticker did not get SIGINT on stop"
grep -q 'stubborn did not stop within 1.00 s: killing it' "$work/out" || fail "stubborn process not killed"
pgrep -f 'trap "" INT; echo ignoring INT' > /dev/null && fail "stubborn process survived"

# Stopping goes in the reverse of the file's order, each process gone before the next is asked: the first
# (a recorder) still runs when the last has finished its shutdown, which takes it 0.3 s here. The 3 s
# run leaves both time to set their traps on a loaded machine.
cat > "$work/order.yaml" <<YAML
processes:
  - name: recorder
    command: [bash, -c, 'trap "[ -e $work/executive-gone ] && echo after > $work/order || echo before > $work/order; exit 0" INT; while true; do sleep 0.05; done']
  - name: executive
    command: [bash, -c, 'trap "sleep 0.3; touch $work/executive-gone; exit 0" INT; while true; do sleep 0.05; done']
YAML
ifar launch "$work/order.yaml" --duration 3 --no-colour > "$work/out" 2>&1 || fail "order launch failed"
[ "$(cat "$work/order" 2>/dev/null)" = after ] || fail "the first process was stopped before the last had gone"

cat > "$work/required.yaml" <<'YAML'
processes:
  - name: long
    command: [sleep, '30']
  - name: mission
    command: [bash, -c, 'echo failing; exit 4']
    required: true
YAML
status=0
ifar launch "$work/required.yaml" --no-colour > "$work/out" 2>&1 || status=$?
[ $status = 1 ] || fail "a failed required process gave exit code $status, expected 1"
grep -q 'stopping: required process mission exited with code 4' "$work/out" || fail "no reason given"

# The readiness summary: once after readiness_after_s, then only when a line changes. No heartbeat comes
# from these processes: one is starting, the other crash-loops and says why.
cat > "$work/readiness.yaml" <<'YAML'
readiness_after_s: 1
processes:
  - name: quiet
    command: [sleep, '30']
  - name: crasher
    command: [bash, -c, 'echo "cannot open the device"; exit 3']
    respawn: true
    respawn_delay_s: 0.2
YAML
ifar launch "$work/readiness.yaml" --duration 2.5 --no-colour > "$work/out" 2>&1 || fail "readiness launch failed"
grep -q '^launch  *| readiness after 1 s: 0 of 2 ready$' "$work/out" || fail "no readiness summary after 1 s"
grep -q '^launch  *|   quiet    starting$' "$work/out" || fail "readiness does not show quiet starting"
grep -q '^launch  *|   crasher  restarting: exited with code 3: cannot open the device$' "$work/out" ||
  fail "readiness does not say why crasher restarts"
[ "$(grep -c 'readiness after' "$work/out")" = 1 ] || fail "readiness summary repeated without a change"

# `after`: the goal is sent once, at once, when it starts; it is in the log only if lcm-logger was
# already subscribed (it prints its file name before it subscribes). On a port of its own.
export LCM_DEFAULT_URL="udpm://239.255.76.67:$((7700 + RANDOM % 200))?ttl=0"
cat > "$work/after.yaml" <<YAML
processes:
  - name: recorder
    command: [ifar, record, --dir, "$work/logs"]
  - name: goal
    command: [ifar-goal, '1,2', --id, '7', --repeats, '1']
    after: [recorder]
YAML
ifar launch "$work/after.yaml" --duration 3 --no-colour > "$work/out" 2>&1 || fail "after launch failed"
grep -q '^launch  *| goal starts when ready: recorder$' "$work/out" || fail "goal does not say what it waits for"
recording=$(grep -n '^recorder *| ifar record: recording$' "$work/out" | head -1 | cut -d: -f1)
started=$(grep -n '^launch *| started goal' "$work/out" | head -1 | cut -d: -f1)
[ -n "$recording" ] && [ -n "$started" ] && [ "$started" -gt "$recording" ] ||
  fail "goal was not started after the recorder reported recording"
log=$(ls "$work"/logs/ifar-*.lcmlog* | head -1)
ifar log-info "$log" > "$work/info" || fail "log-info on $log"
grep -qE '^GOAL +goal_t +1 ' "$work/info" || { cat "$work/info"; fail "the goal sent at start is not in the log"; }

# A process waited on that never reports ready: the waiting one starts after start_wait_s anyway.
cat > "$work/wait.yaml" <<'YAML'
start_wait_s: 1
processes:
  - name: quiet
    command: [sleep, '30']
  - name: follower
    command: [bash, -c, 'echo started; sleep 30']
    after: [quiet]
YAML
ifar launch "$work/wait.yaml" --duration 2.5 --no-colour > "$work/out" 2>&1 || fail "wait launch failed"
grep -q '^launch  *| starting follower after waiting 1.00 s; not ready: quiet$' "$work/out" ||
  fail "no start after the start wait"
grep -q '^follower *| started$' "$work/out" || fail "the waiting process did not start"
unset LCM_DEFAULT_URL

printf 'processes:\n  - name: x\n    comand: [true]\n' > "$work/bad.yaml"
status=0
ifar launch "$work/bad.yaml" > "$work/out" 2>&1 || status=$?
[ $status = 2 ] || fail "bad launch file gave exit code $status, expected 2"
grep -qF "key 'processes[0].command': missing required key" "$work/out" || fail "bad launch file message"
printf 'processes:\n  - name: x\n    command: [true]\n    after: [y]\n' > "$work/bad.yaml"
status=0
ifar launch "$work/bad.yaml" > "$work/out" 2>&1 || status=$?
[ $status = 2 ] || fail "an unknown after gave exit code $status, expected 2"
grep -qF "'y' is not a process listed before x" "$work/out" || fail "unknown after message"
echo "PASS: ifar launch supervises, respawns, stops, says what is ready and rejects bad files"
