#include "apps/render/medium_region.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "apps/render/light_paths.hpp"

namespace gcsim::render {

double luminance(const scene::Rgb& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

bool MediumRegion::changes_nothing() const {
  return medium.sigma_s == scene::Rgb(0.0) && medium.sigma_a == scene::Rgb(0.0);
}

bool MediumRegion::contains(const glm::dvec3& p) const {
  if (const auto* box = std::get_if<scene::Box>(&shape))
    return glm::all(glm::greaterThanEqual(p, box->lo)) && glm::all(glm::lessThanEqual(p, box->hi));
  const auto& s = std::get<scene::Sphere>(shape);
  return glm::dot(p - s.center, p - s.center) <= s.radius * s.radius;
}

bool MediumRegion::clip(const glm::dvec3& o, const glm::dvec3& d, double t_min, double t_max, double& t0,
                        double& t1) const {
  t0 = t_min, t1 = t_max;
  if (const auto* box = std::get_if<scene::Box>(&shape)) {
    for (int a = 0; a < 3; ++a) {
      if (d[a] == 0.0) {
        if (o[a] < box->lo[a] || o[a] > box->hi[a]) return false;
        continue;
      }
      double near = (box->lo[a] - o[a]) / d[a], far = (box->hi[a] - o[a]) / d[a];
      if (near > far) std::swap(near, far);
      t0 = std::max(t0, near), t1 = std::min(t1, far);
    }
    return t0 < t1;
  }
  const auto& s = std::get<scene::Sphere>(shape);
  const glm::dvec3 oc = o - s.center;
  const double a = glm::dot(d, d), b = glm::dot(oc, d), c = glm::dot(oc, oc) - s.radius * s.radius;
  const double disc = b * b - a * c;
  if (disc <= 0.0) return false;
  const double root = std::sqrt(disc);
  t0 = std::max(t0, (-b - root) / a), t1 = std::min(t1, (-b + root) / a);
  return t0 < t1;
}

namespace {

bool boxes_overlap(const MediumRegion& a, const MediumRegion& b) {
  auto bounds = [](const MediumRegion& r, glm::dvec3& lo, glm::dvec3& hi) {
    if (const auto* box = std::get_if<scene::Box>(&r.shape)) {
      lo = box->lo, hi = box->hi;
    } else {
      const auto& s = std::get<scene::Sphere>(r.shape);
      lo = s.center - s.radius, hi = s.center + s.radius;
    }
  };
  glm::dvec3 alo, ahi, blo, bhi;
  bounds(a, alo, ahi), bounds(b, blo, bhi);
  return glm::all(glm::lessThan(alo, bhi)) && glm::all(glm::lessThan(blo, ahi));
}

}  // namespace

scene::SceneDescription without_invisible_boundaries(const scene::SceneDescription& d) {
  scene::SceneDescription out = d;
  std::erase_if(out.shapes, [&](const scene::Shape& s) { return invisible_boundary(d.materials.at(std::size_t(s.material))); });
  return out;
}

SplitScene split_media(const scene::SceneDescription& d, const std::string& file) {
  SplitScene out;
  out.surfaces = d;
  out.surfaces.shapes.clear();
  for (std::size_t i = 0; i < d.shapes.size(); ++i) {
    const scene::Shape& shape = d.shapes[i];
    const scene::Material& m = d.materials.at(std::size_t(shape.material));
    if (!m.medium) {
      out.surfaces.shapes.push_back(shape);
      continue;
    }
    const std::string what = fmt::format("{}: shape {} (material '{}') bounds a participating medium", file, i + 1, m.name);
    if (!invisible_boundary(m))
      throw std::invalid_argument(what + " and reflects, emits or refracts light (index " + fmt::format("{}", m.medium->boundary_ior) +
                                  "): `gcsim render` shows media bounded by invisible shapes (index 1, no reflectance) only; "
                                  "`gcsim run media` renders refracting objects filled with a medium");
    MediumRegion r{m.name, {}, *m.medium};
    if (const auto* box = std::get_if<scene::Box>(&shape.geometry)) r.shape = *box;
    else if (const auto* sphere = std::get_if<scene::Sphere>(&shape.geometry)) r.shape = *sphere;
    else throw std::invalid_argument(what + " with a polygon or mesh: `gcsim render` takes a box or a sphere as a medium's bound");
    out.media.push_back(r);
  }
  // The view's segments and the photon pass take a point to be in one medium at most.
  for (std::size_t a = 0; a < out.media.size(); ++a)
    for (std::size_t b = a + 1; b < out.media.size(); ++b)
      if (boxes_overlap(out.media[a], out.media[b]))
        throw std::invalid_argument(fmt::format("{}: the media of '{}' and '{}' may overlap: `gcsim render` takes disjoint media only",
                                                file, out.media[a].material, out.media[b].material));
  return out;
}

}  // namespace gcsim::render
