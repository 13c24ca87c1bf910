# Sourced by the build scripts: compile through ccache when it is installed
# (scripts/install-deps.sh installs it), with paths taken relative to the
# checkout so that a second clone of the same commit (CI's) hits the cache.
# SSAO_CCACHE=0 turns it off.
ssao_cmake_launcher=()
if [ "${SSAO_CCACHE:-1}" != 0 ] && command -v ccache >/dev/null; then
  export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$PWD} CCACHE_NOHASHDIR=1
  ssao_cmake_launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
