#pragma once
// The ordered closest-hit traversal (traverse_ordered: A2, A3, A4's rays) for up to eight rays at
// once, for coherent primary rays. Each ray (lane) gets exactly the hit and the counts that
// traverse_ordered gives it alone, because the simulated time is charged from those counts:
//  - a lane takes part in a node exactly when its own walk would pop it and not prune it (its
//    own box hit, its own entry against its own nearest hit so far);
//  - children are visited in each lane's own near-first order: when the lanes disagree, the
//    majority's first child is visited once more afterwards for the others (every lane still
//    meets the children in its own order, and other lanes' visits do not change its state);
//  - slab tests, primitive tests and the tie-break are the single-ray ones, lane by lane.
// Eight lanes run in AVX2 registers when the host has AVX2 (checked at run time: the build sets
// no -march); otherwise, or when a walk would need more stack than the single-ray walk has, the
// lanes are traced one by one with traverse_ordered.
#include "apps/common/geometry/hit.hpp"
#include "apps/common/geometry/packed_tree.hpp"
#include "apps/common/geometry/primitive_intersection.hpp"

namespace gcsim::geometry {

inline constexpr int kPacketLanes = 8;

// For each lane i with bit i of `lanes` set: what traverse_ordered(prims, tree, rays[i], hits[i],
// tallies[i]) would do. Other lanes are not read or written.
void traverse_ordered_packet(const PrimitiveArrays& prims, const PackedTree& tree, const Ray rays[kPacketLanes],
                             unsigned lanes, Hit hits[kPacketLanes], TestTally tallies[kPacketLanes]);

// True when traverse_ordered_packet runs the eight-lane kernel on this host.
bool packet_kernel_vectorized();

}  // namespace gcsim::geometry
