#pragma once
// The layout traversal reads: each node holds the boxes of its two children, so expanding a node
// tests both children from one 64-byte cache line, one axis per 4-wide vector
// (lo of child 0, lo of child 1, hi of child 0, hi of child 1). Built from a BVH or a subtree.
#include <cstddef>
#include <cstdint>
#include <vector>
#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "apps/common/geometry/tree_node.hpp"

namespace gcsim::geometry {

struct alignas(64) PairNode {
  float bounds[3][4];  // [axis][lo child 0, lo child 1, hi child 0, hi child 1]
  NodeRef child[2];
};

// Writes the boxes of n's two children, a and b, in the node's layout.
inline void set_child_boxes(PairNode& n, const Bounds3& a, const Bounds3& b) {
#if defined(__SSE2__)
  // Each box as two overlapping loads inside its 24 bytes: (lo.x lo.y lo.z hi.x), (lo.z hi.x hi.y hi.z).
  static_assert(offsetof(Bounds3, hi) == 3 * sizeof(float) && sizeof(Bounds3) == 6 * sizeof(float));
  const __m128 a0 = _mm_loadu_ps(&a.lo.x), a1 = _mm_loadu_ps(&a.lo.z);
  const __m128 b0 = _mm_loadu_ps(&b.lo.x), b1 = _mm_loadu_ps(&b.lo.z);
  const __m128 t = _mm_unpacklo_ps(a0, b0);  // a.lo.x b.lo.x a.lo.y b.lo.y
  const __m128 u = _mm_unpackhi_ps(a0, b0);  // a.lo.z b.lo.z a.hi.x b.hi.x
  const __m128 v = _mm_unpackhi_ps(a1, b1);  // a.hi.y b.hi.y a.hi.z b.hi.z
  _mm_store_ps(n.bounds[0], _mm_shuffle_ps(t, u, _MM_SHUFFLE(3, 2, 1, 0)));
  _mm_store_ps(n.bounds[1], _mm_shuffle_ps(t, v, _MM_SHUFFLE(1, 0, 3, 2)));
  _mm_store_ps(n.bounds[2], _mm_shuffle_ps(u, v, _MM_SHUFFLE(3, 2, 1, 0)));
#else
  const Bounds3* boxes[2] = {&a, &b};
  for (int c = 0; c < 2; ++c)
    for (int k = 0; k < 3; ++k) {
      n.bounds[k][c] = boxes[c]->lo[k];
      n.bounds[k][2 + c] = boxes[c]->hi[k];
    }
#endif
}

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
