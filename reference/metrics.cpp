#include "metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <utility>

namespace metrics {

double percentile(std::vector<double> v, double q) {
    if (v.empty()) return 0.0;
    q = std::min(std::max(q, 0.0), 100.0);
    // Nearest rank: the smallest value with at least q% of the values <= it.
    size_t rank = size_t(std::ceil(q / 100.0 * double(v.size())));
    if (rank < 1) rank = 1;
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(rank - 1), v.end());
    return v[rank - 1];
}

Stats stats_over(const std::vector<float>& test, const std::vector<float>& ref, const std::vector<uint8_t>& mask,
                 const std::vector<float>* std_error, const std::string& name) {
    Stats s;
    s.mask = name;
    double se = 0.0, sum = 0.0, noise = 0.0, noise2 = 0.0;
    std::vector<double> abs_err;
    for (size_t i = 0; i < mask.size() && i < test.size() && i < ref.size(); ++i) {
        if (!mask[i]) continue;
        if (!std::isfinite(test[i])) {
            ++s.non_finite;
            continue;
        }
        const double e = double(test[i]) - double(ref[i]);
        se += e * e;
        sum += e;
        abs_err.push_back(std::fabs(e));
        s.max_abs_error = std::max(s.max_abs_error, std::fabs(e));
        if (std_error && i < std_error->size()) {
            const double sd = (*std_error)[i];
            noise += sd;
            noise2 += sd * sd;
        }
        ++s.pixels;
    }
    if (s.pixels > 0) {
        const double n = double(s.pixels);
        s.rmse = std::sqrt(se / n);
        s.mean_error = sum / n;
        s.noise_mean = std_error ? noise / n : std::numeric_limits<double>::quiet_NaN();
        s.noise_rms = std_error ? std::sqrt(noise2 / n) : std::numeric_limits<double>::quiet_NaN();
    } else {
        s.noise_mean = s.noise_rms = std::numeric_limits<double>::quiet_NaN();
    }
    s.psnr = s.rmse > 0.0 ? -20.0 * std::log10(s.rmse) : std::numeric_limits<double>::infinity();
    if (s.pixels == 0) s.psnr = std::numeric_limits<double>::quiet_NaN();
    s.p99_abs_error = percentile(std::move(abs_err), 99.0);
    return s;
}

namespace {

// Square (Chebyshev) dilation by r pixels, separable.
std::vector<uint8_t> dilate(const std::vector<uint8_t>& m, int w, int h, int r) {
    if (r <= 0) return m;
    std::vector<uint8_t> tmp(m.size(), 0), out(m.size(), 0);
    for (int y = 0; y < h; ++y) {
        int last = -1000000;  // most recent set pixel to the left (incl. x + r lookahead)
        // Two sweeps are simplest: distance to nearest set pixel in the row.
        std::vector<int> dist(size_t(w), 1 << 29);
        for (int x = 0; x < w; ++x) {
            if (m[size_t(y) * size_t(w) + size_t(x)]) last = x;
            dist[size_t(x)] = x - last;
        }
        last = 1000000;
        for (int x = w - 1; x >= 0; --x) {
            if (m[size_t(y) * size_t(w) + size_t(x)]) last = x;
            dist[size_t(x)] = std::min(dist[size_t(x)], last - x);
            tmp[size_t(y) * size_t(w) + size_t(x)] = dist[size_t(x)] <= r;
        }
    }
    for (int x = 0; x < w; ++x) {
        int last = -1000000;
        std::vector<int> dist(size_t(h), 1 << 29);
        for (int y = 0; y < h; ++y) {
            if (tmp[size_t(y) * size_t(w) + size_t(x)]) last = y;
            dist[size_t(y)] = y - last;
        }
        last = 1000000;
        for (int y = h - 1; y >= 0; --y) {
            if (tmp[size_t(y) * size_t(w) + size_t(x)]) last = y;
            dist[size_t(y)] = std::min(dist[size_t(y)], last - y);
            out[size_t(y) * size_t(w) + size_t(x)] = dist[size_t(y)] <= r;
        }
    }
    return out;
}

}  // namespace

