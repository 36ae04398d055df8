#!/usr/bin/env bash
# Install every Debian package the build, the tests and the demo need.
# Idempotent and non-interactive: does nothing when all are present.
set -euo pipefail

packages=(
  cmake g++ make pkg-config
  liblcm-dev liblcm-bin liblcm-java libglib2.0-dev
  libeigen3-dev nlohmann-json3-dev libfmt-dev libspdlog-dev libcli11-dev libsystemd-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  default-jdk-headless libjchart2d-java
  supervisor iproute2 util-linux procps python3 jq
  python3-matplotlib
  clang-format git
  libceres-dev
  libboost-dev
  # The console's browser test (headless Chromium through chromedriver) and load_test.sh's
  # WebSocket readers (--console-clients).
  chromium chromium-driver python3-selenium python3-websocket
)

# Every refloc program's LCM URL asks for this UDP receive buffer (recv_buf_size, common/lcm_url.hpp:
# a 1 s stall of one process at 50 Hz); the kernel silently caps it at net.core.rmem_max. The sysctl
# is global (a network namespace reads the host's and cannot set it), so it is set here, on the
# host, never lowered, and kept in a drop-in applied at boot. A container whose /proc/sys is
# read-only gets a warning (the services WARN at start and count lcm_recv_buf_clamped_to_bytes).
rmem_max_bytes=2097152
sysctl_dropin=/etc/sysctl.d/60-refloc.conf
raise_rmem_max() {
  local now
  now="$(cat /proc/sys/net/core/rmem_max 2>/dev/null || echo 0)"
  if [ "$(id -u)" -ne 0 ]; then
    [ "$now" -ge "$rmem_max_bytes" ] ||
      echo "install-deps: WARNING: net.core.rmem_max = $now < $rmem_max_bytes: LCM receive buffers are" \
        "clamped and a stall loses messages; as root: sysctl -w net.core.rmem_max=$rmem_max_bytes" >&2
    return 0
  fi
  # Written even when the value is already high enough, so that it still is after a reboot.
  { echo "# refloc (deploy/install-deps.sh): the LCM URL's recv_buf_size, see common/lcm_url.hpp"
    echo "net.core.rmem_max = $rmem_max_bytes"; } >"$sysctl_dropin" 2>/dev/null ||
    echo "install-deps: WARNING: cannot write $sysctl_dropin" >&2
  if [ "$now" -lt "$rmem_max_bytes" ]; then
    # Only our drop-in: `sysctl --system` would also re-apply every other file's settings.
    sysctl -q -p "$sysctl_dropin" >/dev/null 2>&1 || true
    now="$(cat /proc/sys/net/core/rmem_max 2>/dev/null || echo 0)"
  fi
  if [ "$now" -ge "$rmem_max_bytes" ]; then
    echo "install-deps: net.core.rmem_max = $now (>= $rmem_max_bytes the LCM URL asks for; $sysctl_dropin)"
  else
    echo "install-deps: WARNING: cannot raise net.core.rmem_max ($now < $rmem_max_bytes; read-only" \
      "/proc/sys in a container?): set it on the host: sysctl -w net.core.rmem_max=$rmem_max_bytes" >&2
  fi
}

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  raise_rmem_max
  exit 0
fi
if [ "$(id -u)" -ne 0 ]; then
  echo "install-deps: missing packages: ${missing[*]}; run as root (or: sudo $0)" >&2
  exit 1
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
if ! apt-get install -y -q --no-install-recommends "${missing[@]}"; then
  apt-get update -q
  apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
raise_rmem_max
