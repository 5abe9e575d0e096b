#pragma once
// Nodes of a binary box tree. Leaves are primitives themselves: a child reference >= 0 is a node,
// < 0 is the primitive ~ref. The same layout serves the whole tree and per-subregion subtrees.
#include <cstdint>

#include "apps/common/geometry/bounds.hpp"

namespace gcsim::geometry {

using NodeRef = std::int32_t;
inline bool is_primitive(NodeRef r) { return r < 0; }
inline int primitive_of(NodeRef r) { return ~r; }
inline NodeRef primitive_ref(int prim) { return ~prim; }

struct BvhNode {
  Bounds3 box;
  NodeRef child[2];
};

}  // namespace gcsim::geometry
