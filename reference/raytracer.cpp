#include "raytracer.h"

#include "row_pool.h"
#include "sampling.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

namespace raytrace {
namespace {

using sampling::hash32;
using sampling::to_unit;

void device_error(void* user, RTCError, const char* str) {
    auto* s = static_cast<std::string*>(user);
    if (s->empty()) *s = str ? str : "unknown Embree error";
}

}  // namespace

struct Tracer::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::string error;
    std::string device_message;
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> indices;
    float size = 1.0f;
    float eps = 1e-5f;

    // Occlusion test along unit `dir` from `org` (already offset), within (tnear, tfar).
    bool occluded(const glm::vec3& org, const glm::vec3& dir, float tnear, float tfar) const {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        RTCRay ray;
        ray.org_x = org.x; ray.org_y = org.y; ray.org_z = org.z;
        ray.dir_x = dir.x; ray.dir_y = dir.y; ray.dir_z = dir.z;
        ray.tnear = tnear;
        ray.tfar = tfar;
        ray.time = 0.0f;
        ray.mask = 0xFFFFFFFFu;
        ray.id = 0;
        ray.flags = 0;
        rtcOccluded1(scene, &ctx, &ray);
        return ray.tfar == -std::numeric_limits<float>::infinity();
    }

    Estimate ao(const glm::vec3& p, const glm::vec3& n, float radius, int samples, uint32_t rot_hash) const {
        glm::vec3 t, b;
        sampling::basis(n, t, b);
        // Offset scaled to the point's own magnitude too (float spacing grows with |p|).
        const float mag = std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
        const float off = eps + mag * 2e-6f;
        const glm::vec3 org = p + n * off;
        const float tfar = std::isinf(radius) ? std::numeric_limits<float>::infinity() : radius * (1.0f + 1e-4f);
        const sampling::Shift shift = sampling::shift_from(rot_hash);
        int unoccluded = 0;
        const int N = std::max(samples, 1);
        for (int i = 0; i < N; ++i) {
            const glm::dvec3 c = sampling::cosine_direction(i, N, shift);
            const glm::vec3 d = glm::normalize(t * float(c.x) + b * float(c.y) + n * float(c.z));
            if (!occluded(org, d, off * 0.5f, tfar)) ++unoccluded;
        }
        Estimate e;
        e.rays = N;
        e.visibility = double(unoccluded) / double(N);
        e.std_error = N > 1 ? std::sqrt(e.visibility * (1.0 - e.visibility) / double(N - 1)) : 0.5;
        return e;
    }

    bool hit(const glm::vec3& o, const glm::vec3& d, float tnear, float tfar, float& t_out, glm::vec3& p_out,
             glm::vec3& n_out) const {
        RTCIntersectContext ctx;
        rtcInitIntersectContext(&ctx);
        RTCRayHit rh;
        rh.ray.org_x = o.x; rh.ray.org_y = o.y; rh.ray.org_z = o.z;
        rh.ray.dir_x = d.x; rh.ray.dir_y = d.y; rh.ray.dir_z = d.z;
        rh.ray.tnear = tnear;
        rh.ray.tfar = tfar;
        rh.ray.time = 0.0f;
        rh.ray.mask = 0xFFFFFFFFu;
        rh.ray.id = 0;
        rh.ray.flags = 0;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene, &ctx, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
        const size_t prim = rh.hit.primID;
        const glm::vec3 v0 = positions[indices[prim * 3]], v1 = positions[indices[prim * 3 + 1]],
                        v2 = positions[indices[prim * 3 + 2]];
        const float u = rh.hit.u, v = rh.hit.v;
        p_out = v0 * (1.0f - u - v) + v1 * u + v2 * v;  // more precise than o + t d
        glm::vec3 n = glm::cross(v1 - v0, v2 - v0);
        const float len = glm::length(n);
        n_out = len > 0.0f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
        t_out = rh.ray.tfar;
        return true;
    }
};

