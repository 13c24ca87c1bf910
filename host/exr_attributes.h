// exr_attributes.h - string attributes for a tinyexr header (what an image was
// made with: host/provenance.h), shared by ssao-host's and the reference
// tools' EXR writers. The attributes point into `pairs`, which must outlive
// the SaveEXRImageToFile call.
#pragma once

#include <tinyexr.h>

#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace exr_attributes {

inline std::vector<EXRAttribute> strings(const std::vector<std::pair<std::string, std::string>>& pairs) {
    std::vector<EXRAttribute> out(pairs.size());
    for (size_t i = 0; i < pairs.size(); ++i) {
        std::memset(&out[i], 0, sizeof out[i]);
        std::strncpy(out[i].name, pairs[i].first.c_str(), sizeof out[i].name - 1);
        std::strcpy(out[i].type, "string");
        out[i].value = reinterpret_cast<unsigned char*>(const_cast<char*>(pairs[i].second.data()));
        out[i].size = static_cast<int>(pairs[i].second.size());
    }
    return out;
}

}  // namespace exr_attributes
