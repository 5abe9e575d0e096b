// Every algorithm returns the same nearest hit as brute force for every pixel of every scene,
// at reduced resolution, for every subregion size; and the paper's ordering of test counts.
#include <gtest/gtest.h>

#include <cstring>
#include <type_traits>

#include "apps/raytrace/builtin_scenes.hpp"
#include "apps/raytrace/camera.hpp"
#include "apps/raytrace/primary_tracer.hpp"
#include "apps/raytrace/render.hpp"

namespace gcsim::raytrace {
namespace {

struct Frame {
  std::vector<Hit> hits;
  TraceCounters counters;
};

Frame trace_all(const Scene& s, const Bvh& bvh, Algorithm a, int size, int tile, bool packets = true) {
  const Camera cam(s.camera, size, size);
  PrimaryTracer tracer(s, bvh, cam, a);
  tracer.use_packets(packets);
  Frame f;
  f.hits.resize(std::size_t(size) * size);
  std::vector<Hit> tile_hits;
  const Tiling tiling{size, size, tile};
  for (int i = 0; i < tiling.count(); ++i) {
    const auto r = tiling.rect(i);
    tracer.trace_tile(r.x0, r.y0, r.x1, r.y1, tile_hits, f.counters);
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x) f.hits[std::size_t(y) * size + x] = tile_hits[std::size_t(y - r.y0) * (r.x1 - r.x0) + (x - r.x0)];
  }
  return f;
}

class EveryScene : public ::testing::TestWithParam<std::string_view> {};

TEST_P(EveryScene, EveryAlgorithmFindsTheBruteForceHitAtEveryPixel) {
  const Scene s = make_builtin_scene(GetParam());
  const Bvh bvh = build_bvh_by_clustering(s);
  const int size = 72;  // not a multiple of 32 or 16: partial subregions at the borders too
  const Frame ref = trace_all(s, bvh, Algorithm::brute, size, 8);
  int background = 0;
  for (const Hit& h : ref.hits) background += !h.valid();
  EXPECT_LT(background, size * size) << "the camera sees nothing";
  for (Algorithm a : paper_algorithms()) {
    for (int tile : {4, 8, 16, 32}) {
      if (!uses_subtree(a) && tile != 8) continue;
      const Frame f = trace_all(s, bvh, a, size, tile);
      int mismatches = 0;
      for (std::size_t i = 0; i < ref.hits.size(); ++i) {
        if (f.hits[i].prim != ref.hits[i].prim || f.hits[i].t != ref.hits[i].t) {
          if (++mismatches <= 3)
            ADD_FAILURE() << name_of(a) << " tile " << tile << " pixel (" << i % size << ", " << i / size << "): prim "
                          << f.hits[i].prim << " t " << f.hits[i].t << ", brute force prim " << ref.hits[i].prim << " t "
                          << ref.hits[i].t;
        }
      }
      EXPECT_EQ(mismatches, 0) << name_of(a) << " tile " << tile;
      EXPECT_EQ(f.counters.primary_rays, size * size);
    }
  }
}

// The single-ray path (what bench times against rtcIntersect1) and the packets give the same
// hits, bit for bit, and the same counts, which the simulated time is charged from.
TEST_P(EveryScene, SingleRaysAndPacketsAgreeExactly) {
  static_assert(std::is_trivially_copyable_v<TraceCounters> && sizeof(TraceCounters) % 8 == 0);
  const Scene s = make_builtin_scene(GetParam());
  const Bvh bvh = build_bvh_by_clustering(s);
  const int size = 72;
  for (Algorithm a : {Algorithm::A2, Algorithm::A3, Algorithm::A4}) {
    for (int tile : {4, 8, 32}) {
      const Frame single = trace_all(s, bvh, a, size, tile, false), packets = trace_all(s, bvh, a, size, tile, true);
      ASSERT_EQ(single.hits.size(), packets.hits.size());
      for (std::size_t i = 0; i < single.hits.size(); ++i)
        ASSERT_EQ(std::memcmp(&single.hits[i], &packets.hits[i], sizeof(Hit)), 0)
            << name_of(a) << " tile " << tile << " pixel " << i;
      EXPECT_EQ(std::memcmp(&single.counters, &packets.counters, sizeof(TraceCounters)), 0)
          << name_of(a) << " tile " << tile;
      EXPECT_GT(single.counters.primary_box_tests, 0);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, EveryScene, ::testing::ValuesIn(builtin_scene_names()),
                         [](const auto& info) {
                           std::string n(info.param);
                           for (char& c : n) if (c == '-') c = '_';
                           return n;
                         });

// At the paper's setting (512 x 512, 8 x 8 subregions), on all five scenes of table 1.
TEST(PaperOrdering, SubtreesCutTestsAndA4HasFewestBoxTests) {
  for (std::string_view name : paper_scene_names()) {
    const Scene s = make_builtin_scene(name);
    const Bvh bvh = build_bvh_by_clustering(s);
    auto per_ray = [&](Algorithm a) {
      const Frame f = trace_all(s, bvh, a, 512, 8);
      return std::pair{double(f.counters.primary_box_tests) / f.counters.primary_rays,
                       double(f.counters.primary_box_tests + f.counters.primary_prim_tests) / f.counters.primary_rays};
    };
    const auto a1 = per_ray(Algorithm::A1), a2 = per_ray(Algorithm::A2), a2p = per_ray(Algorithm::A2p),
               a3 = per_ray(Algorithm::A3), a4 = per_ray(Algorithm::A4);
    const auto b1 = per_ray(Algorithm::B1);
    for (auto other : {a2, a2p, a3, a4, b1}) EXPECT_GT(a1.second, other.second) << name;  // A1 the most tests
    EXPECT_GT(a1.second, 2.0 * a2p.second) << name;  // "far fewer"
    EXPECT_LE(a4.first, a3.first) << name;
    EXPECT_LE(a3.first, a2p.first) << name;
    EXPECT_LT(a4.first, a1.first) << name;
    EXPECT_LT(a4.first, a2.first) << name;
  }
}

TEST(Bvh, ClusteredTreeHoldsEveryPrimitiveOnce) {
  const Scene s = make_builtin_scene("teapots");
  const Bvh bvh = build_bvh_by_clustering(s);
  std::vector<int> seen(s.prim_count(), 0);
  std::vector<NodeRef> stack{bvh.root};
  while (!stack.empty()) {
    const NodeRef r = stack.back();
    stack.pop_back();
    if (is_primitive(r)) { ++seen[primitive_of(r)]; continue; }
    for (NodeRef c : bvh.nodes[r].child) {
      const Bounds3 cb = is_primitive(c) ? bvh.prim_bounds[primitive_of(c)] : bvh.nodes[c].box;
      EXPECT_TRUE(bvh.nodes[r].box.contains(cb.lo) && bvh.nodes[r].box.contains(cb.hi));
      stack.push_back(c);
    }
  }
  for (int v : seen) EXPECT_EQ(v, 1);
  EXPECT_EQ(bvh.nodes.size(), std::size_t(s.prim_count() - 1));
  EXPECT_LT(bvh.depth(), 64);
}

TEST(Algorithm, NamesRoundTrip) {
  for (Algorithm a : paper_algorithms()) EXPECT_EQ(parse_algorithm(name_of(a)), a);
  EXPECT_EQ(parse_algorithm("A2'"), Algorithm::A2p);
  EXPECT_EQ(parse_algorithm("a4"), Algorithm::A4);
  EXPECT_FALSE(parse_algorithm("A5"));
}

}  // namespace
}  // namespace gcsim::raytrace
