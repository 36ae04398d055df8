#!/usr/bin/env bash
# Run a command in a private network namespace whose only network is a
# loopback with multicast, so LCM traffic of parallel tests stays apart and
# nothing ever leaves the machine.
#   run_in_netns.sh COMMAND [ARGS...]
set -euo pipefail
if [ $# -eq 0 ]; then
  echo "usage: $0 COMMAND [ARGS...]" >&2
  exit 64
fi
if [ "${REFLOC_IN_NETNS:-}" = "1" ]; then
  exec "$@"
fi
export REFLOC_IN_NETNS=1
exec unshare --net -- bash -c '
  set -e
  ip link set lo up
  ip link set lo multicast on
  ip route add 224.0.0.0/4 dev lo
  exec "$@"' run_in_netns "$@"
