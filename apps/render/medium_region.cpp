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

bool MediumRegion::contains(const MediumRegion& inner) const {
  glm::dvec3 lo, hi;
  if (const auto* box = std::get_if<scene::Box>(&inner.shape)) {
    lo = box->lo, hi = box->hi;
    if (std::holds_alternative<scene::Sphere>(shape)) {  // every corner inside the sphere
      for (int k = 0; k < 8; ++k)
        if (!contains(glm::dvec3(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z))) return false;
      return true;
    }
  } else {
    const auto& s = std::get<scene::Sphere>(inner.shape);
    if (const auto* outer = std::get_if<scene::Sphere>(&shape))
      return glm::length(s.center - outer->center) + s.radius <= outer->radius;
    lo = s.center - s.radius, hi = s.center + s.radius;
  }
  return contains(lo) && contains(hi);  // inside a box: its two extreme corners are
}

double MediumRegion::volume() const {
  if (const auto* box = std::get_if<scene::Box>(&shape)) {
    const glm::dvec3 e = box->hi - box->lo;
    return e.x * e.y * e.z;
  }
  const double r = std::get<scene::Sphere>(shape).radius;
  return 4.0 / 3.0 * 3.14159265358979323846 * r * r * r;
}

std::vector<MediumInterval> medium_intervals(const std::vector<MediumRegion>& regions, const glm::dvec3& o,
                                             const glm::dvec3& d, double t_max) {
  std::vector<MediumInterval> whole;
  std::vector<double> ends;
  for (std::size_t i = 0; i < regions.size(); ++i) {
    double t0, t1;
    if (!regions[i].clip(o, d, 0.0, t_max, t0, t1)) continue;
    whole.push_back({i, t0, t1});
    ends.push_back(t0), ends.push_back(t1);
  }
  if (whole.size() <= 1) return whole;
  // Nested media: cut at every bound and give each piece to the smallest medium holding its middle.
  std::sort(ends.begin(), ends.end());
  std::vector<MediumInterval> out;
  for (std::size_t k = 0; k + 1 < ends.size(); ++k) {
    const double a = ends[k], b = ends[k + 1], middle = 0.5 * (a + b);
    if (!(b > a)) continue;
    const MediumInterval* best = nullptr;
    for (const MediumInterval& w : whole)
      if (w.t0 <= middle && middle <= w.t1 && (!best || regions[w.region].volume() < regions[best->region].volume())) best = &w;
    if (!best) continue;
    if (!out.empty() && out.back().region == best->region && out.back().t1 == a) out.back().t1 = b;
    else out.push_back({best->region, a, b});
  }
  return out;
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

// Fresnel glass of the medium's index, all of it reflected or refracted (the paper's object).
scene::Material dielectric_of(const scene::Material& m) {
  scene::Material glass;
  glass.name = m.name + " (boundary)";
  glass.diffuse = scene::Rgb(0.0);
  glass.transmittance = 1.0;
  glass.ior = m.medium->boundary_ior;
  glass.fresnel = true;
  return glass;
}

}  // namespace

scene::SceneDescription without_invisible_boundaries(const scene::SceneDescription& d) {
  scene::SceneDescription out = d;
  std::erase_if(out.shapes, [&](const scene::Shape& s) { return invisible_boundary(d.materials.at(std::size_t(s.material))); });
  return out;
}

namespace {

// "FILE:LINE: [[sphere]]" for a shape read from a scene file, "FILE: shape N" for one built in code.
std::string place_of(const scene::Shape& shape, std::size_t index, const std::string& file) {
  if (shape.source_line <= 0) return fmt::format("{}: shape {}", file, index + 1);
  static constexpr const char* kTable[] = {"[[polygon]]", "[[sphere]]", "[[box]]", "[[mesh]]"};
  return fmt::format("{}:{}: {}", file, shape.source_line, kTable[shape.geometry.index()]);
}

}  // namespace

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
    const std::string where = place_of(shape, i, file);
    const std::string what = fmt::format("{} (material '{}') bounds a participating medium", where, m.name);
    if (!invisible_boundary(m)) {
      if (!only_bounds_medium(m))
        throw std::invalid_argument(what + " and also reflects or emits light: `gcsim render` takes a medium's bound that "
                                           "is invisible (index 1) or a plain dielectric (index != 1, nothing else)");
      scene::Shape glass = shape;  // the bound stays, as Fresnel glass of the medium's index
      glass.material = out.surfaces.add_material(dielectric_of(m));
      out.surfaces.shapes.push_back(glass);
    }
    MediumRegion r{m.name, {}, *m.medium, where};
    if (const auto* box = std::get_if<scene::Box>(&shape.geometry)) r.shape = *box;
    else if (const auto* sphere = std::get_if<scene::Sphere>(&shape.geometry)) r.shape = *sphere;
    else throw std::invalid_argument(what + " with a polygon or mesh: `gcsim render` takes a box or a sphere as a medium's bound");
    out.media.push_back(r);
  }
  // A point is in one medium, or in nested ones (the smallest holds it); partial overlaps are refused.
  for (std::size_t a = 0; a < out.media.size(); ++a)
    for (std::size_t b = a + 1; b < out.media.size(); ++b)
      if (boxes_overlap(out.media[a], out.media[b]) && !out.media[a].contains(out.media[b]) && !out.media[b].contains(out.media[a]))
        throw std::invalid_argument(fmt::format("{} (material '{}') and {} (material '{}'): their media overlap without "
                                                "one holding the other; `gcsim render` takes disjoint or nested media only",
                                                out.media[a].where, out.media[a].material, out.media[b].where,
                                                out.media[b].material));
  return out;
}

glm::dvec3 channel_transmittance(const glm::dvec3& sigma_t, double length) {
  return {std::exp(-sigma_t.r * length), std::exp(-sigma_t.g * length), std::exp(-sigma_t.b * length)};
}

glm::dvec3 segment_transmittance(const std::vector<MediumRegion>& regions, const glm::dvec3& origin,
                                 const glm::dvec3& direction, double length) {
  glm::dvec3 through(1.0);
  for (const MediumInterval& part : medium_intervals(regions, origin, direction, length)) {
    const scene::Medium& m = regions[part.region].medium;
    through *= channel_transmittance(m.sigma_s + m.sigma_a, part.t1 - part.t0);
  }
  return through;
}

}  // namespace gcsim::render
