#include "apps/raytrace/embree_reference.hpp"

#ifdef GCSIM_HAVE_EMBREE
#include <algorithm>
#include <limits>
#include <utility>

#include <embree3/rtcore.h>

#include "apps/raytrace/bench_clock.hpp"
#endif

namespace gcsim::raytrace {

#ifndef GCSIM_HAVE_EMBREE
bool embree_available() { return false; }
std::optional<EmbreeTiming> time_embree_primary_rays(const Scene&, const Camera&, int) { return std::nullopt; }
#else
bool embree_available() { return true; }

namespace {

std::pair<double, std::int64_t> time_single_rays(RTCScene rs, const Camera& camera) {
  std::int64_t hits = 0;
  const double start = bench_thread_seconds();
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  for (int y = 0; y < camera.height(); ++y)
    for (int x = 0; x < camera.width(); ++x) {
      const Ray ray = camera.pixel_ray(x, y);
      RTCRayHit rh;
      rh.ray.org_x = ray.origin.x;
      rh.ray.org_y = ray.origin.y;
      rh.ray.org_z = ray.origin.z;
      rh.ray.dir_x = ray.direction.x;
      rh.ray.dir_y = ray.direction.y;
      rh.ray.dir_z = ray.direction.z;
      rh.ray.tnear = 0.0f;
      rh.ray.tfar = std::numeric_limits<float>::infinity();
      rh.ray.mask = ~0u;
      rh.ray.time = 0.0f;
      rh.ray.flags = 0;
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(rs, &context, &rh);
      hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    }
  return {bench_thread_seconds() - start, hits};
}

// Coherent packets: the 4 x 2 pixels of a block, lanes outside the image masked off.
std::pair<double, std::int64_t> time_packets8(RTCScene rs, const Camera& camera) {
  std::int64_t hits = 0;
  const double start = bench_thread_seconds();
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  alignas(32) RTCRayHit8 rh;
  alignas(32) int valid[8];
  for (int y0 = 0; y0 < camera.height(); y0 += 2)
    for (int x0 = 0; x0 < camera.width(); x0 += 4) {
      for (int k = 0; k < 8; ++k) {
        const int x = x0 + k % 4, y = y0 + k / 4;
        valid[k] = x < camera.width() && y < camera.height() ? -1 : 0;
        const Ray ray = camera.pixel_ray(std::min(x, camera.width() - 1), std::min(y, camera.height() - 1));
        rh.ray.org_x[k] = ray.origin.x, rh.ray.org_y[k] = ray.origin.y, rh.ray.org_z[k] = ray.origin.z;
        rh.ray.dir_x[k] = ray.direction.x, rh.ray.dir_y[k] = ray.direction.y, rh.ray.dir_z[k] = ray.direction.z;
        rh.ray.tnear[k] = 0.0f;
        rh.ray.tfar[k] = std::numeric_limits<float>::infinity();
        rh.ray.mask[k] = ~0u;
        rh.ray.time[k] = 0.0f;
        rh.ray.flags[k] = 0;
        rh.ray.id[k] = unsigned(k);
        rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
      }
      rtcIntersect8(valid, rs, &context, &rh);
      for (int k = 0; k < 8; ++k) hits += valid[k] && rh.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID;
    }
  return {bench_thread_seconds() - start, hits};
}

}  // namespace

std::optional<EmbreeTiming> time_embree_primary_rays(const Scene& scene, const Camera& camera, int repeat) {
  RTCDevice device = rtcNewDevice("threads=1");
  if (!device) return std::nullopt;
  RTCScene rs = rtcNewScene(device);
  if (!scene.triangles.empty()) {
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    const std::size_t n = scene.triangles.size();
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * n));
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), n));
    for (std::size_t i = 0; i < n; ++i) {
      const Triangle& t = scene.triangles[i];
      for (int k = 0; k < 3; ++k) {
        const glm::vec3& p = k == 0 ? t.p0 : k == 1 ? t.p1 : t.p2;
        v[9 * i + 3 * k + 0] = p.x;
        v[9 * i + 3 * k + 1] = p.y;
        v[9 * i + 3 * k + 2] = p.z;
        idx[3 * i + k] = unsigned(3 * i + k);
      }
    }
    rtcCommitGeometry(g);
    rtcAttachGeometry(rs, g);
    rtcReleaseGeometry(g);
  }
  if (!scene.spheres.empty()) {
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    const std::size_t n = scene.spheres.size();
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), n));
    for (std::size_t i = 0; i < n; ++i) {
      v[4 * i + 0] = scene.spheres[i].center.x;
      v[4 * i + 1] = scene.spheres[i].center.y;
      v[4 * i + 2] = scene.spheres[i].center.z;
      v[4 * i + 3] = scene.spheres[i].radius;
    }
    rtcCommitGeometry(g);
    rtcAttachGeometry(rs, g);
    rtcReleaseGeometry(g);
  }
  rtcCommitScene(rs);
  EmbreeTiming best{std::numeric_limits<double>::infinity(), 0, std::numeric_limits<double>::infinity(), 0};
  for (int r = 0; r < repeat; ++r) {
    const auto [s1, h1] = time_single_rays(rs, camera);
    if (s1 < best.seconds_per_frame) best.seconds_per_frame = s1, best.hits = h1;
    const auto [s8, h8] = time_packets8(rs, camera);
    if (s8 < best.packet8_seconds_per_frame) best.packet8_seconds_per_frame = s8, best.packet8_hits = h8;
  }
  rtcReleaseScene(rs);
  rtcReleaseDevice(device);
  return best;
}
#endif

}  // namespace gcsim::raytrace
