#include "apps/common/scene/description_to_world.hpp"

#include <algorithm>
#include <map>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

namespace gcsim::scene {

namespace {

// One entity under construction: its surfaces are created per material, those of its layout first,
// the others on first use.
class EntityLowering {
 public:
  EntityLowering(std::string name, const SceneDescription& d, const ObjectLayout* layout) : d_(d), layout_(layout) {
    e_.name = std::move(name);
    if (!layout) return;
    for (int m : layout->surface_materials) surface_of(m);
  }

  int surface_of(int material) {
    if (material < 0 || material >= int(d_.materials.size()))
      throw std::invalid_argument(fmt::format("entity '{}' uses material {}, but there are {}", e_.name, material,
                                              d_.materials.size()));
    auto [it, added] = surface_index_.emplace(material, int(e_.surfaces.size()));
    if (added) e_.surfaces.push_back({d_.materials[material].diffuse, d_.materials[material].emission, material});
    return it->second;
  }
  int vertex(const Vec3& v) {
    e_.vertices.push_back(v);
    return int(e_.vertices.size()) - 1;
  }
  // A patch record and its elements, oriented as EntityBuilder::oriented does.
  PolygonRecord record(std::array<int, 4> v, int count, const std::optional<Vec3>& facing, bool back, int owner) const {
    if (facing) {
      geometry::Polygon p;
      p.count = count;
      for (int k = 0; k < count; ++k) p.v[k] = e_.vertices[v[k]];
      if (glm::dot(geometry::newell_normal(p), *facing) < 0) std::reverse(v.begin(), v.begin() + count);
    }
    if (back) std::reverse(v.begin(), v.begin() + count);
    return {owner, v, count};
  }
  int add_patch(const PolygonRecord& r) {
    e_.patches.push_back(r);
    return int(e_.patches.size()) - 1;
  }
  void add_element(const PolygonRecord& r) { e_.elements.push_back(r); }

  void polygon(const Polygon& p, int material, int back_material);
  void single_patch(const Polygon& p, int front, int back);
  void box(const Box& b, int material);
  void sphere(const Sphere& s, int material);
  void mesh(const Mesh& m, int material);
  // The entity's instances: its layout's placements, else one unmoved.
  std::vector<Placement> placements() const {
    if (!layout_ || layout_->instances.empty()) return {Placement{}};
    return layout_->instances;
  }
  Entity take() {
    if (layout_ && !layout_->vertices.empty()) shared_vertex(int(layout_->vertices.size()) - 1);  // unused ones last
    return std::move(e_);
  }

