#!/bin/sh
# ifar-run's exit codes: 2 and one error line naming the input and the problem on bad input (3 for a picture
# that cannot be written); 0 with the JSON summary as the last line when the vehicle arrives (a small
# builtin room), 1 when it does not.
set -u
config="$IFAR_SOURCE_DIR/config"
room="$IFAR_SOURCE_DIR/config/worlds/room.yaml"
failures=0

# expect_exit CODE DESCRIPTION NEEDLE COMMAND...: exit code CODE and one error line holding NEEDLE.
expect_exit() {
  wanted="$1"; description="$2"; needle="$3"; shift 3
  output=$("$@" 2>&1 >/dev/null)
  code=$?
  if [ "$code" -ne "$wanted" ]; then
    echo "FAIL $description: exit code $code, expected $wanted ($output)"; failures=$((failures + 1)); return
  fi
  case "$output" in
    *"$needle"*) echo "ok   $description: $output" ;;
    *) echo "FAIL $description: message lacks '$needle': $output"; failures=$((failures + 1)) ;;
  esac
}

expect_exit 2 "missing world file" "/nonexistent/world.yaml" \
  ifar-run /nonexistent/world.yaml --config-dir "$config"
expect_exit 2 "NaN goal" "--goal: expected X,Y (numbers separated by commas), got 'nan,5'" \
  ifar-run "$room" --goal nan,5 --config-dir "$config"
expect_exit 2 "malformed goal" "--goal: expected X,Y (numbers separated by commas), got '3'" \
  ifar-run "$room" --goal 3 --config-dir "$config"
expect_exit 2 "a goal and all goals" "give --goal or --all-goals, not both" \
  ifar-run "$room" --goal 3,4 --all-goals --config-dir "$config"
expect_exit 2 "missing config directory" "--config-dir '/nonexistent/config': no such folder" \
  ifar-run "$room" --config-dir /nonexistent/config
expect_exit 2 "non-positive max time" "--max-time" \
  ifar-run "$room" --max-time 0 --config-dir "$config"
expect_exit 2 "graph time without a picture" "--graph-at and --graph-window need --graph-png" \
  ifar-run "$room" --graph-at 2 --config-dir "$config"
expect_exit 2 "negative graph time" "--graph-at: must be a number of seconds >= 0" \
  ifar-run "$room" --graph-png /tmp/unused.png --graph-at -1 --config-dir "$config"
expect_exit 2 "malformed graph window" "--graph-window: expected X0,Y0,X1,Y1" \
  ifar-run "$room" --graph-png /tmp/unused.png --graph-window 1,2,3 --config-dir "$config"
expect_exit 3 "picture into a missing folder" "--png: cannot write '/nonexistent/run.png': folder '/nonexistent' does not exist" \
  ifar-run "$room" --png /nonexistent/run.png --config-dir "$config"
expect_exit 3 "graph picture into a missing folder" "--graph-png: cannot write '/nonexistent/graph.png'" \
  ifar-run "$room" --graph-png /nonexistent/graph.png --config-dir "$config"

# --help works and names the command's options.
if ! ifar-run --help | grep -q -- "--no-interaction"; then
  echo "FAIL --help does not list --no-interaction"; failures=$((failures + 1))
fi
# A short run that arrives: exit 0, the last stdout line is the JSON summary, the picture is written.
picture="${IFAR_BINARY_DIR:-/tmp}/runner_cli_test.png"
rm -f "$picture"
graph_picture="${IFAR_BINARY_DIR:-/tmp}/runner_cli_graph_test.png"
rm -f "$graph_picture"
output=$(ifar-run push_light --goal 8,6 --json --png "$picture" --graph-png "$graph_picture" --graph-at 2 \
  --graph-window 0,0,12,12 --config-dir "$config" 2>/dev/null)
code=$?
last=$(printf '%s\n' "$output" | tail -n 1)
case "$code:$last" in
  '0:{"arrived":true,"reason":"arrived",'*) echo "ok   arrives: $last" ;;
  *) echo "FAIL arrives: exit code $code, last line: $last"; failures=$((failures + 1)) ;;
esac
if [ ! -s "$picture" ]; then
  echo "FAIL --png wrote no picture at $picture"; failures=$((failures + 1))
fi
if [ ! -s "$graph_picture" ]; then
  echo "FAIL --graph-png wrote no picture at $graph_picture"; failures=$((failures + 1))
fi
rm -f "$picture" "$graph_picture"

# The same goal with one simulated second: not arrived, exit 1.
output=$(ifar-run push_light --goal 8,6 --json --max-time 1 --config-dir "$config" 2>/dev/null)
code=$?
last=$(printf '%s\n' "$output" | tail -n 1)
case "$code:$last" in
  '1:{"arrived":false,"reason":"timeout after 1 s'*) echo "ok   times out: $last" ;;
  *) echo "FAIL times out: exit code $code, last line: $last"; failures=$((failures + 1)) ;;
esac
exit "$failures"
