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
  clang-format git
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
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
