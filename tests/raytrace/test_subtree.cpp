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

// A row filtered with the children's lanes prepared once per tree holds the same entries and
// pairs, bit for bit, and counts the same, as one that works them out per node.
TEST(Subtree, RowFilterWithPreparedPairsIsTheSame) {
  for (const char* name : {"spheres-a", "spheres-b", "spheres-random", "teapot", "teapots"}) {
    const Scene scene = make_builtin_scene(name);
    const Bvh bvh = build_bvh_by_clustering(scene);
    const PreparedChildPairs prepared(bvh);
    const int size = 64, tile = 8;
    const Camera camera(scene.camera, size, size);
    std::size_t entries = 0;
    for (int y0 = 0; y0 < size; y0 += tile) {
      const Plane a = camera.row_plane(y0), b = flipped(camera.row_plane(y0 + tile));
      PlaneFilteredTree plain, fast;
      TraceCounters plain_counts, fast_counts;
      filter_by_two_planes(bvh, a, b, plain, plain_counts);
      filter_by_two_planes(bvh, a, b, fast, fast_counts, &prepared);
      EXPECT_EQ(fast_counts.plane_tests, plain_counts.plane_tests) << name;
      EXPECT_EQ(fast_counts.subtree_nodes, plain_counts.subtree_nodes) << name;
      ASSERT_EQ(fast.root, plain.root) << name;
      ASSERT_EQ(fast.entries.size(), plain.entries.size()) << name;
      ASSERT_EQ(fast.children.size(), plain.children.size()) << name;
      for (std::size_t i = 0; i < plain.entries.size(); ++i) {
        const auto &f = fast.entries[i], &p = plain.entries[i];
        ASSERT_EQ(f.ref, p.ref) << name << " entry " << i;
        ASSERT_EQ(f.inside, p.inside) << name << " entry " << i;
        ASSERT_EQ(f.child[0], p.child[0]) << name << " entry " << i;
        ASSERT_EQ(f.child[1], p.child[1]) << name << " entry " << i;
        ASSERT_EQ(f.children, p.children) << name << " entry " << i;
        ASSERT_EQ(std::memcmp(&f.bounds, &p.bounds, sizeof(Bounds3)), 0) << name << " entry " << i;
      }
      for (std::size_t i = 0; i < plain.children.size(); ++i) {
        const auto &f = fast.children[i], &p = plain.children[i];
        ASSERT_EQ(std::memcmp(&f.lanes, &p.lanes, sizeof f.lanes), 0) << name << " pair " << i;
        ASSERT_EQ(std::memcmp(f.box, p.box, sizeof f.box), 0) << name << " pair " << i;
        ASSERT_EQ(f.ref[0], p.ref[0]) << name << " pair " << i;
        ASSERT_EQ(f.ref[1], p.ref[1]) << name << " pair " << i;
        ASSERT_EQ(f.pair[0], p.pair[0]) << name << " pair " << i;
        ASSERT_EQ(f.pair[1], p.pair[1]) << name << " pair " << i;
      }
      entries += plain.entries.size();
    }
    EXPECT_GT(entries, 0u) << name;
  }
}

}  // namespace
}  // namespace gcsim::raytrace
