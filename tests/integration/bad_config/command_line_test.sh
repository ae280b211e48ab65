#!/usr/bin/env bash
# Every ifar program: --help exits 0, says what the program does and shows its usage as "ifar NAME" (no
# build path); --describe prints one line, which `ifar --help` lists beside the name; an unknown option
# exits 2 ("bad input") with a message (CLI11 may name a missing required argument first). CLI11 alone
# exits 106, 109... `ifar --version` names the version and the commit.
set -u
bin="${IFAR_BINARY_DIR:?}/bin"
failures=0
checked=0
listing=$("$bin/ifar" --help 2>&1)
version=$("$bin/ifar" --version 2>&1)
if ! [[ "$version" =~ ^ifar\ [0-9]+\.[0-9]+\.[0-9]+\ \(commit\ ([0-9a-f]{7,}(-dirty)?|unknown.*)\)$ ]]; then
  echo "FAIL: ifar --version printed '$version'"; failures=$((failures + 1))
fi
for program in "$bin"/ifar "$bin"/ifar-*; do
  [ -x "$program" ] || continue
  name=$(basename "$program")
  checked=$((checked + 1))
  help=$(timeout 10 "$program" --help 2>&1)
  status=$?
  if [ $status != 0 ] || [ ${#help} -lt 40 ]; then
    echo "FAIL: $name --help: exit code $status, output: ${help:0:200}"; failures=$((failures + 1))
  fi
  usage=$(echo "$help" | grep '^Usage: ' | head -1)
  wanted="Usage: ${name/ifar-/ifar } "
  [ "$name" = ifar ] && wanted="Usage: ifar "
  if [[ "$usage" != "$wanted"* ]]; then
    echo "FAIL: $name --help: usage line '$usage', expected it to start with '$wanted'"; failures=$((failures + 1))
  fi
  if [ "$name" != ifar ]; then
    description=$(timeout 10 "$program" --describe 2>&1)
    if [ -z "$description" ] || [ "$(echo "$description" | wc -l)" != 1 ]; then
      echo "FAIL: $name --describe: '$description'"; failures=$((failures + 1))
    elif ! grep -qxF "  ${name#ifar-}$(printf '%*s' $((18 - ${#name} + 5)) '')$description" <<< "$listing"; then
      echo "FAIL: ifar --help does not list '${name#ifar-}' with '$description'"; failures=$((failures + 1))
    fi
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
