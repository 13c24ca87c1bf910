# Checks shared by the package tests (sourced by run_package_test.sh and
# run_deb_test.sh): an installed tree at a prefix P, wherever it came from
# (cmake --install, or Debian packages extracted with dpkg-deb -x).
# Sourced as `. checks.sh BUILD_DIR SOURCE_DIR` after setting $here (this
# folder) and $test_name (for messages); sets $build, $source, $work (a scratch
# folder, removed on exit), fail and step, and clears the variables through
# which a run could reach the build tree.
build=$(cd "$1" && pwd)
source=$(cd "$2" && pwd)
work=$(mktemp -d /tmp/ssao-package.XXXXXX)
trap 'rm -rf "$work"' EXIT
fail() { echo "$test_name: $*" >&2; exit 1; }
step() { echo "== $*"; }
unset SSAO_PLUGIN SSAO_DATA_DIR PYTHONPATH

# The version every file of the package states: project(ssao VERSION ...).
ssao_version=$(sed -n 's/^project(ssao VERSION \([0-9.]*\).*/\1/p' "$source/CMakeLists.txt")
[ -n "$ssao_version" ] || fail "no project(ssao VERSION ...) in $source/CMakeLists.txt"
ssao_api=${ssao_version%.*}   # major.minor: the C interface version

# No absolute path of the build or source tree in any installed file: the
# programs find the plugin and data relative to themselves only.
check_no_build_paths() {
  local p=$1 f hits=""
  while IFS= read -r -d '' f; do
    if strings -a "$f" | grep -qF -e "$build" -e "$source"; then
      hits+=" ${f#$p/}: $(strings -a "$f" | grep -F -e "$build" -e "$source" | head -n 2 | tr '\n' ' ')"
    fi
  done < <(find "$p" -type f -print0)
  [ -z "$hits" ] || fail "installed files name the build or source tree:$hits"
}

# Every tool's --version states the package version and the interface version.
check_versions() {
  local p=$1 tool v
  for tool in ssao-host ssao-reference ssao-error ssao-bench ssao-viewer; do
    v=$("$p/bin/$tool" --version)
    echo "$v"
    [ "$v" = "$tool $ssao_version (C ABI $ssao_api)" ] || fail "$tool --version printed '$v', not '$tool $ssao_version (C ABI $ssao_api)'"
  done
}

# The installed viewer names the installed demo script in its --help.
check_viewer() {
  local p=$1
  [ -f "$p/share/ssao/viewer/demo.txt" ] || fail "missing share/ssao/viewer/demo.txt"
  "$p/bin/ssao-viewer" --help | grep -qF "A tour of the keys: $p/share/ssao/viewer/demo.txt" ||
    fail "ssao-viewer --help does not name $p/share/ssao/viewer/demo.txt"
}

# The installed host renders the bundled scene with the installed plugin.
check_host_renders() {
  local p=$1 out
  out=$("$p/bin/ssao-host" --width 64 --height 48 --frames 2 --out "$work/render")
  echo "$out" | sed -n '1p;/plugin:/p'
  echo "$out" | grep -qF "ssao-host: $p/share/ssao/models/spot-on-ground.glb" || fail "the host did not render the installed bundled scene"
  echo "$out" | grep -qF "plugin: $(readlink -f "$p/lib/libssao.so.1")" || echo "$out" | grep -qF "plugin: $p/lib/libssao.so.1" ||
    fail "the host did not load the installed plugin"
  for f in ao.png ao.exr lit_ao.png lit_no_ao.png; do [ -s "$work/render/$f" ] || fail "the host wrote no $f"; done
}

# The installed Python package: its version, and Library() finds the installed library.
check_python() {
  local p=$1 got
  [ -f "$p/lib/python3/dist-packages/ssao/__init__.py" ] || fail "missing lib/python3/dist-packages/ssao"
  [ ! -e "$p/lib/python3/dist-packages/ssao/_build_paths.py" ] || fail "the installed Python package names the build tree"
  got=$(cd "$work" && env -u SSAO_PLUGIN PYTHONPATH="$p/lib/python3/dist-packages" /usr/bin/python3 -c \
        'import ssao; lib = ssao.Library(); print(ssao.__version__, lib.path, "%d.%d" % lib.version)')
  echo "python: $got"
  [ "$got" = "$ssao_version $p/lib/libssao.so.1 $ssao_api" ] || fail "python printed '$got', not '$ssao_version $p/lib/libssao.so.1 $ssao_api'"
}

# The find_package and pkg-config consumers, built against P and run; they
# require this version and are refused a newer one.
check_consumers() {
  local p=$1 newer
  newer="${ssao_version%%.*}.$(( $(echo "$ssao_version" | cut -d. -f2) + 1 ))"
  step "consumer: find_package(ssao $ssao_api CONFIG REQUIRED)"
  cmake -S "$here/find_package" -B "$work/fp" -DCMAKE_PREFIX_PATH="$p" -DSSAO_REQUIRED_VERSION="$ssao_api" \
        -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$work/fp" -j2 >/dev/null
  "$work/fp/consumer"
  LD_LIBRARY_PATH="$p/lib" "$work/fp/consumer_dlopen"
  if cmake -S "$here/find_package" -B "$work/fp-newer" -DCMAKE_PREFIX_PATH="$p" -DSSAO_REQUIRED_VERSION="$newer" \
       >"$work/fp-newer.log" 2>&1; then
    fail "find_package(ssao $newer) accepted version $ssao_version"
  fi
  grep -qF "$ssao_version" "$work/fp-newer.log" || fail "find_package(ssao $newer) failed without naming $ssao_version"
  echo "find_package(ssao $newer) refused, as it should"

  step "consumer: pkg-config --atleast-version=$ssao_api ssao"
  export PKG_CONFIG_PATH="$p/lib/pkgconfig"
  [ "$(pkg-config --modversion ssao)" = "$ssao_version" ] || fail "pkg-config --modversion ssao is '$(pkg-config --modversion ssao)'"
  pkg-config --atleast-version="$ssao_api" ssao || fail "pkg-config --atleast-version=$ssao_api ssao failed"
  ! pkg-config --atleast-version="$newer" ssao || fail "pkg-config --atleast-version=$newer ssao passed for $ssao_version"
  echo "pkg-config: $(pkg-config --cflags --libs ssao) (version $(pkg-config --modversion ssao))"
  make -s -C "$here/pkg_config" OUT="$work"
  LD_LIBRARY_PATH="$p/lib" "$work/consumer"
}
