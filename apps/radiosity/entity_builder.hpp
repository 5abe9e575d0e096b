#pragma once
// Builds ENTITY records from simple shapes: quads split into a grid of patches, each patch split
// into a grid of elements (vertices shared on the grid), and boxes whose faces share their corner
// vertices or keep their own; the result is exactly what a parsed ENTITY file gives. The analytic
// form-factor cases and the test scenes use it; the built-in scenes are scene descriptions made with
// ObjectBuilder (object_builder.hpp), which to_world lowers to the same ENTITY as these calls.
#include <array>
#include <functional>
#include <string>

#include "apps/radiosity/scene.hpp"

namespace gcsim::radiosity {

struct QuadCorners {
  Vec3 c00, c10, c11, c01;  // u runs c00 -> c10, v runs c00 -> c01
};

class EntityBuilder {
 public:
  explicit EntityBuilder(std::string name) { e_.name = std::move(name); }

  int surface(const Rgb& reflectance, const Rgb& exitance = Rgb(0.0));

  // A quad facing towards `facing` (a direction; the vertex order is chosen to match), split into
  // pu x pv patches, each split into eu x ev elements. surface_of(i, j) picks each patch's surface.
  void quad(const QuadCorners& q, const Vec3& facing, int pu, int pv, int eu, int ev,
            const std::function<int(int, int)>& surface_of);
  void quad(const QuadCorners& q, const Vec3& facing, int pu, int pv, int eu, int ev, int surface) {
    quad(q, facing, pu, pv, eu, ev, [surface](int, int) { return surface; });
  }

  // Faces of an axis-aligned box [lo, hi], facing outwards; one patch and one element per face.
  enum Face { kTop = 1, kBottom = 2, kMinX = 4, kMaxX = 8, kMinZ = 16, kMaxZ = 32, kSides = 4 | 8 | 16 | 32 };
  // Faces share the box's 8 corner vertices.
  void box_shared(const Vec3& lo, const Vec3& hi, int faces, const std::function<int(Face)>& surface_of);
  // Every face has its own 4 vertices.
  void box_separate(const Vec3& lo, const Vec3& hi, int faces, const std::function<int(Face)>& surface_of);

  int add_vertex(const Vec3& v) {
    e_.vertices.push_back(v);
    return int(e_.vertices.size()) - 1;
  }
  // One patch with one element on the given vertices, ordered to face `facing`.
  void single(std::array<int, 4> v, const Vec3& facing, int surface);

  Entity take() { return std::move(e_); }

 private:
  PolygonRecord oriented(std::array<int, 4> v, int count, const Vec3& facing, int owner) const;
  Entity e_;
};

// A box's faces in the order both builders emit them (so that records come out alike), each as
// four of the 8 corners (bit 0 = x, bit 1 = y, bit 2 = z) and its outward normal.
struct BoxFace {
  EntityBuilder::Face face;
  std::array<int, 4> corner;
  Vec3 normal;
};
inline constexpr BoxFace kBoxFaces[] = {
    {EntityBuilder::kTop, {2, 3, 7, 6}, {0, 1, 0}},   {EntityBuilder::kBottom, {0, 1, 5, 4}, {0, -1, 0}},
    {EntityBuilder::kMinX, {0, 2, 6, 4}, {-1, 0, 0}}, {EntityBuilder::kMaxX, {1, 3, 7, 5}, {1, 0, 0}},
    {EntityBuilder::kMinZ, {0, 1, 3, 2}, {0, 0, -1}}, {EntityBuilder::kMaxZ, {4, 5, 7, 6}, {0, 0, 1}},
};
inline Vec3 box_corner(const Vec3& lo, const Vec3& hi, int k) {
  return {(k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z};
}

}  // namespace gcsim::radiosity
