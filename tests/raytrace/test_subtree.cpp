// The subtree pass lays out its nodes for traversal directly and classifies a node's two children
// in one pass. It must build what the recursive pass with its separate packing built (kept here
// as the reference): the same nodes in the same order, the same children and boxes, the same
// counts of plane tests and nodes, for every tile of every paper scene.
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "apps/raytrace/builtin_scenes.hpp"
#include "apps/raytrace/camera.hpp"
#include "apps/raytrace/subtree.hpp"

namespace gcsim::raytrace {
namespace {

struct ReferencePass {
  const Bvh& bvh;
  const PlaneFilteredTree& row;
  std::array<Plane, 2> planes;
  std::vector<BvhNode> nodes{};
  std::int64_t tests = 0;

  bool visit(int e, std::uint8_t inside, NodeRef* ref) {
    const auto& entry = row.entries[e];
    for (int i = 0; i < 2; ++i) {
      if (inside & (1u << i)) continue;
      ++tests;
      const Side s = classify(BoxCentre(entry.bounds), planes[i], abs_components(planes[i].normal));
      if (s == Side::outside) return false;
      if (s == Side::inside) inside |= (1u << i);
    }
    if (is_primitive(entry.ref)) {
      *ref = entry.ref;
      return true;
    }
    NodeRef c[2];
    bool has[2] = {false, false};
    for (int i = 0; i < 2; ++i)
      if (entry.child[i] >= 0) has[i] = visit(entry.child[i], inside, &c[i]);
    if (!has[0] && !has[1]) return false;
    if (!has[0] || !has[1]) {
      *ref = has[0] ? c[0] : c[1];
      return true;
    }
    nodes.push_back({bvh.nodes[entry.ref].box, {c[0], c[1]}});
    *ref = static_cast<NodeRef>(nodes.size() - 1);
    return true;
  }
};

TEST(Subtree, SameAsTheRecursivePassAndItsPacking) {
  for (const char* name : {"spheres-a", "spheres-b", "spheres-random", "teapot", "teapots"}) {
    const Scene scene = make_builtin_scene(name);
    const Bvh bvh = build_bvh_by_clustering(scene);
    const int size = 64, tile = 8;
    const Camera camera(scene.camera, size, size);
    int nonempty = 0;
    for (int y0 = 0; y0 < size; y0 += tile) {
      PlaneFilteredTree row;
      TraceCounters row_counters;
      filter_by_two_planes(bvh, camera.row_plane(y0), flipped(camera.row_plane(y0 + tile)), row, row_counters);
      for (int x0 = 0; x0 < size; x0 += tile) {
        const Plane c = camera.column_plane(x0), d = flipped(camera.column_plane(x0 + tile));
        Subtree got;
        TraceCounters counters;
        subtree_from_filtered(row, c, d, got, counters);
        ReferencePass ref{bvh, row, {c, d}};
        NodeRef root = 0;
        const bool any = row.root >= 0 && ref.visit(row.root, 0, &root);
        ASSERT_EQ(got.empty, !any) << name << " tile " << x0 << "," << y0;
        EXPECT_EQ(counters.plane_tests, ref.tests) << name;
        EXPECT_EQ(counters.subtree_nodes, std::int64_t(ref.nodes.size())) << name;
        if (!any) continue;
        ++nonempty;
        PackedTree want;
        pack_tree(ref.nodes, root, false, bvh.prim_bounds, want);
        ASSERT_EQ(got.root, root) << name;
        ASSERT_EQ(got.packed.root, want.root) << name;
        ASSERT_EQ(got.packed.nodes.size(), want.nodes.size()) << name;
        EXPECT_EQ(std::memcmp(&got.packed.root_box, &want.root_box, sizeof(Bounds3)), 0) << name;
        for (std::size_t i = 0; i < want.nodes.size(); ++i) {
          const PairNode &g = got.packed.nodes[i], &w = want.nodes[i];
          ASSERT_EQ(std::memcmp(g.bounds, w.bounds, sizeof w.bounds), 0) << name << " node " << i;
          ASSERT_EQ(g.child[0], w.child[0]) << name << " node " << i;
          ASSERT_EQ(g.child[1], w.child[1]) << name << " node " << i;
        }
      }
    }
    EXPECT_GT(nonempty, 0) << name;
  }
}

}  // namespace
}  // namespace gcsim::raytrace
