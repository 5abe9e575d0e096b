#pragma once
// The largest vertex coordinate a scene file may give: the WORLD parser's limit (1e15), so both
// loaders accept the same geometry. Beyond it, squared lengths and areas leave float's range; the
// builders and kernels cope, but a file with such numbers is almost surely wrong.
// Kept apart from the OBJ loader so that any loader (tinyobjloader's included) can call it.
#include <cmath>
#include <string>

#include <fmt/format.h>

namespace gcsim::raytrace {

inline constexpr double kMaxVertexCoordinate = 1e15;

// Empty when `value`, coordinate `axis` (0, 1, 2) of a vertex, is finite and within the limit;
// otherwise what is wrong, to be prefixed with the file and line.
inline std::string vertex_coordinate_error(double value, int axis) {
  const char* name = axis == 0 ? "x" : axis == 1 ? "y" : "z";
  if (!std::isfinite(value)) return fmt::format("vertex {} coordinate is {}; expected a finite number", name, value);
  if (std::abs(value) > kMaxVertexCoordinate)
    return fmt::format("vertex {} coordinate {:g} is too large; expected a magnitude of at most 1e15", name, value);
  return {};
}

}  // namespace gcsim::raytrace
