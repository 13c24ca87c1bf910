// locate.h - where the running program finds the bundled data and the build
// it came from, so that an installed (or moved) tree never depends on the
// build tree or the source tree that produced it.
#pragma once

#include <string>

namespace locate {

// The directory of the running executable (from /proc/self/exe, symlinks
// resolved), or "" when it cannot be read.
std::string executable_dir();

// The build tree's own paths are not compiled into the programs: CMake writes
// them into a file, kBuildTreeFile, at the top of the build directory only
// (never installed). A program lies in a build tree when that file is in its
// own directory or one above it; installed and moved copies find none.
inline constexpr const char* kBuildTreeFile = "ssao-build-tree.txt";

// Whether the running executable lies inside a build tree (an uninstalled build).
bool in_build_tree();

// A value of the build tree's file ("plugin": the built libssao.so; "data":
// the source tree's assets/), or "" outside a build tree or for an unknown key.
std::string build_tree_value(const std::string& key);

// The bundled data (models/, scenes/), first found of:
//   1. $SSAO_DATA_DIR
//   2. <executable dir>/../share/ssao      (the installed layout)
//   3. the build tree file's "data"         (uninstalled builds only)
// "" when none holds the data.
std::string data_dir();

// A bundled file by its path under the data directory ("models/spot-on-ground.glb").
// When the data directory is not found, returns the relative path itself, so
// the loader's message names the file it could not open.
std::string bundled(const std::string& relative);

}  // namespace locate
