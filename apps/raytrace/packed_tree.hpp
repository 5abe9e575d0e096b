#pragma once
// The layout traversal reads: each node holds the boxes of its two children, so expanding a node
// tests both children from one 64-byte cache line, with the near and far slab planes chosen once
// per ray from the signs of its direction. Built from a BVH or a subtree (same references).
#include <cstdint>
#include <vector>

#include "apps/raytrace/tree_node.hpp"

namespace gcsim::raytrace {

struct alignas(64) PairNode {
  float bounds[6][2];  // [lo x, lo y, lo z, hi x, hi y, hi z][child]
  NodeRef child[2];
};

struct PackedTree {
  std::vector<PairNode> nodes;
  NodeRef root = 0;       // a node of `nodes`, or a primitive
  Bounds3 root_box;
  bool empty = true;
};

// Re-lays out nodes/root (node indices of `nodes`), reading primitive boxes from prim_bounds.
void pack_tree(const std::vector<BvhNode>& nodes, NodeRef root, bool empty, const std::vector<Bounds3>& prim_bounds,
               PackedTree& out);

}  // namespace gcsim::raytrace
