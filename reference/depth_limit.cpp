#include "depth_limit.h"

#include "row_pool.h"
#include "sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace depth_limit {
namespace {

// The 4 edge neighbours, in the bit order of Layer::joined_.
constexpr int kNeighbourX[4] = {1, -1, 0, 0};
constexpr int kNeighbourY[4] = {0, 0, 1, -1};

// Affine function of the segment parameter s: v0 + v1 * s.
struct Lin {
    double v0 = 0.0, v1 = 0.0;
    double at(double s) const { return v0 + v1 * s; }
};

// Appends the roots of a + b s = 0 that lie in (lo, hi).
void linear_roots(double a, double b, double lo, double hi, std::vector<double>& out) {
    if (b == 0.0) return;
    const double s = -a / b;
    if (s > lo && s < hi) out.push_back(s);
}

// Appends the roots of a s^2 + b s + c = 0 in (lo, hi) (the stable form).
void quadratic_roots(double a, double b, double c, double lo, double hi, std::vector<double>& out) {
    const double scale = std::max({std::fabs(a), std::fabs(b), std::fabs(c)});
    if (scale == 0.0 || !std::isfinite(scale)) return;
    if (std::fabs(a) <= 1e-14 * scale) {
        linear_roots(c, b, lo, hi, out);
        return;
    }
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0.0) return;
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    for (double s : {q / a, q != 0.0 ? c / q : std::numeric_limits<double>::quiet_NaN()})
        if (s > lo && s < hi) out.push_back(s);
}

}  // namespace

double surface_depth(const Texel& t, const glm::dvec3& s, bool ortho) {
    const double d_q = -t.q.z;
    if (ortho) {
        if (!(t.n.z > kEdgeOn)) return d_q;
        const double z = t.q.z - (t.n.x * (s.x - t.q.x) + t.n.y * (s.y - t.q.y)) / t.n.z;
        return -z;
    }
    const double nq = glm::dot(t.n, t.q);
    const double ns = glm::dot(t.n, s);
    const double depth_s = -s.z;
    if (!(nq < 0.0) || !(ns < -kEdgeOn * depth_s)) return d_q;
    // The eye ray x = u s meets the plane n.(x - q) = 0 at u = n.q / n.s (> 0 here).
    return nq / ns * depth_s;
}

bool blocked_by(const Texel& t, const glm::dvec3& s, double thickness, bool ortho) {
    const double delta = -s.z - surface_depth(t, s, ortho);
    return delta > kSelfEpsilon * -t.q.z && delta < thickness;
}

Layer::Layer(const camera::Camera& cam, const raytrace::Image& img)
    : width_(img.width), height_(img.height), ortho_(cam.orthographic) {
    proj_ = glm::dmat4(camera::projection_matrix(cam, float(img.width) / float(img.height)));
    const size_t n = size_t(width_) * size_t(height_);
    texels_.resize(n);
    geometry_.assign(n, 0);
    if (img.mask.size() != n || img.position.size() != n * 3 || img.normal.size() != n * 3) return;  // all sky
    for (size_t i = 0; i < n; ++i) {
        const float* p = &img.position[i * 3];
        const float* nn = &img.normal[i * 3];
        const glm::dvec3 normal(nn[0], nn[1], nn[2]);
        const double len = glm::length(normal);
        geometry_[i] = img.mask[i] > 0.5f && len > 0.0 && std::isfinite(len) && std::isfinite(p[0]) &&
                       std::isfinite(p[1]) && std::isfinite(p[2]);
        if (geometry_[i]) texels_[i] = {glm::dvec3(p[0], p[1], p[2]), normal / len};
    }
    // Which neighbours' planes join each texel's read (see the header).
    joined_.assign(n, 0);
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const size_t i = size_t(y) * size_t(width_) + size_t(x);
            if (!geometry_[i]) continue;
            const Texel& a = texels_[i];
            const double d_a = -a.q.z;
            for (int k = 0; k < 4; ++k) {
                const int xx = x + kNeighbourX[k], yy = y + kNeighbourY[k];
                if (xx < 0 || yy < 0 || xx >= width_ || yy >= height_) continue;
                const size_t j = size_t(yy) * size_t(width_) + size_t(xx);
                if (!geometry_[j]) continue;
                const Texel& b = texels_[j];
                const bool continues = std::fabs(-b.q.z - d_a) <= kContinuity * d_a;
                const bool convex = glm::dot(a.n, b.q - a.q) < 0.0 && glm::dot(b.n, a.q - b.q) < 0.0;
                if (continues && convex) joined_[i] |= uint8_t(1u << k);
            }
        }
}

