#include "apps/radiosity/entity_builder.hpp"

#include <algorithm>

namespace gcsim::radiosity {

int EntityBuilder::surface(const Rgb& reflectance, const Rgb& exitance) {
  e_.surfaces.push_back({reflectance, exitance});
  return int(e_.surfaces.size()) - 1;
}

PolygonRecord EntityBuilder::oriented(std::array<int, 4> v, int count, const Vec3& facing, int owner) const {
  Polygon p;
  p.count = count;
  for (int k = 0; k < count; ++k) p.v[k] = e_.vertices[v[k]];
  if (glm::dot(newell_normal(p), facing) < 0) std::reverse(v.begin(), v.begin() + count);
  PolygonRecord r;
  r.owner = owner;
  r.vertex = v;
  r.count = count;
  return r;
}

void EntityBuilder::quad(const QuadCorners& q, const Vec3& facing, int pu, int pv, int eu, int ev,
                         const std::function<int(int, int)>& surface_of) {
  const int nu = pu * eu, nv = pv * ev;
  const int base = int(e_.vertices.size());
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      double s = double(i) / nu, t = double(j) / nv;
      add_vertex((1 - s) * (1 - t) * q.c00 + s * (1 - t) * q.c10 + s * t * q.c11 + (1 - s) * t * q.c01);
    }
  auto at = [&](int i, int j) { return base + j * (nu + 1) + i; };
  for (int pj = 0; pj < pv; ++pj)
    for (int pi = 0; pi < pu; ++pi) {
      int i0 = pi * eu, j0 = pj * ev;
      e_.patches.push_back(oriented({at(i0, j0), at(i0 + eu, j0), at(i0 + eu, j0 + ev), at(i0, j0 + ev)}, 4, facing,
                                    surface_of(pi, pj)));
      int patch = int(e_.patches.size()) - 1;
      for (int ej = 0; ej < ev; ++ej)
        for (int ei = 0; ei < eu; ++ei) {
          int i = i0 + ei, j = j0 + ej;
          e_.elements.push_back(oriented({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}, 4, facing, patch));
        }
    }
}

void EntityBuilder::single(std::array<int, 4> v, const Vec3& facing, int surface) {
  e_.patches.push_back(oriented(v, 4, facing, surface));
  e_.elements.push_back(oriented(v, 4, facing, int(e_.patches.size()) - 1));
}

void EntityBuilder::box_shared(const Vec3& lo, const Vec3& hi, int faces, const std::function<int(Face)>& surface_of) {
  // Only the corners some chosen face uses become vertices.
  int index[8];
  std::fill(std::begin(index), std::end(index), -1);
  for (const auto& f : kBoxFaces)
    if (faces & f.face)
      for (int k : f.corner)
        if (index[k] < 0) index[k] = 0;
  for (int k = 0; k < 8; ++k)
    if (index[k] == 0) index[k] = add_vertex(box_corner(lo, hi, k));
  for (const auto& f : kBoxFaces)
    if (faces & f.face)
      single({index[f.corner[0]], index[f.corner[1]], index[f.corner[2]], index[f.corner[3]]}, f.normal,
             surface_of(f.face));
}

void EntityBuilder::box_separate(const Vec3& lo, const Vec3& hi, int faces,
                                 const std::function<int(Face)>& surface_of) {
  for (const auto& f : kBoxFaces)
    if (faces & f.face) {
      std::array<int, 4> v;
      for (int k = 0; k < 4; ++k) v[k] = add_vertex(box_corner(lo, hi, f.corner[k]));
      single(v, f.normal, surface_of(f.face));
    }
}

}  // namespace gcsim::radiosity
