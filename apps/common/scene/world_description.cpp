#include "apps/common/scene/world_description.hpp"

#include <fmt/format.h>

#include "apps/common/scene/world_loader.hpp"

namespace gcsim::scene {

namespace {

bool valid_record(const PolygonRecord& rec, const Entity& e) {
  if (rec.count < 3 || rec.count > 4) return false;
  for (int k = 0; k < rec.count; ++k)
    if (rec.vertex[k] < 0 || rec.vertex[k] >= int(e.vertices.size())) return false;
  return true;
}

}  // namespace

std::string world_problem(const World& w, const std::string& of) {
  for (const Instance& inst : w.instances)
    if (inst.entity < 0 || inst.entity >= int(w.entities.size()))
      return fmt::format("the WORLD file{} places an entity it does not define", of);
  for (const Entity& e : w.entities) {
    for (const auto* records : {&e.patches, &e.elements})
      for (const PolygonRecord& rec : *records)
        if (!valid_record(rec, e)) return fmt::format("entity '{}'{} has a polygon with a bad vertex list", e.name, of);
    for (const PolygonRecord& p : e.patches)
      if (p.owner < 0 || p.owner >= int(e.surfaces.size()))
        return fmt::format("entity '{}'{} has a patch of an unknown surface", e.name, of);
    for (const PolygonRecord& el : e.elements)
      if (el.owner < 0 || el.owner >= int(e.patches.size()))
        return fmt::format("entity '{}'{} has an element of an unknown patch", e.name, of);
  }
  return "";
}

void add_world(const World& w, const std::string& prefix, SceneDescription& out) {
  std::vector<int> first_material(w.entities.size());
  for (std::size_t e = 0; e < w.entities.size(); ++e) {
    first_material[e] = int(out.materials.size());
    for (std::size_t k = 0; k < w.entities[e].surfaces.size(); ++k) {
      Material m;
      m.name = fmt::format("{}/{}/surface {}", prefix, w.entities[e].name, k);
      m.diffuse = w.entities[e].surfaces[k].reflectance;
      m.emission = w.entities[e].surfaces[k].exitance;
      out.add_material(m);
    }
  }
  for (std::size_t i = 0; i < w.instances.size(); ++i) {
    const Instance& inst = w.instances[i];
    const Entity& e = w.entities.at(inst.entity);
    const Vec3& sc = inst.placement.scale;
    const bool mirrored = (sc.x < 0) != ((sc.y < 0) != (sc.z < 0));  // as radiosity's flatten
    auto placed = [&](const PolygonRecord& rec, std::array<glm::dvec3, 4>& v) {
      for (int k = 0; k < rec.count; ++k)
        v[k] = inst.placement.apply(e.vertices.at(rec.vertex[mirrored ? rec.count - 1 - k : k]));
    };
    for (std::size_t pi = 0; pi < e.patches.size(); ++pi) {
      Polygon p;
      p.count = e.patches[pi].count;
      placed(e.patches[pi], p.vertex);
      for (const PolygonRecord& el : e.elements)
        if (el.owner == int(pi)) {
          ExplicitElement x;
          x.count = el.count;
          placed(el, x.vertex);
          p.elements.push_back(x);
        }
      Shape s;
      s.geometry = p;
      s.material = first_material[inst.entity] + e.patches[pi].owner;
      s.object = fmt::format("{}/{}#{}", prefix, e.name, i);
      out.shapes.push_back(s);
    }
  }
  if (!out.camera) out.camera = w.camera;
}

SceneDescription load_world_description(const std::filesystem::path& file) {
  World w = load_world(file);
  if (const std::string problem = world_problem(w, ""); !problem.empty()) throw SceneError(file.string(), 0, problem);
  SceneDescription d;
  d.name = w.name.empty() ? file.stem().string() : w.name;
  add_world(w, file.stem().string(), d);
  d.source_world = std::move(w);
  return d;
}

}  // namespace gcsim::scene
