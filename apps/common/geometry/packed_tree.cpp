#include "apps/common/geometry/packed_tree.hpp"

namespace gcsim::geometry {

void pack_tree(const std::vector<BvhNode>& nodes, NodeRef root, bool empty, const std::vector<Bounds3>& prim_bounds,
               PackedTree& out) {
  out.nodes.resize(nodes.size());
  out.root = root;
  out.empty = empty;
  if (empty) return;
  out.root_box = is_primitive(root) ? prim_bounds[primitive_of(root)] : nodes[root].box;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    PairNode& p = out.nodes[i];
    for (int c = 0; c < 2; ++c) {
      const NodeRef r = nodes[i].child[c];
      const Bounds3& b = is_primitive(r) ? prim_bounds[primitive_of(r)] : nodes[r].box;
      for (int a = 0; a < 3; ++a) {
        p.bounds[a][c] = b.lo[a];
        p.bounds[a][2 + c] = b.hi[a];
      }
      p.child[c] = r;
    }
  }
}

}  // namespace gcsim::geometry
