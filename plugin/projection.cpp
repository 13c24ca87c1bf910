#include "projection.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace ssao_impl {

namespace {

// The shaders get the matrix and its inverse as 32-bit floats and multiply
// view positions by them: an element past kMaxElement overflows to inf with
// ordinary coordinates, and one below FLT_MIN is a denormal, which GPUs flush
// to zero. Either way every pixel would come out wrong (all 1.0) with an OK
// status. Elements negligible beside the matrix's largest (rounding residue
// of the inverse) may flush to zero harmlessly.
constexpr double kMaxElement = 1e30;

// A magnitude as a message prints it: 6.4e+30, not 31 digits.
std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

bool usable_in_float(const glm::dmat4& m, std::string& why) {
    double largest = 0.0;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) largest = std::max(largest, std::abs(m[c][r]));
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            const double v = std::abs(m[c][r]);
            const bool too_large = !(v <= kMaxElement);
            const bool denormal = v > 0.0 && v < double(std::numeric_limits<float>::min()) && v >= largest * 1e-20;
            if (too_large || denormal) {
                why = "the projection (or its inverse) has an element of magnitude " + number(v) +
                      ", outside what 32-bit float shaders can use (" +
                      (too_large ? "above 1e30, it overflows" : "a denormal, flushed to zero") + ")";
                return false;
            }
        }
    }
    return true;
}

}  // namespace

ssao_status analyse_projection(const float m[16], ssao_clip_range clip, ProjectionInfo& out,
                               std::string& why) {
    for (int i = 0; i < 16; ++i) {
        if (!std::isfinite(m[i])) {
            why = "projection element " + std::to_string(i) + " is not finite";
            return SSAO_ERROR_INVALID_VALUE;
        }
    }
    // A projection is homogeneous: k P maps every view point to the same NDC
    // for any k > 0, but a k far from 1 would overflow the shaders' squares
    // of clip w (AO 1 everywhere). Scaled by the power of two that brings
    // clip w's coefficient (of view z in perspective, the constant in
    // orthographic) into [1, 2), which is exact in binary floating point,
    // every such k P gives the same constants as P does; GL's and D3D's
    // matrices (-1 and 1 there) are used as given.
    const double w_coefficient = m[11] != 0.0f ? m[11] : m[15];
    const double scale = w_coefficient != 0.0 ? std::ldexp(1.0, -std::ilogb(w_coefficient)) : 1.0;
    ProjectionInfo p;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) p.proj[c][r] = m[c * 4 + r] * scale;
    p.ndc_per_depth = clip == SSAO_CLIP_ZERO_TO_ONE ? 1.0 : 2.0;
    const double ndc_lo = clip == SSAO_CLIP_ZERO_TO_ONE ? 0.0 : -1.0;

    // Row 3 (clip w) decides the kind: -z for perspective, constant for ortho.
    const double w_x = p.proj[0][3], w_y = p.proj[1][3], w_z = p.proj[2][3], w_1 = p.proj[3][3];
    const double z_z = p.proj[2][2], z_1 = p.proj[3][2];  // clip z = z_z * z + z_1 (x, y terms unused)
    if (w_x != 0.0 || w_y != 0.0) {
        why = "the projection's w row depends on view x or y; only perspective and orthographic projections are supported";
        return SSAO_ERROR_INVALID_PROJECTION;
    }
    if (w_z != 0.0 && w_1 == 0.0) {
        if (w_z > 0.0) {
            why = "the projection looks down +z (left-handed); view space must be right-handed, camera looking down -z";
            return SSAO_ERROR_INVALID_PROJECTION;
        }
        p.orthographic = false;
    } else if (w_z == 0.0 && w_1 != 0.0) {
        p.orthographic = true;
    } else {
        why = "the projection is neither perspective (w = -z) nor orthographic (w constant)";
        return SSAO_ERROR_INVALID_PROJECTION;
    }
    if (p.proj[0][0] == 0.0 || p.proj[1][1] == 0.0 || (z_z == 0.0 && p.orthographic) || (z_1 == 0.0 && !p.orthographic)) {
        why = "the projection is singular (a zero scale on x, y or depth)";
        return SSAO_ERROR_INVALID_PROJECTION;
    }
    const double det = glm::determinant(p.proj);
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) {
        why = "the projection matrix is singular";
        return SSAO_ERROR_INVALID_PROJECTION;
    }
    p.inverse = glm::inverse(p.proj);
    if (!usable_in_float(p.proj, why) || !usable_in_float(p.inverse, why)) return SSAO_ERROR_INVALID_PROJECTION;

    // ndc_z as a function of the view distance t (z = -t).
    if (!p.orthographic) {
        const double s = -w_z;                      // w = s * t
        // ndc(t) = (-z_z * t + z_1) / (s * t) = -z_z / s + z_1 / (s * t)
        p.reverse_z = z_1 / s > 0.0;                // ndc falls with distance
        const double a = -z_z / s, b = z_1 / s;     // ndc = a + b / t
        const double ndc_near = p.reverse_z ? 1.0 : ndc_lo;
        const double ndc_far = p.reverse_z ? ndc_lo : 1.0;
        p.near_distance = b / (ndc_near - a);
        const double denom = ndc_far - a;
        const double far_t = denom != 0.0 ? b / denom : std::numeric_limits<double>::infinity();
        // A far plane past 1e12 * near is taken as infinite.
        p.infinite_far = !(far_t > 0.0) || far_t > p.near_distance * 1e12 || std::isinf(far_t);
        p.far_distance = p.infinite_far ? std::numeric_limits<double>::infinity() : far_t;
        if (!(p.near_distance > 0.0) || !std::isfinite(p.near_distance)) {
            why = "the projection's near plane is not in front of the camera";
            return SSAO_ERROR_INVALID_PROJECTION;
        }
    } else {
        // ndc(t) = (-z_z * t + z_1) / w_1
        const double a = z_1 / w_1, b = -z_z / w_1;  // ndc = a + b t
        p.reverse_z = b < 0.0;
        const double ndc_near = p.reverse_z ? 1.0 : ndc_lo;
        const double ndc_far = p.reverse_z ? ndc_lo : 1.0;
        p.near_distance = (ndc_near - a) / b;
        p.far_distance = (ndc_far - a) / b;
        p.infinite_far = false;
    }
    p.sky_depth = p.reverse_z ? 0.0f : 1.0f;
    out = p;
    return SSAO_OK;
}