bool build_masks(const Inputs& in, Masks& m, std::string& error) {
    const int w = in.width, h = in.height;
    if (w <= 0 || h <= 0 || !in.test || !in.reference) {
        error = "empty images";
        return false;
    }
    const size_t n = size_t(w) * size_t(h);
    auto check = [&](const std::vector<float>* v, const char* what) {
        if (v && v->size() != n) {
            error = std::string("the ") + what + " image is " + std::to_string(v->size()) + " pixels, expected " +
                    std::to_string(n) + " (" + std::to_string(w) + "x" + std::to_string(h) + ")";
            return false;
        }
        return true;
    };
    if (!check(in.test, "tested") || !check(in.reference, "reference") || !check(in.sky, "coverage") ||
        !check(in.std_error, "standard-error") || !check(in.depth, "depth"))
        return false;

    m.geometry.assign(n, 0);
    for (size_t i = 0; i < n; ++i) {
        bool geo = std::isfinite((*in.reference)[i]);
        if (in.sky) geo = geo && (*in.sky)[i] > 0.5f;
        if (in.depth) geo = geo && std::isfinite((*in.depth)[i]) && (*in.depth)[i] > 0.0f;
        m.geometry[i] = geo;
    }
    // Edges: between geometry and sky, and depth (or AO) discontinuities.
    std::vector<uint8_t> edge(n, 0);
    auto mark_pair = [&](size_t a, size_t b) {
        bool e = false;
        if (m.geometry[a] != m.geometry[b]) e = true;
        else if (m.geometry[a]) {
            if (in.depth) {
                const float za = (*in.depth)[a], zb = (*in.depth)[b];
                e = std::fabs(za - zb) > in.depth_jump * std::min(za, zb);
            } else {
                e = std::fabs((*in.reference)[a] - (*in.reference)[b]) > in.ao_jump;
            }
        }
        if (e) edge[a] = edge[b] = 1;
    };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * size_t(w) + size_t(x);
            if (x + 1 < w) mark_pair(i, i + 1);
            if (y + 1 < h) mark_pair(i, i + size_t(w));
        }
    const int k = std::max(in.band, 0);
    std::vector<uint8_t> band = dilate(edge, w, h, std::max(k - 1, 0));
    m.silhouette.assign(n, 0);
    m.border.assign(n, 0);
    m.interior.assign(n, 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * size_t(w) + size_t(x);
            if (!m.geometry[i]) continue;
            const int d = std::min(std::min(x, y), std::min(w - 1 - x, h - 1 - y));
            m.border[i] = d < k;
            m.silhouette[i] = k > 0 && band[i];
            m.interior[i] = !m.border[i] && !m.silhouette[i];
        }
    return true;
}

bool compute(const Inputs& in, std::vector<Stats>& out, std::string& error) {
    Masks m;
    if (!build_masks(in, m, error)) return false;
    out.clear();
    out.push_back(stats_over(*in.test, *in.reference, m.geometry, in.std_error, "all"));
    out.push_back(stats_over(*in.test, *in.reference, m.interior, in.std_error, "interior"));
    out.push_back(stats_over(*in.test, *in.reference, m.silhouette, in.std_error, "silhouette"));
    out.push_back(stats_over(*in.test, *in.reference, m.border, in.std_error, "border"));
    return true;
}

bool compute_split(const Inputs& in, const std::vector<float>& limit, const std::vector<float>* limit_std_error,
                   Split& out, std::string& error) {
    Masks m;
    if (!build_masks(in, m, error)) return false;
    const size_t n = m.geometry.size();
    if (limit.size() != n || (limit_std_error && limit_std_error->size() != n)) {
        error = "the limit image is " + std::to_string(limit.size()) + " pixels, expected " + std::to_string(n);
        return false;
    }
    for (size_t i = 0; i < n; ++i)
        if (m.geometry[i] && !std::isfinite(limit[i])) {
            error = "the limit image has non-finite values on geometry pixels";
            return false;
        }
    const std::pair<const char*, const std::vector<uint8_t>*> masks[] = {
        {"all", &m.geometry}, {"interior", &m.interior}, {"silhouette", &m.silhouette}, {"border", &m.border}};
    Split s;
    for (const auto& [name, mask] : masks) {
        s.ours_vs_reference.push_back(stats_over(*in.test, *in.reference, *mask, in.std_error, name));
        s.limit_vs_reference.push_back(stats_over(limit, *in.reference, *mask, in.std_error, name));
        s.ours_vs_limit.push_back(stats_over(*in.test, limit, *mask, limit_std_error, name));
    }
    out = std::move(s);
    return true;
}

namespace {
std::string num(double v, int prec) {
    if (std::isnan(v)) return "-";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", prec, v);
    return buf;
}
}  // namespace

std::string table(const std::vector<Stats>& s) {
    std::ostringstream o;
    char line[256];
    std::snprintf(line, sizeof line, "%-11s %9s %8s %9s %10s %9s %9s %10s %9s\n", "mask", "pixels", "RMSE", "PSNR(dB)",
                  "mean err", "p99|err|", "max|err|", "ref noise", "noise rms");
    o << line;
    for (const auto& r : s) {
        std::snprintf(line, sizeof line, "%-11s %9zu %8s %9s %10s %9s %9s %10s %9s\n", r.mask.c_str(), r.pixels,
                      num(r.rmse, 5).c_str(), num(r.psnr, 2).c_str(), num(r.mean_error, 5).c_str(),
                      num(r.p99_abs_error, 4).c_str(), num(r.max_abs_error, 4).c_str(), num(r.noise_mean, 5).c_str(),
                      num(r.noise_rms, 5).c_str());
        o << line;
    }
    return o.str();
}

