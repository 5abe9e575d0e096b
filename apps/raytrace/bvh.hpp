#pragma once
// A binary tree of axis-aligned boxes (section 2.1: the paper argues for a binary tree, which
// makes the front-to-back ordering of children a single comparison). Leaves are primitives
// themselves: a child reference >= 0 is a node, < 0 is the primitive ~ref.
// The same node layout serves the whole tree and the per-subregion subtrees of 2.2.1.
#include <cstdint>
#include <vector>

#include "apps/raytrace/bounds.hpp"

namespace gcsim::raytrace {

class Scene;

using NodeRef = std::int32_t;
inline bool is_primitive(NodeRef r) { return r < 0; }
inline int primitive_of(NodeRef r) { return ~r; }
inline NodeRef primitive_ref(int prim) { return ~prim; }

struct BvhNode {
  Bounds3 box;
  NodeRef child[2];
};

struct Bvh {
  std::vector<BvhNode> nodes;       // depth-first order, root first (when the root is a node)
  NodeRef root = 0;                 // a node, or a primitive when the scene has only one
  std::vector<Bounds3> prim_bounds; // the box of every primitive, by id

  int depth() const;                // longest root-to-primitive path, in nodes
};

// Builds the tree bottom-up by agglomerative clustering: repeatedly merge the two clusters whose
// common box has the least surface area (nearest-neighbour chains make this O(n^2)). Scenes with
// more than a few thousand primitives are first split top-down at centroid medians into groups
// that are clustered separately, which keeps large OBJ files tractable.
Bvh build_bvh_by_clustering(const Scene& scene);

}  // namespace gcsim::raytrace
