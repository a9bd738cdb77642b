#!/usr/bin/env bash
# Install the Debian packages spcontact needs, only those missing.
# Called by `make` before building; a machine that has everything returns in well under a second.
set -euo pipefail
# libopenblas0-serial: Debian's optimized BLAS/LAPACK (it takes over libblas.so.3 from the reference
# BLAS); MUMPS factors 2D Jacobians 2-3x faster with it (src/solver-direct.c). Serial: no BLAS
# threads competing with the MPI ranks.
PKGS=(make gcc pkg-config petsc-dev libmetis-dev libyaml-dev libhdf5-openmpi-dev openmpi-bin gmsh libopenblas0-serial
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
