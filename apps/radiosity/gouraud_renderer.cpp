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

// A Z-buffer of W x H pixels holding perspective-correct Gouraud colours, and which pixels show an
// emitter (left out of the automatic exposure).
class GouraudRaster {
 public:
  GouraudRaster(int width, int height, double fov_y_degrees)
      : W_(width),
        H_(height),
        f_(1.0 / std::tan(fov_y_degrees * std::numbers::pi / 360.0)),
        aspect_(double(width) / height),
        zbuf_(std::size_t(width) * height, std::numeric_limits<double>::infinity()),
        color_(std::size_t(width) * height, Rgb(0.0)),
        emitter_px_(std::size_t(width) * height, 0) {}

  // One polygon in camera space, clipped against the near plane (z >= near), as a triangle fan.
  void draw_polygon(const CameraVertex* cv, int count, double near, bool emitter) {
    for (int tri = 0; tri + 2 < count; ++tri) {
      const CameraVertex in[3] = {cv[0], cv[tri + 1], cv[tri + 2]};
      CameraVertex out[4];  // a clipped triangle is at most a quad
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
        const CameraVertex t[3] = {out[0], out[k], out[k + 1]};
        draw_triangle(t, emitter);
      }
    }
  }

  // The given exposure, or (0) the automatic one: the 97th percentile of lit non-emitter pixels
  // shows at 0.85.
  double exposure(double requested) const {
    if (requested > 0) return requested;
    std::vector<double> lum;
    for (std::size_t k = 0; k < color_.size(); ++k)
      if (std::isfinite(zbuf_[k]) && !emitter_px_[k]) lum.push_back(std::max({color_[k].r, color_[k].g, color_[k].b}));
    if (lum.empty()) return 1.0;
    std::size_t at = std::min(lum.size() - 1, std::size_t(0.97 * double(lum.size())));
    std::nth_element(lum.begin(), lum.begin() + at, lum.end());
    return lum[at] > 0 ? 0.85 / lum[at] : 1.0;
  }

  apps::Image image(double exposure) const {
    apps::Image img(W_, H_);
    for (int y = 0; y < H_; ++y)
      for (int x = 0; x < W_; ++x) {
        const Rgb& c = color_[std::size_t(y) * W_ + x];
        img.at(x, y) = glm::vec3(float(c.r * exposure), float(c.g * exposure), float(c.b * exposure));
      }
    return img;
  }

 private:
  void draw_triangle(const CameraVertex* t, bool emitter) {
    double sx[3], sy[3], iz[3];
    for (int k = 0; k < 3; ++k) {
      iz[k] = 1.0 / t[k].p.z;
      sx[k] = (t[k].p.x * f_ / aspect_ * iz[k] + 1) * 0.5 * W_;
      sy[k] = (1 - t[k].p.y * f_ * iz[k]) * 0.5 * H_;
    }
    double area = (sx[1] - sx[0]) * (sy[2] - sy[0]) - (sx[2] - sx[0]) * (sy[1] - sy[0]);
    if (std::abs(area) < 1e-12 || !std::isfinite(area)) return;
    // Clamp in floating point first: a vertex close to the eye can land far outside any int.
    auto to_px = [](double v, int hi) { return int(std::clamp(v, -1.0, double(hi) + 1)); };
    int x0 = std::max(0, to_px(std::floor(std::min({sx[0], sx[1], sx[2]})), W_));
    int x1 = std::min(W_ - 1, to_px(std::ceil(std::max({sx[0], sx[1], sx[2]})), W_));
    int y0 = std::max(0, to_px(std::floor(std::min({sy[0], sy[1], sy[2]})), H_));
    int y1 = std::min(H_ - 1, to_px(std::ceil(std::max({sy[0], sy[1], sy[2]})), H_));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        double px = x + 0.5, py = y + 0.5;
        double w0 = ((sx[1] - px) * (sy[2] - py) - (sx[2] - px) * (sy[1] - py)) / area;
        double w1 = ((sx[2] - px) * (sy[0] - py) - (sx[0] - px) * (sy[2] - py)) / area;
        double w2 = 1 - w0 - w1;
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        double z_inv = w0 * iz[0] + w1 * iz[1] + w2 * iz[2];
        double z = 1 / z_inv;
        std::size_t k = std::size_t(y) * W_ + x;
        if (z >= zbuf_[k]) continue;
        zbuf_[k] = z;
        // Perspective-correct interpolation of the vertex radiosities.
        color_[k] = (w0 * iz[0] * t[0].c + w1 * iz[1] * t[1].c + w2 * iz[2] * t[2].c) * z;
        emitter_px_[k] = emitter;
      }
  }

  int W_, H_;
  double f_, aspect_;
  std::vector<double> zbuf_;
  std::vector<Rgb> color_;
  std::vector<char> emitter_px_;
};

apps::Image render(const Scene& scene, const std::vector<Rgb>& b, const Camera& cam, const RenderOptions& o,
                   double* chosen_exposure) {
  const std::vector<std::array<Rgb, 4>> corners = element_corner_radiosity(scene, b);
  const Vec3 fwd = glm::normalize(cam.look_at - cam.eye);
  const Vec3 right = glm::normalize(glm::cross(fwd, cam.up));
  const Vec3 up = glm::cross(right, fwd);
  const double near = 1e-4 * scene.extent();

  GouraudRaster raster(o.width, o.height, cam.fov_y_degrees);
  for (int e = 0; e < int(scene.elements.size()); ++e) {
    const SceneElement& el = scene.elements[e];
    if (glm::dot(el.normal, cam.eye - el.center) <= 0) continue;  // one-sided: seen from behind
    CameraVertex cv[4];
    for (int k = 0; k < el.count; ++k) {
      Vec3 d = scene.vertices[el.vertex[k]] - cam.eye;
      cv[k] = {{glm::dot(d, right), glm::dot(d, up), glm::dot(d, fwd)}, corners[e][k]};
    }
    raster.draw_polygon(cv, el.count, near, channel_sum(scene.surface_of_element(e).exitance) > 0);
  }
  const double exposure = raster.exposure(o.exposure);
  if (chosen_exposure) *chosen_exposure = exposure;
  return raster.image(exposure);
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