std::string split_table(const Split& s) {
    std::ostringstream o;
    char line[256];
    std::snprintf(line, sizeof line, "%-11s %9s  %-25s  %-25s  %-25s\n", "", "", "ours vs V_R",
                  "limit vs V_R (unavoidable)", "ours vs limit (estimator)");
    o << line;
    std::snprintf(line, sizeof line, "%-11s %9s  %8s %7s %8s  %8s %7s %8s  %8s %7s %8s\n", "mask", "pixels", "RMSE",
                  "PSNR", "mean", "RMSE", "PSNR", "mean", "RMSE", "PSNR", "mean");
    o << line;
    for (size_t i = 0; i < s.ours_vs_reference.size(); ++i) {
        const Stats &a = s.ours_vs_reference[i], &b = s.limit_vs_reference[i], &c = s.ours_vs_limit[i];
        std::snprintf(line, sizeof line, "%-11s %9zu  %8s %7s %8s  %8s %7s %8s  %8s %7s %8s\n", a.mask.c_str(),
                      a.pixels, num(a.rmse, 5).c_str(), num(a.psnr, 2).c_str(), num(a.mean_error, 4).c_str(),
                      num(b.rmse, 5).c_str(), num(b.psnr, 2).c_str(), num(b.mean_error, 4).c_str(),
                      num(c.rmse, 5).c_str(), num(c.psnr, 2).c_str(), num(c.mean_error, 4).c_str());
        o << line;
    }
    return o.str();
}

std::string csv_header() {
    return "label,mask,pixels,non_finite,rmse,psnr_db,mean_error,p99_abs_error,max_abs_error,ref_noise_mean,ref_noise_rms,"
           "against\n";
}

std::string csv_rows(const Split& s, const std::string& label) {
    return csv_rows(s.ours_vs_reference, label, "V_R") + csv_rows(s.ours_vs_limit, label, "limit") +
           csv_rows(s.limit_vs_reference, label, "limit_vs_V_R");
}

std::string csv_rows(const std::vector<Stats>& s, const std::string& label, const std::string& against) {
    std::ostringstream o;
    for (const auto& r : s) {
        std::string l = label;
        for (char& c : l)
            if (c == ',' || c == '\n') c = ' ';
        o << l << ',' << r.mask << ',' << r.pixels << ',' << r.non_finite << ',' << num(r.rmse, 7) << ','
          << num(r.psnr, 4) << ',' << num(r.mean_error, 7) << ',' << num(r.p99_abs_error, 7) << ','
          << num(r.max_abs_error, 7) << ',' << num(r.noise_mean, 7) << ',' << num(r.noise_rms, 7) << ',' << against
          << '\n';
    }
    return o.str();
}

std::vector<double> cell_pattern(const std::vector<float>& test, const std::vector<float>& reference,
                                 const std::vector<uint8_t>& geometry, int width, int height, int cell) {
    std::vector<double> sum(size_t(cell) * size_t(cell), 0.0);
    std::vector<size_t> count(sum.size(), 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const size_t i = size_t(y) * size_t(width) + size_t(x);
            if (!geometry[i] || !std::isfinite(test[i])) continue;
            const size_t k = size_t(y % cell) * size_t(cell) + size_t(x % cell);
            sum[k] += double(test[i]) - double(reference[i]);
            ++count[k];
        }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> pattern(sum.size(), nan);
    double mean = 0.0;
    size_t filled = 0;
    for (size_t k = 0; k < sum.size(); ++k)
        if (count[k] > 0) {
            pattern[k] = sum[k] / double(count[k]);
            mean += pattern[k];
            ++filled;
        }
    if (filled) mean /= double(filled);
    for (double& m : pattern) m -= mean;  // NaN stays NaN
    return pattern;
}

double pattern_spread(const std::vector<double>& pattern) {
    double sq = 0.0;
    size_t n = 0;
    for (double x : pattern)
        if (std::isfinite(x)) {
            sq += x * x;
            ++n;
        }
    return n ? std::sqrt(sq / double(n)) : std::numeric_limits<double>::quiet_NaN();
}

double cell_spread(const std::vector<float>& test, const std::vector<float>& reference,
                   const std::vector<uint8_t>& geometry, int width, int height, int cell) {
    return pattern_spread(cell_pattern(test, reference, geometry, width, height, cell));
}

double common_pattern(const std::vector<std::vector<double>>& patterns) {
    if (patterns.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::vector<double> mean(patterns[0].size(), 0.0);
    for (const auto& p : patterns)
        for (size_t k = 0; k < mean.size(); ++k) mean[k] += k < p.size() ? p[k] : std::numeric_limits<double>::quiet_NaN();
    for (double& m : mean) m /= double(patterns.size());
    return pattern_spread(mean);
}

double occluded_bias(const std::vector<float>& test, const std::vector<float>& reference,
                     const std::vector<uint8_t>& geometry, double below) {
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < test.size(); ++i)
        if (geometry[i] && reference[i] < below && std::isfinite(test[i])) {
            sum += double(test[i]) - double(reference[i]);
            ++n;
        }
    return n ? sum / double(n) : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace metrics
