#include "apps/radiosity/gouraud_renderer.hpp"
#include "apps/radiosity/element_corners.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace gcsim::radiosity {

namespace {

struct CameraVertex {
  Vec3 p;  // camera space: x right, y up, z forward
  Rgb c;
};

}  // namespace

namespace {

apps::Image render(const Scene& scene, const std::vector<Rgb>& b, const Camera& cam, const RenderOptions& o,
                   double* chosen_exposure) {
  const int W = o.width, H = o.height;
  const std::vector<std::array<Rgb, 4>> corners = element_corner_radiosity(scene, b);

  Vec3 fwd = glm::normalize(cam.look_at - cam.eye);
  Vec3 right = glm::normalize(glm::cross(fwd, cam.up));
  Vec3 up = glm::cross(right, fwd);
  const double f = 1.0 / std::tan(cam.fov_y_degrees * std::numbers::pi / 360.0);
  const double aspect = double(W) / H;
  const double near = 1e-4 * scene.extent();

  std::vector<double> zbuf(std::size_t(W) * H, std::numeric_limits<double>::infinity());
  std::vector<Rgb> color(std::size_t(W) * H, Rgb(0.0));
  std::vector<char> emitter_px(std::size_t(W) * H, 0);

  auto raster_triangle = [&](const CameraVertex* t, bool emitter) {
    double sx[3], sy[3], iz[3];
    for (int k = 0; k < 3; ++k) {
      iz[k] = 1.0 / t[k].p.z;
      sx[k] = (t[k].p.x * f / aspect * iz[k] + 1) * 0.5 * W;
      sy[k] = (1 - t[k].p.y * f * iz[k]) * 0.5 * H;
    }
    double area = (sx[1] - sx[0]) * (sy[2] - sy[0]) - (sx[2] - sx[0]) * (sy[1] - sy[0]);
    if (std::abs(area) < 1e-12) return;
    // Clamp in floating point first: a vertex close to the eye can land far outside any int.
    auto to_px = [](double v, int hi) { return int(std::clamp(v, -1.0, double(hi) + 1)); };
    int x0 = std::max(0, to_px(std::floor(std::min({sx[0], sx[1], sx[2]})), W));
    int x1 = std::min(W - 1, to_px(std::ceil(std::max({sx[0], sx[1], sx[2]})), W));
    int y0 = std::max(0, to_px(std::floor(std::min({sy[0], sy[1], sy[2]})), H));
    int y1 = std::min(H - 1, to_px(std::ceil(std::max({sy[0], sy[1], sy[2]})), H));
    if (!(std::isfinite(area))) return;
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        double px = x + 0.5, py = y + 0.5;
        double w0 = ((sx[1] - px) * (sy[2] - py) - (sx[2] - px) * (sy[1] - py)) / area;
        double w1 = ((sx[2] - px) * (sy[0] - py) - (sx[0] - px) * (sy[2] - py)) / area;
        double w2 = 1 - w0 - w1;
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        double z_inv = w0 * iz[0] + w1 * iz[1] + w2 * iz[2];
        double z = 1 / z_inv;
        std::size_t k = std::size_t(y) * W + x;
        if (z >= zbuf[k]) continue;
        zbuf[k] = z;
        // Perspective-correct interpolation of the vertex radiosities.
        color[k] = (w0 * iz[0] * t[0].c + w1 * iz[1] * t[1].c + w2 * iz[2] * t[2].c) * z;
        emitter_px[k] = emitter;
      }
  };

  for (int e = 0; e < int(scene.elements.size()); ++e) {
    const SceneElement& el = scene.elements[e];
    if (glm::dot(el.normal, cam.eye - el.center) <= 0) continue;  // one-sided: seen from behind
    CameraVertex cv[4];
    for (int k = 0; k < el.count; ++k) {
      Vec3 d = scene.vertices[el.vertex[k]] - cam.eye;
      cv[k] = {{glm::dot(d, right), glm::dot(d, up), glm::dot(d, fwd)}, corners[e][k]};
    }
    bool emitter = channel_sum(scene.surface_of_element(e).exitance) > 0;
    for (int tri = 0; tri + 2 < el.count; ++tri) {
      CameraVertex in[3] = {cv[0], cv[tri + 1], cv[tri + 2]};
      // Clip against the near plane (z >= near): a triangle becomes at most a quad.
      CameraVertex out[4];
      int m = 0;
      for (int i = 0; i < 3; ++i) {
        const CameraVertex& a = in[i];
        const CameraVertex& c = in[(i + 1) % 3];
        double fa = a.p.z - near, fc = c.p.z - near;
        if (fa >= 0) out[m++] = a;
        if ((fa >= 0) != (fc >= 0)) {
          double s = fa / (fa - fc);
          out[m++] = {a.p + (c.p - a.p) * s, a.c + (c.c - a.c) * s};
        }
      }
      for (int k = 1; k + 1 < m; ++k) {
        CameraVertex t[3] = {out[0], out[k], out[k + 1]};
        raster_triangle(t, emitter);
      }
    }
  }

  double exposure = o.exposure;
  if (exposure <= 0) {
    std::vector<double> lum;
    for (std::size_t k = 0; k < color.size(); ++k)
      if (std::isfinite(zbuf[k]) && !emitter_px[k]) lum.push_back(std::max({color[k].r, color[k].g, color[k].b}));
    if (!lum.empty()) {
      std::size_t at = std::min(lum.size() - 1, std::size_t(0.97 * double(lum.size())));
      std::nth_element(lum.begin(), lum.begin() + at, lum.end());
      exposure = lum[at] > 0 ? 0.85 / lum[at] : 1.0;
    } else {
      exposure = 1.0;
    }
  }
  if (chosen_exposure) *chosen_exposure = exposure;
  apps::Image img(W, H);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const Rgb& c = color[std::size_t(y) * W + x];
      img.at(x, y) = glm::vec3(float(c.r * exposure), float(c.g * exposure), float(c.b * exposure));
    }
  return img;
}

}  // namespace

apps::Image render_gouraud(const Scene& scene, const std::vector<Rgb>& b, const Camera& cam, const RenderOptions& o) {
  return render(scene, b, cam, o, nullptr);
}

double auto_exposure(const Scene& scene, const std::vector<Rgb>& b, const Camera& cam, const RenderOptions& o) {
  RenderOptions automatic = o;
  automatic.exposure = 0;
  double e = 1;
  render(scene, b, cam, automatic, &e);
  return e;
}

}  // namespace gcsim::radiosity
