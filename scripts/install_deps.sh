#!/usr/bin/env bash
# Installs every build, test and benchmark dependency of DryDEM from Debian 12 packages.
# Idempotent: installs only what is missing. Run as root (or with sudo available).
set -euo pipefail
packages=(
  g++ cmake ninja-build pkg-config git
  libtomlplusplus-dev libcli11-dev libfmt-dev libspdlog-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev libomp-dev libtiff-dev libeigen3-dev
  python3-matplotlib python3-vtk9 python3-numpy python3-pil time universal-ctags
  python3-scipy python3-sklearn   # drydem calibrate: qmc start, Gaussian-process surrogate
  slurm-wlm munge                 # --scheduler slurm; the test starts its own one-node cluster
  libhypre-dev                    # BoomerAMG for the transport solves (pulls Open MPI)
  libopenmpi-dev openmpi-bin      # MPI domain decomposition (docs/parallel.md), mpirun for ctest
  clang-format-14                 # the format check (ctest format; .clang-format)
)
# The peer benchmark (bench/peer_bench.sh) also needs LIGGGHTS and LAMMPS: pass --peers.
if [[ "${1:-}" == "--peers" ]]; then packages+=(liggghts lammps); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  echo "install_deps: all ${#packages[@]} packages present"
  exit 0
fi
echo "install_deps: installing ${missing[*]}"
SUDO=""
if [[ $(id -u) -ne 0 ]]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
