#!/usr/bin/env bash
# The Debian package test (CTest: package.deb).
#   run_deb_test.sh BUILD_DIR SOURCE_DIR
# Runs cpack -G DEB on BUILD_DIR, checks each package's control fields
# (dpkg-deb --info: name, version, dependencies) and files (--contents),
# extracts them all (dpkg-deb -x) into a temporary root, and from that root:
# no file names the build or source tree, the tools state the version and
# render with the extracted plugin, the Python package finds the extracted
# library, and the find_package and pkg-config consumers build and run.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
test_name="deb test"
. "$here/checks.sh" "$1" "$2"
command -v dpkg-shlibdeps >/dev/null || fail "dpkg-shlibdeps not found: apt-get install dpkg-dev (scripts/install-deps.sh)"

step "cpack -G DEB"
cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/debs" >"$work/cpack.log" 2>&1 || { cat "$work/cpack.log"; fail "cpack failed"; }
arch=$(dpkg --print-architecture)
declare -A deb=(
  [libssao1]="$work/debs/libssao1_${ssao_version}_$arch.deb"
  [libssao-dev]="$work/debs/libssao-dev_${ssao_version}_$arch.deb"
  [ssao-tools]="$work/debs/ssao-tools_${ssao_version}_$arch.deb"
  [python3-ssao]="$work/debs/python3-ssao_${ssao_version}_all.deb"
)
for name in "${!deb[@]}"; do [ -f "${deb[$name]}" ] || fail "no ${deb[$name]##*/} (made: $(ls "$work/debs"/*.deb | xargs -n1 basename | tr '\n' ' '))"; done

field() { dpkg-deb --field "${deb[$1]}" "$2"; }
# A Depends entry of package $1 that starts with $2 (e.g. "libssao1 (= 1.2.0)").
depends_on() {
  field "$1" Depends | tr ',' '\n' | sed 's/^ *//' | grep -qF -- "$2" || fail "$1 does not depend on '$2' (Depends: $(field "$1" Depends))"
}
step "control fields"
for name in "${!deb[@]}"; do
  [ "$(field "$name" Package)" = "$name" ] || fail "${deb[$name]##*/} is package '$(field "$name" Package)'"
  [ "$(field "$name" Version)" = "$ssao_version" ] || fail "$name has version '$(field "$name" Version)'"
  echo "$name $ssao_version: Depends: $(field "$name" Depends)"
done
depends_on libssao1 "libc6"
depends_on libssao1 "libstdc++6"
depends_on libssao-dev "libssao1 (= $ssao_version)"
depends_on ssao-tools "libssao1 (= $ssao_version)"
depends_on ssao-tools "libegl1"
depends_on ssao-tools "libglfw3"
depends_on python3-ssao "libssao1 (= $ssao_version)"
depends_on python3-ssao "python3"
for name in "${!deb[@]}"; do
  description=$(field "$name" Description)
  [[ "${description%%$'\n'*}" == "Drop-in "*"("*")" ]] || fail "$name has no one-line summary: ${description%%$'\n'*}"
  [[ "$description" == *$'\n'* ]] || fail "$name has no long description"
done

step "contents"
# Package $1 holds path $2 (as dpkg-deb --contents lists it: ./usr/...).
holds() { dpkg-deb --contents "${deb[$1]}" | awk '{print $6}' | grep -qx -- "./usr/$2" || fail "$1 does not hold /usr/$2"; }
lacks() { ! dpkg-deb --contents "${deb[$1]}" | awk '{print $6}' | grep -q -- "$2" || fail "$1 holds $2"; }
holds libssao1 "lib/libssao.so.$ssao_version"
holds libssao1 "lib/libssao.so.1"
lacks libssao1 "include/"
lacks libssao1 "lib/libssao.so\$"
holds libssao-dev "include/ssao/ssao.h"
holds libssao-dev "lib/libssao.so"
holds libssao-dev "lib/cmake/ssao/ssaoConfig.cmake"
holds libssao-dev "lib/cmake/ssao/ssaoConfigVersion.cmake"
holds libssao-dev "lib/pkgconfig/ssao.pc"
holds libssao-dev "share/doc/ssao/docs/api.md"
lacks libssao-dev "lib/libssao.so.$ssao_version"
for tool in ssao-host ssao-reference ssao-error ssao-bench ssao-viewer; do holds ssao-tools "bin/$tool"; done
holds ssao-tools "share/ssao/models/spot-on-ground.glb"
holds ssao-tools "share/ssao/viewer/demo.txt"
lacks ssao-tools "lib/libssao"
holds python3-ssao "lib/python3/dist-packages/ssao/__init__.py"
for name in libssao1 libssao-dev ssao-tools python3-ssao; do
  holds $name "share/doc/$name/copyright"
  # Extracted whole: a pipe into tar or grep that stops reading early ends its writer with SIGPIPE (pipefail).
  dpkg-deb -x "${deb[$name]}" "$work/copyright-$name"
  grep -q "^Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/" \
    "$work/copyright-$name/usr/share/doc/$name/copyright" ||
    fail "$name's copyright is not in Debian's machine-readable format"
done
lacks python3-ssao "_build_paths"

step "extract into $work/root"
for name in "${!deb[@]}"; do dpkg-deb -x "${deb[$name]}" "$work/root"; done
p="$work/root/usr"
check_no_build_paths "$work/root"
check_versions "$p"
check_viewer "$p"
step "the extracted ssao-host renders with the extracted plugin"
check_host_renders "$p"
step "the extracted Python package finds the extracted library"
check_python "$p"
check_consumers "$p"
echo "deb test: all passed"
