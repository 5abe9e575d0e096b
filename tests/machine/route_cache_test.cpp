#include "machine/route_cache.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "machine/mesh.hpp"

namespace gcsim::machine {
namespace {

// Messages between random pairs, accounted through caches of every size (one entry: every other
// pair evicts; enough for all pairs: none does), give each channel exactly the totals of walking
// every message's route at once.
TEST(RouteCache, DeferredSumsEqualTheEagerOnesWithAndWithoutEvictions) {
  const Mesh mesh(4, 3);
  for (std::size_t size : {1u, 4u, 16u, 4096u}) {
    RouteCache cache(mesh, size);
    std::vector<std::int64_t> bytes(mesh.channel_count()), eager_bytes(mesh.channel_count());
    std::vector<SimTime> busy(mesh.channel_count()), eager_busy(mesh.channel_count());
    std::uint32_t rng = 7;
    auto next = [&rng] { return rng = rng * 1664525u + 1013904223u, rng >> 8; };
    for (int m = 0; m < 3000; ++m) {
      const int src = static_cast<int>(next() % 12), dst = static_cast<int>(next() % 12);
      const std::int64_t b = next() % 5000;
      const SimTime t = next() % 100000;
      RouteCache::Entry& e = cache.find(src, dst, bytes, busy);
      ASSERT_EQ(e.hops, mesh.hops(src, dst));
      ASSERT_EQ(e.route, mesh.route(src, dst));
      e.bytes += b;
      e.busy += t;
      for (int ch : mesh.route(src, dst)) eager_bytes[ch] += b, eager_busy[ch] += t;
    }
    cache.flush(bytes, busy);
    EXPECT_EQ(bytes, eager_bytes) << size << " entries";
    EXPECT_EQ(busy, eager_busy) << size << " entries";
    cache.flush(bytes, busy);  // a second flush adds nothing
    EXPECT_EQ(bytes, eager_bytes);
  }
}

TEST(RouteCache, HoldsEveryPairOfASmallMachine) {
  const Mesh mesh(8, 8);
  EXPECT_EQ(RouteCache(mesh).entries(), 4096u);
  EXPECT_EQ(RouteCache(Mesh(2, 2)).entries(), 16u);
  EXPECT_EQ(RouteCache(Mesh(256, 256)).entries(), 4096u);
}

}  // namespace
}  // namespace gcsim::machine
