#include "apps/radiosity/object_builder.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace gcsim::radiosity {

ObjectBuilder::ObjectBuilder(scene::SceneDescription& d, std::string object)
    : d_(d), object_(std::move(object)), layout_(d.layouts.size()) {
  d_.layouts.push_back({object_, {}, {}, {}});
}

int ObjectBuilder::surface(const Rgb& reflectance, const Rgb& exitance) {
  scene::Material m;
  m.name = fmt::format("{} {}", object_, layout().surface_materials.size());
  m.diffuse = reflectance;
  m.emission = exitance;
  const int material = d_.add_material(m);
  layout().surface_materials.push_back(material);
  return material;
}

scene::Polygon& ObjectBuilder::add_polygon(int material, int back_material) {
  scene::Shape s;
  s.geometry = scene::Polygon{};
  s.material = material;
  s.back_material = back_material;
  s.object = object_;
  d_.shapes.push_back(std::move(s));
  return std::get<scene::Polygon>(d_.shapes.back().geometry);
}

void ObjectBuilder::quad(const QuadCorners& q, const Vec3& facing, int pu, int pv, int eu, int ev,
                         const std::function<int(int, int)>& surface_of) {
  std::vector<int> materials;
  for (int j = 0; j < pv; ++j)
    for (int i = 0; i < pu; ++i) materials.push_back(surface_of(i, j));
  scene::Polygon& p = add_polygon(materials.front());
  p.vertex = {q.c00, q.c10, q.c11, q.c01};
  p.patch_columns = pu, p.patch_rows = pv;
  p.element_columns = eu, p.element_rows = ev;
  p.facing = facing;
  if (std::any_of(materials.begin(), materials.end(), [&](int m) { return m != materials.front(); }))
    p.patch_materials = std::move(materials);
}

void ObjectBuilder::single(const QuadCorners& q, const Vec3& facing, int surface, int back_surface) {
  scene::Polygon& p = add_polygon(surface, back_surface);
  p.vertex = {q.c00, q.c10, q.c11, q.c01};
  p.facing = facing;
  p.single_patch = true;
}

void ObjectBuilder::box_shared(const Vec3& lo, const Vec3& hi, int faces, const std::function<int(Face)>& surface_of) {
  // Only the corners some chosen face uses become (shared) vertices, in corner order.
  int index[8];
  std::fill(std::begin(index), std::end(index), -1);
  for (const auto& f : kBoxFaces)
    if (faces & f.face)
      for (int k : f.corner) index[k] = 0;
  for (int k = 0; k < 8; ++k)
    if (index[k] == 0) {
      index[k] = int(layout().vertices.size());
      layout().vertices.push_back(box_corner(lo, hi, k));
    }
  for (const auto& f : kBoxFaces)
    if (faces & f.face) {
      scene::Polygon& p = add_polygon(surface_of(f.face));
      std::array<int, 4> shared{};
      for (int k = 0; k < 4; ++k) {
        shared[k] = index[f.corner[k]];
        p.vertex[k] = box_corner(lo, hi, f.corner[k]);
      }
      p.layout_vertex = shared;
      p.facing = f.normal;
      p.single_patch = true;
    }
}

void ObjectBuilder::box_separate(const Vec3& lo, const Vec3& hi, int faces,
                                 const std::function<int(Face)>& surface_of) {
  for (const auto& f : kBoxFaces)
    if (faces & f.face)
      single({box_corner(lo, hi, f.corner[0]), box_corner(lo, hi, f.corner[1]), box_corner(lo, hi, f.corner[2]),
              box_corner(lo, hi, f.corner[3])},
             f.normal, surface_of(f.face));
}

void ObjectBuilder::place(const Vec3& translation, double rotate_y_degrees) {
  scene::Placement at;
  at.translation = translation;
  at.rotation_degrees = {0, rotate_y_degrees, 0};
  layout().instances.push_back(at);
}

}  // namespace gcsim::radiosity