int Layer::planes(int x, int y, Texel out[5]) const {
    const size_t i = size_t(y) * size_t(width_) + size_t(x);
    if (!geometry_[i]) return 0;
    int count = 0;
    out[count++] = texels_[i];
    for (int k = 0; k < 4; ++k)
        if (joined_[i] & (1u << k))
            out[count++] = texels_[size_t(y + kNeighbourY[k]) * size_t(width_) + size_t(x + kNeighbourX[k])];
    return count;
}

namespace {

// The rule over a texel's planes (planes[0] is the texel's own).
double farthest_surface(const Texel* planes, int count, const glm::dvec3& s, bool ortho) {
    double d = surface_depth(planes[0], s, ortho);
    for (int j = 1; j < count; ++j) d = std::max(d, surface_depth(planes[j], s, ortho));
    return d;
}

bool blocked_by_planes(const Texel* planes, int count, const glm::dvec3& s, double thickness, bool ortho) {
    const double delta = -s.z - farthest_surface(planes, count, s, ortho);
    return delta > kSelfEpsilon * -planes[0].q.z && delta < thickness;
}

}  // namespace

double Layer::surface_depth_at(const glm::dvec3& s) const {
    int x = 0, y = 0;
    Texel p[5];
    if (!pixel_of(s, x, y)) return std::numeric_limits<double>::infinity();
    const int count = planes(x, y, p);
    return count ? farthest_surface(p, count, s, ortho_) : std::numeric_limits<double>::infinity();
}

bool Layer::pixel_of(const glm::dvec3& s, int& x, int& y) const {
    const glm::dvec4 c = proj_ * glm::dvec4(s, 1.0);
    if (!(c.w > 0.0)) return false;
    const double fx = (c.x / c.w + 1.0) * 0.5 * width_;
    const double fy = (1.0 - c.y / c.w) * 0.5 * height_;  // row 0 = top
    if (!(fx >= 0.0 && fx < width_ && fy >= 0.0 && fy < height_)) return false;
    x = std::min(int(fx), width_ - 1);
    y = std::min(int(fy), height_ - 1);
    return true;
}

bool Layer::texel(int x, int y, Texel& t) const {
    const size_t i = size_t(y) * size_t(width_) + size_t(x);
    if (!geometry_[i]) return false;
    t = texels_[i];
    return true;
}

bool Layer::point_blocked(const glm::dvec3& s, double thickness) const {
    int x = 0, y = 0;
    Texel p[5];
    if (!pixel_of(s, x, y)) return false;
    const int count = planes(x, y, p);
    return count > 0 && blocked_by_planes(p, count, s, thickness, ortho_);
}