 private:
  void grid_side(const Polygon& p, int base, int surface, bool back);
  int patch_surface(const Polygon& p, int pi, int pj, int surface);
  std::array<int, 4> corners(const Polygon& p);
  int shared_vertex(int layout_index);
  const SceneDescription& d_;
  const ObjectLayout* layout_;
  Entity e_;
  std::map<int, int> surface_index_;
  std::vector<int> shared_index_;  // entity vertex of each layout vertex added so far
};

void EntityLowering::grid_side(const Polygon& p, int base, int surface, bool back) {
  const int eu = p.element_columns, ev = p.element_rows, nu = p.patch_columns * eu;
  auto at = [&](int i, int j) { return base + j * (nu + 1) + i; };
  for (int pj = 0; pj < p.patch_rows; ++pj)
    for (int pi = 0; pi < p.patch_columns; ++pi) {
      const int i0 = pi * eu, j0 = pj * ev;
      const int patch = add_patch(record({at(i0, j0), at(i0 + eu, j0), at(i0 + eu, j0 + ev), at(i0, j0 + ev)}, 4,
                                         p.facing, back, back ? surface : patch_surface(p, pi, pj, surface)));
      for (int ej = 0; ej < ev; ++ej)
        for (int ei = 0; ei < eu; ++ei) {
          const int i = i0 + ei, j = j0 + ej;
          add_element(record({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}, 4, p.facing, back, patch));
        }
    }
}

// A grid patch's surface: its own material where the polygon gives one per patch.
int EntityLowering::patch_surface(const Polygon& p, int pi, int pj, int surface) {
  if (p.patch_materials.empty()) return surface;
  if (p.patch_materials.size() != std::size_t(p.patch_rows) * p.patch_columns)
    throw std::invalid_argument(fmt::format("entity '{}': a polygon of {} x {} patches gives {} patch materials", e_.name,
                                            p.patch_columns, p.patch_rows, p.patch_materials.size()));
  return surface_of(p.patch_materials[std::size_t(pj) * p.patch_columns + pi]);
}

// The entity's vertex for a layout vertex. Layout vertices enter the entity in their order, each no
// later than the first polygon that uses it, as EntityBuilder adds a box's shared corners just
// before its faces.
int EntityLowering::shared_vertex(int i) {
  if (!layout_ || i < 0 || i >= int(layout_->vertices.size()))
    throw std::invalid_argument(fmt::format("entity '{}': a polygon names shared vertex {}, but its layout has {}",
                                            e_.name, i, layout_ ? layout_->vertices.size() : 0));
  while (int(shared_index_.size()) <= i) shared_index_.push_back(vertex(layout_->vertices[shared_index_.size()]));
  return shared_index_[i];
}

// The corners of a one-patch polygon: the object's shared vertices it names, or vertices of its own.
std::array<int, 4> EntityLowering::corners(const Polygon& p) {
  std::array<int, 4> v{};
  for (int k = 0; k < p.count; ++k) v[k] = p.layout_vertex ? shared_vertex((*p.layout_vertex)[k]) : vertex(p.vertex[k]);
  return v;
}

// One patch on the corners; its elements explicit or the patch itself; the back side on the same corners.
void EntityLowering::single_patch(const Polygon& p, int front, int back) {
  if (!p.patch_materials.empty())
    throw std::invalid_argument(fmt::format("entity '{}': a one-patch polygon gives patch materials", e_.name));
  const std::array<int, 4> v = corners(p);
  for (int side = 0; side < (back >= 0 ? 2 : 1); ++side) {
    const int patch = add_patch(record(v, p.count, p.facing, side == 1, side == 1 ? back : front));
    if (p.elements.empty()) add_element(record(v, p.count, p.facing, side == 1, patch));
    for (const ExplicitElement& x : p.elements) {
      std::array<int, 4> ev{};
      for (int k = 0; k < x.count; ++k) ev[k] = vertex(x.vertex[k]);
      add_element(record(ev, x.count, p.facing, side == 1, patch));
    }
  }
}

void EntityLowering::polygon(const Polygon& p, int material, int back_material) {
  const int front = surface_of(material);
  const int back = back_material >= 0 ? surface_of(back_material) : -1;
  if (!p.elements.empty() || p.count == 3 || p.single_patch || p.layout_vertex) return single_patch(p, front, back);
  // The grid of EntityBuilder::quad: u runs vertex 0 -> 1, v runs vertex 0 -> 3.
  const Vec3 c00 = p.vertex[0], c10 = p.vertex[1], c11 = p.vertex[2], c01 = p.vertex[3];
  const int nu = p.patch_columns * p.element_columns, nv = p.patch_rows * p.element_rows;
  const int base = int(e_.vertices.size());
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      double s = double(i) / nu, t = double(j) / nv;
      vertex((1 - s) * (1 - t) * c00 + s * (1 - t) * c10 + s * t * c11 + (1 - s) * t * c01);
    }
  grid_side(p, base, front, false);
  if (back >= 0) grid_side(p, base, back, true);
}

void EntityLowering::box(const Box& b, int material) {
  const int s = surface_of(material);
  int corner[8];
  for (int k = 0; k < 8; ++k) corner[k] = vertex({k & 1 ? b.hi.x : b.lo.x, k & 2 ? b.hi.y : b.lo.y, k & 4 ? b.hi.z : b.lo.z});
  // Each face counter-clockwise seen from outside.
  static constexpr int kFaces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : kFaces) {
    const std::array<int, 4> v{corner[f[0]], corner[f[1]], corner[f[2]], corner[f[3]]};
    add_element(record(v, 4, std::nullopt, false, add_patch(record(v, 4, std::nullopt, false, s))));
  }
}

