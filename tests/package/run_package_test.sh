#!/usr/bin/env bash
# The package test (CTest: package.install_and_consume).
#   run_package_test.sh BUILD_DIR SOURCE_DIR
# Installs BUILD_DIR into a temporary prefix, moves the prefix (mv), then from
# the moved tree: checks the installed files, the versions and that no file
# names the build or source tree, builds and runs three outside consumers
# (find_package, pkg-config, add_subdirectory of SOURCE_DIR), imports the
# Python package, and renders the bundled scene with the moved bin/ssao-host.
# Nothing may come from the build tree: the moved host must report the moved
# plugin and scene. The checks are in checks.sh (shared with run_deb_test.sh).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
test_name="package test"
. "$here/checks.sh" "$1" "$2"

step "install into $work/first, move it to $work/moved"
cmake --install "$build" --prefix "$work/first" >/dev/null
mv "$work/first" "$work/moved"
p="$work/moved"

step "installed files (version $ssao_version)"
for f in "lib/libssao.so.$ssao_version" include/ssao/ssao.h lib/cmake/ssao/ssaoConfig.cmake \
         lib/cmake/ssao/ssaoConfigVersion.cmake lib/pkgconfig/ssao.pc bin/ssao-host bin/ssao-reference \
         bin/ssao-error bin/ssao-bench bin/ssao-viewer share/ssao/models/spot-on-ground.glb share/ssao/models/teapot-on-ground.glb \
         share/ssao/models/README.md share/ssao/scenes/corner.gltf share/ssao/scenes/overhang.gltf \
         share/ssao/scenes/creases.gltf share/ssao/scenes/clutter.gltf share/ssao/viewer/demo.txt share/doc/ssao/docs/api.md \
         share/doc/ssao/README.md share/doc/ssao/LICENSE lib/python3/dist-packages/ssao/__init__.py; do
  [ -f "$p/$f" ] || fail "missing $f"
done
# The Debian packages' per-package copyright files are theirs alone.
[ ! -e "$p/share/doc/libssao1" ] || fail "a plain install holds the Debian package's share/doc/libssao1"
[ "$(readlink "$p/lib/libssao.so.1")" = "libssao.so.$ssao_version" ] || fail "lib/libssao.so.1 is not a link to libssao.so.$ssao_version"
[ "$(readlink "$p/lib/libssao.so")" = libssao.so.1 ] || fail "lib/libssao.so is not a link to libssao.so.1"
soname=$(objdump -p "$p/lib/libssao.so.$ssao_version" | awk '$1 == "SONAME" {print $2}')
[ "$soname" = libssao.so.1 ] || fail "SONAME is '$soname', not libssao.so.1"
# No file, binary or text, names the build, the source or the first prefix.
check_no_build_paths "$p"
if grep -rlF -e "$work/first" "$p"; then
  fail "the files above embed the install prefix they were installed to"
fi
check_versions "$p"
check_viewer "$p"

step "the moved ssao-host renders the bundled scene"
check_host_renders "$p"

step "the moved ssao-reference traces the bundled scene"
"$p/bin/ssao-reference" --width 32 --height 24 --samples 16 --quiet --out "$work/reference" | sed -n 1p
[ -s "$work/reference/reference_ao.exr" ] || fail "ssao-reference wrote no reference_ao.exr"

step "the moved Python package finds the moved library"
check_python "$p"

check_consumers "$p"

step "consumer: add_subdirectory of the source tree (library only)"
cmake -S "$here/add_subdirectory" -B "$work/sub" -DSSAO_SOURCE_DIR="$source" -DCMAKE_BUILD_TYPE=Release >/dev/null
if grep -E '^(embree_DIR|doctest_DIR|tinyexr_DIR|SSAO_TINYGLTF_LIBRARY)' "$work/sub/CMakeCache.txt"; then
  fail "configuring the library alone looked for the tools' or tests' dependencies"
fi
cmake --build "$work/sub" -j2 --target consumer >/dev/null
"$work/sub/consumer"
echo "package test: all passed"