namespace {

// Appends the segment parameters in (0, s_end) where the projection of p + s
// dir crosses a pixel boundary or the image's edge (clip coordinates c0 + s c1).
void pixel_cuts(const glm::dvec4& c0, const glm::dvec4& c1, double s_end, int width, int height,
                std::vector<double>& cuts) {
    auto boundaries = [&](double a0, double a1, int size, bool flip) {
        // Window coordinate f(s) = (ndc + 1)/2 * size, or (1 - ndc)/2 * size when flipped.
        auto window = [&](double s) {
            const double ndc = (a0 + s * a1) / (c0.w + s * c1.w);
            return flip ? (1.0 - ndc) * 0.5 * size : (ndc + 1.0) * 0.5 * size;
        };
        const double f0 = window(0.0), f1 = window(s_end);
        if (!std::isfinite(f0) || !std::isfinite(f1)) return;
        const double lo = std::max(std::min(f0, f1), 0.0), hi = std::min(std::max(f0, f1), double(size));
        for (int k = int(std::floor(lo)) + 1; k < hi; ++k) {
            const double ndc = flip ? 1.0 - 2.0 * k / size : 2.0 * k / size - 1.0;
            linear_roots(a0 - ndc * c0.w, a1 - ndc * c1.w, 0.0, s_end, cuts);
        }
        // The exact edges of the image too (the segment may leave through them).
        for (int k : {0, size}) {
            const double ndc = flip ? 1.0 - 2.0 * k / size : 2.0 * k / size - 1.0;
            linear_roots(a0 - ndc * c0.w, a1 - ndc * c1.w, 0.0, s_end, cuts);
        }
    };
    boundaries(c0.x, c1.x, width, false);
    boundaries(c0.y, c1.y, height, true);
}

// Quick exit: where the texel's own plane t is read over the whole interval
// (u0, u1) and both ends are on the camera's side of it (n.(S - Q) >= 0,
// linear in s), its Delta <= 0 throughout, and the farthest plane only lowers
// Delta: open. Most of every segment is like that.
bool clearly_open(const Texel& t, const glm::dvec3& p, const glm::dvec3& dir, const Lin& depth, double u0, double u1,
                  bool ortho) {
    const double b0 = glm::dot(t.n, p + dir * u0 - t.q), b1 = glm::dot(t.n, p + dir * u1 - t.q);
    if (!(b0 >= 0.0 && b1 >= 0.0)) return false;
    if (ortho) return t.n.z > kEdgeOn;
    auto reads_plane = [&](double s) { return glm::dot(t.n, p + dir * s) < -kEdgeOn * depth.at(s); };
    return glm::dot(t.n, t.q) < 0.0 && reads_plane(u0) && reads_plane(u1);
}

// Appends the points in (u0, u1) where the rule's outcome can change: where
// any plane's Delta crosses eps or the thickness, where any plane switches to
// its edge-on fallback (the farthest plane can only change at a point where
// two planes' depths cross, and the outcome only where the farthest one's
// Delta crosses eps or T, which is one of these).
void critical_points(const Texel* planes, int count, const glm::dvec3& p, const glm::dvec3& dir, const Lin& depth,
                     double eps, double thickness, double u0, double u1, bool ortho, std::vector<double>& crit) {
    for (int j = 0; j < count; ++j) {
        const Texel& pl = planes[j];
        const double d_j = -pl.q.z;
        for (double k_ : {eps, thickness}) {
            if (!std::isfinite(k_)) continue;
            linear_roots(depth.v0 - d_j - k_, depth.v1, u0, u1, crit);  // edge-on fallback: depth - d_j = k
            if (ortho) {
                // Delta(s) = -n.(p + s dir - q) / n.z
                const double nz = pl.n.z;
                if (nz > kEdgeOn)
                    linear_roots(-glm::dot(pl.n, p - pl.q) / nz - k_, -glm::dot(pl.n, dir) / nz, u0, u1, crit);
            } else {
                // Delta = A (C - nq) / C = k  <=>  A (C - nq) - k C = 0, with A = depth, C = n.S.
                const double nq = glm::dot(pl.n, pl.q);
                const Lin C{glm::dot(pl.n, p), glm::dot(pl.n, dir)};
                quadratic_roots(depth.v1 * C.v1, depth.v0 * C.v1 + depth.v1 * (C.v0 - nq) - k_ * C.v1,
                                depth.v0 * (C.v0 - nq) - k_ * C.v0, u0, u1, crit);
            }
        }
        if (!ortho) {  // the edge-on switch: n.S = -kEdgeOn * depth(S)
            linear_roots(glm::dot(pl.n, p) + kEdgeOn * depth.v0, glm::dot(pl.n, dir) + kEdgeOn * depth.v1, u0, u1,
                         crit);
        }
    }
}

}  // namespace

bool Layer::segment_blocked(const glm::dvec3& p, const glm::dvec3& dir, double radius, double thickness) const {
    // Clip coordinates along the segment: c(s) = c0 + s c1.
    const glm::dvec4 c0 = proj_ * glm::dvec4(p, 1.0);
    const glm::dvec4 c1 = proj_ * glm::dvec4(dir, 0.0);
    if (!(c0.w > 0.0)) return false;
    double s_end = radius;
    // Perspective: stop where the segment reaches the eye plane; points that
    // close to the eye are in front of every surface (open).
    if (c1.w < 0.0) s_end = std::min(s_end, (1e-6 * c0.w - c0.w) / c1.w);
    if (!(s_end > 0.0)) return false;

    // Every pixel boundary the projected segment crosses (the projection of a
    // segment in front of the eye is a segment, monotone in s).
    thread_local std::vector<double> cuts, crit;  // reused: this runs per direction
    cuts.clear();
    pixel_cuts(c0, c1, s_end, width_, height_, cuts);
    cuts.push_back(0.0);
    cuts.push_back(s_end);
    std::sort(cuts.begin(), cuts.end());

    const Lin depth{-p.z, -dir.z};
    for (size_t k = 0; k + 1 < cuts.size(); ++k) {
        const double u0 = cuts[k], u1 = cuts[k + 1];
        if (!(u1 > u0)) continue;
        const double mid = 0.5 * (u0 + u1);
        int x = 0, y = 0;
        // Off the image or behind the eye: it cannot come back (a segment's
        // projection leaves a convex window once), so the rest is open.
        if (!pixel_of(p + dir * mid, x, y)) return false;
        Texel planes_here[5];
        const int count = planes(x, y, planes_here);
        if (count == 0) continue;  // sky: open
        if (clearly_open(planes_here[0], p, dir, depth, u0, u1, ortho_)) continue;
        const double eps = kSelfEpsilon * -planes_here[0].q.z;
        crit.clear();
        crit.push_back(u0);
        critical_points(planes_here, count, p, dir, depth, eps, thickness, u0, u1, ortho_, crit);
        crit.push_back(u1);
        std::sort(crit.begin(), crit.end());
        for (size_t j = 0; j + 1 < crit.size(); ++j) {
            if (!(crit[j + 1] > crit[j])) continue;
            const double m = 0.5 * (crit[j] + crit[j + 1]);
            if (blocked_by_planes(planes_here, count, p + dir * m, thickness, ortho_)) return true;
        }
    }
    return false;
}

