#!/usr/bin/env bash
# cmake --install into a temporary prefix, then use it as a new user would: the files in their places, a
# project built against it with find_package(ifar) and with pkg-config that decodes a message, and
# `ifar run demo_room --json` from another folder on the installed configuration (and IFAR_CONFIG_DIR
# taking precedence over it).
set -uo pipefail
build=${IFAR_BINARY_DIR:?}
source_dir=${IFAR_SOURCE_DIR:?}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
ok() { echo "ok   $*"; }

cmake --install "$build" --prefix "$prefix" > "$work/install.log" 2>&1 || { cat "$work/install.log"; echo "FAIL cmake --install"; exit 1; }
ok "cmake --install --prefix $prefix ($(grep -c 'Installing:' "$work/install.log") files)"

for file in bin/ifar bin/ifar-run bin/ifar-demo bin/ifar-planner bin/ifar-velodyne-driver \
            include/ifar/ifar/goal_t.hpp include/ifar/lcmtypes/checked_decode.hpp include/ifar/common/config.hpp \
            include/ifar/drivers/velodyne/packet_decoder.hpp lib/libifar_lcmtypes_schema.a lib/libifar_common.a \
            lib/cmake/ifar/ifarConfig.cmake lib/cmake/ifar/ifarConfigVersion.cmake lib/cmake/ifar/ifarTargets.cmake \
            lib/pkgconfig/ifar-lcmtypes.pc lib/pkgconfig/ifar-common.pc share/java/ifar_lcmtypes.jar \
            share/ifar/lcmtypes/goal_t.lcm share/ifar/vehicle.yaml share/ifar/planner.yaml \
            share/ifar/worlds/demo_room.yaml share/ifar/launch/vehicle.yaml share/ifar/launch/sim_demo.yaml \
            share/ifar/onboard/can.yaml; do
  [ -e "$prefix/$file" ] || fail "installed file missing: $file"
done
for file in bin/ifar-bench include/ifar/tests include/ifar/testing include/ifar/bench lib/libifar_test_support.a; do
  [ -e "$prefix/$file" ] && fail "installed what stays in the build: $file"
done
[ "$failures" = 0 ] && ok "files in place, tests and benchmarks left out"

# A consumer project: find_package(ifar), link ifar::lcmtypes, decode a goal_t.
if cmake -S "$source_dir/tests/install/consumer" -B "$work/consumer" -G Ninja -DCMAKE_BUILD_TYPE=Release \
     -DCMAKE_PREFIX_PATH="$prefix" > "$work/consumer.log" 2>&1 &&
   cmake --build "$work/consumer" >> "$work/consumer.log" 2>&1; then
  output=$("$work/consumer/consumer")
  [ "$output" = "decoded 41 bytes: goal 7 at 8.0,26.0" ] && ok "find_package(ifar) consumer: $output" ||
    fail "find_package(ifar) consumer printed '$output'"
  libraries=$(ls "$prefix"/lib/libifar_*.a | wc -l)
  output=$("$work/consumer/every_library")
  [ "$output" = "parsed 2 numbers, linked $((libraries + 1)) libraries" ] && ok "every ifar:: library links: $output" ||
    fail "every_library printed '$output' ($libraries static libraries and ifar::lcmtypes installed)"
else
  cat "$work/consumer.log"; fail "find_package(ifar) consumer did not build"
fi

# The same program through pkg-config.
if flags=$(PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config --cflags --libs ifar-lcmtypes 2>"$work/pc.err") &&
   # shellcheck disable=SC2086
   g++ -std=c++17 -o "$work/pc_consumer" "$source_dir/tests/install/consumer/consumer.cpp" $flags 2>"$work/pc.err"; then
  output=$("$work/pc_consumer")
  [ "$output" = "decoded 41 bytes: goal 7 at 8.0,26.0" ] && ok "pkg-config consumer: $output" ||
    fail "pkg-config consumer printed '$output'"
else
  cat "$work/pc.err"; fail "pkg-config ifar-lcmtypes consumer did not build"
fi

