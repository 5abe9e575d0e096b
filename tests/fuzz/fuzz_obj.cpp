// Fuzz target: Wavefront OBJ files for the ray tracer, loaded and then built into a BVH (where a
// vertex at 1e23 used to crash). Errors must be ObjError or Scene::validate's
// invalid_argument.
#include <sstream>
#include <stdexcept>
#include <string>

#include "apps/common/geometry/bvh.hpp"
#include "apps/raytrace/obj_loader.hpp"
#include "tests/fuzz/fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gcsim::raytrace;
  if (size > 64 * 1024) return 0;  // the clustering is O(n^2): keep each run quick
  try {
    std::istringstream in{std::string(gcsim::fuzz::as_text(data, size))};
    const Scene s = parse_obj_scene(in, "fuzz.obj");
    s.validate();
    const Bvh bvh = build_bvh_by_clustering(s);
    if (bvh.depth() > s.prim_count()) __builtin_trap();
  } catch (const ObjError&) {
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
