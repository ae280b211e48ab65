#!/usr/bin/env python3
"""--print-config: every daemon and `ifar-run` print the effective configuration as YAML and exit 0. The
output parses, every value the shipped file sets is printed with that value, and the printed text is
itself a valid config that the daemon loads strictly to the same output (nothing lost, nothing extra).
    print_config_test.py BIN_DIR"""
import os
import subprocess
import sys
import tempfile

import yaml

SOURCE = os.environ.get("IFAR_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", "..", ".."))
DAEMONS = [("ifar-planner", "config/planner.yaml"), ("ifar-executive", "config/executive.yaml"),
           ("ifar-sim", "config/sim.yaml"), ("ifar-force-driver", "config/can.yaml"),
           ("ifar-motor-driver", "config/can.yaml"), ("ifar-velodyne-driver", "config/velodyne.yaml")]


def leaves(tree, prefix=""):
    """The scalar values of a YAML map by dotted key."""
    out = {}
    for key, value in (tree or {}).items():
        path = prefix + str(key)
        if isinstance(value, dict):
            out.update(leaves(value, path + "."))
        else:
            out[path] = value
    return out


def same(expected, printed):
    if isinstance(expected, bool) or isinstance(printed, bool):
        return expected == printed
    if isinstance(expected, (int, float)) and isinstance(printed, (int, float)):
        return float(expected) == float(printed)
    return expected == printed


def compare(what, file_values, printed_values):
    problems = []
    for key, value in file_values.items():
        if key not in printed_values:
            problems.append("%s: %s not printed" % (what, key))
        elif not same(value, printed_values[key]):
            problems.append("%s: %s is %r in the file, printed %r" % (what, key, value, printed_values[key]))
    return problems


def run(command):
    result = subprocess.run(command, cwd=SOURCE, capture_output=True, text=True, timeout=60)
    return result.returncode, result.stdout, result.stderr


def check_daemon(bin_dir, daemon, config, folder):
    code, text, error = run([os.path.join(bin_dir, daemon), "--config", config, "--print-config"])
    if code != 0:
        return ["%s --print-config: exit code %d: %s" % (daemon, code, error.strip())]
    with open(os.path.join(SOURCE, config)) as shipped:
        problems = compare(daemon, leaves(yaml.safe_load(shipped)), leaves(yaml.safe_load(text)))
    # The printed text is a config of its own: loaded strictly, it prints the same again.
    again = os.path.join(folder, daemon + ".yaml")
    with open(again, "w") as out:
        out.write(text)
    code, second, error = run([os.path.join(bin_dir, daemon), "--config", again, "--print-config"])
    if code != 0:
        problems.append("%s: the printed config does not load: %s" % (daemon, error.strip()))
    elif second.splitlines()[1:] != text.splitlines()[1:]:
        problems.append("%s: the printed config prints differently" % daemon)
    return problems


def check_runner(bin_dir):
    code, text, error = run([os.path.join(bin_dir, "ifar-run"), "--config-dir", "config", "--print-config"])
    if code != 0:
        return ["ifar-run --print-config: exit code %d: %s" % (code, error.strip())]
    documents = {}
    for document in text.split("--- # ")[1:]:
        title, _, body = document.partition("\n")
        documents[os.path.basename(title.strip())] = yaml.safe_load(body)
    problems = []
    for name in ("vehicle.yaml", "planner.yaml", "executive.yaml", "sim.yaml", "can.yaml", "velodyne.yaml"):
        if name not in documents:
            problems.append("ifar-run: no document for %s" % name)
            continue
        with open(os.path.join(SOURCE, "config", name)) as shipped:
            problems += compare("ifar-run " + name, leaves(yaml.safe_load(shipped)), leaves(documents[name]))
    return problems


def main():
    bin_dir = sys.argv[1]
    problems = []
    with tempfile.TemporaryDirectory() as folder:
        for daemon, config in DAEMONS:
            problems += check_daemon(bin_dir, daemon, config, folder)
    problems += check_runner(bin_dir)
    for problem in problems:
        print("FAIL " + problem)
    print("print_config: %d problems" % len(problems))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
