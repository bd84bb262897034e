#!/usr/bin/env bash
# Installs every Debian package the build, the tests and the tools need. Idempotent: packages
# already present are skipped, and apt is asked only when something is missing.
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config git
  libgtest-dev libgmock-dev libbenchmark-dev
  libglm-dev libepoxy-dev libegl-dev libegl1 libgl1-mesa-dri libegl-mesa0
  nlohmann-json3-dev libcli11-dev libstb-dev
  libopenvdb-dev libopenvdb-tools libtbb-dev libboost-dev libboost-iostreams-dev
  libblosc-dev zlib1g-dev libimath-dev
  libassimp-dev  # mesh files (glTF 2.0, OBJ) in scenes
  libglfw3-dev xvfb xauth  # pyro view's window; its tests run it under xvfb-run
  libimgui-dev  # pyro view's panels (Dear ImGui with its GLFW and OpenGL 3 backends)
  libopenexr-dev libavcodec-dev libavformat-dev libswscale-dev libavutil-dev  # OpenEXR images and MP4/WebM/GIF videos (engine/io/exr_file.h, video_file.h)
  colord-data  # CIE 1931 colour-matching functions: content/data/cie1931_2deg_xyz.cmf is checked against it
  python3 python3-matplotlib  # tools/plots (run with /usr/bin/python3, not a pyenv python3)
  python3-jsonschema  # the scene schema tests validate with it (tests/tools/validate_json.py)
  slurm-wlm munge  # pyro farm's test starts a single-node Slurm cluster (tests/farm/slurm_farm_test.sh)
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
