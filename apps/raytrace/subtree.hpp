#pragma once
// The dynamic subtree of section 2.2.1: the part of the BVH whose boxes meet a pyramid (the eye
// and a subregion's four corners) or any other region bounded by four planes (a pencil, 2.3).
//
// Each node gets four flags, one per plane: inside, outside or crossing. A node outside any
// plane is dropped with its descendants; a node inside a plane passes that flag down, so its
// descendants are never tested against that plane again. A node left with a single child is
// replaced by that child (figure 2), which is why a subtree is much shallower than the tree.
//
// Along a row of subregions the top and bottom planes are the same, so they are evaluated once
// per row (RowFilter) and only the left and right planes per subregion: 2(n/m + 1) planes for
// an n x n image in m x m subregions.
#include <array>
#include <cstdint>
#include <vector>

#include "apps/common/geometry/bvh.hpp"
#include "apps/raytrace/geometry_names.hpp"
#include "apps/raytrace/camera.hpp"
#include "apps/raytrace/counters.hpp"
#include "apps/raytrace/plane_classification4.hpp"

namespace gcsim::raytrace {

// Laid out for traversal only: each node holds its children's boxes (packed_tree.hpp), which is
// also all the uniformity test reads.
struct Subtree {
  NodeRef root = 0;  // a node of packed.nodes, or a primitive
  bool empty = true;
  PackedTree packed;
};

// The BVH filtered by two planes: the node and primitive entries not outside either, with the
// mask of planes they are entirely inside.
class PlaneFilteredTree {
 public:
  struct Entry {
    NodeRef ref;            // BVH node or primitive
    std::uint8_t inside;    // bit i: entirely inside plane i
    std::int32_t child[2];  // entries; -1 where the child was dropped
    std::int32_t children;  // a node's pair of children in `children`; -1 for a primitive
    Bounds3 bounds;         // its box: what a subtree's node holds of it
  };
  // What the subtree pass reads of a node's two children, in one place, so that it reads no
  // entry: their lanes for the two planes, boxes, references and own pairs.
  struct ChildPair {
    BoxLanes lanes;        // both children in the lanes a subregion's two planes are classified in
    Bounds3 box[2];        // the children's boxes, as their entries hold them
    NodeRef ref[2];        // the children's BVH nodes or primitives
    std::int32_t pair[2];  // a child node's own pair; kPrimitive, or kDropped where the child was dropped
  };
  static constexpr std::int32_t kPrimitive = -1, kDropped = -2;
  std::vector<Entry> entries;
  std::vector<ChildPair> children;
  int root = -1;  // -1: nothing survives
  BoxCentre root_box;  // the root entry's box, prepared: every subregion of the row classifies it
};

// What a row's filter copies of each BVH node's two children (lanes, boxes, references; pairs
// kDropped), worked out once per tree: none of it depends on a plane, and each row met it again.
class PreparedChildPairs {
 public:
  explicit PreparedChildPairs(const Bvh& bvh);
  const PlaneFilteredTree::ChildPair& of(NodeRef node) const { return pairs_[std::size_t(node)]; }

 private:
  std::vector<PlaneFilteredTree::ChildPair> pairs_;
};

// Filters the whole BVH by planes a and b (bits 0 and 1); with `prepared`, the children's lanes
// are copied from it instead of being worked out (the same entries either way).
void filter_by_two_planes(const Bvh& bvh, const Plane& a, const Plane& b, PlaneFilteredTree& out, TraceCounters& counters,
                          const PreparedChildPairs* prepared = nullptr);

// The subtree of the entries of `row` also inside planes c and d.
void subtree_from_filtered(const PlaneFilteredTree& row, const Plane& c, const Plane& d, Subtree& out,
                           TraceCounters& counters);

// Both steps for an arbitrary four-plane region (pencils).
void build_subtree(const Bvh& bvh, const std::array<Plane, 4>& planes, Subtree& out, TraceCounters& counters);

// The planes of the pyramid through the eye and the pixel rectangle [x0, x1) x [y0, y1):
// top, bottom (shared along a row), left, right.
std::array<Plane, 4> pyramid_planes(const Camera& camera, int x0, int y0, int x1, int y1);

}  // namespace gcsim::raytrace
