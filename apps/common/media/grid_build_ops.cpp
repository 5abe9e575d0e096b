#include "apps/common/media/grid_build_ops.hpp"

#include <cstdint>

namespace gcsim::media {

std::vector<parix::OpCount> grid_build_ops(const GridBuildCounts& c) {
  auto n = [](std::uint64_t v) { return static_cast<std::int64_t>(v); };
  return {{"media_knn_lookup", n(c.knn_queries + c.range_queries)},  // a tree descent either way
          {"media_knn_photon", n(c.knn_photons)},
          {"media_range_candidate", n(c.range_candidates)},
          {"media_sh_project", n(c.projections)},
          {"media_sh_accumulate", n(c.photon_adds)}};
}

}  // namespace gcsim::media
