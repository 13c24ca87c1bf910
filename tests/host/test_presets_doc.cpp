// The presets have one source: the plugin's table (plugin/presets.cpp), read
// here through preset_settings. The header's preset comments, the README's
// preset table and ssao-host --help must each say what it returns, in the
// words of host/preset_text (so a changed row fails here until every copy
// follows).
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include "plugin_loader.h"
#include "preset_text.h"

#include <doctest/doctest.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace {

std::string read_file(const std::string& path) {
    std::ifstream f(path);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

std::string run_help() {
    std::string out;
    FILE* p = popen((std::string(SSAO_HOST_EXE) + " --help 2>&1").c_str(), "r");
    REQUIRE(p != nullptr);
    std::array<char, 4096> buf{};
    size_t n = 0;
    while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) out.append(buf.data(), n);
    CHECK(pclose(p) == 0);
    return out;
}

struct Named {
    ssao_preset preset;
    const char* enumerator;  // in the header
    const char* readme;      // the README table's first cell
};
const Named kPresets[] = {{SSAO_PRESET_LOW, "SSAO_PRESET_LOW", "`LOW`"},
                          {SSAO_PRESET_MEDIUM, "SSAO_PRESET_MEDIUM", "`MEDIUM` = `DEFAULT`"},
                          {SSAO_PRESET_HIGH, "SSAO_PRESET_HIGH", "`HIGH`"},
                          {SSAO_PRESET_ULTRA, "SSAO_PRESET_ULTRA", "`ULTRA`"},
                          {SSAO_PRESET_CHAPTER, "SSAO_PRESET_CHAPTER", "`CHAPTER`"}};

// The text of the line that starts with `start` (after leading blanks), or "".
std::string line_with(const std::string& text, const std::string& start) {
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        const size_t first = line.find_first_not_of(' ');
        if (first != std::string::npos && line.compare(first, start.size(), start) == 0) return line;
    }
    return "";
}

}  // namespace

TEST_CASE("the header, the README and ssao-host --help describe each preset as preset_settings returns it") {
    plugin::Library lib;
    std::string error;
    REQUIRE_MESSAGE(lib.open_default("", error), error);
    const std::string header = read_file(std::string(SSAO_SOURCE_DIR) + "/include/ssao/ssao.h");
    const std::string readme = read_file(std::string(SSAO_SOURCE_DIR) + "/README.md");
    const std::string help = run_help();
    REQUIRE(!header.empty());
    REQUIRE(!readme.empty());
    for (const Named& n : kPresets) {
        CAPTURE(n.enumerator);
        ssao_settings s{};
        s.size = sizeof s;
        REQUIRE(lib.api().preset_settings(n.preset, &s) == SSAO_OK);
        const std::string words = preset_text::describe(s);
        CAPTURE(words);
        const std::string h = line_with(header, std::string(n.enumerator) + " =");
        CAPTURE(h);
        CHECK(h.find("/**< " + words + " */") != std::string::npos);
        const std::string r = line_with(readme, std::string("| ") + n.readme + " |");
        CAPTURE(r);
        CHECK(r.find("| " + words + " |") != std::string::npos);
        CHECK(help.find(std::string(preset_text::name(n.preset)) + std::string(8 - std::string(preset_text::name(n.preset)).size(), ' ') +
                        words) != std::string::npos);
    }
    // A zeroed struct is the DEFAULT preset, which is MEDIUM.
    ssao_settings zero{}, resolved{}, medium{};
    zero.size = resolved.size = medium.size = sizeof zero;
    REQUIRE(lib.api().resolve_settings(&zero, &resolved) == SSAO_OK);
    REQUIRE(lib.api().preset_settings(SSAO_PRESET_MEDIUM, &medium) == SSAO_OK);
    CHECK(preset_text::describe(resolved) == preset_text::describe(medium));
}
