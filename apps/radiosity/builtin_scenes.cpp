#include "apps/radiosity/builtin_scenes.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "apps/radiosity/entity_builder.hpp"
#include "apps/common/scene/world_loader.hpp"

namespace gcsim::radiosity {

namespace {

using F = EntityBuilder::Face;

Instance at(int entity, Vec3 translation, double rotate_y_degrees = 0) {
  Instance i;
  i.entity = entity;
  i.placement.translation = translation;
  i.placement.rotation_degrees = {0, rotate_y_degrees, 0};
  return i;
}

// Room of W x H x D metres (x, y, z), floor at y = 0, inner faces looking inwards.
struct RoomShape {
  double w = 5.0, h = 2.6, d = 4.0;
  QuadCorners floor() const { return {{0, 0, 0}, {w, 0, 0}, {w, 0, d}, {0, 0, d}}; }
  QuadCorners ceiling() const { return {{0, h, 0}, {w, h, 0}, {w, h, d}, {0, h, d}}; }
  QuadCorners wall_z(double z) const { return {{0, 0, z}, {w, 0, z}, {w, h, z}, {0, h, z}}; }
  QuadCorners wall_x(double x) const { return {{x, 0, 0}, {x, 0, d}, {x, h, d}, {x, h, 0}}; }
};

// The pieces of furniture the two rooms share. Each returns an entity in local coordinates.
Entity ceiling_light(double size, const Rgb& exitance) {
  EntityBuilder b("ceiling light");
  int s = b.surface({0.80, 0.80, 0.80}, exitance);
  double r = size / 2;
  b.quad({{-r, 0, -r}, {r, 0, -r}, {r, 0, r}, {-r, 0, r}}, {0, -1, 0}, 1, 1, 1, 1, s);
  return b.take();
}
void table_top(EntityBuilder& b) {
  int top = b.surface({0.62, 0.44, 0.26});
  int edge = b.surface({0.42, 0.28, 0.16});
  b.box_separate({-0.7, 0.72, -0.4}, {0.7, 0.77, 0.4}, F::kTop | F::kSides,
                 [&](F f) { return f == F::kTop ? top : edge; });
}
void table_base(EntityBuilder& b) {
  int metal = b.surface({0.30, 0.30, 0.33});
  b.box_separate({-0.08, 0, -0.08}, {0.08, 0.72, 0.08}, F::kSides, [&](F) { return metal; });
}
// A block chair facing +z: a seat block and a back rest, corners shared within each block.
Entity chair() {
  EntityBuilder b("chair");
  int seat = b.surface({0.25, 0.35, 0.60});
  int seat_wood = b.surface({0.50, 0.34, 0.20});
  int back = b.surface({0.25, 0.35, 0.60});
  int back_wood = b.surface({0.50, 0.34, 0.20});
  b.box_shared({-0.23, 0, -0.23}, {0.23, 0.46, 0.23}, F::kTop | F::kSides,
               [&](F f) { return f == F::kTop ? seat : seat_wood; });
  b.box_shared({-0.23, 0.46, -0.23}, {0.23, 0.95, -0.17}, F::kTop | F::kSides,
               [&](F f) { return f == F::kMaxZ ? back : back_wood; });
  return b.take();
}
Entity cabinet() {
  EntityBuilder b("cabinet");
  int top = b.surface({0.55, 0.40, 0.25});
  int body = b.surface({0.70, 0.66, 0.58});
  b.box_separate({-0.2, 0, -0.25}, {0.2, 1.8, 0.25}, F::kTop | F::kSides,
                 [&](F f) { return f == F::kTop ? top : body; });
  return b.take();
}
// Lies 5 mm above the floor: nearly coplanar with it on purpose.
Entity rug() {
  EntityBuilder b("rug");
  int s = b.surface({0.60, 0.16, 0.12});
  b.quad({{-1.0, 0.005, -0.7}, {1.0, 0.005, -0.7}, {1.0, 0.005, 0.7}, {-1.0, 0.005, 0.7}}, {0, 1, 0}, 1, 1, 1, 1, s);
  return b.take();
}

Camera room_camera() {
  Camera c;
  c.eye = {4.75, 1.65, 0.2};
  c.look_at = {1.6, 0.75, 3.1};
  c.fov_y_degrees = 62;
  return c;
}

}  // namespace

World room_world() {
  World w;
  w.name = "ROOM";
  RoomShape r;
  {
    EntityBuilder b("room shell");
    int floor = b.surface({0.55, 0.40, 0.28});
    int ceiling = b.surface({0.80, 0.80, 0.78});
    int north = b.surface({0.75, 0.70, 0.60});
    int south = b.surface({0.75, 0.70, 0.60});
    int west = b.surface({0.40, 0.52, 0.70});
    int east = b.surface({0.75, 0.70, 0.60});
    b.quad(r.floor(), {0, 1, 0}, 2, 2, 3, 3, floor);
    b.quad(r.ceiling(), {0, -1, 0}, 1, 1, 2, 2, ceiling);
    b.quad(r.wall_z(r.d), {0, 0, -1}, 2, 1, 3, 4, north);
    b.quad(r.wall_z(0), {0, 0, 1}, 2, 1, 3, 4, south);
    b.quad(r.wall_x(0), {1, 0, 0}, 1, 1, 6, 6, west);
    b.quad(r.wall_x(r.w), {-1, 0, 0}, 1, 1, 6, 6, east);
    w.entities.push_back(b.take());
  }
  w.entities.push_back(ceiling_light(0.6, {12.0, 11.4, 10.0}));
  {
    EntityBuilder b("table top");
    table_top(b);
    w.entities.push_back(b.take());
  }
  {
    EntityBuilder b("table base");
    table_base(b);
    w.entities.push_back(b.take());
  }
  w.entities.push_back(chair());
  w.entities.push_back(cabinet());
  w.entities.push_back(rug());
  w.instances = {at(0, {0, 0, 0}),          at(1, {1.7, r.h - 0.01, 2.0}), at(1, {3.3, r.h - 0.01, 2.0}),
                 at(2, {2.5, 0, 2.2}),      at(3, {2.5, 0, 2.2}),          at(4, {2.5, 0, 1.3}),
                 at(4, {2.5, 0, 3.1}, 180), at(5, {0.21, 0, 0.9}),         at(6, {2.5, 0, 2.2})};
  w.camera = room_camera();
  return w;
}

World picroom_world() {
  World w;
  w.name = "PICROOM";
  RoomShape r;
  {
    EntityBuilder b("room shell");
    int floor = b.surface({0.55, 0.40, 0.28});
    int ceiling = b.surface({0.80, 0.80, 0.78});
    int walls = b.surface({0.75, 0.72, 0.64});
    b.quad(r.floor(), {0, 1, 0}, 3, 3, 1, 1, floor);
    b.quad(r.ceiling(), {0, -1, 0}, 3, 3, 2, 2, ceiling);
    b.quad(r.wall_z(r.d), {0, 0, -1}, 3, 1, 1, 1, walls);
    b.quad(r.wall_z(0), {0, 0, 1}, 3, 1, 1, 1, walls);
    b.quad(r.wall_x(0), {1, 0, 0}, 1, 1, 1, 2, walls);
    b.quad(r.wall_x(r.w), {-1, 0, 0}, 1, 1, 1, 2, walls);
    w.entities.push_back(b.take());
  }
  w.entities.push_back(ceiling_light(0.8, {14.0, 13.3, 11.7}));
  {
    EntityBuilder b("table");
    table_top(b);
    table_base(b);
    w.entities.push_back(b.take());
  }
  w.entities.push_back(chair());
  w.entities.push_back(cabinet());
  w.entities.push_back(rug());
  {
    // A landscape of 9 x 6 patches: sky, sun, grass. Local plane z = 0, facing +z.
    EntityBuilder b("picture: landscape");
    int sky = b.surface({0.45, 0.62, 0.85});
    int sun = b.surface({0.95, 0.80, 0.20});
    int grass = b.surface({0.25, 0.55, 0.20});
    b.quad({{-0.675, -0.45, 0}, {0.675, -0.45, 0}, {0.675, 0.45, 0}, {-0.675, 0.45, 0}}, {0, 0, 1}, 9, 6, 1, 1,
           [&](int i, int j) {
             if (j < 2 || (j == 2 && i >= 2 && i <= 5)) return grass;  // a hill
             if (j >= 4 && i >= 6 && i <= 7) return sun;
             return sky;
           });
    w.entities.push_back(b.take());
  }
  {
    // An abstract of 6 x 5 patches in three colours.
    EntityBuilder b("picture: abstract");
    int red = b.surface({0.80, 0.15, 0.10});
    int navy = b.surface({0.10, 0.15, 0.45});
    int cream = b.surface({0.90, 0.86, 0.72});
    b.quad({{-0.45, -0.375, 0}, {0.45, -0.375, 0}, {0.45, 0.375, 0}, {-0.45, 0.375, 0}}, {0, 0, 1}, 6, 5, 1, 1,
           [&](int i, int j) {
             if (i <= 2 && j >= 2) return red;
             if (i >= 4 && j <= 1) return navy;
             return cream;
           });
    w.entities.push_back(b.take());
  }
  w.instances = {at(0, {0, 0, 0}),
                 at(1, {2.5, r.h - 0.01, 2.0}),
                 at(2, {2.5, 0, 2.2}),
                 at(3, {2.5, 0, 1.3}),
                 at(3, {2.5, 0, 3.1}, 180),
                 at(4, {0.21, 0, 0.9}),
                 at(5, {2.5, 0, 2.2}),
                 at(6, {2.2, 1.55, r.d - 0.01}, 180),  // on the north wall, facing -z
                 at(7, {0.01, 1.5, 1.9}, 90),          // two on the west wall, facing +x
                 at(7, {0.01, 1.5, 3.1}, 90)};
  w.camera = room_camera();
  return w;
}

World cornell_world() {
  // The Cornell box as published by the Cornell Program of Computer Graphics (mm); the usual RGB
  // approximations of its measured reflectances and of the light's emission.
  World w;
  w.name = "CORNELL";
  const Rgb white{0.725, 0.71, 0.68}, red{0.63, 0.065, 0.05}, green{0.14, 0.45, 0.091};
  const Vec3 inside{278, 274, 280};
  auto wall = [&](const char* name, const Rgb& rho, QuadCorners q, int pu, int pv, int eu, int ev) {
    EntityBuilder b(name);
    int s = b.surface(rho);
    Vec3 c = 0.25 * (q.c00 + q.c10 + q.c11 + q.c01);
    b.quad(q, inside - c, pu, pv, eu, ev, s);
    w.entities.push_back(b.take());
  };
  wall("floor", white, {{552.8, 0, 0}, {0, 0, 0}, {0, 0, 559.2}, {549.6, 0, 559.2}}, 4, 4, 2, 2);
  wall("ceiling", white, {{556, 548.8, 0}, {0, 548.8, 0}, {0, 548.8, 559.2}, {556, 548.8, 559.2}}, 4, 4, 1, 1);
  wall("back wall", white, {{549.6, 0, 559.2}, {0, 0, 559.2}, {0, 548.8, 559.2}, {556, 548.8, 559.2}}, 4, 4, 1, 1);
  wall("red wall", red, {{552.8, 0, 0}, {549.6, 0, 559.2}, {556, 548.8, 559.2}, {556, 548.8, 0}}, 4, 4, 1, 1);
  wall("green wall", green, {{0, 0, 559.2}, {0, 0, 0}, {0, 548.8, 0}, {0, 548.8, 559.2}}, 4, 4, 1, 1);
  auto block = [&](const char* name, std::array<Vec3, 4> top, double height, int top_pu, int top_pv, int top_e,
                   int side_pv) {
    EntityBuilder b(name);
    int s = b.surface(white);
    Vec3 c = 0.25 * (top[0] + top[1] + top[2] + top[3]) - Vec3(0, height / 2, 0);
    b.quad({top[0], top[1], top[2], top[3]}, {0, 1, 0}, top_pu, top_pv, top_e, top_e, s);
    for (int k = 0; k < 4; ++k) {
      Vec3 a = top[k], d = top[(k + 1) % 4];
      Vec3 a0{a.x, 0, a.z}, d0{d.x, 0, d.z};
      Vec3 mid = 0.5 * (a0 + d) ;
      b.quad({a0, d0, d, a}, Vec3(mid.x - c.x, 0, mid.z - c.z), 1, side_pv, 1, 1, s);
    }
    w.entities.push_back(b.take());
  };
  block("short block", {Vec3{130, 165, 65}, {82, 165, 225}, {240, 165, 272}, {290, 165, 114}}, 165, 1, 2, 2, 2);
  block("tall block", {Vec3{423, 330, 247}, {265, 330, 296}, {314, 330, 456}, {472, 330, 406}}, 330, 1, 4, 1, 4);
  {
    // The light hangs 0.1 mm below the ceiling; its housing (upper side) is black.
    EntityBuilder b("light");
    int emitter = b.surface({0.78, 0.78, 0.78}, {18.4, 15.6, 8.0});
    int housing = b.surface({0.0, 0.0, 0.0});
    int v0 = b.add_vertex({343, 548.7, 227}), v1 = b.add_vertex({343, 548.7, 332});
    int v2 = b.add_vertex({213, 548.7, 332}), v3 = b.add_vertex({213, 548.7, 227});
    b.single({v0, v1, v2, v3}, {0, -1, 0}, emitter);
    b.single({v0, v1, v2, v3}, {0, 1, 0}, housing);
    w.entities.push_back(b.take());
  }
  for (int i = 0; i < int(w.entities.size()); ++i) w.instances.push_back(at(i, {0, 0, 0}));
  Camera cam;
  cam.eye = {278, 273, -800};
  cam.look_at = {278, 273, 0};
  cam.fov_y_degrees = 39.3;  // 35 mm focal length, 25 mm film
  w.camera = cam;
  return w;
}

std::vector<std::string> builtin_scene_names() { return {"room", "picroom", "cornell"}; }

World load_scene_world(const std::string& name) {
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  if (lower == "room") return room_world();
  if (lower == "picroom") return picroom_world();
  if (lower == "cornell") return cornell_world();
  if (std::filesystem::exists(name)) return load_world(name);
  throw std::invalid_argument(
      fmt::format("unknown scene '{}': expected room, picroom, cornell or the path of a WORLD file", name));
}

SceneCounts thesis_counts(std::string_view name) {
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  if (lower == "room") return {9, 22, 48, 197, 326};
  if (lower == "picroom") return {10, 27, 176, 205, 343};
  if (lower == "cornell") return {8, 9, 112, 166, 274};
  return {};
}

}  // namespace gcsim::radiosity
