#include "apps/radiosity/hard_case_scenes.hpp"

#include "apps/common/scene/description_to_world.hpp"
#include "apps/radiosity/object_builder.hpp"

namespace gcsim::radiosity {

Scene facing_unit_squares(double d, double rho) {
  scene::SceneDescription s;
  s.name = "facing squares";
  ObjectBuilder b(s, "facing squares");
  const int light = b.surface(Rgb(0.0), Rgb(1.0));
  const int grey = b.surface(Rgb(rho));
  b.quad({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {0, 0, 1}, 1, 1, 1, 1, light);
  b.quad({{0, 0, d}, {1, 0, d}, {1, 1, d}, {0, 1, d}}, {0, 0, -1}, 1, 1, 1, 1, grey);
  return flatten(scene::to_world(s));
}

Scene closed_box(double s, int n, int m, double rho, double e) {
  scene::SceneDescription d;
  d.name = "closed box";
  ObjectBuilder b(d, "closed box");
  const int surf = b.surface(Rgb(rho), Rgb(e));
  b.quad({{0, 0, 0}, {s, 0, 0}, {s, 0, s}, {0, 0, s}}, {0, 1, 0}, n, n, m, m, surf);
  b.quad({{0, s, 0}, {s, s, 0}, {s, s, s}, {0, s, s}}, {0, -1, 0}, n, n, m, m, surf);
  b.quad({{0, 0, 0}, {0, s, 0}, {0, s, s}, {0, 0, s}}, {1, 0, 0}, n, n, m, m, surf);
  b.quad({{s, 0, 0}, {s, s, 0}, {s, s, s}, {s, 0, s}}, {-1, 0, 0}, n, n, m, m, surf);
  b.quad({{0, 0, 0}, {s, 0, 0}, {s, s, 0}, {0, s, 0}}, {0, 0, 1}, n, n, m, m, surf);
  b.quad({{0, 0, s}, {s, 0, s}, {s, s, s}, {0, s, s}}, {0, 0, -1}, n, n, m, m, surf);
  return flatten(scene::to_world(d));
}

}  // namespace gcsim::radiosity
