// struct_versions.h - the sizes of every published version of the ABI's
// versioned structs, so an entry point accepts a struct from a host compiled
// against an older header ("Future versions only append fields; the library
// accepts the sizes of every version it knows", ssao.h).
//
// Registering a struct that grew: add a specialisation of KnownSizes listing
// each published size, oldest first, ending with sizeof(T); pin the literal
// old sizes to the layout with a static_assert on the offset of the first
// appended field. Then, in the entry point:
//   - a struct the library fills (out):  if (!is_known_size<T>(out->size)) -> STRUCT_SIZE;
//                                        write_prefix(out, full);
//   - a struct the library reads (in):   if (!is_known_size<T>(in->size)) -> STRUCT_SIZE;
//                                        const T full = read_prefix(*in);  // appended fields zero
//     (a zero field means "the default" throughout the ABI, so an old
//     struct's missing tail reads as defaults).
#pragma once

#include <ssao/ssao.h>

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace ssao_impl {

// Unregistered structs have one version: this header's.
template <typename T>
struct KnownSizes {
    static constexpr uint32_t sizes[] = {static_cast<uint32_t>(sizeof(T))};
};

// ssao_timings: 1.0 ended at total_ms; 1.1 appended the per-pass times.
constexpr uint32_t kTimingsSize_1_0 = 40;
static_assert(offsetof(ssao_timings, pass_count) == kTimingsSize_1_0, "ssao_timings 1.0 prefix moved");
template <>
struct KnownSizes<ssao_timings> {
    static constexpr uint32_t sizes[] = {kTimingsSize_1_0, static_cast<uint32_t>(sizeof(ssao_timings))};
};

// ssao_settings: 1.0 ended at output_format; 1.1 appended method .. resolution;
// 1.2 fade_start .. debug_view (1.3 added none); 1.4 max_step_texels.
static_assert(offsetof(ssao_settings, method) == SSAO_SETTINGS_SIZE_1_0, "ssao_settings 1.0 prefix moved");
static_assert(offsetof(ssao_settings, fade_start) == SSAO_SETTINGS_SIZE_1_1, "ssao_settings 1.1 prefix moved");
static_assert(offsetof(ssao_settings, max_step_texels) == SSAO_SETTINGS_SIZE_1_2, "ssao_settings 1.2 prefix moved");
template <>
struct KnownSizes<ssao_settings> {
    static constexpr uint32_t sizes[] = {SSAO_SETTINGS_SIZE_1_0, SSAO_SETTINGS_SIZE_1_1, SSAO_SETTINGS_SIZE_1_2,
                                         static_cast<uint32_t>(sizeof(ssao_settings))};
};

// ssao_inputs: 1.0 and 1.1 ended at output_texture; 1.2 appended sample_index .. frame_index.
static_assert(offsetof(ssao_inputs, sample_index) == SSAO_INPUTS_SIZE_1_1, "ssao_inputs 1.1 prefix moved");
template <>
struct KnownSizes<ssao_inputs> {
    static constexpr uint32_t sizes[] = {SSAO_INPUTS_SIZE_1_1, static_cast<uint32_t>(sizeof(ssao_inputs))};
};

template <typename T>
constexpr bool is_known_size(uint32_t size) {
    for (uint32_t s : KnownSizes<T>::sizes)
        if (s == size) return true;
    return false;
}

// Copies the first out->size bytes of `full` into *out and keeps out->size
// (the caller's version). out->size must be known (is_known_size).
template <typename T>
void write_prefix(T* out, const T& full) {
    const uint32_t size = out->size;
    std::memcpy(static_cast<void*>(out), &full, size);
    out->size = size;
}

// The full struct from a caller's (possibly older, shorter) one: the fields
// it lacks are zero, and size says this library's version.
template <typename T>
T read_prefix(const T& in) {
    T full{};
    std::memcpy(static_cast<void*>(&full), &in, in.size);
    full.size = static_cast<uint32_t>(sizeof(T));
    return full;
}

}  // namespace ssao_impl
