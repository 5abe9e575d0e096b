#pragma once
// The ray tracer uses the shared geometry kernels (apps/common/geometry) under its own namespace,
// so its code and the paper's algorithms read `Ray`, `Bounds3`, `Bvh` unqualified.
namespace gcsim::geometry {}

namespace gcsim::raytrace {
using namespace gcsim::geometry;
}  // namespace gcsim::raytrace
