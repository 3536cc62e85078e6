#!/usr/bin/env bash
# Installs the Debian 12 packages that Kiln's build, tests and docs need.
# Idempotent: when everything is present it only checks (a second or two).
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  trilinos-all-dev
  # Debian's Trilinos targets name these libraries by absolute path:
  libscotch-dev libptscotch-dev libblas-dev liblapack-dev
  libmetis-dev
  libhdf5-openmpi-dev hdf5-tools
  openmpi-bin libopenmpi-dev
  libexodusii-dev libnetcdf-dev
  libgtest-dev
  # formulas in x, y, z, t (src/base/expression):
  libmuparser-dev
  clang-format
  # tools/kiln-diff and the gold-file regression tests:
  python3-h5py python3-numpy
  # the verification report (doc/verification/report.py) and benchmarks/scaling.py's plots:
  python3-matplotlib
  # scipy's netCDF writer, for the Exodus file the Exodus library misreads (tests/cli):
  python3-scipy
  # ParaView's own readers (pvpython) open the results of every cell type in a test
  # (tests/tools/paraview_open_test.py):
  paraview
  # GNU time, for the peak memory per rank in benchmarks/scaling.py (and its smoke test):
  time
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
  [ "$status" = "installed" ] || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "packages/install.sh: all ${#packages[@]} packages present"
  exit 0
fi

echo "packages/install.sh: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
