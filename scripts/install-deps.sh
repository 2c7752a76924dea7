#!/usr/bin/env bash
# Installs, with apt, the Debian 12 packages rotinterp needs that are not there yet.
# Why each one is needed is in README.md ("Dependencies").
set -euo pipefail
packages=(
  build-essential cmake pkg-config git
  ccache                   # compiler cache: a second build rebuilds only what changed (docs/development.md)
  libeigen3-dev            # rotation math
  libassimp-dev            # reading BVH/FBX/glTF/Collada, exporting FBX/glTF/Collada
  libcli11-dev             # command line
  nlohmann-json3-dev       # JSON reports
  libfmt-dev               # formatting
  libstb-dev               # PNG writing, TrueType text
  zlib1g-dev               # PNG deflate for rendered frames
  fonts-dejavu-core        # the font for titles and labels
  libplplot-dev plplot-driver-cairo   # eval plots
  libosmesa6-dev libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri   # offscreen rendering
  ffmpeg                   # render --video: H.264 MP4 and GIF encoding (run as a program), ffprobe in its tests
  libgtest-dev libgmock-dev libbenchmark-dev   # tests and benchmarks
  libglm-dev               # test-only reference for squad
  python3-dev pybind11-dev python3-numpy   # the Python module (import rotinterp)
  python3-pytest python3-scipy             # its tests: pytest, scipy as the reference
  python3-matplotlib       # docs/python.md plots its example
  time                     # /usr/bin/time: peak memory in bench/memory.sh
  blender python3-numpy    # tests/clients: Blender imports what rotinterp writes (its glTF importer needs numpy)
  assimp-utils             # tests/clients: `assimp info` reads every BVH rotinterp writes
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}" >&2
  SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -q
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
