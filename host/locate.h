// locate.h - where the running program finds the bundled data and the build
// it came from, so that an installed (or moved) tree never depends on the
// build tree or the source tree that produced it.
#pragma once

#include <string>

namespace locate {

// The directory of the running executable (from /proc/self/exe, symlinks
// resolved), or "" when it cannot be read.
std::string executable_dir();

// Whether the running executable lies inside the build tree it was built in
// (an uninstalled build). Installed and moved copies answer false.
bool in_build_tree();

// The bundled data (models/, scenes/), first found of:
//   1. $SSAO_DATA_DIR
//   2. <executable dir>/../share/ssao      (the installed layout)
//   3. <source tree>/assets                 (uninstalled builds only)
// "" when none holds the data.
std::string data_dir();

// A bundled file by its path under the data directory ("models/spot-on-ground.glb").
// When the data directory is not found, returns the relative path itself, so
// the loader's message names the file it could not open.
std::string bundled(const std::string& relative);

}  // namespace locate
