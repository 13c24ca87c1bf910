#!/usr/bin/env bash
# Installs the Debian packages the build and the tests need (run as root).
# Skips apt-get entirely when everything is already installed.
set -euo pipefail
packages=(
  build-essential cmake pkg-config
  libglm-dev libegl-dev libgl-dev libgl1-mesa-dri libegl-mesa0
  python3 python3-glad
  libtinygltf-dev nlohmann-json3-dev libstb-dev libtinyexr-dev
  libembree-dev doctest-dev
  python3-moderngl python3-numpy          # the Python host and its tests
  libglfw3-dev xvfb xauth                # ssao-viewer and its tests in a virtual X server
  python3-pil fonts-dejavu-core          # scripts/make-pictures.sh
  clang-14 libclang-rt-14-dev            # scripts/run-sanitizers.sh: ASan/UBSan/TSan and libFuzzer
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
if [ "$(id -u)" -ne 0 ]; then
  echo "install-deps: missing ${missing[*]}; run as root (or with sudo) to install them" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
