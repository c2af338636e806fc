#!/usr/bin/env bash
# Installs fixel's build dependencies from Debian packages when any is missing.
# Idempotent: does nothing (and touches no network) when all are present.
set -euo pipefail
packages=(
  cmake g++ make librsvg2-bin
  clang clang-format libclang-rt-14-dev
  libcgal-dev libgmp-dev libeigen3-dev libboost-dev
  nlohmann-json3-dev libcli11-dev libgtest-dev libbenchmark-dev
  libbox2d-dev libmpfi-dev libtbb-dev libsiconos-numerics-dev
  libflint-dev libflint-arb-dev
  pybind11-dev python3-dev python3-pybind11
  python3-numpy python3-matplotlib python3-pytest python3-hypothesis python3-tqdm
  python3-dask python3-distributed
  python3-meshio
)
missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "install-deps: installing ${missing[*]}" >&2
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
