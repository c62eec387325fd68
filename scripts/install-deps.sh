#!/usr/bin/env bash
# Installs the Debian 12 packages twb builds, tests and plots with.
# Idempotent: packages already present are left alone; runs as root or via sudo.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libsundials-dev libsuitesparse-dev libeigen3-dev libfmt-dev
  libyaml-cpp-dev libudunits2-dev libcli11-dev libboost-dev
  libgtest-dev libgmock-dev libbenchmark-dev nlohmann-json3-dev
  # Calibration to measurements: Ceres Solver's bounded Levenberg-Marquardt.
  libceres-dev
  python3-matplotlib python3-numpy python3-pandas
  # The Python module (import twb): pybind11 and the interpreter's headers.
  pybind11-dev python3-dev
  # MPI jobs of the twb command (optional for building; CI tests them).
  libopenmpi-dev openmpi-bin
  # The scene fuzzer: clang with libFuzzer and its sanitizers, llvm-symbolizer for
  # readable reports (GCC's sanitizers come with build-essential).
  clang libclang-rt-14-dev llvm
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

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
echo "install-deps: installing ${missing[*]}"
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
