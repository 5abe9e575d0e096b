#pragma once
// Radiosity reads the shared double-precision polygon geometry (apps/common/geometry/polygon.hpp)
// unqualified, as it did when the file was its own.
namespace gcsim::geometry {}

namespace gcsim::radiosity {
using namespace gcsim::geometry;
}  // namespace gcsim::radiosity