# From another folder, with no user configuration: the install's share/ifar.
mkdir -p "$work/elsewhere" "$work/home"
run_installed() { (cd "$work/elsewhere" && env -u IFAR_CONFIG_DIR -u XDG_CONFIG_HOME HOME="$work/home" "$@"); }
status=0
run_installed "$prefix/bin/ifar" run demo_room --json --log run.lcmlog > "$work/run.out" 2> "$work/run.err" || status=$?
if [ $status != 0 ]; then
  fail "ifar run demo_room --json exited $status: $(tail -3 "$work/run.err")"
elif ! tail -1 "$work/run.out" | grep -q '^{"arrived":true,"reason":"arrived",'; then
  fail "ifar run demo_room --json: last line is not an arrived summary: $(tail -1 "$work/run.out")"
elif ! grep -q "^configuration: vehicle.yaml, planner.yaml, executive.yaml, sim.yaml, can.yaml, velodyne.yaml from $prefix/share/ifar (install)$" "$work/run.err"; then
  fail "ifar run did not say it used the install's configuration: $(head -3 "$work/run.err")"
elif ! grep -q "^world 'demo_room' from $prefix/share/ifar/worlds/demo_room.yaml," "$work/run.err"; then
  fail "ifar run did not take demo_room from the install: $(head -3 "$work/run.err")"
else
  ok "ifar run demo_room --json from $work/elsewhere: $(tail -1 "$work/run.out" | cut -c1-80)..."
fi

# ifar run-summary (what ifar demo prints) writes the same schema from the run's log: the same keys.
status=0
run_installed "$prefix/bin/ifar" run-summary run.lcmlog --goal 8,26 --json > "$work/summary.out" 2>&1 || status=$?
if [ $status != 0 ]; then
  fail "ifar run-summary --json exited $status: $(cat "$work/summary.out")"
elif ! python3 - "$work/run.out" "$work/summary.out" <<'PY'
import json, sys
run = json.loads(open(sys.argv[1]).read().splitlines()[-1])
summary = json.loads(open(sys.argv[2]).read())
for a, b, where in [(run, summary, ""), (run["planner_frame_ms"], summary["planner_frame_ms"], "planner_frame_ms."),
                    (run["interaction_ms"], summary["interaction_ms"], "interaction_ms."),
                    (run["stage_ms"], summary["stage_ms"], "stage_ms.")]:
    if list(a) != list(b):
        sys.exit("keys differ at %s: %s / %s" % (where or "top", list(a), list(b)))
# Every PLANNER_STATUS gives each stage a time, and a stage is a part of its frame.
for source, where in [(run, "ifar run"), (summary, "ifar run-summary")]:
    frames = source["planner_frame_ms"]
    for stage, times in source["stage_ms"].items():
        if times["frames"] != frames["frames"] or times["max"] is None or times["max"] > frames["max"]:
            sys.exit("%s: stage %s %s against the frames %s" % (where, stage, times, frames))
if summary["losses"] != {"valid": False, "problem": "not computed from a log (ifar run computes it)"}:
    sys.exit("losses: %s" % summary["losses"])
if summary["pushes"] != run["pushes"] or abs(summary["distance_m"] - run["distance_m"]) > 0.1:
    sys.exit("pushes or distance differ: %s / %s" % (summary, run))
PY
then
  fail "ifar run-summary --json and ifar run --json differ in their schema"
else
  ok "ifar run-summary --json on the run's log: the schema of ifar run --json"
fi

# IFAR_CONFIG_DIR comes before the install, file by file: a planner.yaml there with a typo stops the run.
mkdir -p "$work/etc"
{ cat "$prefix/share/ifar/planner.yaml"; echo "graph_votes: 3"; } > "$work/etc/planner.yaml"
status=0
message=$(run_installed env IFAR_CONFIG_DIR="$work/etc" "$prefix/bin/ifar" run demo_room 2>&1 >/dev/null) || status=$?
if [ $status = 2 ] && [[ "$message" == *"$work/etc/planner.yaml"*"graph_votes"* ]]; then
  ok "IFAR_CONFIG_DIR's planner.yaml is read first: $message"
else
  fail "IFAR_CONFIG_DIR planner.yaml: exit $status: $message"
fi

if [ "$failures" -ne 0 ]; then
  echo "$failures failures"
  exit 1
fi
echo "PASS"