Tracer::Tracer(const scene::Mesh& mesh) : impl_(new Impl) {
    Impl& m = *impl_;
    m.positions = mesh.positions;
    m.indices = mesh.indices;
    m.indices.resize(m.indices.size() - m.indices.size() % 3);
    for (uint32_t i : m.indices)
        if (i >= m.positions.size()) {
            m.error = "mesh index out of range";
            return;
        }
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const auto& p : m.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    if (!m.positions.empty()) m.size = std::max(glm::length(hi - lo), 1e-6f);
    m.eps = m.size * 2e-6f;

    m.device = rtcNewDevice(nullptr);
    if (!m.device) {
        m.error = "Embree could not create a device (error " + std::to_string(int(rtcGetDeviceError(nullptr))) + ")";
        return;
    }
    rtcSetDeviceErrorFunction(m.device, device_error, &m.device_message);
    m.scene = rtcNewScene(m.device);
    rtcSetSceneFlags(m.scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(m.scene, RTC_BUILD_QUALITY_HIGH);
    if (!m.indices.empty() && !m.positions.empty()) {
        RTCGeometry g = rtcNewGeometry(m.device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                               3 * sizeof(float), m.positions.size()));
        auto* ib = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                  3 * sizeof(uint32_t), m.indices.size() / 3));
        if (!vb || !ib) {
            rtcReleaseGeometry(g);
            m.error = "Embree could not allocate the geometry buffers (" + m.device_message + ")";
            return;
        }
        for (size_t i = 0; i < m.positions.size(); ++i) {
            vb[i * 3] = m.positions[i].x;
            vb[i * 3 + 1] = m.positions[i].y;
            vb[i * 3 + 2] = m.positions[i].z;
        }
        std::copy(m.indices.begin(), m.indices.end(), ib);
        rtcCommitGeometry(g);
        rtcAttachGeometry(m.scene, g);
        rtcReleaseGeometry(g);
    }
    rtcCommitScene(m.scene);
    if (!m.device_message.empty()) m.error = "Embree failed: " + m.device_message;
}

Tracer::~Tracer() {
    if (impl_->scene) rtcReleaseScene(impl_->scene);
    if (impl_->device) rtcReleaseDevice(impl_->device);
}

bool Tracer::ok() const { return impl_->error.empty(); }
const std::string& Tracer::error() const { return impl_->error; }
float Tracer::scene_size() const { return impl_->size; }
float Tracer::epsilon() const { return impl_->eps; }

Estimate Tracer::ao_at(const glm::vec3& p, const glm::vec3& n, float radius, int samples, uint32_t seed) const {
    glm::vec3 nn = glm::length(n) > 0.0f ? glm::normalize(n) : glm::vec3(0.0f, 1.0f, 0.0f);
    return impl_->ao(p, nn, radius, samples, hash32(seed * 0x9E3779B1u + 0x7f4a7c15u));
}

bool Tracer::intersect(const glm::vec3& origin, const glm::vec3& dir, float tnear, float tfar, float& t,
                       glm::vec3& normal) const {
    glm::vec3 p;
    return impl_->hit(origin, glm::normalize(dir), tnear, tfar, t, p, normal);
}

