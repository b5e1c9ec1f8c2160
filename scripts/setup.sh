#!/usr/bin/env bash
# Installs the Debian 12 packages foveate needs to build, test and run.
# Idempotent: packages already present are skipped by apt.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config clang-format clang-15 libfuzzer-15-dev
  libegl-dev libegl-mesa0 libgl1-mesa-dri libglx-mesa0 libepoxy-dev
  libglfw3-dev libimgui-dev libglm-dev libcli11-dev nlohmann-json3-dev libstb-dev libpng-dev
  libassimp-dev libmeshoptimizer-dev
  libzmq3-dev cppzmq-dev libmsgpack-cxx-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth xdotool chromium
  libavcodec-dev libavformat-dev libswscale-dev libavutil-dev ffmpeg
  python3-dev pybind11-dev python3-numpy python3-pytest
)

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages already installed"
  exit 0
fi

echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
