#!/bin/sh
# A config error stops ifar-executive with exit code 2 and a message naming the key.
config="$IFAR_SOURCE_DIR/config/vehicle.yaml"   # a valid YAML file that is not an executive config
output=$(ifar-executive --log-dir '' --config "$config" --vehicle "$IFAR_SOURCE_DIR/config/vehicle.yaml" 2>&1)
status=$?
if [ "$status" -ne 2 ]; then
  echo "expected exit code 2, got $status: $output"
  exit 1
fi
case "$output" in
  *"key 'obstacles': missing required section"*) echo "ok: $output" ;;  # the first section read
  *) echo "message does not name the key: $output"; exit 1 ;;
esac