void EntityLowering::sphere(const Sphere& sp, int material) {
  const int s = surface_of(material);
  const double pi = std::numbers::pi;
  auto point = [&](int slice, int stack) {
    const double theta = pi * stack / kSphereStacks, phi = 2 * pi * slice / kSphereSlices;
    return sp.center + sp.radius * Vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
  };
  for (int j = 0; j < kSphereStacks; ++j)
    for (int i = 0; i < kSphereSlices; ++i) {
      // In this order the front looks outwards; at the poles two corners coincide and one is dropped.
      const std::array<Vec3, 4> q{point(i, j), point(i + 1, j), point(i + 1, j + 1), point(i, j + 1)};
      std::array<int, 4> v{};
      int count = 0;
      for (int k = 0; k < 4; ++k)
        if (!(j == 0 && k == 1) && !(j == kSphereStacks - 1 && k == 2)) v[count++] = vertex(q[k]);
      add_element(record(v, count, std::nullopt, false, add_patch(record(v, count, std::nullopt, false, s))));
    }
}

void EntityLowering::mesh(const Mesh& m, int material) {
  const int s = surface_of(material);
  const int base = int(e_.vertices.size());
  for (const Vec3& p : m.mesh.positions) vertex(p);
  for (const auto& t : m.mesh.triangles) {
    const std::array<int, 4> v{base + t[0], base + t[1], base + t[2], 0};
    add_element(record(v, 3, std::nullopt, false, add_patch(record(v, 3, std::nullopt, false, s))));
  }
}

std::string default_object_name(const Shape& s, std::size_t index) {
  static constexpr const char* kKinds[] = {"polygon", "sphere", "box", "mesh"};
  return fmt::format("{} {}", kKinds[s.geometry.index()], index);
}

// The layout of each named object (null where it has none); a layout naming no shape's object is an error.
std::map<std::string, const ObjectLayout*> layouts_by_object(const SceneDescription& d) {
  std::map<std::string, const ObjectLayout*> layouts;
  for (const Shape& s : d.shapes) layouts.emplace(s.object, nullptr);
  for (const ObjectLayout& l : d.layouts) {
    auto it = layouts.find(l.object);
    if (l.object.empty() || it == layouts.end())
      throw std::invalid_argument(fmt::format("scene '{}': a layout for object '{}', which no shape belongs to", d.name, l.object));
    if (it->second) throw std::invalid_argument(fmt::format("scene '{}': two layouts for object '{}'", d.name, l.object));
    it->second = &l;
  }
  return layouts;
}

}  // namespace

World to_world(const SceneDescription& d) {
  if (d.source_world) return *d.source_world;
  World w;
  w.name = d.name;
  std::vector<EntityLowering> entities;
  std::map<std::string, std::size_t> by_object;
  const auto layouts = layouts_by_object(d);
  for (std::size_t i = 0; i < d.shapes.size(); ++i) {
    const Shape& s = d.shapes[i];
    std::size_t e;
    if (s.object.empty() || !by_object.count(s.object)) {
      e = entities.size();
      entities.emplace_back(s.object.empty() ? default_object_name(s, i) : s.object, d,
                            s.object.empty() ? nullptr : layouts.at(s.object));
      if (!s.object.empty()) by_object[s.object] = e;
    } else {
      e = by_object[s.object];
    }
    EntityLowering& x = entities[e];
    if (const auto* p = std::get_if<Polygon>(&s.geometry)) x.polygon(*p, s.material, s.back_material);
    else if (const auto* b = std::get_if<Box>(&s.geometry)) x.box(*b, s.material);
    else if (const auto* sp = std::get_if<Sphere>(&s.geometry)) x.sphere(*sp, s.material);
    else x.mesh(std::get<Mesh>(s.geometry), s.material);
  }
  for (EntityLowering& x : entities) {
    const int index = int(w.entities.size());
    for (const Placement& at : x.placements()) w.instances.push_back({index, at});
    w.entities.push_back(x.take());
  }
  w.camera = d.camera;
  return w;
}

}  // namespace gcsim::scene
