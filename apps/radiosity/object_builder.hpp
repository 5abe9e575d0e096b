#pragma once
// Builds one object of the shared scene description the way the thesis's entities are made: quads
// split into a grid of patches and elements, box faces as single patches on corners of their own
// or shared, surfaces declared in order, and placements (instances). `to_world` lowers the object
// to exactly the ENTITY that EntityBuilder (entity_builder.hpp) makes from the same calls; the
// built-in scenes (builtin_descriptions.cpp) are written with it.
#include <functional>
#include <string>

#include "apps/common/scene/scene_description.hpp"
#include "apps/radiosity/entity_builder.hpp"

namespace gcsim::radiosity {

class ObjectBuilder {
 public:
  using Face = EntityBuilder::Face;

  // Adds the object's layout to `d`; the object's shapes are appended to d.shapes as they are built.
  ObjectBuilder(scene::SceneDescription& d, std::string object);

  // A new material (diffuse reflectance, emission) that is the entity's next surface.
  int surface(const Rgb& reflectance, const Rgb& exitance = Rgb(0.0));

  // A quad facing towards `facing`, split into pu x pv patches of eu x ev elements; surface_of(i, j)
  // picks each patch's material (EntityBuilder::quad).
  void quad(const QuadCorners& q, const Vec3& facing, int pu, int pv, int eu, int ev,
            const std::function<int(int, int)>& surface_of);
  void quad(const QuadCorners& q, const Vec3& facing, int pu, int pv, int eu, int ev, int surface) {
    quad(q, facing, pu, pv, eu, ev, [surface](int, int) { return surface; });
  }
  // Outward faces of an axis-aligned box, one patch and one element each, on the box's shared corners
  // or on corners of their own (EntityBuilder::box_shared, box_separate).
  void box_shared(const Vec3& lo, const Vec3& hi, int faces, const std::function<int(Face)>& surface_of);
  void box_separate(const Vec3& lo, const Vec3& hi, int faces, const std::function<int(Face)>& surface_of);
  // One patch with one element on the corners in their order, facing `facing`; the back side, if
  // given, a second patch on the same corners (EntityBuilder::single twice).
  void single(const QuadCorners& q, const Vec3& facing, int surface, int back_surface = -1);

  // One more instance of the object: rotated about y (degrees), then moved.
  void place(const Vec3& translation, double rotate_y_degrees = 0);

 private:
  scene::ObjectLayout& layout() { return d_.layouts[layout_]; }
  scene::Polygon& add_polygon(int material, int back_material = -1);
  scene::SceneDescription& d_;
  std::string object_;
  std::size_t layout_;
};

}  // namespace gcsim::radiosity
