#!/usr/bin/env bash
# Installs the Debian 12 packages Tephra builds against; only what is missing.
# Every dependency comes from Debian's archive (nothing else is downloaded).
set -euo pipefail
PKGS=(build-essential cmake pkg-config ccache
      libeigen3-dev libpugixml-dev libhdf5-dev
      libopenmpi-dev openmpi-bin libhypre-dev libsundials-dev libfftw3-dev
      libgtest-dev python3)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all Debian packages present"
  exit 0
fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