bool Tracer::render(const camera::Camera& cam, const RenderOptions& o, Image& out, std::string& error) const {
    if (!ok()) {
        error = impl_->error;
        return false;
    }
    if (o.width <= 0 || o.height <= 0 || o.width > 16384 || o.height > 16384) {
        error = "image size must be 1..16384 in each direction";
        return false;
    }
    if (!(o.radius > 0.0f) || o.samples < 1) {
        error = "radius must be > 0 and samples >= 1";
        return false;
    }
    const float aspect = float(o.width) / float(o.height);
    const glm::dmat4 view = glm::dmat4(camera::view_matrix(cam));
    const glm::dmat4 proj = glm::dmat4(camera::projection_matrix(cam, aspect));
    const glm::dmat4 inv = glm::inverse(proj * view);
    // NDC depth of the near and far planes in this convention.
    const double z_near = cam.reverse_z ? 1.0 : (cam.zero_to_one ? 0.0 : -1.0);
    const double z_far = cam.reverse_z ? 0.0 : 1.0;
    const double z_mid = 0.5 * (z_near + z_far);

    const size_t n = size_t(o.width) * size_t(o.height);
    Image img;
    img.width = o.width;
    img.height = o.height;
    img.ao.assign(n, 1.0f);
    img.std_error.assign(n, 0.0f);
    img.mask.assign(n, 0.0f);
    img.depth.assign(n, std::numeric_limits<float>::infinity());
    img.normal.assign(n * 3, 0.0f);
    img.position.assign(n * 3, std::numeric_limits<float>::quiet_NaN());

    const glm::mat3 view3 = glm::mat3(camera::view_matrix(cam));
    const uint32_t seed_hash = hash32(o.seed * 0x9E3779B1u + 0x85ebca6bu);
    std::atomic<uint64_t> rays{0};

    auto unproject = [&](double x, double y, double z, bool& finite) {
        const glm::dvec4 h = inv * glm::dvec4(x, y, z, 1.0);
        finite = std::fabs(h.w) > 1e-300;
        return finite ? glm::dvec3(h) / h.w : glm::dvec3(0.0);
    };

    auto row = [&](int y) {
        uint64_t local_rays = 0;
        for (int x = 0; x < o.width; ++x) {
            const double ndc_x = (double(x) + 0.5) / double(o.width) * 2.0 - 1.0;
            const double ndc_y = 1.0 - (double(y) + 0.5) / double(o.height) * 2.0;  // row 0 = top
            bool f0 = false, f1 = false, f2 = false;
            const glm::dvec3 p0 = unproject(ndc_x, ndc_y, z_near, f0);
            const glm::dvec3 p1 = unproject(ndc_x, ndc_y, z_mid, f1);
            const glm::dvec3 p2 = unproject(ndc_x, ndc_y, z_far, f2);
            if (!f0 || !f1) continue;
            glm::dvec3 dir = p1 - p0;
            const double len = glm::length(dir);
            if (!(len > 0.0)) continue;
            dir /= len;
            double tfar = std::numeric_limits<double>::infinity();
            if (f2 && std::isfinite(p2.x) && std::isfinite(p2.y) && std::isfinite(p2.z))
                tfar = glm::dot(p2 - p0, dir);
            float t = 0.0f;
            glm::vec3 p, ng;
            ++local_rays;
            if (!impl_->hit(glm::vec3(p0), glm::vec3(dir), 0.0f, float(tfar), t, p, ng)) continue;
            if (glm::dot(ng, glm::vec3(dir)) > 0.0f) ng = -ng;
            const size_t i = size_t(y) * size_t(o.width) + size_t(x);
            const Estimate e = impl_->ao(p, ng, o.radius, o.samples, hash32(seed_hash ^ uint32_t(i * 0x27d4eb2dU)));
            local_rays += uint64_t(e.rays);
            img.ao[i] = float(e.visibility);
            img.std_error[i] = float(e.std_error);
            img.mask[i] = 1.0f;
            const glm::dvec4 pv = view * glm::dvec4(glm::dvec3(p), 1.0);
            img.depth[i] = float(-pv.z);
            for (int k = 0; k < 3; ++k) img.position[i * 3 + size_t(k)] = float(pv[k]);
            const glm::vec3 nv = glm::normalize(view3 * ng);
            img.normal[i * 3] = nv.x;
            img.normal[i * 3 + 1] = nv.y;
            img.normal[i * 3 + 2] = nv.z;
        }
        rays.fetch_add(local_rays);
    };
    img.seconds = row_pool::run(o.height, o.threads, o.progress, "traced", row);
    img.rays = rays.load();
    out = std::move(img);
    return true;
}

}  // namespace raytrace
