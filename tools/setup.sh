#!/usr/bin/env bash
# Installs what fabform needs from Debian's packages (only what is missing), then configures
# and builds it in build/ (Release, warnings on). Sourced by tools/fit.sh and tools/test.sh.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

packages=(cmake g++ make pkg-config python3 python3-matplotlib python3-numpy chromium libjs-three
          libeigen3-dev libassimp-dev libembree-dev libtomlplusplus-dev libcli11-dev nlohmann-json3-dev libcoin-dev libtinyxml2-dev
          libcgal-dev libsuitesparse-dev libhypre-dev libopenblas-dev libssl-dev libpng-dev
          libgtest-dev clang libclang-rt-14-dev slurm-wlm munge)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "fabform: installing ${missing[*]}" >&2
  sudo_cmd=""
  [[ $(id -u) -ne 0 ]] && sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# In unity batches of eight files: a fresh build takes about half the time (the headers and the
# templates they share compiled once a batch); configure another folder without it to rebuild
# single files while editing.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=ON >/dev/null
cmake --build build -j"$(nproc)"
