#pragma once
// The layout traversal reads: each node holds the boxes of its two children, so expanding a node
// tests both children from one 64-byte cache line, one axis per 4-wide vector
// (lo of child 0, lo of child 1, hi of child 0, hi of child 1). Built from a BVH or a subtree.
#include <cstdint>
#include <vector>

#include "apps/common/geometry/tree_node.hpp"

namespace gcsim::geometry {

struct alignas(64) PairNode {
  float bounds[3][4];  // [axis][lo child 0, lo child 1, hi child 0, hi child 1]
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

}  // namespace gcsim::geometry
