#pragma once
// A binary tree of axis-aligned boxes (section 2.1: the paper argues for a binary tree, which
// makes the front-to-back ordering of children a single comparison). Leaves are primitives
// themselves (tree_node.hpp).
#include <cstdint>
#include <vector>

#include "apps/common/geometry/bounds.hpp"
#include "apps/common/geometry/packed_tree.hpp"
#include "apps/common/geometry/tree_node.hpp"

namespace gcsim::geometry {

struct PrimitiveArrays;

struct Bvh {
  std::vector<BvhNode> nodes;       // depth-first order, root first (when the root is a node)
  NodeRef root = 0;                 // a node, or a primitive when the scene has only one
  std::vector<Bounds3> prim_bounds; // the box of every primitive, by id
  PackedTree packed;                // the same tree laid out for traversal

  int depth() const;                // longest root-to-primitive path, in nodes
};

// Builds the tree bottom-up by agglomerative clustering: repeatedly merge the two clusters whose
// common box has the least surface area (nearest-neighbour chains make this O(n^2)). Scenes with
// more than a few thousand primitives are first split top-down at centroid medians into groups
// that are clustered separately, which keeps large OBJ files tractable.
Bvh build_bvh_by_clustering(const PrimitiveArrays& prims);

}  // namespace gcsim::geometry
