#include "apps/common/image.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include <png.h>

#include "machine/output_file.hpp"

namespace gcsim::apps {
namespace {

std::uint8_t to_srgb8(float linear) {
  if (!std::isfinite(linear)) linear = 0.0f;
  float v = std::clamp(linear, 0.0f, 1.0f);
  float s = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
  return static_cast<std::uint8_t>(std::lround(s * 255.0f));
}

}  // namespace

void write_png(const std::filesystem::path& file, const Image& image, float exposure) {
  std::unique_ptr<FILE, int (*)(FILE*)> fp(std::fopen(file.c_str(), "wb"), &std::fclose);
  if (!fp) throw std::runtime_error("cannot write image '" + file.string() + "'");
  // libpng's own handlers print "libpng error: ..." first; gcsim's one message comes from here.
  png_structp png = png_create_write_struct(
      PNG_LIBPNG_VER_STRING, nullptr, [](png_structp p, png_const_charp) { png_longjmp(p, 1); },
      [](png_structp, png_const_charp) {});
  png_infop info = png_create_info_struct(png);
  if (!png || !info || setjmp(png_jmpbuf(png))) {
    const int err = errno;  // libpng stops here on a short write (a full disk) too
    png_destroy_write_struct(&png, &info);
    throw machine::write_error("image", file.string(), err);
  }
  png_init_io(png, fp.get());
  png_set_IHDR(png, info, image.width(), image.height(), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_write_info(png, info);
  std::vector<std::uint8_t> row(std::size_t(image.width()) * 3);
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const glm::vec3 c = image.at(x, y) * exposure;
      row[3 * x + 0] = to_srgb8(c.r);
      row[3 * x + 1] = to_srgb8(c.g);
      row[3 * x + 2] = to_srgb8(c.b);
    }
    png_write_row(png, row.data());
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  errno = 0;
  const bool written = std::fflush(fp.get()) == 0 && !std::ferror(fp.get());
  const int err = errno;
  const bool closed = std::fclose(fp.release()) == 0;
  if (!written || !closed) throw machine::write_error("image", file.string(), err ? err : errno);
}

}  // namespace gcsim::apps