ViewFromZ view_from_z(const ProjectionInfo& p, int viewport_width, int viewport_height) {
    const glm::dmat4& m = p.proj;  // m[column][row]
    ViewFromZ c;
    c.w_z = m[2][3];
    c.w_1 = m[3][3];
    c.z_z = m[2][2];
    c.z_1 = m[3][2];
    c.det = c.z_z * c.w_1 - c.z_1 * c.w_z;
    // ndc.xy * w = M2 * xy + m2xy * z + m3xy (w independent of x, y), so
    // xy = M2^-1 (ndc * (w_z z + w_1) - m2xy z - m3xy), with ndc = px * s - 1.
    const glm::dmat2 m2(m[0][0], m[0][1], m[1][0], m[1][1]);
    const glm::dmat2 inv = glm::inverse(m2);
    const glm::dmat2 scale(2.0 / viewport_width, 0.0, 0.0, 2.0 / viewport_height);
    const glm::dvec2 m2xy(m[2][0], m[2][1]), m3xy(m[3][0], m[3][1]);
    const glm::dvec2 inv_one = inv * glm::dvec2(1.0, 1.0);
    c.mul_z = c.w_z * (inv * scale);
    c.add_z = -c.w_z * inv_one - inv * m2xy;
    c.mul_1 = c.w_1 * (inv * scale);
    c.add_1 = -c.w_1 * inv_one - inv * m3xy;
    return c;
}

glm::dvec3 view_position_from_z(const ViewFromZ& c, double px_x, double px_y, double view_z) {
    const glm::dvec2 px(px_x, px_y);
    const glm::dvec2 xy = (c.mul_z * px + c.add_z) * view_z + (c.mul_1 * px + c.add_1);
    return glm::dvec3(xy, view_z);
}

glm::dvec3 view_position(const ProjectionInfo& p, double ndc_x, double ndc_y, double depth) {
    const double ndc_z = p.ndc_per_depth == 2.0 ? depth * 2.0 - 1.0 : depth;
    const glm::dvec4 v = p.inverse * glm::dvec4(ndc_x, ndc_y, ndc_z, 1.0);
    return glm::dvec3(v) / v.w;
}

double depth_of(const ProjectionInfo& p, const glm::dvec3& view) {
    const glm::dvec4 c = p.proj * glm::dvec4(view, 1.0);
    const double ndc_z = c.z / c.w;
    return p.ndc_per_depth == 2.0 ? ndc_z * 0.5 + 0.5 : ndc_z;
}

}  // namespace ssao_impl
