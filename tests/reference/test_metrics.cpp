// Metrics on images whose answers are known, and the EXR reader on files it must refuse.
#include "image_io.h"
#include "metrics.h"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <unistd.h>

TEST_SUITE("metrics") {

TEST_CASE("constant offset: RMSE, PSNR, mean error, percentile") {
    const int w = 20, h = 10;
    std::vector<float> ref(size_t(w * h), 0.5f), test(size_t(w * h), 0.6f);
    metrics::Inputs in;
    in.width = w;
    in.height = h;
    in.test = &test;
    in.reference = &ref;
    in.band = 0;
    std::vector<metrics::Stats> s;
    std::string err;
    REQUIRE(metrics::compute(in, s, err));
    REQUIRE(s.size() == 4u);
    CHECK(s[0].mask == "all");
    CHECK(s[0].pixels == 200u);
    CHECK(s[0].rmse == doctest::Approx(0.1).epsilon(1e-5));
    CHECK(s[0].psnr == doctest::Approx(20.0).epsilon(1e-4));
    CHECK(s[0].mean_error == doctest::Approx(0.1).epsilon(1e-5));
    CHECK(s[0].p99_abs_error == doctest::Approx(0.1).epsilon(1e-5));
    CHECK(std::isnan(s[0].noise_mean));
    // With no bands everything is interior.
    CHECK(s[1].pixels == 200u);
    CHECK(s[2].pixels == 0u);
    CHECK(s[3].pixels == 0u);
}

TEST_CASE("the split by the limit: ours vs V_R, limit vs V_R, ours vs limit over the same masks") {
    const int w = 20, h = 10;
    // V_R 0.8, the limit 0.7 (0.1 too dark: what no depth-only method avoids),
    // ours 0.6 (0.1 below the limit: what the estimator adds). Top row is sky,
    // where the tested image and the limit are wildly off: must not count.
    std::vector<float> ref(size_t(w * h), 0.8f), limit(size_t(w * h), 0.7f), ours(size_t(w * h), 0.6f),
        cover(size_t(w * h), 1.0f);
    for (int x = 0; x < w; ++x) {
        cover[size_t(x)] = 0.0f;
        ours[size_t(x)] = limit[size_t(x)] = 5.0f;
    }
    metrics::Inputs in;
    in.width = w;
    in.height = h;
    in.test = &ours;
    in.reference = &ref;
    in.sky = &cover;
    in.band = 2;
    metrics::Split s;
    std::string err;
    REQUIRE(metrics::compute_split(in, limit, nullptr, s, err));
    REQUIRE(s.ours_vs_reference.size() == 4u);
    REQUIRE(s.limit_vs_reference.size() == 4u);
    REQUIRE(s.ours_vs_limit.size() == 4u);
    std::vector<metrics::Stats> plain;
    REQUIRE(metrics::compute(in, plain, err));
    for (size_t m = 0; m < 4; ++m) {
        INFO(plain[m].mask);
        CHECK(s.ours_vs_reference[m].pixels == plain[m].pixels);  // the same masks as compute()
        CHECK(s.limit_vs_reference[m].pixels == plain[m].pixels);
        CHECK(s.ours_vs_limit[m].pixels == plain[m].pixels);
        CHECK(s.ours_vs_reference[m].rmse == doctest::Approx(plain[m].rmse));
    }
    CHECK(s.ours_vs_reference[0].pixels == 180u);
    CHECK(s.ours_vs_reference[0].mean_error == doctest::Approx(-0.2).epsilon(1e-5));
    CHECK(s.limit_vs_reference[0].rmse == doctest::Approx(0.1).epsilon(1e-5));
    CHECK(s.limit_vs_reference[0].psnr == doctest::Approx(20.0).epsilon(1e-4));
    CHECK(s.ours_vs_limit[0].mean_error == doctest::Approx(-0.1).epsilon(1e-5));
    const std::string table = metrics::split_table(s);
    CHECK(table.find("limit vs V_R") != std::string::npos);
    const std::string csv = metrics::csv_rows(s, "x");
    CHECK(csv.find("x,all,180,0,0.2000000,") != std::string::npos);
    CHECK(csv.find(",V_R\n") != std::string::npos);
    CHECK(csv.find(",limit\n") != std::string::npos);
    CHECK(csv.find(",limit_vs_V_R\n") != std::string::npos);
    // A limit of the wrong size, or NaN on geometry, is refused.
    std::vector<float> small(10, 0.5f);
    CHECK_FALSE(metrics::compute_split(in, small, nullptr, s, err));
    limit[50] = std::numeric_limits<float>::quiet_NaN();
    CHECK_FALSE(metrics::compute_split(in, limit, nullptr, s, err));
    CHECK(err.find("non-finite") != std::string::npos);
}

TEST_CASE("too dark gives a negative mean error, identical images give infinite PSNR") {
    std::vector<float> ref(16, 0.8f), dark(16, 0.6f);
    std::vector<uint8_t> all(16, 1);
    const auto s = metrics::stats_over(dark, ref, all, nullptr, "all");
    CHECK(s.mean_error == doctest::Approx(-0.2).epsilon(1e-5));
    const auto same = metrics::stats_over(ref, ref, all, nullptr, "all");
    CHECK(same.rmse == 0.0);
    CHECK(std::isinf(same.psnr));
}

TEST_CASE("percentile is nearest-rank") {
    std::vector<double> v;
    for (int i = 0; i < 100; ++i) v.push_back(i / 100.0);
    CHECK(metrics::percentile(v, 99.0) == doctest::Approx(0.98));
    CHECK(metrics::percentile(v, 100.0) == doctest::Approx(0.99));
    CHECK(metrics::percentile(v, 50.0) == doctest::Approx(0.49));
    CHECK(metrics::percentile({}, 99.0) == 0.0);
    CHECK(metrics::percentile({3.0}, 99.0) == 3.0);
}

TEST_CASE("known RMSE from mixed errors") {
    // Errors 0.3 on one pixel in four, 0 elsewhere: RMSE = 0.3 / 2 = 0.15.
    std::vector<float> ref(400, 0.5f), test(400, 0.5f);
    for (size_t i = 0; i < 400; i += 4) test[i] = 0.8f;
    std::vector<uint8_t> all(400, 1);
    const auto s = metrics::stats_over(test, ref, all, nullptr, "all");
    CHECK(s.rmse == doctest::Approx(0.15).epsilon(1e-5));
    CHECK(s.psnr == doctest::Approx(-20.0 * std::log10(0.15)).epsilon(1e-4));
    CHECK(s.mean_error == doctest::Approx(0.075).epsilon(1e-5));
    CHECK(s.p99_abs_error == doctest::Approx(0.3).epsilon(1e-5));
    CHECK(s.max_abs_error == doctest::Approx(0.3).epsilon(1e-5));
}

TEST_CASE("sky is excluded, non-finite test pixels are counted and skipped") {
    const int w = 10, h = 10;
    std::vector<float> ref(100, 0.5f), test(100, 0.5f), cover(100, 1.0f);
    for (int i = 0; i < 10; ++i) {
        cover[size_t(i)] = 0.0f;  // top row is sky
        test[size_t(i)] = 100.0f;  // wildly wrong there: must not count
    }
    test[55] = std::numeric_limits<float>::quiet_NaN();
    metrics::Inputs in;
    in.width = w;
    in.height = h;
    in.test = &test;
    in.reference = &ref;
    in.sky = &cover;
    in.band = 0;
    std::vector<metrics::Stats> s;
    std::string err;
    REQUIRE(metrics::compute(in, s, err));
    CHECK(s[0].pixels == 89u);
    CHECK(s[0].non_finite == 1u);
    CHECK(s[0].rmse == 0.0);
}

TEST_CASE("border band and silhouette band from depth") {
    const int w = 20, h = 20;
    std::vector<float> ref(400, 1.0f), test(400, 1.0f), depth(400, 10.0f), se(400, 0.01f);
    for (int y = 0; y < h; ++y)
        for (int x = 10; x < w; ++x) depth[size_t(y * w + x)] = 20.0f;  // a step between columns 9 and 10
    metrics::Inputs in;
    in.width = w;
    in.height = h;
    in.test = &test;
    in.reference = &ref;
    in.depth = &depth;
    in.std_error = &se;
    in.band = 3;
    metrics::Masks m;
    std::string err;
    REQUIRE(metrics::build_masks(in, m, err));
    size_t border = 0, sil = 0, interior = 0;
    for (size_t i = 0; i < 400; ++i) {
        border += m.border[i];
        sil += m.silhouette[i];
        interior += m.interior[i];
    }
    CHECK(border == size_t(400 - 14 * 14));
    CHECK(sil == size_t(6 * 20));  // columns 7..12: three either side of the step
    CHECK(interior == size_t(14 * 14 - 6 * 14));
    std::vector<metrics::Stats> s;
    REQUIRE(metrics::compute(in, s, err));
    CHECK(s[0].noise_mean == doctest::Approx(0.01).epsilon(1e-5));
    CHECK(s[0].noise_rms == doctest::Approx(0.01).epsilon(1e-5));
    CHECK(metrics::table(s).find("silhouette") != std::string::npos);
    CHECK(metrics::csv_rows(s, "x").find("x,border,204,") != std::string::npos);
}

TEST_CASE("mismatched sizes are an error") {
    std::vector<float> a(16, 0.0f), b(15, 0.0f);
    metrics::Inputs in;
    in.width = 4;
    in.height = 4;
    in.test = &a;
    in.reference = &b;
    std::vector<metrics::Stats> s;
    std::string err;
    CHECK_FALSE(metrics::compute(in, s, err));
    CHECK(err.find("reference") != std::string::npos);
}

TEST_CASE("EXR round trip keeps NaN-free floats and channel names") {
    const auto dir = std::filesystem::temp_directory_path() / ("ssao_metrics_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "t.exr").string();
    std::vector<float> y(12), a(12);
    for (size_t i = 0; i < 12; ++i) {
        y[i] = float(i) / 11.0f;
        a[i] = float(i % 2);
    }
    std::string err;
    REQUIRE(refio::write_exr(path, 4, 3, {{"Y", &y}, {"A", &a}}, err));
    std::vector<float> back;
    int w = 0, h = 0;
    std::string used;
    REQUIRE(refio::read_exr_channel(path, {"Y"}, back, w, h, err, &used));
    CHECK(w == 4);
    CHECK(h == 3);
    CHECK(used == "Y");
    CHECK(back == y);
    REQUIRE(refio::read_exr_channel(path, {"A"}, back, w, h, err));
    CHECK(back == a);
    CHECK(refio::exr_has_channel(path, "A"));
    CHECK_FALSE(refio::exr_has_channel(path, "Z"));
    CHECK_FALSE(refio::read_exr_channel((dir / "missing.exr").string(), {"Y"}, back, w, h, err));
    CHECK(err.find("missing.exr") != std::string::npos);
    std::filesystem::remove_all(dir);
}

TEST_CASE("a truncated EXR is refused with a sentence, and nothing it allocated is kept") {
    // Cut in the pixels: tinyexr 1.0.1 frees a failed load's channel buffers only up to the
    // image's channel count, which it sets after decoding: every truncated
    // file leaked its buffers (LeakSanitizer, found by fuzz_exr).
    const auto dir = std::filesystem::temp_directory_path() / ("ssao_metrics_cut_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "cut.exr").string();
    std::vector<float> y(64, 0.5f), a(64, 1.0f);
    std::string err;
    REQUIRE(refio::write_exr(path, 8, 8, {{"Y", &y}, {"A", &a}}, err));
    std::filesystem::resize_file(path, std::filesystem::file_size(path) - 10);
    std::vector<float> back;
    int w = 0, h = 0;
    CHECK_FALSE(refio::read_exr_channel(path, {"Y"}, back, w, h, err));
    CHECK(err.find("cut.exr") != std::string::npos);
    CHECK(err.find("cannot read the EXR pixels") != std::string::npos);
    // Cut inside the header, after its channel list: tinyexr had filled the
    // header's channels before failing, and a failed parse was not freed.
    REQUIRE(refio::write_exr(path, 8, 8, {{"Y", &y}, {"A", &a}}, err));
    std::string bytes;
    {
        std::ifstream in(path, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    const size_t cut = bytes.find("compression");
    REQUIRE(cut != std::string::npos);
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes.substr(0, cut + 3);
    CHECK_FALSE(refio::read_exr_channel(path, {"Y"}, back, w, h, err));
    CHECK(err.find("cannot parse the EXR header") != std::string::npos);
    CHECK_FALSE(refio::exr_has_channel(path, "Y"));
    // A data window from INT_MIN: tinyexr sizes its buffers from it (an
    // exabyte request, or std::length_error thrown out of its C API); the
    // reader refuses the file first.
    REQUIRE(refio::write_exr(path, 8, 8, {{"Y", &y}, {"A", &a}}, err));
    {
        std::ifstream in(path, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    const std::string key("dataWindow\0box2i\0", 17);
    const size_t window = bytes.find(key);
    REQUIRE(window != std::string::npos);
    bytes[window + key.size() + 4 + 4 + 3] = char(0x80);  // y_min's high byte
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
    CHECK_FALSE(refio::read_exr_channel(path, {"Y"}, back, w, h, err));
    CHECK(err.find("cut.exr") != std::string::npos);
    CHECK(err.find("data window") != std::string::npos);
    std::filesystem::remove_all(dir);
}

TEST_CASE("an EXR that tinyexr would abort on is refused with a sentence: a foreign type attribute, a tiled file") {
    // tinyexr asserts (the program aborts) on a "type" attribute outside its
    // four kinds or against the tiled flag, and on a tiled file's "tiles"
    // attribute of any size but 9 bytes (found by fuzz_exr).
    const auto dir = std::filesystem::temp_directory_path() / ("ssao_metrics_type_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "t.exr").string();
    std::vector<float> y(16, 0.25f), back;
    int w = 0, h = 0;
    std::string err;
    for (const std::string type : {"deeptile", "tiledimage", "deepscanline", "anything"}) {
        CAPTURE(type);
        REQUIRE(refio::write_exr(path, 4, 4, {{"Y", &y}}, err, {{"type", type}}));
        err.clear();
        CHECK_FALSE(refio::read_exr_channel(path, {"Y"}, back, w, h, err));
        CHECK(err.find(path + ": only scanline EXR images are supported") == 0);
        CHECK_FALSE(refio::exr_has_channel(path, "Y"));
    }
    // The one kind it reads, named or not: the same pixels.
    REQUIRE(refio::write_exr(path, 4, 4, {{"Y", &y}}, err, {{"type", "scanlineimage"}}));
    REQUIRE(refio::read_exr_channel(path, {"Y"}, back, w, h, err));
    CHECK(back == y);
    // The version's tiled bit (byte 5, 0x2) set on a scanline file.
    std::string bytes;
    {
        std::ifstream in(path, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    bytes[5] = char(bytes[5] | 0x2);
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
    CHECK_FALSE(refio::read_exr_channel(path, {"Y"}, back, w, h, err));
    CHECK(err == path + ": tiled EXR files are not supported.");
    std::filesystem::remove_all(dir);
}

TEST_CASE("cell spread: a pattern that repeats every 8 pixels, against noise-free and evenly spread errors") {
    const int w = 64, h = 48;
    const size_t n = size_t(w) * size_t(h);
    const std::vector<float> ref(n, 0.5f);
    const std::vector<uint8_t> geometry(n, 1);
    // The same error everywhere: no pattern at all.
    CHECK(metrics::cell_spread(std::vector<float>(n, 0.6f), ref, geometry, w, h) == doctest::Approx(0.0).epsilon(1e-9));
    // +0.1 at the even positions of the 8-pixel tile, -0.1 at the odd ones: a spread of 0.1.
    std::vector<float> tiled(n);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) tiled[size_t(y) * w + x] = 0.5f + (((x % 8) + (y % 8)) % 2 ? -0.1f : 0.1f);
    CHECK(metrics::cell_spread(tiled, ref, geometry, w, h) == doctest::Approx(0.1).epsilon(1e-5));
    // A pattern whose period is not the cell's averages out over the tiles.
    std::vector<float> other(n);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) other[size_t(y) * w + x] = 0.5f + ((x / 8) % 2 ? -0.1f : 0.1f);
    CHECK(metrics::cell_spread(other, ref, geometry, w, h) < 1e-6);
    // Sky is left out: a tiled error only on sky pixels counts for nothing.
    std::vector<uint8_t> half(n, 1);
    for (size_t i = 0; i < n; ++i) half[i] = tiled[i] < 0.5f;
    CHECK(metrics::cell_spread(tiled, ref, half, w, h) == doctest::Approx(0.0).epsilon(1e-9));
}

TEST_CASE("cell pattern: the tile's centred means, NaN where a position has no pixel, the common part of several") {
    const int w = 64, h = 48;
    const size_t n = size_t(w) * size_t(h);
    const std::vector<float> ref(n, 0.5f);
    const std::vector<uint8_t> geometry(n, 1);
    // A tile of +0.1 / -0.1 on a +0.2 offset: the pattern is the tile without the offset.
    std::vector<float> tiled(n);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) tiled[size_t(y) * w + x] = 0.7f + (((x % 8) + (y % 8)) % 2 ? -0.1f : 0.1f);
    const std::vector<double> p = metrics::cell_pattern(tiled, ref, geometry, w, h);
    REQUIRE(p.size() == 64);
    for (int k = 0; k < 64; ++k) CHECK(p[k] == doctest::Approx(((k % 8) + (k / 8)) % 2 ? -0.1 : 0.1).epsilon(1e-5));
    // Only column 0 of each tile holds geometry: the other positions are NaN.
    std::vector<uint8_t> column(n, 0);
    for (int y = 0; y < h; ++y) column[size_t(y) * w] = 1;
    const std::vector<double> q = metrics::cell_pattern(tiled, ref, column, w, h);
    CHECK(std::isfinite(q[0]));
    CHECK(std::isnan(q[1]));
    CHECK(metrics::cell_spread(tiled, ref, column, w, h) == doctest::Approx(0.1).epsilon(1e-5));

    // Several images: the tile in all of them survives their mean, patterns
    // that differ from image to image (here two opposite ones) cancel.
    std::vector<double> a(64), b(64), c(64);
    for (int k = 0; k < 64; ++k) {
        a[k] = p[k] + (k % 3 == 0 ? 0.05 : -0.025);
        b[k] = p[k] - (k % 3 == 0 ? 0.05 : -0.025);
        c[k] = -p[k];
    }
    CHECK(metrics::common_pattern({a, b}) == doctest::Approx(0.1).epsilon(1e-5));
    CHECK(metrics::common_pattern({p, c}) == doctest::Approx(0.0).epsilon(1e-12));
    // A position NaN in any image is left out; none at all gives NaN.
    std::vector<double> holed = a;
    holed[0] = std::numeric_limits<double>::quiet_NaN();
    CHECK(metrics::common_pattern({holed, b}) == doctest::Approx(0.1).epsilon(1e-5));
    CHECK(std::isnan(metrics::common_pattern({})));
}

TEST_CASE("occluded bias: the mean error where the reference is below 0.5, NaN where there is none") {
    const std::vector<float> ref = {0.2f, 0.4f, 0.9f, 0.3f};
    const std::vector<float> test = {0.3f, 0.6f, 0.5f, 0.0f};
    CHECK(metrics::occluded_bias(test, ref, {1, 1, 1, 0}) == doctest::Approx((0.1 + 0.2) / 2).epsilon(1e-6));
    CHECK(std::isnan(metrics::occluded_bias(test, ref, {0, 0, 1, 0})));
}

}  // TEST_SUITE
