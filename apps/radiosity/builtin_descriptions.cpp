#include "apps/radiosity/builtin_descriptions.hpp"

#include <string>

#include "apps/radiosity/object_builder.hpp"

namespace gcsim::radiosity {

namespace {

using F = EntityBuilder::Face;
using scene::SceneDescription;

// Room of W x H x D metres (x, y, z), floor at y = 0, inner faces looking inwards.
struct RoomShape {
  double w = 5.0, h = 2.6, d = 4.0;
  QuadCorners floor() const { return {{0, 0, 0}, {w, 0, 0}, {w, 0, d}, {0, 0, d}}; }
  QuadCorners ceiling() const { return {{0, h, 0}, {w, h, 0}, {w, h, d}, {0, h, d}}; }
  QuadCorners wall_z(double z) const { return {{0, 0, z}, {w, 0, z}, {w, h, z}, {0, h, z}}; }
  QuadCorners wall_x(double x) const { return {{x, 0, 0}, {x, 0, d}, {x, h, d}, {x, h, 0}}; }
};

// The pieces of furniture the two rooms share, in local coordinates; the caller places them.
ObjectBuilder ceiling_light(SceneDescription& d, double size, const Rgb& exitance) {
  ObjectBuilder b(d, "ceiling light");
  int s = b.surface({0.80, 0.80, 0.80}, exitance);
  double r = size / 2;
  b.quad({{-r, 0, -r}, {r, 0, -r}, {r, 0, r}, {-r, 0, r}}, {0, -1, 0}, 1, 1, 1, 1, s);
  return b;
}
void table_top(ObjectBuilder& b) {
  int top = b.surface({0.62, 0.44, 0.26});
  int edge = b.surface({0.42, 0.28, 0.16});
  b.box_separate({-0.7, 0.72, -0.4}, {0.7, 0.77, 0.4}, F::kTop | F::kSides,
                 [&](F f) { return f == F::kTop ? top : edge; });
}
void table_base(ObjectBuilder& b) {
  int metal = b.surface({0.30, 0.30, 0.33});
  b.box_separate({-0.08, 0, -0.08}, {0.08, 0.72, 0.08}, F::kSides, [&](F) { return metal; });
}
// A block chair facing +z: a seat block and a back rest, corners shared within each block.
ObjectBuilder chair(SceneDescription& d) {
  ObjectBuilder b(d, "chair");
  int seat = b.surface({0.25, 0.35, 0.60});
  int seat_wood = b.surface({0.50, 0.34, 0.20});
  int back = b.surface({0.25, 0.35, 0.60});
  int back_wood = b.surface({0.50, 0.34, 0.20});
  b.box_shared({-0.23, 0, -0.23}, {0.23, 0.46, 0.23}, F::kTop | F::kSides,
               [&](F f) { return f == F::kTop ? seat : seat_wood; });
  b.box_shared({-0.23, 0.46, -0.23}, {0.23, 0.95, -0.17}, F::kTop | F::kSides,
               [&](F f) { return f == F::kMaxZ ? back : back_wood; });
  return b;
}
ObjectBuilder cabinet(SceneDescription& d) {
  ObjectBuilder b(d, "cabinet");
  int top = b.surface({0.55, 0.40, 0.25});
  int body = b.surface({0.70, 0.66, 0.58});
  b.box_separate({-0.2, 0, -0.25}, {0.2, 1.8, 0.25}, F::kTop | F::kSides,
                 [&](F f) { return f == F::kTop ? top : body; });
  return b;
}
// Lies 5 mm above the floor: nearly coplanar with it on purpose.
ObjectBuilder rug(SceneDescription& d) {
  ObjectBuilder b(d, "rug");
  int s = b.surface({0.60, 0.16, 0.12});
  b.quad({{-1.0, 0.005, -0.7}, {1.0, 0.005, -0.7}, {1.0, 0.005, 0.7}, {-1.0, 0.005, 0.7}}, {0, 1, 0}, 1, 1, 1, 1, s);
  return b;
}

scene::Camera room_camera() {
  scene::Camera c;
  c.eye = {4.75, 1.65, 0.2};
  c.look_at = {1.6, 0.75, 3.1};
  c.fov_y_degrees = 62;
  return c;
}

void room_shell(SceneDescription& d, const RoomShape& r) {
  ObjectBuilder b(d, "room shell");
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
  b.place({0, 0, 0});
}

void picroom_shell(SceneDescription& d, const RoomShape& r) {
  ObjectBuilder b(d, "room shell");
  int floor = b.surface({0.55, 0.40, 0.28});
  int ceiling = b.surface({0.80, 0.80, 0.78});
  int walls = b.surface({0.75, 0.72, 0.64});
  b.quad(r.floor(), {0, 1, 0}, 3, 3, 1, 1, floor);
  b.quad(r.ceiling(), {0, -1, 0}, 3, 3, 2, 2, ceiling);
  b.quad(r.wall_z(r.d), {0, 0, -1}, 3, 1, 1, 1, walls);
  b.quad(r.wall_z(0), {0, 0, 1}, 3, 1, 1, 1, walls);
  b.quad(r.wall_x(0), {1, 0, 0}, 1, 1, 1, 2, walls);
  b.quad(r.wall_x(r.w), {-1, 0, 0}, 1, 1, 1, 2, walls);
  b.place({0, 0, 0});
}

// A landscape of 9 x 6 patches: sky, sun, grass. Local plane z = 0, facing +z.
ObjectBuilder landscape(SceneDescription& d) {
  ObjectBuilder b(d, "picture: landscape");
  int sky = b.surface({0.45, 0.62, 0.85});
  int sun = b.surface({0.95, 0.80, 0.20});
  int grass = b.surface({0.25, 0.55, 0.20});
  b.quad({{-0.675, -0.45, 0}, {0.675, -0.45, 0}, {0.675, 0.45, 0}, {-0.675, 0.45, 0}}, {0, 0, 1}, 9, 6, 1, 1,
         [&](int i, int j) {
           if (j < 2 || (j == 2 && i >= 2 && i <= 5)) return grass;  // a hill
           if (j >= 4 && i >= 6 && i <= 7) return sun;
           return sky;
         });
  return b;
}

// An abstract of 6 x 5 patches in three colours.
ObjectBuilder abstract_picture(SceneDescription& d) {
  ObjectBuilder b(d, "picture: abstract");
  int red = b.surface({0.80, 0.15, 0.10});
  int navy = b.surface({0.10, 0.15, 0.45});
  int cream = b.surface({0.90, 0.86, 0.72});
  b.quad({{-0.45, -0.375, 0}, {0.45, -0.375, 0}, {0.45, 0.375, 0}, {-0.45, 0.375, 0}}, {0, 0, 1}, 6, 5, 1, 1,
         [&](int i, int j) {
           if (i <= 2 && j >= 2) return red;
           if (i >= 4 && j <= 1) return navy;
           return cream;
         });
  return b;
}

}  // namespace

SceneDescription room_description() {
  SceneDescription d;
  d.name = "ROOM";
  const RoomShape r;
  room_shell(d, r);
  ObjectBuilder light = ceiling_light(d, 0.6, {12.0, 11.4, 10.0});
  light.place({1.7, r.h - 0.01, 2.0});
  light.place({3.3, r.h - 0.01, 2.0});
  ObjectBuilder top(d, "table top");
  table_top(top);
  top.place({2.5, 0, 2.2});
  ObjectBuilder base(d, "table base");
  table_base(base);
  base.place({2.5, 0, 2.2});
  ObjectBuilder chairs = chair(d);
  chairs.place({2.5, 0, 1.3});
  chairs.place({2.5, 0, 3.1}, 180);
  cabinet(d).place({0.21, 0, 0.9});
  rug(d).place({2.5, 0, 2.2});
  d.camera = room_camera();
  return d;
}

SceneDescription picroom_description() {
  SceneDescription d;
  d.name = "PICROOM";
  const RoomShape r;
  picroom_shell(d, r);
  ceiling_light(d, 0.8, {14.0, 13.3, 11.7}).place({2.5, r.h - 0.01, 2.0});
  ObjectBuilder table(d, "table");
  table_top(table);
  table_base(table);
  table.place({2.5, 0, 2.2});
  ObjectBuilder chairs = chair(d);
  chairs.place({2.5, 0, 1.3});
  chairs.place({2.5, 0, 3.1}, 180);
  cabinet(d).place({0.21, 0, 0.9});
  rug(d).place({2.5, 0, 2.2});
  landscape(d).place({2.2, 1.55, r.d - 0.01}, 180);  // on the north wall, facing -z
  ObjectBuilder abstracts = abstract_picture(d);      // two on the west wall, facing +x
  abstracts.place({0.01, 1.5, 1.9}, 90);
  abstracts.place({0.01, 1.5, 3.1}, 90);
  d.camera = room_camera();
  return d;
}

// The Cornell box as published by the Cornell Program of Computer Graphics (mm); the usual RGB
// approximations of its measured reflectances and of the light's emission. scenes/cornell.toml
// transcribes it (tests/radiosity/builtin_descriptions_test.cpp checks they give one WORLD).
SceneDescription cornell_description() {
  SceneDescription d;
  d.name = "CORNELL";
  const Rgb white{0.725, 0.71, 0.68}, red{0.63, 0.065, 0.05}, green{0.14, 0.45, 0.091};
  const Vec3 inside{278, 274, 280};
  auto wall = [&](const char* name, const Rgb& rho, QuadCorners q, int pu, int pv, int eu, int ev) {
    ObjectBuilder b(d, name);
    Vec3 c = 0.25 * (q.c00 + q.c10 + q.c11 + q.c01);
    b.quad(q, inside - c, pu, pv, eu, ev, b.surface(rho));
  };
  wall("floor", white, {{552.8, 0, 0}, {0, 0, 0}, {0, 0, 559.2}, {549.6, 0, 559.2}}, 4, 4, 2, 2);
  wall("ceiling", white, {{556, 548.8, 0}, {0, 548.8, 0}, {0, 548.8, 559.2}, {556, 548.8, 559.2}}, 4, 4, 1, 1);
  wall("back wall", white, {{549.6, 0, 559.2}, {0, 0, 559.2}, {0, 548.8, 559.2}, {556, 548.8, 559.2}}, 4, 4, 1, 1);
  wall("red wall", red, {{552.8, 0, 0}, {549.6, 0, 559.2}, {556, 548.8, 559.2}, {556, 548.8, 0}}, 4, 4, 1, 1);
  wall("green wall", green, {{0, 0, 559.2}, {0, 0, 0}, {0, 548.8, 0}, {0, 548.8, 559.2}}, 4, 4, 1, 1);
  auto block = [&](const char* name, std::array<Vec3, 4> top, double height, int top_pu, int top_pv, int top_e,
                   int side_pv) {
    ObjectBuilder b(d, name);
    int s = b.surface(white);
    Vec3 c = 0.25 * (top[0] + top[1] + top[2] + top[3]) - Vec3(0, height / 2, 0);
    b.quad({top[0], top[1], top[2], top[3]}, {0, 1, 0}, top_pu, top_pv, top_e, top_e, s);
    for (int k = 0; k < 4; ++k) {
      Vec3 a = top[k], e = top[(k + 1) % 4];
      Vec3 a0{a.x, 0, a.z}, e0{e.x, 0, e.z};
      Vec3 mid = 0.5 * (a0 + e);
      b.quad({a0, e0, e, a}, Vec3(mid.x - c.x, 0, mid.z - c.z), 1, side_pv, 1, 1, s);
    }
  };
  block("short block", {Vec3{130, 165, 65}, {82, 165, 225}, {240, 165, 272}, {290, 165, 114}}, 165, 1, 2, 2, 2);
  block("tall block", {Vec3{423, 330, 247}, {265, 330, 296}, {314, 330, 456}, {472, 330, 406}}, 330, 1, 4, 1, 4);
  // The light hangs 0.1 mm below the ceiling; its housing (upper side) is black.
  ObjectBuilder light(d, "light");
  const int emitter = light.surface({0.78, 0.78, 0.78}, {18.4, 15.6, 8.0});
  const int housing = light.surface({0.0, 0.0, 0.0});
  light.single({{343, 548.7, 227}, {343, 548.7, 332}, {213, 548.7, 332}, {213, 548.7, 227}}, {0, -1, 0}, emitter,
               housing);
  scene::Camera cam;
  cam.eye = {278, 273, -800};
  cam.look_at = {278, 273, 0};
  cam.fov_y_degrees = 39.3;  // 35 mm focal length, 25 mm film
  d.camera = cam;
  return d;
}

}  // namespace gcsim::radiosity
