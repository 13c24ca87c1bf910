// test_struct_versions.cpp - the helper entry points use to accept the structs
// of older headers (plugin/struct_versions.h): known sizes, and prefix copies
// that never touch memory past the caller's struct.
#include "struct_versions.h"

#include <doctest/doctest.h>

#include <cstring>
#include <initializer_list>

using namespace ssao_impl;

TEST_CASE("struct versions: ssao_timings knows its 1.0 and 1.1 sizes and no other") {
    CHECK(is_known_size<ssao_timings>(40));
    CHECK(is_known_size<ssao_timings>(sizeof(ssao_timings)));
    for (uint32_t size : {0u, 4u, 36u, 39u, 41u, 44u, 48u, static_cast<uint32_t>(sizeof(ssao_timings) + 8)})
        CHECK_FALSE(is_known_size<ssao_timings>(size));
    // Unregistered structs have one version.
    CHECK(is_known_size<ssao_output>(sizeof(ssao_output)));
    CHECK_FALSE(is_known_size<ssao_output>(sizeof(ssao_output) - 4));
}

TEST_CASE("struct versions: write_prefix fills only the caller's version, read_prefix zero-fills the rest") {
    ssao_timings full{};
    full.size = sizeof full;
    full.available = 1;
    full.frame = 42;
    full.total_ms = 3.5;
    full.pass_count = 2;
    full.pass_ms[1] = 1.25;

    ssao_timings old;
    std::memset(&old, 0xA5, sizeof old);
    old.size = 40;
    write_prefix(&old, full);
    CHECK(old.size == 40u);
    CHECK(old.available == 1u);
    CHECK(old.frame == 42u);
    CHECK(old.total_ms == 3.5);
    unsigned char tail[sizeof(ssao_timings) - 40];
    std::memset(tail, 0xA5, sizeof tail);
    CHECK(std::memcmp(reinterpret_cast<const unsigned char*>(&old) + 40, tail, sizeof tail) == 0);

    // Reading a 1.0 struct: the 1.1 fields it lacks are zero ("default").
    const ssao_timings read = read_prefix(old);
    CHECK(read.size == sizeof(ssao_timings));
    CHECK(read.frame == 42u);
    CHECK(read.pass_count == 0u);
    CHECK(read.pass_ms[1] == 0.0);
}
