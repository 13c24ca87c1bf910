#!/usr/bin/env bash
# Installs the Debian packages a job needs (run as root), and nothing else.
# Usage: scripts/install-deps.sh [demo|all]
#   demo  the plugin and ssao-host (scripts/run-demo.sh): compilers, GL, glTF, EXR
#   all   (default) everything the build and the tests need: also Embree (the
#         ray-traced reference), doctest, the Python host, the viewer under
#         Xvfb, the picture script and the sanitizer/fuzzer toolchain
# Skips apt-get entirely when everything is already installed, and waits for
# another apt-get's lock instead of failing at once.
set -euo pipefail
group=${1:-all}
demo=(
  build-essential cmake pkg-config
  libglm-dev libegl-dev libgl-dev libgl1-mesa-dri libegl-mesa0
  python3 python3-glad                   # glad 2 generates the GL loader at build time
  libtinygltf-dev nlohmann-json3-dev libstb-dev libtinyexr-dev
)
rest=(
  libembree-dev doctest-dev
  python3-moderngl python3-numpy          # the Python host and its tests
  libglfw3-dev xvfb xauth                # ssao-viewer and its tests in a virtual X server
  python3-pil fonts-dejavu-core          # scripts/make-pictures.sh
  clang-14 libclang-rt-14-dev            # scripts/run-sanitizers.sh: ASan/UBSan/TSan and libFuzzer
  ccache                                 # the test and sanitizer builds reuse unchanged objects
  python3-pip python3-setuptools python3-wheel   # pip install ./python (offline, --no-build-isolation)
  dpkg-dev                               # cpack -G DEB: dpkg-shlibdeps finds the packages' dependencies
  doxygen                                # the API reference of ssao.h (CTest docs.api_reference)
)
case $group in
  demo) packages=("${demo[@]}") ;;
  all) packages=("${demo[@]}" "${rest[@]}") ;;
  *) echo "install-deps: unknown group '$group' (demo or all)" >&2; exit 2 ;;
esac
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages of '$group' present"
  exit 0
fi
if [ "$(id -u)" -ne 0 ]; then
  echo "install-deps: missing ${missing[*]}; run as root (or with sudo) to install them" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
# Another apt-get or an unattended upgrade may hold the locks: wait up to 10 minutes.
lock=(-o DPkg::Lock::Timeout=600)
apt-get "${lock[@]}" update -qq
apt-get "${lock[@]}" install -y -qq --no-install-recommends "${missing[@]}"
