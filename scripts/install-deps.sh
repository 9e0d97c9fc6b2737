#!/usr/bin/env bash
# Installs everything taa needs to build and test, from Debian 12 packages only.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libopenimageio-dev openimageio-tools libopenexr-dev libimath-dev
  libopencolorio-dev
  libdeflate-dev zlib1g-dev  # ZIP: taatool's codec (zlib's one-shot calls on libdeflate), the chunk reader
  libglm-dev
  nlohmann-json3-dev  # header-only JSON: the camera sidecar
  libgl-dev libegl-dev libegl-mesa0 libosmesa6-dev libgl1-mesa-dri  # headless GL on llvmpipe
  libgtest-dev
  pybind11-dev python3-dev python3-numpy python3-pytest python3-openimageio  # Python module
  blender fonts-dejavu-core  # real renders for the yardstick and its tests; contact sheet labels
  slurmctld slurmd slurm-client munge  # taa-farm's test runs a one-node Slurm cluster (tests/farm)
  clang-14 libclang-rt-14-dev  # scripts/sanitize.sh and scripts/fuzz.sh: ASan, UBSan, libFuzzer
)

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi

if ! dpkg -s "${packages[@]}" >/dev/null 2>&1; then
  "${sudo_cmd[@]}" apt-get update
  "${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends \
    "${packages[@]}"
fi
