// tiny_gltf_quiet.h - tiny_gltf.h with the warnings its code raises under our
// flags (-Wshadow, -Wunused-parameter, -Wpedantic) silenced for it alone.
#pragma once

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wpedantic"
#endif
#include <tiny_gltf.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
