// raw_enum.h - the 32 bits a caller stored in an ABI enum field.
// A C caller may store any 32-bit value in an enum field (0xffffffff
// included), but in C++ loading a value outside the enum's range as the enum
// type is undefined behaviour (UBSan: "load of value ... not a valid value
// for type"). So every enum that comes through the ABI is range-checked on its
// raw bits, and only read as its enum type once it is known to be valid.
#pragma once

#include <cstdint>
#include <cstring>

namespace ssao_impl {

template <typename E>
uint32_t raw_enum(const E& field) {
    static_assert(sizeof(E) == sizeof(uint32_t), "ABI enums are 32 bits wide");
    uint32_t raw;
    std::memcpy(&raw, &field, sizeof raw);
    return raw;
}

// Is the field's raw value one of 0..last?
template <typename E>
bool raw_enum_at_most(const E& field, uint32_t last) {
    return raw_enum(field) <= last;
}

}  // namespace ssao_impl
