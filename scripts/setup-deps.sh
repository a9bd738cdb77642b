#!/usr/bin/env bash
# Install the Debian packages spcontact needs, only those missing.
# Called by `make` before building; a machine that has everything returns in well under a second.
set -euo pipefail
PKGS=(make gcc pkg-config petsc-dev libmetis-dev libhdf5-openmpi-dev openmpi-bin gmsh
      python3-h5py python3-numpy python3-matplotlib paraview python3-paraview xvfb xauth python3-meshio)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "setup-deps: installing missing Debian packages: ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup-deps: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  SUDO=sudo
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup-deps: done"
