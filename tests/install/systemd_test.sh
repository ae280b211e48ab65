#!/usr/bin/env bash
# The systemd units cmake --install writes for its prefix: `systemd-analyze verify` passes, `systemd-analyze
# security` scores each OK or better (exposure below 5.0), they run as the ifar user that the sysusers.d file
# creates, they start the programs of that prefix, and the CAN unit's command brings the interface up at
# the bit rate of the configuration it finds (dry run: no interface is touched). Skipped (exit 77) where
# systemd-analyze is absent (Debian: the systemd package; scripts/setup installs it).
set -uo pipefail
if ! command -v systemd-analyze > /dev/null; then
  echo "SKIP: systemd-analyze is not installed (Debian package systemd)"
  exit 77
fi
build=${IFAR_BINARY_DIR:?}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"
units="$prefix/lib/systemd/system"
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
ok() { echo "ok   $*"; }

cmake --install "$build" --prefix "$prefix" > "$work/install.log" 2>&1 || { cat "$work/install.log"; echo "FAIL cmake --install"; exit 1; }
for unit in ifar.service ifar-can.service; do
  [ -f "$units/$unit" ] || { fail "$unit not installed in $units"; continue; }
  if output=$(cd "$units" && systemd-analyze verify --man=no "$unit" 2>&1); then
    ok "systemd-analyze verify $unit"
  else
    fail "systemd-analyze verify $unit: $output"
  fi
  report=$(cd "$units" && systemd-analyze security --offline=yes "$unit" 2>&1)
  level=$(echo "$report" | sed -n 's/.*Overall exposure level for [^:]*: \([0-9.]*\) \([A-Z]*\).*/\1 \2/p')
  case "$level" in
    *" OK" | *" SAFE" | *" PERFECT") ok "systemd-analyze security $unit: $level" ;;
    *) fail "systemd-analyze security $unit: '$level', expected OK or better: $(echo "$report" | tail -3)" ;;
  esac
  (cd "$units" && systemd-analyze security --offline=yes --threshold=49 "$unit" > /dev/null 2>&1) ||
    fail "systemd-analyze security --threshold=49 $unit failed (exposure above 4.9)"
  grep -qx "User=ifar" "$units/$unit" || fail "$unit does not run as the ifar user"
  grep -q "^ExecStart=$prefix/bin/ifar" "$units/$unit" || fail "$unit does not start $prefix/bin's programs: $(grep ^ExecStart "$units/$unit")"
done
grep -qx "ExecStart=$prefix/bin/ifar launch vehicle --no-colour" "$units/ifar.service" &&
  ok "ifar.service starts $prefix/bin/ifar launch vehicle" || fail "ifar.service ExecStart: $(grep ^ExecStart "$units/ifar.service")"
grep -qx "CapabilityBoundingSet=" "$units/ifar.service" || fail "ifar.service keeps capabilities"
grep -qx "CapabilityBoundingSet=CAP_NET_ADMIN" "$units/ifar-can.service" || fail "ifar-can.service is not limited to CAP_NET_ADMIN"

# The user both run as: systemd-sysusers creates it from the installed file (into a scratch root).
mkdir -p "$work/root/etc"
if systemd-sysusers --root="$work/root" "$prefix/lib/sysusers.d/ifar.conf" > /dev/null 2>&1 &&
   grep -q '^ifar:x:[0-9]*:[0-9]*:ifar navigation stack:/var/lib/ifar:' "$work/root/etc/passwd"; then
  ok "sysusers.d/ifar.conf creates the ifar user"
else
  fail "sysusers.d/ifar.conf: $(cat "$work/root/etc/passwd" 2>&1)"
fi

# The CAN unit's own command, with the configuration a deployment puts in /etc/ifar (IFAR_CONFIG_DIR in the
# unit): the interface and bit rate come from that file, dry run.
mkdir -p "$work/etc/onboard"
sed -e 's/^  interface: can0 /  interface: can1 /' -e 's/^  bitrate: 500000 /  bitrate: 250000 /' \
  "$prefix/share/ifar/onboard/can.yaml" > "$work/etc/onboard/can.yaml"
command=$(sed -n 's/^ExecStart=//p' "$units/ifar-can.service")
# shellcheck disable=SC2086
output=$(cd "$work" && IFAR_CONFIG_DIR="$work/etc" $command --dry-run 2>&1)
expected="ip link set can1 type can bitrate 250000 restart-ms 100"
if [[ "$output" == *"configuration $work/etc/onboard/can.yaml (IFAR_CONFIG_DIR)"*"$expected"*"ip link set can1 up"* ]]; then
  ok "ifar-can.service's command: $expected"
else
  fail "ifar-can.service's command '$command --dry-run' printed: $output"
fi
# shellcheck disable=SC2086
output=$(cd "$work" && env -u IFAR_CONFIG_DIR HOME="$work" $command --dry-run 2>&1)
[[ "$output" == *"ip link set can0 type can bitrate 500000 restart-ms 100"* ]] &&
  ok "without /etc/ifar: the installed onboard/can.yaml (can0, 500000 bit/s)" ||
  fail "ifar-can.service's command without IFAR_CONFIG_DIR printed: $output"

if [ "$failures" -ne 0 ]; then
  echo "$failures failures"
  exit 1
fi
echo "PASS"
