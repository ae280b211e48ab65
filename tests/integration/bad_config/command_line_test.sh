#!/usr/bin/env bash
# Every ifar program: --help exits 0 and says what the program does; an unknown option exits 2 ("bad
# input") with a message (CLI11 may name a missing required argument first). CLI11 alone exits 106, 109...
set -u
bin="${IFAR_BINARY_DIR:?}/bin"
failures=0
checked=0
for program in "$bin"/ifar "$bin"/ifar-*; do
  [ -x "$program" ] || continue
  name=$(basename "$program")
  checked=$((checked + 1))
  help=$(timeout 10 "$program" --help 2>&1)
  status=$?
  if [ $status != 0 ] || [ ${#help} -lt 40 ]; then
    echo "FAIL: $name --help: exit code $status, output: ${help:0:200}"; failures=$((failures + 1))
  fi
  error=$(timeout 10 "$program" --no-such-option 2>&1)
  status=$?
  if [ $status != 2 ] || [ -z "$error" ]; then
    echo "FAIL: $name --no-such-option: exit code $status (expected 2), output: ${error:0:200}"
    failures=$((failures + 1))
  fi
done
[ $checked -ge 20 ] || { echo "FAIL: only $checked programs found in $bin"; exit 1; }
[ $failures = 0 ] || { echo "FAIL: $failures of $checked programs"; exit 1; }
echo "PASS: $checked programs"
