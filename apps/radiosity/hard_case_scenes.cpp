#include "apps/radiosity/hard_case_scenes.hpp"

#include "apps/radiosity/entity_builder.hpp"

namespace gcsim::radiosity {

namespace {

Scene single_entity_scene(EntityBuilder& b, const char* name) {
  World w;
  w.name = name;
  w.entities.push_back(b.take());
  w.instances.push_back({0, {}});
  return flatten(w);
}

}  // namespace

Scene facing_unit_squares(double d, double rho) {
  EntityBuilder b("facing squares");
  const int light = b.surface(Rgb(0.0), Rgb(1.0));
  const int grey = b.surface(Rgb(rho));
  b.quad({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {0, 0, 1}, 1, 1, 1, 1, light);
  b.quad({{0, 0, d}, {1, 0, d}, {1, 1, d}, {0, 1, d}}, {0, 0, -1}, 1, 1, 1, 1, grey);
  return single_entity_scene(b, "facing squares");
}

Scene closed_box(double s, int n, int m, double rho, double e) {
  EntityBuilder b("closed box");
  const int surf = b.surface(Rgb(rho), Rgb(e));
  b.quad({{0, 0, 0}, {s, 0, 0}, {s, 0, s}, {0, 0, s}}, {0, 1, 0}, n, n, m, m, surf);
  b.quad({{0, s, 0}, {s, s, 0}, {s, s, s}, {0, s, s}}, {0, -1, 0}, n, n, m, m, surf);
  b.quad({{0, 0, 0}, {0, s, 0}, {0, s, s}, {0, 0, s}}, {1, 0, 0}, n, n, m, m, surf);
  b.quad({{s, 0, 0}, {s, s, 0}, {s, s, s}, {s, 0, s}}, {-1, 0, 0}, n, n, m, m, surf);
  b.quad({{0, 0, 0}, {s, 0, 0}, {s, s, 0}, {0, s, 0}}, {0, 0, 1}, n, n, m, m, surf);
  b.quad({{0, 0, s}, {s, 0, s}, {s, s, s}, {0, s, s}}, {0, 0, -1}, n, n, m, m, surf);
  return single_entity_scene(b, "closed box");
}

}  // namespace gcsim::radiosity
