#!/usr/bin/env bash
# ifar can play over LCM (memq, in process): bad lines are skipped and counted; a file with no candump
# frame at all is bad input (exit 2), not "sent 0 frames".
set -u
can="${IFAR_BINARY_DIR:?}/bin/ifar-can"
folder=$(mktemp -d)
trap 'rm -rf "$folder"' EXIT
printf 'not a frame\n(12.5) can0 zz#00\n' > "$folder/bad.log"
printf '(1795320266.193869) can0 701#00\nnot a frame\n' > "$folder/mixed.log"
play() { "$can" --bus lcm --channel CAN_TEST --lcm-url memq:// play --speed 0 "$1" 2>&1; }

output=$(play "$folder/bad.log"); status=$?
if [ $status != 2 ] || [[ "$output" != *"sent 0 frames, skipped 2 bad lines"* ]] ||
   [[ "$output" != *"no line of $folder/bad.log is a candump -l frame"* ]]; then
  echo "FAIL: all-bad file: exit $status, output: $output"; exit 1
fi
output=$(play "$folder/mixed.log"); status=$?
if [ $status != 0 ] || [[ "$output" != *"sent 1 frames, skipped 1 bad lines"* ]]; then
  echo "FAIL: mixed file: exit $status, output: $output"; exit 1
fi
echo "PASS"
