#!/usr/bin/env python3
"""ifar-sim --sensing: the profile named on the command line replaces the config's sensing.profile (its
values show in --print-config, the config's other sensing keys still apply), and an unknown profile is a
bad command line (exit 2, naming the known profiles)."""
import os
import subprocess
import sys
import tempfile

SOURCE = os.environ.get("IFAR_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))


def run(*arguments):
    return subprocess.run(["ifar-sim", *arguments], cwd=SOURCE, capture_output=True, text=True, timeout=30)


def main():
    failures = []
    shipped = run("--print-config")
    if shipped.returncode != 0 or "profile: ideal" not in shipped.stdout:
        failures.append("shipped config: expected profile ideal, got %r" % shipped.stdout[:300])
    with tempfile.TemporaryDirectory() as folder:
        config = os.path.join(folder, "sim.yaml")
        with open(os.path.join(SOURCE, "config", "sim.yaml")) as original, open(config, "w") as copy:
            copy.write(original.read().replace("  profile: ideal", "  profile: ideal\n  lidar: {range_noise_m: 0.03}"))
        field = run("--config", config, "--sensing", "field", "--print-config")
        for expected in ("profile: field", "range_noise_m: 0.03", "latency_s: 0.05", "encoder_counts_per_rev: 4096"):
            if expected not in field.stdout:
                failures.append("--sensing field: %r missing from --print-config" % expected)
    bad = run("--sensing", "noisy", "--print-config")
    if bad.returncode != 2 or "ideal" not in bad.stderr or "field" not in bad.stderr:
        failures.append("--sensing noisy: expected exit 2 naming ideal and field, got %d %r"
                        % (bad.returncode, bad.stderr))
    for failure in failures:
        print("FAIL:", failure)
    print("sim_sensing_cli: %s" % ("ok" if not failures else "%d failures" % len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
