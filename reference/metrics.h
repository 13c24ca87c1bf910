// metrics.h - error of an AO image against the ray-traced reference, over masks.
// Reused by ssao-error and the benchmark.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace metrics {

struct Stats {
    std::string mask;            // "all", "interior", "silhouette", "border"
    size_t pixels = 0;           // pixels compared (geometry, finite in both images)
    size_t non_finite = 0;       // geometry pixels where the tested image is NaN/inf (not compared)
    double rmse = 0.0;
    double psnr = 0.0;           // dB, peak 1; +inf when rmse == 0
    double mean_error = 0.0;     // mean of (test - reference): < 0 too dark, > 0 too light
    double p99_abs_error = 0.0;  // 99th percentile of |test - reference|
    double max_abs_error = 0.0;
    double noise_mean = 0.0;     // mean reference standard error (NaN when unknown)
    double noise_rms = 0.0;      // sqrt(mean(std_error^2)): the RMSE the reference's own noise explains
};

struct Inputs {
    int width = 0, height = 0;
    const std::vector<float>* test = nullptr;       // AO under test
    const std::vector<float>* reference = nullptr;  // ray-traced AO
    const std::vector<float>* sky = nullptr;        // optional: 1 = geometry, 0 = sky (else NaN reference = sky)
    const std::vector<float>* std_error = nullptr;  // optional: reference standard error
    const std::vector<float>* depth = nullptr;      // optional: reference view depth (0 or non-finite = sky)
    int band = 3;                                   // width of the silhouette and border bands, pixels
    float depth_jump = 0.05f;                       // relative depth step counted as a discontinuity
    float ao_jump = 0.25f;                          // without depth: AO step counted as an edge
};

// Masks (width*height, 1 = in the mask); geometry only.
struct Masks {
    std::vector<uint8_t> geometry, silhouette, border, interior;
};
bool build_masks(const Inputs& in, Masks& out, std::string& error);

// Stats for all, interior, silhouette and border, in that order.
bool compute(const Inputs& in, std::vector<Stats>& out, std::string& error);

// Stats of `test` against `reference` over the pixels where mask != 0
// (sky and non-finite pixels must already be excluded by the mask, except
// that non-finite test values are counted and skipped).
Stats stats_over(const std::vector<float>& test, const std::vector<float>& reference, const std::vector<uint8_t>& mask,
                 const std::vector<float>* std_error, const std::string& name);

// Percentile q in [0,100] of values (nearest rank); 0 for an empty list.
double percentile(std::vector<double> values, double q);

// The error split by the depth-only limit (ssao-reference --limit, limit_ao.exr),
// over the masks of compute(): ours vs V_R (in.test vs in.reference), limit vs
// V_R (what no depth-only method can avoid) and ours vs the limit (what the
// estimator adds). limit_std_error (optional) is the noise of the limit.
struct Split {
    std::vector<Stats> ours_vs_reference, limit_vs_reference, ours_vs_limit;
};
bool compute_split(const Inputs& in, const std::vector<float>& limit, const std::vector<float>* limit_std_error,
                   Split& out, std::string& error);

// Text tables and CSV rows. The CSV's last column, `against`, names what the
// row compares: "V_R" (the tested image against the reference), "limit" (the
// tested image against the limit) or "limit_vs_V_R" (the limit against V_R).
// The error (test - reference) averaged separately at each of the cell x cell
// positions of a tile of pixels, less the mean of those averages: what repeats
// every `cell` pixels, cell * cell values row by row (NaN at a position with
// no pixel). Pixels where `geometry` is 0 are left out.
std::vector<double> cell_pattern(const std::vector<float>& test, const std::vector<float>& reference,
                                 const std::vector<uint8_t>& geometry, int width, int height, int cell = 8);

// The fixed-pattern ("stipple") figure of one image: the spread (RMS) of its
// cell_pattern. A rotation pattern that repeats every `cell` pixels shows as a
// spread well above what noise and content leave; but noise whose blotches
// are a few pixels wide raises it too. NaN when no position has a pixel.
double cell_spread(const std::vector<float>& test, const std::vector<float>& reference,
                   const std::vector<uint8_t>& geometry, int width, int height, int cell = 8);
// The same from a cell_pattern already computed: the RMS of its finite values.
double pattern_spread(const std::vector<double>& pattern);

// The part of several images' cell patterns (of one size of cell) that they
// share: the RMS over the positions of their mean, leaving out a position
// that is NaN in any of them. A pattern fixed on the screen (a rotation tile,
// where a reduced grid picks its pixels) survives the mean; noise and content,
// which differ from image to image, shrink with it (independent noise as
// 1/sqrt(count)). NaN for none.
double common_pattern(const std::vector<std::vector<double>>& patterns);

// Mean of (test - reference) over the geometry pixels whose reference AO is
// below `below`: the bias in the occluded places (contact shadows, creases),
// which the image's mean hides among the open ones. NaN when there is none.
double occluded_bias(const std::vector<float>& test, const std::vector<float>& reference,
                     const std::vector<uint8_t>& geometry, double below = 0.5);

std::string table(const std::vector<Stats>& s);
std::string split_table(const Split& s);
std::string csv_header();
std::string csv_rows(const std::vector<Stats>& s, const std::string& label, const std::string& against = "V_R");
std::string csv_rows(const Split& s, const std::string& label);

}  // namespace metrics
