#include "apps/radiosity/hemicube.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "apps/radiosity/pixel_span.hpp"

namespace gcsim::radiosity {

namespace {

std::vector<HemicubeCell> make_cells(const HemicubeOptions& o, int resolution) {
  if (o.hierarchical_levels < 0 || o.hierarchical_levels > 8)
    throw std::invalid_argument("hierarchical levels must be in [0, 8]");
  int scale = 1 << o.hierarchical_levels;
  if (resolution % (2 * scale) != 0)
    throw std::invalid_argument(fmt::format("hemicube resolution {} must be a multiple of {} for {} hierarchical levels",
                                            resolution, 2 * scale, o.hierarchical_levels));
  auto cells = hemicube_cells(resolution / scale, o.cells_per_side);
  for (auto& c : cells) c.i0 *= scale, c.j0 *= scale, c.i1 *= scale, c.j1 *= scale;
  return cells;
}

// Whether a sample hemicube of resolution r keeps every cell non-empty and the hierarchical grid.
bool usable_sample_resolution(const HemicubeOptions& o, int r) {
  const int scale = 1 << o.hierarchical_levels;
  return r >= 16 && r % (2 * scale) == 0 && r / scale >= o.cells_per_side;
}

// Face coordinates (a across, b up, d depth) from the shooter frame's (u, v, n) coordinates.
Vec3 to_face(int face, const Vec3& l) {
  switch (face) {
    case kTopFace: return {l.x, l.y, l.z};
    case kPlusU: return {l.y, l.z, l.x};
    case kMinusU: return {-l.y, l.z, -l.x};
    case kPlusV: return {-l.x, l.z, l.y};
    default: return {l.x, l.z, -l.y};
  }
}

// Sutherland-Hodgman against the plane f(q) >= 0.
template <class F>
int clip(const Vec3* in, int n, Vec3* out, F f) {
  int m = 0;
  for (int i = 0; i < n; ++i) {
    const Vec3& a = in[i];
    const Vec3& b = in[next_vertex(i, n)];
    double fa = f(a), fb = f(b);
    if (fa >= 0) out[m++] = a;
    if ((fa >= 0) != (fb >= 0)) out[m++] = a + (b - a) * (fa / (fa - fb));
  }
  return m;
}

}  // namespace

void check_hemicube_options(const HemicubeOptions& o) {
  if (o.resolution < 2 || o.resolution % 2 != 0)
    throw std::invalid_argument(fmt::format("hemicube resolution must be even and at least 2, got {}", o.resolution));
  if (o.max_shooter_samples < 1 || !std::has_single_bit(unsigned(o.max_shooter_samples)))
    throw std::invalid_argument(
        fmt::format("near-field samples per side must be a power of two (1, 2, 4, ...), got {}", o.max_shooter_samples));
  if (!(o.near_field_ratio > 0) || !std::isfinite(o.near_field_ratio))
    throw std::invalid_argument("the near-field ratio must be a positive finite number");
  make_cells(o, o.resolution);  // the partition's own checks; cells are small, unlike the pixel tables
}

HemicubeRenderer::HemicubeRenderer(const Scene& scene, const HemicubeOptions& o, SamplesPerSideMemo* memo)
    : scene_(scene), options_(o), near_(1e-9 * scene.extent()) {
  check_hemicube_options(o);
  grids_.push_back({o.resolution, shared_delta_form_factors(o.resolution), make_cells(o, o.resolution)});
  for (int n = 2; n <= o.max_shooter_samples; n *= 2) {
    const int r = o.resolution / n;  // the pixel work of one hemicube, whatever n
    if (!usable_sample_resolution(o, r)) break;
    grids_.push_back({r, shared_delta_form_factors(r), make_cells(o, r)});
  }
  const int max_per_side = 1 << (grids_.size() - 1);
  per_side_ = memo ? memo->get(scene, o.near_field_ratio, max_per_side)
                   : std::make_shared<const std::vector<int>>(shooter_samples_per_side(scene, o.near_field_ratio, max_per_side));
  acc_.assign(scene.elements.size(), 0.0);
}

void HemicubeRenderer::project(int shooter, OpCounts& ops) {
  shooter_ = shooter;
  const int n = (*per_side_)[shooter];
  grid_ = &grids_[std::countr_zero(unsigned(n))];
  // Reuse our buffers unless a cache still hands them to other replicas.
  if (!own_ || own_.use_count() > 1) own_ = std::make_shared<HemicubeProjection>();
  HemicubeProjection& pr = *own_;
  current_.reset();
  pr.shooter = shooter;
  pr.samples_per_side = n;
  pr.samples = shooter_samples(scene_.patches[shooter], n);
  pr.faces.resize(pr.samples.size());
  pr.cost = OpCounts{};
  for (std::size_t k = 0; k < pr.samples.size(); ++k) project_from(pr.samples[k].point, pr.faces[k], pr.cost);
  ops += pr.cost;
  current_ = own_;
}

void HemicubeRenderer::use_projection(std::shared_ptr<const HemicubeProjection> projection, OpCounts& ops) {
  if (!projection || projection->shooter < 0 || projection->shooter >= int(per_side_->size()) ||
      projection->samples_per_side != (*per_side_)[projection->shooter])
    throw std::logic_error("HemicubeRenderer: a projection from a renderer of another scene or options");
  shooter_ = projection->shooter;
  grid_ = &grids_[std::countr_zero(unsigned(projection->samples_per_side))];
  ops += projection->cost;
  current_ = std::move(projection);
}

void HemicubeRenderer::project_from(const Vec3& origin, Faces& faces, OpCounts& ops) {
  for (auto& f : faces) f.clear();
  const ScenePatch& sp = scene_.patches[shooter_];
  const Frame fr = Frame::from_normal(sp.normal);
  const double r = grid_->resolution, eps = 1e-3 * near_;  // 1e-12 of the scene's extent
  for (int e = 0; e < int(scene_.elements.size()); ++e) {
    const SceneElement& el = scene_.elements[e];
    if (el.patch == shooter_) continue;
    Vec3 local[4];
    double max_up = -std::numeric_limits<double>::infinity();
    for (int k = 0; k < el.count; ++k) {
      local[k] = fr.to_local(el.polygon.v[k] - origin);
      max_up = std::max(max_up, local[k].z);
    }
    if (max_up <= eps) continue;  // wholly behind the shooter's plane: never seen
    Vec3 nl = fr.to_local(el.normal);
    double k = glm::dot(nl, local[0]);
    if (std::abs(k) <= eps) continue;  // its plane passes through the hemicube centre: seen edge-on
    const bool front = k < 0;
    ops.polygon_project += kHemicubeFaces;
    for (int face = 0; face < kHemicubeFaces; ++face) {
      Vec3 buf0[12], buf1[12];
      int n = el.count;
      for (int i = 0; i < n; ++i) buf0[i] = to_face(face, local[i]);
      const double nr = near_;
      n = clip(buf0, n, buf1, [nr](const Vec3& q) { return q.z - nr; });
      n = clip(buf1, n, buf0, [](const Vec3& q) { return q.z - q.x; });
      n = clip(buf0, n, buf1, [](const Vec3& q) { return q.z + q.x; });
      n = clip(buf1, n, buf0, [](const Vec3& q) { return q.z - q.y; });
      if (face == kTopFace)
        n = clip(buf0, n, buf1, [](const Vec3& q) { return q.z + q.y; });
      else
        n = clip(buf0, n, buf1, [](const Vec3& q) { return q.y; });
      if (n < 3) continue;
      Projected p;
      p.element = e;
      p.front = front;
      p.plane_n = to_face(face, nl);
      p.plane_k = k;
      // Vertices snap to 1/256 of a pixel and edge functions are then exact: ties on shared edges are
      // settled by one rule, and rounding noise (scene scale, clipping) cannot flip a pixel.
      int m = 0;
      for (int i = 0; i < n; ++i) {
        double x = (buf1[i].x / buf1[i].z + 1) * r / 2;
        double y = face == kTopFace ? (buf1[i].y / buf1[i].z + 1) * r / 2 : buf1[i].y / buf1[i].z * r / 2;
        std::array<double, 2> q{std::round(x * kSubpixel), std::round(y * kSubpixel)};
        if (m > 0 && q == p.p[m - 1]) continue;
        p.p[m++] = q;
      }
      while (m > 1 && p.p[m - 1] == p.p[0]) --m;
      if (m < 3) continue;
      p.count = m;
      double area2 = 0, x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
      for (int i = 0; i < m; ++i) {
        const auto& a = p.p[i];
        const auto& b = p.p[next_vertex(i, m)];
        area2 += a[0] * b[1] - a[1] * b[0];
        x0 = std::min(x0, a[0]), x1 = std::max(x1, a[0]), y0 = std::min(y0, a[1]), y1 = std::max(y1, a[1]);
      }
      if (area2 == 0) continue;  // degenerate after projection (seen edge-on)
      p.edge_sign = area2 > 0 ? 1.0 : -1.0;
      x0 /= kSubpixel, x1 /= kSubpixel, y0 /= kSubpixel, y1 /= kSubpixel;
      p.fx0 = x0, p.fx1 = x1, p.fy0 = y0, p.fy1 = y1;
      // Pixels whose centres can be inside: centre i + 0.5 in [x0, x1].
      int h = grid_->dff->height(face);
      p.bx0 = std::max(0, int(std::ceil(x0 - 0.5)));
      p.bx1 = std::min(grid_->resolution, int(std::floor(x1 - 0.5)) + 1);
      p.by0 = std::max(0, int(std::ceil(y0 - 0.5)));
      p.by1 = std::min(h, int(std::floor(y1 - 0.5)) + 1);
      faces[face].push_back(p);
    }
  }
}

Vec3 HemicubeRenderer::pixel_ray(int face, double px, double py) const {
  const double r = grid_->resolution;
  return {px * 2 / r - 1, face == kTopFace ? py * 2 / r - 1 : py * 2 / r, 1.0};
}

double HemicubeRenderer::depth(const Projected& poly, const Vec3& ray) {
  double den = glm::dot(poly.plane_n, ray);
  if (den == 0) return std::numeric_limits<double>::infinity();
  double t = poly.plane_k / den;
  return t > 0 ? t : std::numeric_limits<double>::infinity();
}

CellFormFactors HemicubeRenderer::cell_form_factors(int cell, OpCounts& ops) {
  if (shooter_ < 0) throw std::logic_error("HemicubeRenderer: project() before cell_form_factors()");
  CellFormFactors out;
  out.cell = cell;
  touched_.clear();
  const HemicubeCell& c = grid_->cells.at(cell);
  const HemicubeProjection& pr = *current_;
  for (std::size_t k = 0; k < pr.samples.size(); ++k) {
    if (options_.hierarchical_levels > 0)
      hierarchical_cell(pr.faces[k], c, pr.samples[k].weight, ops);
    else
      fixed_cell(pr.faces[k], c, pr.samples[k].weight, ops);
  }
  std::sort(touched_.begin(), touched_.end());
  for (int e : touched_) {
    out.element.push_back(e);
    out.value.push_back(acc_[e]);
    acc_[e] = 0;
  }
  ops.form_factor_sum += std::int64_t(out.element.size());
  return out;
}

void HemicubeRenderer::add(int element, double form_factor) {
  if (acc_[element] == 0) touched_.push_back(element);
  acc_[element] += form_factor;
}

void HemicubeRenderer::fixed_cell(const Faces& faces, const HemicubeCell& c, double weight, OpCounts& ops) {
  const int w = c.i1 - c.i0, h = c.j1 - c.j0;
  zbuf_.assign(std::size_t(w) * h, std::numeric_limits<double>::infinity());
  item_.assign(std::size_t(w) * h, -1);
  // The rays through the cell's pixel centres, one division per column and per row rather than two
  // per pixel and element (the same numbers pixel_ray makes).
  column_x_.resize(std::size_t(w)), row_y_.resize(std::size_t(h));
  for (int i = 0; i < w; ++i) column_x_[std::size_t(i)] = pixel_ray(c.face, c.i0 + i + 0.5, 0.0).x;
  for (int j = 0; j < h; ++j) row_y_[std::size_t(j)] = pixel_ray(c.face, 0.0, c.j0 + j + 0.5).y;
  for (const Projected& p : faces[c.face]) {
    int x0 = std::max(p.bx0, c.i0), x1 = std::min(p.bx1, c.i1);
    int y0 = std::max(p.by0, c.j0), y1 = std::min(p.by1, c.j1);
    if (x0 >= x1 || y0 >= y1) continue;
    ops.hemicube_pixel += std::int64_t(x1 - x0) * (y1 - y0);
    const int item = p.front ? p.element : -2;  // -2: hidden by the back of an element
    const RowSpans spans(p);
    for (int j = y0; j < y1; ++j) {
      const PixelSpan span = spans.at(j, x0, x1);
      const double y = row_y_[std::size_t(j - c.j0)];
      for (int i = span.begin; i < span.end; ++i) {
        const double z = depth(p, Vec3{column_x_[std::size_t(i - c.i0)], y, 1.0});
        std::size_t k = std::size_t(j - c.j0) * w + (i - c.i0);
        if (z < zbuf_[k]) {
          zbuf_[k] = z;
          item_[k] = item;
        }
      }
    }
  }
  gather_cell(c, weight);
}

// Each seen element's delta form factors into acc_, in pixel order as add() would: a run of one
// element's pixels is summed in a register (the same additions in the same order), not through
// acc_ in memory, whose store each next pixel's add had to wait for.
void HemicubeRenderer::gather_cell(const HemicubeCell& c, double weight) {
  const int w = c.i1 - c.i0, h = c.j1 - c.j0;
  for (int j = 0; j < h; ++j) {
    const int* items = item_.data() + std::size_t(j) * w;
    const double* dff = &grid_->dff->face(c.face)[std::size_t(c.j0 + j) * grid_->dff->resolution() + c.i0];
    for (int i = 0; i < w;) {
      const int e = items[i];
      if (e < 0) {
        ++i;
        continue;
      }
      double sum = acc_[e];
      for (; i < w && items[i] == e; ++i) {
        if (sum == 0) touched_.push_back(e);
        sum += weight == 1.0 ? dff[i] : weight * dff[i];
      }
      acc_[e] = sum;
    }
  }
}

int HemicubeRenderer::sample(const Faces& faces, int face, const std::vector<int>& candidates, double px, double py,
                             OpCounts& ops) const {
  double best = std::numeric_limits<double>::infinity();
  int item = -1;
  const auto& polys = faces[face];
  ops.hemicube_sample += std::int64_t(candidates.size());
  for (int ci : candidates) {
    const Projected& p = polys[ci];
    if (!covers_point(p, px, py)) continue;
    double z = depth(p, pixel_ray(face, px, py));
    if (z < best) {
      best = z;
      item = p.front ? p.element : -2;
    }
  }
  return item;
}

void HemicubeRenderer::subdivide(const Faces& faces, int face, const std::vector<int>& parent, int i0, int j0, int size,
                                 double weight, OpCounts& ops) {
  // Only elements whose projection reaches this square can be seen in it.
  std::vector<int> candidates;
  const auto& polys = faces[face];
  ops.hemicube_cull += std::int64_t(parent.size());
  for (int k : parent) {
    const Projected& p = polys[k];
    if (p.fx0 <= i0 + size && p.fx1 >= i0 && p.fy0 <= j0 + size && p.fy1 >= j0) candidates.push_back(k);
  }
  int centre = sample(faces, face, candidates, i0 + size * 0.5, j0 + size * 0.5, ops);
  bool uniform = size == 1;
  if (!uniform) {
    uniform = true;
    const double cx[4] = {0.0, 1.0, 0.0, 1.0}, cy[4] = {0.0, 0.0, 1.0, 1.0};
    for (int k = 0; k < 4 && uniform; ++k) {
      // Corners pulled a hair inside so they belong to this square.
      double px = i0 + (cx[k] == 0 ? 1e-6 : size - 1e-6), py = j0 + (cy[k] == 0 ? 1e-6 : size - 1e-6);
      uniform = sample(faces, face, candidates, px, py, ops) == centre;
    }
  }
  if (uniform) {
    if (centre >= 0) {
      const double f = grid_->dff->rect_sum(face, i0, j0, i0 + size, j0 + size);
      add(centre, weight == 1.0 ? f : weight * f);
    }
    return;
  }
  int half = size / 2;
  for (int q = 0; q < 4; ++q)
    subdivide(faces, face, candidates, i0 + (q & 1) * half, j0 + (q >> 1) * half, half, weight, ops);
}

void HemicubeRenderer::hierarchical_cell(const Faces& faces, const HemicubeCell& c, double weight, OpCounts& ops) {
  const int size = 1 << options_.hierarchical_levels;
  std::vector<int> all(faces[c.face].size());
  for (int k = 0; k < int(all.size()); ++k) all[k] = k;
  for (int j = c.j0; j < c.j1; j += size)
    for (int i = c.i0; i < c.i1; i += size) subdivide(faces, c.face, all, i, j, size, weight, ops);
}

std::vector<double> HemicubeRenderer::form_factor_row(int shooter, OpCounts& ops) {
  project(shooter, ops);
  std::vector<double> row(scene_.elements.size(), 0.0);
  for (int c = 0; c < cell_count(); ++c) {
    CellFormFactors cf = cell_form_factors(c, ops);
    for (std::size_t k = 0; k < cf.element.size(); ++k) row[cf.element[k]] += cf.value[k];
  }
  return row;
}

}  // namespace gcsim::radiosity