Estimate Layer::visibility(int x, int y, double radius, double thickness, int directions, uint32_t pixel_seed) const {
    Estimate e;
    Texel t;
    if (!texel(x, y, t)) return e;
    glm::dvec3 tx, ty;
    sampling::basis(t.n, tx, ty);
    const int per = std::max(directions / kReplicas, 1);
    double means[kReplicas];
    double sum = 0.0;
    for (int r = 0; r < kReplicas; ++r) {
        const sampling::Shift shift = sampling::shift_from(sampling::hash32(pixel_seed + uint32_t(r) * 0x9E3779B1u));
        int open = 0;
        for (int i = 0; i < per; ++i) {
            const glm::dvec3 c = sampling::cosine_direction(i, per, shift);
            const glm::dvec3 w = glm::normalize(tx * c.x + ty * c.y + t.n * c.z);
            if (!segment_blocked(t.q, w, radius, thickness)) ++open;
        }
        means[r] = double(open) / double(per);
        sum += means[r];
    }
    e.visibility = sum / kReplicas;
    double var = 0.0;
    for (double m : means) var += (m - e.visibility) * (m - e.visibility);
    e.std_error = std::sqrt(var / double(kReplicas * (kReplicas - 1)));
    return e;
}

uint32_t pixel_seed(uint32_t seed, int x, int y, int width) {
    const uint32_t seed_hash = sampling::hash32(seed * 0x9E3779B1u + 0x5bd1e995u);
    const uint32_t i = uint32_t(size_t(y) * size_t(width) + size_t(x));
    return sampling::hash32(seed_hash ^ (i * 0x27d4eb2dU));
}

std::string check(const Options& o) {
    if (!(o.radius > 0.0) || !std::isfinite(o.radius)) return "the radius must be a finite number greater than 0";
    if (!(o.thickness > 0.0)) return "the thickness must be greater than 0 (or inf)";
    if (o.directions < kReplicas || o.directions % kReplicas != 0 || o.directions > (1 << 20))
        return "the number of directions must be a multiple of " + std::to_string(kReplicas) + " in " +
               std::to_string(kReplicas) + "..1048576";
    return "";
}

bool compute(const camera::Camera& cam, const raytrace::Image& img, const Options& o, Image& out, std::string& error) {
    error = check(o);
    if (!error.empty()) return false;
    const size_t n = size_t(img.width) * size_t(img.height);
    if (img.width <= 0 || img.height <= 0 || img.mask.size() != n || img.position.size() != n * 3 ||
        img.normal.size() != n * 3) {
        error = "the reference image has no depth layer (positions, normals, coverage)";
        return false;
    }
    const Layer layer(cam, img);
    Image r;
    r.ao.assign(n, 1.0f);
    r.std_error.assign(n, 0.0f);
    r.seconds = row_pool::run(img.height, o.threads, o.progress, "marched", [&](int y) {
        for (int x = 0; x < img.width; ++x) {
            const Estimate e =
                layer.visibility(x, y, o.radius, o.thickness, o.directions, pixel_seed(o.seed, x, y, img.width));
            const size_t i = size_t(y) * size_t(img.width) + size_t(x);
            r.ao[i] = float(e.visibility);
            r.std_error[i] = float(e.std_error);
        }
    });
    out = std::move(r);
    return true;
}

}  // namespace depth_limit
