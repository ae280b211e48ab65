#!/usr/bin/env python3
"""Fails on a benchmark task or a commit named in a comment of the product.

Code and config comments say why a value is what it is in terms of the vehicle, the sensor or the
geometry; which bench task or commit motivated it belongs in bench/results and the issue notes. This
reads the comments of every C++ source and YAML file under the product folders and prints each one that
names a generated world or task of the scenario suite ("office2x-3+4", "tunnel-1 t2", "Willow t3") or a
commit ("at b72a599"), as FILE:LINE: text. Exit code 1 when there is any.
"""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
PRODUCT = ('common', 'lcmtypes', 'bus', 'drivers', 'planner', 'executive', 'sim', 'viz', 'system', 'testing',
           'tools', 'config')
TASK = re.compile(
    r'\b(office2x-\d+\+\d+|office-\d+|tunnel-\d+|room_objects-\d+|room-\d+)\b'  # the suite's world names
    r'|\b[Ww]illow t\d+\b'                                                      # a Willow task
    r'|\b(bench|suite)\b[^.]*\bt\d+\b'                                          # "bench ... t3"
    r'|\bat [0-9a-f]{7,40}\b|\bcommit [0-9a-f]{7,40}\b')                        # a commit
CPP_COMMENT = re.compile(r'//(.*)$|/\*(.*?)\*/')
YAML_COMMENT = re.compile(r'(?:^|\s)#(.*)$')


def comments(path):
    text = path.read_text(errors='replace').splitlines()
    pattern = YAML_COMMENT if path.suffix in ('.yaml', '.yml') else CPP_COMMENT
    in_block = False
    for number, line in enumerate(text, 1):
        if pattern is CPP_COMMENT:
            if in_block:
                yield number, line
                in_block = '*/' not in line
                continue
            if '/*' in line and '*/' not in line.split('/*', 1)[1]:
                in_block = True
                yield number, line.split('/*', 1)[1]
                continue
        for match in pattern.finditer(line):
            yield number, ''.join(group or '' for group in match.groups())


def main():
    problems = []
    for folder in PRODUCT:
        for path in sorted((ROOT / folder).rglob('*')):
            if path.suffix not in ('.cpp', '.hpp', '.h', '.yaml', '.yml') or not path.is_file():
                continue
            for number, comment in comments(path):
                if TASK.search(comment):
                    problems.append(f'{path.relative_to(ROOT)}:{number}: {comment.strip()}')
    for problem in problems:
        print(problem)
    print(f'lab_notebook: {len(problems)} comments name a bench task or a commit' if problems
          else 'lab_notebook: no comment names a bench task or a commit')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
