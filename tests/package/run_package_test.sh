#!/usr/bin/env bash
# The package test (CTest: package.install_and_consume).
#   run_package_test.sh BUILD_DIR SOURCE_DIR
# Installs BUILD_DIR into a temporary prefix, moves the prefix (mv), then from
# the moved tree: checks the installed files, builds and runs three outside
# consumers (find_package, pkg-config, add_subdirectory of SOURCE_DIR), and
# renders the bundled scene with the moved bin/ssao-host. Nothing may come
# from the build tree: the moved host must report the moved plugin and scene.
set -euo pipefail
build=$(cd "$1" && pwd)
source=$(cd "$2" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d /tmp/ssao-package.XXXXXX)
trap 'rm -rf "$work"' EXIT
jobs=-j2
fail() { echo "package test: $*" >&2; exit 1; }
step() { echo "== $*"; }
unset SSAO_PLUGIN SSAO_DATA_DIR

step "install into $work/first, move it to $work/moved"
cmake --install "$build" --prefix "$work/first" >/dev/null
mv "$work/first" "$work/moved"
p="$work/moved"

step "installed files"
for f in lib/libssao.so.1.0.0 include/ssao/ssao.h lib/cmake/ssao/ssaoConfig.cmake \
         lib/cmake/ssao/ssaoConfigVersion.cmake lib/pkgconfig/ssao.pc bin/ssao-host bin/ssao-reference \
         bin/ssao-error bin/ssao-bench share/ssao/models/spot-on-ground.glb share/ssao/models/teapot-on-ground.glb \
         share/ssao/models/README.md share/ssao/scenes/corner.gltf share/doc/ssao/README.md share/doc/ssao/LICENSE; do
  [ -f "$p/$f" ] || fail "missing $f"
done
[ "$(readlink "$p/lib/libssao.so.1")" = libssao.so.1.0.0 ] || fail "lib/libssao.so.1 is not a link to libssao.so.1.0.0"
[ "$(readlink "$p/lib/libssao.so")" = libssao.so.1 ] || fail "lib/libssao.so is not a link to libssao.so.1"
soname=$(objdump -p "$p/lib/libssao.so.1.0.0" | awk '$1 == "SONAME" {print $2}')
[ "$soname" = libssao.so.1 ] || fail "SONAME is '$soname', not libssao.so.1"
# The package's text files name no absolute path of the build, the source or the first prefix.
if grep -rlF -e "$work/first" -e "$build" -e "$source" "$p/lib/cmake" "$p/lib/pkgconfig"; then
  fail "the files above embed an absolute path of the build, the source or the install prefix"
fi
for tool in ssao-host ssao-reference ssao-error ssao-bench; do
  v=$("$p/bin/$tool" --version)
  echo "$v"
  [[ "$v" == "$tool "[0-9]*.[0-9]*.[0-9]*" (C ABI "* ]] || fail "$tool --version printed '$v'"
done

step "the moved ssao-host renders the bundled scene"
out=$("$p/bin/ssao-host" --width 64 --height 48 --frames 2 --out "$work/render")
echo "$out" | sed -n '1p;/plugin:/p'
echo "$out" | grep -qF "ssao-host: $p/share/ssao/models/spot-on-ground.glb" || fail "the host did not render the moved bundled scene"
echo "$out" | grep -qF "plugin: $p/lib/libssao.so.1" || fail "the host did not load the moved plugin"
for f in ao.png ao.exr lit_ao.png lit_no_ao.png; do [ -s "$work/render/$f" ] || fail "the host wrote no $f"; done

step "the moved ssao-reference traces the bundled scene"
"$p/bin/ssao-reference" --width 32 --height 24 --samples 16 --quiet --out "$work/reference" | sed -n 1p
[ -s "$work/reference/reference_ao.exr" ] || fail "ssao-reference wrote no reference_ao.exr"

step "consumer 1: find_package(ssao CONFIG REQUIRED)"
cmake -S "$here/find_package" -B "$work/fp" -DCMAKE_PREFIX_PATH="$p" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/fp" $jobs >/dev/null
"$work/fp/consumer"
LD_LIBRARY_PATH="$p/lib" "$work/fp/consumer_dlopen"

step "consumer 2: pkg-config --cflags --libs ssao"
export PKG_CONFIG_PATH="$p/lib/pkgconfig"
echo "pkg-config: $(pkg-config --cflags --libs ssao) (version $(pkg-config --modversion ssao))"
make -s -C "$here/pkg_config" OUT="$work"
LD_LIBRARY_PATH="$p/lib" "$work/consumer"

step "consumer 3: add_subdirectory of the source tree (library only)"
cmake -S "$here/add_subdirectory" -B "$work/sub" -DSSAO_SOURCE_DIR="$source" -DCMAKE_BUILD_TYPE=Release >/dev/null
if grep -E '^(embree_DIR|doctest_DIR|tinyexr_DIR|SSAO_TINYGLTF_LIBRARY)' "$work/sub/CMakeCache.txt"; then
  fail "configuring the library alone looked for the tools' or tests' dependencies"
fi
cmake --build "$work/sub" $jobs --target consumer >/dev/null
"$work/sub/consumer"
echo "package test: all passed"
