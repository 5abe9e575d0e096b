#pragma once
// The view pass's scene: what the camera's rays meet once the radiosity pass has run.
//  - Diffuse surfaces are the radiosity pass's elements, two triangles per quad, carrying the
//    radiosity at their corners (element_corner_radiosity) times the display exposure: a ray that
//    hits one reads the diffuse illumination the radiosity pass computed, interpolated as the
//    Gouraud display interpolates it.
//  - Mirrors and glass are the shapes the ray tracer lowers (true spheres, not the radiosity
//    pass's tessellation), shaded by following their reflected and refracted rays.
// Without a radiosity pass the view is the lowered scene, lit directly by its point lights.
#include <vector>

#include "apps/common/scene/scene_description.hpp"
#include "apps/radiosity/radiosity.hpp"
#include "apps/raytrace/raytrace.hpp"

namespace gcsim::render {

// Materials the view pass traces further (mirror or glass weight above 0).
bool is_specular(const scene::Material& m);

// `mesh` is radiosity::flatten(to_world(description)); element_radiosity its solution (one per
// element). Radiance stored = radiosity x exposure, the linear colour the PNG's sRGB curve maps.
raytrace::Scene make_view_scene(const scene::SceneDescription& description, const radiosity::Scene& mesh,
                                const std::vector<radiosity::Rgb>& element_radiosity, double exposure);

}  // namespace gcsim::render
