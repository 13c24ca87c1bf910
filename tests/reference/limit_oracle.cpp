#include "limit_oracle.h"

#include <algorithm>
#include <cmath>

namespace limit_oracle {

DepthLayer::DepthLayer(const camera::Camera& cam, const raytrace::Image& img)
    : w_(img.width), h_(img.height), ortho_(cam.orthographic) {
    proj_ = glm::dmat4(camera::projection_matrix(cam, float(img.width) / float(img.height)));
    const size_t n = size_t(w_) * size_t(h_);
    q_.assign(n, glm::dvec3(0.0));
    n_.assign(n, glm::dvec3(0.0, 0.0, 1.0));
    geo_.assign(n, 0);
    convex_neighbours_.assign(n, {});
    if (img.mask.size() != n || img.position.size() != 3 * n || img.normal.size() != 3 * n) return;
    for (size_t i = 0; i < n; ++i) {
        if (!(img.mask[i] > 0.5f)) continue;
        const glm::dvec3 nn(img.normal[3 * i], img.normal[3 * i + 1], img.normal[3 * i + 2]);
        if (!(glm::length(nn) > 0.0)) continue;
        q_[i] = glm::dvec3(img.position[3 * i], img.position[3 * i + 1], img.position[3 * i + 2]);
        n_[i] = glm::normalize(nn);
        geo_[i] = 1;
    }
    for (int y = 0; y < h_; ++y)
        for (int x = 0; x < w_; ++x) {
            const size_t i = idx(x, y);
            if (!geo_[i]) continue;
            const int around[4][2] = {{0, -1}, {-1, 0}, {1, 0}, {0, 1}};
            for (const auto& d : around) {
                const int xx = x + d[0], yy = y + d[1];
                if (xx < 0 || yy < 0 || xx >= w_ || yy >= h_) continue;
                const size_t j = idx(xx, yy);
                if (!geo_[j]) continue;
                const double dq = -q_[i].z, dn = -q_[j].z;
                if (std::fabs(dn - dq) > 0.05 * dq) continue;
                if (glm::dot(n_[i], q_[j] - q_[i]) < 0.0 && glm::dot(n_[j], q_[i] - q_[j]) < 0.0)
                    convex_neighbours_[i].push_back(j);
            }
        }
}

double DepthLayer::plane_read(size_t i, const glm::dvec3& s) const {
    const glm::dvec3 q = q_[i], n = n_[i];
    const double d_q = -q.z;
    if (ortho_) {
        // The line through s along the view axis: (s.x, s.y, z).
        if (!(std::fabs(n.z) > 1e-3)) return d_q;
        return -(q.z - (n.x * (s.x - q.x) + n.y * (s.y - q.y)) / n.z);
    }
    // The eye ray t * s meets the plane where n.(t s - q) = 0.
    const double ns = glm::dot(n, s);
    if (!(std::fabs(ns) > 1e-3 * glm::length(s))) return d_q;
    const double t = glm::dot(n, q) / ns;
    if (!(t > 0.0)) return d_q;
    return t * -s.z;
}

bool DepthLayer::blocked(const glm::dvec3& s, double thickness) const {
    const glm::dvec4 c = proj_ * glm::dvec4(s, 1.0);
    if (!(c.w > 0.0)) return false;
    const double wx = (c.x / c.w * 0.5 + 0.5) * w_;
    const double wy = (0.5 - c.y / c.w * 0.5) * h_;
    if (!(wx >= 0.0 && wy >= 0.0 && wx < w_ && wy < h_)) return false;
    const size_t i = idx(std::min(int(wx), w_ - 1), std::min(int(wy), h_ - 1));
    if (!geo_[i]) return false;
    double d_surf = plane_read(i, s);
    for (size_t j : convex_neighbours_[i]) d_surf = std::max(d_surf, plane_read(j, s));
    const double gap = -s.z - d_surf;
    return gap > 1e-5 * -q_[i].z && gap < thickness;
}

bool DepthLayer::segment_open(const glm::dvec3& p, const glm::dvec3& w, const Options& o) const {
    const double ds = o.radius / o.steps;
    for (int k = 0; k < o.steps; ++k)
        if (blocked(p + w * ((k + 0.5) * ds), o.thickness)) return false;
    return true;
}

double DepthLayer::visibility(int x, int y, const std::vector<glm::dvec3>& dirs, const Options& o) const {
    const size_t i = idx(x, y);
    if (!geo_[i] || dirs.empty()) return 1.0;
    size_t open = 0;
    for (const glm::dvec3& w : dirs)
        if (segment_open(q_[i], w, o)) ++open;
    return double(open) / double(dirs.size());
}

}  // namespace limit_oracle
