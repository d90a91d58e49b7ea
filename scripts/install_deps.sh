#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs what lookahead needs on Debian bookworm (run as root). Idempotent: does nothing
# when every package is already there, so it is cheap to run before every build.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git time clang-format
  libeigen3-dev libopencv-dev libompl-dev liboctomap-dev
  libmrpt-dev libmrpt-ros1bridge-dev mrpt-common mrpt-apps
  librosbag-storage-dev libsensor-msgs-dev libnav-msgs-dev libtf2-msgs-dev python3-rosbag
  libyaml-cpp-dev libcli11-dev libspdlog-dev libfmt-dev nlohmann-json3-dev zlib1g-dev
  libboost-math-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  slurm-wlm munge chromium fonts-dejavu-core
  clang libclang-rt-14-dev
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#packages[@]} packages present"
  exit 0
fi
echo "install_deps: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
