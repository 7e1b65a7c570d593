#!/usr/bin/env bash
# deps.sh — install the Debian packages csgrt needs, once. Silent when every
# package is already there; otherwise runs apt-get (as root, or through sudo).
set -euo pipefail
PACKAGES=(g++ make pkg-config verilator libglm-dev libopenimageio-dev
          openimageio-tools libgtest-dev povray yosys python3 python3-matplotlib)
missing=()
for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "deps: installing ${missing[*]}" >&2
SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
