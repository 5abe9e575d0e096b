#pragma once
// Depth-first traversal of a box tree (the whole BVH or a subregion's subtree) for the nearest hit.
//  - unordered (A1 on the BVH, A2' on a subtree): every child whose box the ray crosses anywhere
//    ahead is visited, with no use of the distance found so far;
//  - ordered (A2, A3; section 2.2.2): children are visited nearest-entry first, and a child whose
//    box starts beyond the nearest hit found so far is pruned (figure 3).
// A primitive child is tested directly; only node children cost a box test.
#include "apps/common/geometry/hit.hpp"
#include "apps/common/geometry/packed_tree.hpp"
#include "apps/common/geometry/primitive_intersection.hpp"

namespace gcsim::geometry {

void traverse_unordered(const PrimitiveArrays& prims, const PackedTree& tree, const Ray& ray, Hit& hit, TestTally& tally);
void traverse_ordered(const PrimitiveArrays& prims, const PackedTree& tree, const Ray& ray, Hit& hit, TestTally& tally);
// traverse_ordered for each of `count` rays in turn (hits[i] for rays[i]), with the per-tree work
// done once for rays that share an octant and an origin (a tile's primary rays): the same hits
// and counts.
void traverse_ordered_rays(const PrimitiveArrays& prims, const PackedTree& tree, const Ray* rays, int count, Hit* hits,
                           TestTally& tally);
// The same walk reading the ray's octant and triangle axes at run time, as it does for a ray
// with a -0 or NaN component: the reference the tests hold the per-octant walks to.
void traverse_ordered_generic(const PrimitiveArrays& prims, const PackedTree& tree, const Ray& ray, Hit& hit,
                              TestTally& tally);
// True if any primitive is hit with tmin < t < tmax (shadow rays); stops at the first.
bool traverse_any_hit(const PrimitiveArrays& prims, const PackedTree& tree, const Ray& ray, float tmax, TestTally& tally);
// test_primitive (primitive_intersection.hpp) with the SSE rejection and, inside all three edges, the
// triangle test finished from its values: the same hit and count, fewer instructions.
void test_primitive_quickly(const PrimitiveArrays& prims, int prim, const Ray& ray, Hit& hit, TestTally& tally);
// Every primitive, no tree: the reference the tests compare with.
void intersect_brute_force(const PrimitiveArrays& prims, const Ray& ray, Hit& hit, TestTally& tally);

}  // namespace gcsim::geometry
