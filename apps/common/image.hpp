#pragma once
// A linear-RGB floating-point image and its PNG output (8-bit sRGB).
#include <filesystem>
#include <vector>

#include <glm/vec3.hpp>

namespace gcsim::apps {

class Image {
 public:
  Image() = default;
  Image(int width, int height) : width_(width), height_(height), pixels_(std::size_t(width) * height) {}

  int width() const { return width_; }
  int height() const { return height_; }
  glm::vec3& at(int x, int y) { return pixels_[std::size_t(y) * width_ + x]; }
  const glm::vec3& at(int x, int y) const { return pixels_[std::size_t(y) * width_ + x]; }
  std::vector<glm::vec3>& pixels() { return pixels_; }
  const std::vector<glm::vec3>& pixels() const { return pixels_; }

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<glm::vec3> pixels_;
};

// Writes linear values through exposure and the sRGB curve, clamped to [0, 1]; row 0 is the top.
// Throws std::runtime_error naming the file if it cannot be written.
void write_png(const std::filesystem::path& file, const Image& image, float exposure = 1.0f);

}  // namespace gcsim::apps
