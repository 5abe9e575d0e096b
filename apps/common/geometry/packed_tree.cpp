#include "apps/common/geometry/packed_tree.hpp"

namespace gcsim::geometry {

void pack_tree(const std::vector<BvhNode>& nodes, NodeRef root, bool empty, const std::vector<Bounds3>& prim_bounds,
               PackedTree& out) {
  out.nodes.resize(nodes.size());
  out.root = root;
  out.empty = empty;
  if (empty) return;
  const auto box = [&](NodeRef r) -> const Bounds3& { return is_primitive(r) ? prim_bounds[primitive_of(r)] : nodes[r].box; };
  out.root_box = box(root);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    PairNode& p = out.nodes[i];
    set_child_boxes(p, box(nodes[i].child[0]), box(nodes[i].child[1]));
    p.child[0] = nodes[i].child[0];
    p.child[1] = nodes[i].child[1];
  }
}

}  // namespace gcsim::geometry
