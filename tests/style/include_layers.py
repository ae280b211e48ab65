#!/usr/bin/env python3
"""Fails on an #include that runs against the project's layer order.

The order is declared once, in the ```layers block of docs/architecture.md: lowest layer first, one layer
a line, the top-level folders of a layer separated by spaces. A file may include its own folder and the
layers before its own; folders that share a line do not include each other. The generated message headers
("ifar/..._t.hpp") belong to lcmtypes. Nothing includes a daemon/ folder but the daemon itself and tests.
Every violation is printed as FILE:LINE: what and why; the exit code is 1 when there is any.
"""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
SOURCES = ('.cpp', '.hpp', '.h', '.cc')


def declared_layers():
    text = (ROOT / 'docs' / 'architecture.md').read_text()
    match = re.search(r'```layers\n(.*?)```', text, re.S)
    if not match:
        sys.exit('include_layers: docs/architecture.md has no ```layers block')
    layer_of = {}
    for rank, line in enumerate(l for l in match.group(1).splitlines() if l.strip()):
        for folder in line.split():
            layer_of[folder] = rank
    return layer_of


def top_folder(relative_path):
    parts = pathlib.PurePosixPath(relative_path).parts
    if parts and parts[0] == 'ifar':  # lcm-gen's headers
        return 'lcmtypes'
    return parts[0] if len(parts) > 1 else None


def daemon_folder(relative_path):
    parts = pathlib.PurePosixPath(relative_path).parts
    return str(pathlib.PurePosixPath(*parts[:parts.index('daemon') + 1])) if 'daemon' in parts[:-1] else None


def main():
    layer_of = declared_layers()
    problems = []
    tracked = [p for p in ROOT.rglob('*') if p.suffix in SOURCES and p.is_file()]
    for path in sorted(tracked):
        relative = path.relative_to(ROOT).as_posix()
        if relative.startswith(('build', '.git')) or '/build' in relative.split('/')[0]:
            continue
        source = top_folder(relative)
        if source not in layer_of:
            if source is not None and not relative.startswith(('build-', '.')):
                problems.append(f'{relative}:1: folder {source}/ is in no layer of docs/architecture.md')
            continue
        source_daemon = daemon_folder(relative)
        for number, line in enumerate(path.read_text(errors='replace').splitlines(), 1):
            match = INCLUDE.match(line)
            if not match:
                continue
            included = match.group(1)
            target = top_folder(included)
            if target is None or target not in layer_of:
                continue
            where = f'{relative}:{number}: #include "{included}"'
            target_daemon = daemon_folder(included)
            if target_daemon and source != 'tests' and target_daemon != source_daemon:
                problems.append(f'{where}: only {target_daemon}/ itself includes its daemon folder')
            if target == source or source == 'tests':
                continue
            if layer_of[target] > layer_of[source]:
                problems.append(f'{where}: {source}/ stands below {target}/ in the layer order')
            elif layer_of[target] == layer_of[source]:
                problems.append(f'{where}: {source}/ and {target}/ share a layer and do not include each other')
    for problem in problems:
        print(problem)
    print(f'include_layers: {len(problems)} problems' if problems else 'include_layers: every include follows the layers')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
