#!/usr/bin/env bash
# A daemon given a config file with an unknown key, or with a value of the wrong type, or with a YAML
# syntax error, must stop at start-up with exit code 2 and a message naming the file and the key.
#   bad_config_test.sh DAEMON GOOD_CONFIG
# GOOD_CONFIG is the daemon's checked-in config; the bad ones are derived from it.
set -euo pipefail
daemon=$1
good=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[ -f "$good" ] || { echo "FAIL: $good missing"; exit 1; }
# Config files may name siblings (vehicle.yaml beside them): the bad copies get the same neighbours.
cp "$(dirname "$good")"/*.yaml "$work/"
failures=0

expect_rejection() {  # CONFIG KEY_TEXT WHAT
  local config=$1 key_text=$2 what=$3 status=0
  "$daemon" --config "$config" --log-dir "" > "$work/out" 2>&1 < /dev/null &
  local pid=$!
  # A daemon that accepted the file would run on: give it a few seconds, then stop it.
  for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
  if kill -0 "$pid" 2>/dev/null; then
    kill -INT "$pid"; wait "$pid" || true
    echo "FAIL ($what): $daemon accepted $config and kept running"; failures=$((failures + 1)); return
  fi
  wait "$pid" || status=$?
  if [ "$status" != 2 ]; then
    echo "FAIL ($what): exit code $status, expected 2"; cat "$work/out"; failures=$((failures + 1)); return
  fi
  if ! grep -qF -- "$config" "$work/out" || ! grep -qF -- "$key_text" "$work/out"; then
    echo "FAIL ($what): message does not name '$config' and '$key_text':"; cat "$work/out"
    failures=$((failures + 1)); return
  fi
  echo "ok ($what): $(head -1 "$work/out")"
}

# 1. An unknown top-level key.
cp "$good" "$work/unknown_key.yaml"
printf '\nlog_levle: debug\n' >> "$work/unknown_key.yaml"
expect_rejection "$work/unknown_key.yaml" "key 'log_levle': unknown key" "unknown key"

# 2. A wrong type: the first top-level scalar setting (other than log_level/lcm_url) becomes a list.
# (|| true: no match is an answer here, not a failure of the pipeline)
key=$( (grep -E '^[a-z_]+: *[^ #{[]' "$good" || true) | (grep -v -E '^(log_level|lcm_url):' || true) | head -1 | cut -d: -f1)
if [ -n "$key" ]; then
  sed -E "s/^$key:.*/$key: [1, 2]/" "$good" > "$work/wrong_type.yaml"
  expect_rejection "$work/wrong_type.yaml" "key '$key': expected" "wrong type of $key"
else
  nested=$( (grep -E '^  [a-z_]+: *[^ #{[]' "$good" || true) | head -1 | sed -E 's/^  ([a-z_]+):.*/\1/')
  section=$(awk -v k="  $nested:" 'index($0, k) == 1 { print prev; exit } /^[a-z_]+:/ { prev = $0 }' "$good" | cut -d: -f1)
  sed -E "0,/^  $nested:.*/s//  $nested: [1, 2]/" "$good" > "$work/wrong_type.yaml"
  expect_rejection "$work/wrong_type.yaml" "key '$section.$nested': expected" "wrong type of $section.$nested"
fi

# 3. An unknown key in each section (a top-level key whose value is an indented map). A file two daemons
# share (can.yaml) is checked whole by both.
for section in $(grep -E '^[a-z_]+: *(#.*)?$' "$good" | cut -d: -f1); do
  awk -v s="$section" '{ print } index($0, s ":") == 1 { print "  not_a_setting: 1" }' "$good" \
    > "$work/unknown_in_$section.yaml"
  expect_rejection "$work/unknown_in_$section.yaml" "key '$section.not_a_setting': unknown key" \
    "unknown key in $section"
done

# 4. A file the config names that cannot be loaded (the planner's prior graph).
if grep -qE '^  prior_graph:' "$good"; then
  # (the vehicle file, named relative to the repository, from the copies beside the config)
  sed -E -e 's|^  prior_graph:.*|  prior_graph: /nonexistent/prior.graph|' \
    -e "s|^vehicle_config:.*|vehicle_config: $work/vehicle.yaml|" "$good" > "$work/missing_prior.yaml"
  expect_rejection "$work/missing_prior.yaml" "key 'daemon.prior_graph': cannot load the prior graph" \
    "missing prior graph"
fi

# 5. Not YAML at all.
printf 'a: [1, 2\n' > "$work/syntax.yaml"
expect_rejection "$work/syntax.yaml" "YAML syntax error" "syntax error"

[ $failures = 0 ] || { echo "FAIL: $failures bad-config cases not rejected properly by $daemon"; exit 1; }
echo "PASS: $daemon rejects bad config files with file and key"
