#!/usr/bin/env python3
"""ifar replay-test as a regression test: `ifar run --log` records a short demo room run (the vehicle drives to
the light box and starts pushing it), then the planner and the executive replayed from that log give what it
recorded (exit 0); a planner setting changed by --set, or in a copy of the config directory, gives exit 1 and
names the first difference; a corrupt log gives exit 2 with the byte offset.
    replay_test_command_test.py       (PATH with build/bin first; IFAR_SOURCE_DIR set by ctest)"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

SOURCE = os.environ.get("IFAR_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
failures = []


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what, flush=True)
    if not condition:
        failures.append(what)


def replay_test(*arguments):
    result = subprocess.run(["ifar", "replay-test", *arguments], cwd=SOURCE, capture_output=True, text=True,
                            timeout=120)
    print(result.stdout + result.stderr, flush=True)
    return result


def main():
    work = tempfile.mkdtemp(prefix="ifar_replay_test_")
    try:
        log = os.path.join(work, "run.lcmlog")
        # 25 simulated seconds: following, the approach and the start of the push (exit 1: not arrived yet).
        run = subprocess.run(["ifar", "run", "config/worlds/demo_room.yaml", "--goal", "8,26", "--max-time", "25",
                              "--log", log], cwd=SOURCE, capture_output=True, text=True, timeout=120)
        check(run.returncode == 1 and os.path.getsize(log) > 1_000_000, f"ifar run --log wrote {log}")

        same = replay_test(log, "--node", "planner")
        check(same.returncode == 0, "planner: unchanged settings give exit 0")
        check(re.search(r"GLOBAL_PATH +(\d+) recorded +\1 replayed  same", same.stdout) is not None,
              "planner: every GLOBAL_PATH the same, as many as recorded")
        check(re.search(r"PLANNER_STATUS +(\d+) recorded +\1 replayed  same", same.stdout) is not None,
              "planner: every PLANNER_STATUS the same")
        check("timers from the runner's clock origin" in same.stdout, "planner: the runner's log is recognised")

        executive = replay_test(log, "--node", "executive")
        check(executive.returncode == 0, "executive: unchanged settings give exit 0")
        check(re.search(r"VELOCITY_CMD +(\d{4,}) recorded +\1 replayed  same", executive.stdout) is not None,
              "executive: over a thousand VELOCITY_CMD, each the same")

        changed = replay_test(log, "--node", "planner", "--set", "interaction.reference_force_n=50")
        check(changed.returncode == 1, "planner: --set interaction.reference_force_n=50 gives exit 1")
        check(re.search(r"^different: GLOBAL_PATH message \d+ of \d+ \(log time [0-9.]+ s\): cost: recorded "
                        r"[0-9.]+, replayed [0-9.]+$", changed.stdout, re.M) is not None,
              "planner: the first difference names the message, its log time and the member (the path's cost)")

        budget = replay_test(log, "--node", "planner", "--set", "interaction.reference_force_n=50", "--set",
                             "interaction.frame_budget_ms=0.001")
        check(budget.returncode == 1 and re.search(r"^note: the planner's interaction planning took [0-9.]+ ms at log "
                                                   r"time [0-9.]+ s, past its wall-clock budget \(0\.0 ms\)",
                                                   budget.stdout, re.M) is not None,
              "planner: a difference after a status past the wall-clock budget says so")

        config = os.path.join(work, "config")
        shutil.copytree(os.path.join(SOURCE, "config"), config)
        planner_yaml = os.path.join(config, "planner.yaml")
        with open(planner_yaml) as file:
            text = file.read()
        edited = re.sub(r"^(  votes: )10\b", r"\g<1>3", text, count=1, flags=re.M)
        check(edited != text, "the copied planner.yaml has graph.votes 10 to change")
        with open(planner_yaml, "w") as file:
            file.write(edited)
        fewer_votes = replay_test(log, "--node", "planner", "--config-dir", config)
        check(fewer_votes.returncode == 1 and "\ndifferent: " in fewer_votes.stdout,
              "planner: a config directory with graph.votes 3 gives exit 1 and the first difference")

        corrupt = os.path.join(work, "corrupt.lcmlog")
        with open(log, "rb") as source, open(corrupt, "wb") as target:
            target.write(source.read(400_000))  # cut short: its last event is truncated
        broken = replay_test(corrupt, "--node", "planner")
        check(broken.returncode == 2 and re.search(r"is corrupt at byte \d+", broken.stderr) is not None,
              "a corrupt log gives exit 2 naming the byte offset")
        unknown = replay_test(log, "--node", "planner", "--set", "graph.vote=3")
        check(unknown.returncode == 2 and "unknown key" in unknown.stderr, "an unknown --set key gives exit 2")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print(f"{1 if not failures else 0} passed, {1 if failures else 0} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
