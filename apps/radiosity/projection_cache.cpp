#include "apps/radiosity/projection_cache.hpp"

namespace gcsim::radiosity {

void ProjectionCache::project(HemicubeRenderer& renderer, int step, int shooter, OpCounts& ops) {
  while (!entries_.empty() && entries_.begin()->first.first < step) entries_.erase(entries_.begin());
  const auto key = std::make_pair(step, shooter);
  if (const auto it = entries_.find(key); it != entries_.end()) {
    renderer.use_projection(it->second, ops);
    ++shared_;
    return;
  }
  renderer.project(shooter, ops);
  entries_.emplace(key, renderer.projection());
  ++computed_;
}

}  // namespace gcsim::radiosity
