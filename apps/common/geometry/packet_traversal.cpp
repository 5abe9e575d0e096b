#include "apps/common/geometry/packet_traversal.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "apps/common/geometry/packet_sphere_lanes.hpp"
#include "apps/common/geometry/packet_triangle_lanes.hpp"
#include "apps/common/geometry/traversal.hpp"

namespace gcsim::geometry {
namespace {

void one_by_one(const PrimitiveArrays& prims, const PackedTree& tree, const Ray rays[], unsigned lanes, Hit hits[],
                TestTally tallies[]) {
  for (int i = 0; i < kPacketLanes; ++i)
    if (lanes >> i & 1u) traverse_ordered(prims, tree, rays[i], hits[i], tallies[i]);
}

#if defined(GCSIM_PACKET_AVX2)

using namespace packet;

constexpr int kPacketStackSize = 256;  // traverse_ordered's: a deeper walk falls back to it

struct alignas(32) Entry {
  float entry[8];  // each lane's lower bound of its entry distance
  NodeRef node;
  unsigned lanes;
};

// Each lane's counts, one 32-bit element per lane: kept apart from State, which the out-of-line
// tests see, so that they can stay in registers through the walk.
struct Counts {
  __m256i boxes, spheres, triangles, sorts;
};

// counter[i] += 1 for every lane i of `lanes`.
GCSIM_AVX2 inline void count(__m256i& counter, unsigned lanes) { counter = _mm256_sub_epi32(counter, lane_mask(lanes)); }
// One primitive for the lanes of `lanes`, counted per lane as test_quickly counts it. Inline in
// the walk: most node visits test a triangle.
GCSIM_AVX2_INLINE void test_lanes(const PrimitiveArrays& prims, int prim, const Ray rays[], const Lanes& l,
                                  unsigned lanes, State& s, Counts& k) {
  if (prim < l.sphere_count) {
    count(k.spheres, lanes);
    sphere_lanes(prims.spheres[prim], prim, l, lanes, s);
    return;
  }
  count(k.triangles, lanes);
  const Triangle& tri = l.triangles[prim - l.sphere_count];
  unsigned scalar = l.axes_count == 1 ? intersect_lanes(tri, prim, l, l.axes[0], lanes, s) : 0u;
  for (int g = 0; g < l.axes_count && l.axes_count > 1; ++g)
    if (l.axes[g].lanes & lanes) scalar |= intersect_lanes(tri, prim, l, l.axes[g], lanes, s);
  for (; scalar; scalar &= scalar - 1) scalar_triangle(tri, prim, rays, std::countr_zero(scalar), s);
}

// kOctant >= 0: every lane runs towards that octant (bit a: -axis a), so the near plane of each
// axis is known without a per-lane blend; -1: mixed octants, blended per lane.
template <int kOctant>
GCSIM_AVX2 inline unsigned child_box(const PairNode& n, int c, const Lanes& l, __m256 tmax, __m256& near) {
  __m256 t0 = _mm256_load_ps(l.tmin), t1 = _mm256_set1_ps(kInfinity);
  for (int a = 0; a < 3; ++a) {
    const __m256 o = _mm256_load_ps(l.o[a]), inv = _mm256_load_ps(l.inv[a]);
    __m256 tn, tf;
    if constexpr (kOctant >= 0) {
      const bool negative = (kOctant >> a) & 1;
      tn = _mm256_mul_ps(_mm256_sub_ps(_mm256_set1_ps(n.bounds[a][negative ? 2 + c : c]), o), inv);
      tf = _mm256_mul_ps(_mm256_sub_ps(_mm256_set1_ps(n.bounds[a][negative ? c : 2 + c]), o), inv);
    } else {
      const __m256 neg = _mm256_castsi256_ps(_mm256_load_si256(reinterpret_cast<const __m256i*>(l.negative[a])));
      const __m256 tl = _mm256_mul_ps(_mm256_sub_ps(_mm256_set1_ps(n.bounds[a][c]), o), inv);
      const __m256 th = _mm256_mul_ps(_mm256_sub_ps(_mm256_set1_ps(n.bounds[a][2 + c]), o), inv);
      tn = _mm256_blendv_ps(tl, th, neg);
      tf = _mm256_blendv_ps(th, tl, neg);
    }
    // max/min return their second operand when one is NaN, as the single-ray test relies on.
    t0 = _mm256_max_ps(tn, t0);
    t1 = _mm256_min_ps(tf, t1);
  }
  const __m256 far = _mm256_min_ps(_mm256_mul_ps(t1, _mm256_set1_ps(1.0f + 2.0f * gamma(3))), tmax);
  near = _mm256_mul_ps(t0, _mm256_set1_ps(1.0f - 2.0f * gamma(3)));
  return unsigned(_mm256_movemask_ps(_mm256_cmp_ps(t0, far, _CMP_LE_OQ)));
}

// intersect_box (bounds.hpp) for every lane: the same per-axis swap, scaling and comparisons; a
// lane that fails on one axis fails whatever the later axes compute.
GCSIM_AVX2 unsigned root_box(const Bounds3& b, const Lanes& l, __m256 tmax, __m256& entry) {
  __m256 t0 = _mm256_load_ps(l.tmin), t1 = tmax, miss = _mm256_setzero_ps();
  for (int a = 0; a < 3; ++a) {
    const __m256 o = _mm256_load_ps(l.o[a]), inv = _mm256_load_ps(l.inv[a]);
    const __m256 lo = _mm256_mul_ps(_mm256_sub_ps(_mm256_set1_ps(b.lo[a]), o), inv);
    const __m256 hi = _mm256_mul_ps(_mm256_sub_ps(_mm256_set1_ps(b.hi[a]), o), inv);
    const __m256 swap = _mm256_cmp_ps(lo, hi, _CMP_GT_OQ);
    const __m256 tn = _mm256_blendv_ps(lo, hi, swap);
    const __m256 tf = _mm256_mul_ps(_mm256_blendv_ps(hi, lo, swap), _mm256_set1_ps(1.0f + 2.0f * gamma(3)));
    t0 = _mm256_blendv_ps(t0, tn, _mm256_cmp_ps(tn, t0, _CMP_GT_OQ));
    t1 = _mm256_blendv_ps(t1, tf, _mm256_cmp_ps(tf, t1, _CMP_LT_OQ));
    miss = _mm256_or_ps(miss, _mm256_cmp_ps(t0, t1, _CMP_GT_OQ));
  }
  entry = _mm256_mul_ps(t0, _mm256_set1_ps(1.0f - 2.0f * gamma(3)));
  return ~unsigned(_mm256_movemask_ps(miss)) & 0xffu;
}

// Pushes a child for `lanes` with their entries; false when the single-ray stack would be full.
GCSIM_AVX2 inline bool push(Entry* stack, int& top, NodeRef node, unsigned lanes, __m256 near) {
  if (!lanes) return true;
  if (top >= kPacketStackSize) return false;
  Entry& e = stack[top++];
  _mm256_store_ps(e.entry, near);
  e.node = node;
  e.lanes = lanes;
  return true;
}

// The walk's results for the lanes it traced: their hits, and their counts added to their tallies.
GCSIM_AVX2 inline void write_back(const State& s, const Counts& k, unsigned lanes, Hit hits[], TestTally tallies[]) {
  alignas(32) std::int32_t boxes[8], spheres[8], triangles[8], sorts[8];
  _mm256_store_si256(reinterpret_cast<__m256i*>(boxes), k.boxes);
  _mm256_store_si256(reinterpret_cast<__m256i*>(spheres), k.spheres);
  _mm256_store_si256(reinterpret_cast<__m256i*>(triangles), k.triangles);
  _mm256_store_si256(reinterpret_cast<__m256i*>(sorts), k.sorts);
  for (unsigned m = lanes; m; m &= m - 1) {
    const int i = std::countr_zero(m);
    hits[i] = s.hit[i];
    tallies[i].boxes += boxes[i];
    tallies[i].spheres += spheres[i];
    tallies[i].triangles += triangles[i];
    tallies[i].sorts += sorts[i];
  }
}

// The walk of ordered<> in traversal.cpp for all lanes at once; false (nothing written) when it
// would need more stack than the single-ray walk has.
template <int kOctant>
GCSIM_AVX2 bool walk(const PrimitiveArrays& prims, const PackedTree& tree, const Ray rays[], unsigned lanes,
                     const Lanes& l, Hit hits[], TestTally tallies[]) {
  State s;
  for (int i = 0; i < kPacketLanes; ++i) {
    s.hit[i] = lanes >> i & 1u ? hits[i] : Hit{};
    s.t[i] = s.hit[i].t;
  }
  Counts k{_mm256_setzero_si256(), _mm256_setzero_si256(), _mm256_setzero_si256(), _mm256_setzero_si256()};
  count(k.boxes, lanes);
  __m256 root_entry;
  const unsigned live = lanes & root_box(tree.root_box, l, _mm256_load_ps(s.t), root_entry);
  thread_local Entry stack[kPacketStackSize];  // fiber stacks are small
  int top = 0;
  // The node to expand next stays in registers: the entry the walk would push last, and so pop
  // at once, is taken without the trip through the stack (same order and checks).
  NodeRef node = tree.root;
  unsigned node_lanes = live;
  __m256 node_entry = root_entry;
  while (node_lanes) {
    const __m256 t = _mm256_load_ps(s.t);
    // figure 3: lanes that found a nearer primitive meanwhile prune the node.
    const unsigned active = node_lanes & ~unsigned(_mm256_movemask_ps(_mm256_cmp_ps(node_entry, t, _CMP_GT_OQ)));
    if (active) {
      const PairNode& n = tree.nodes[node];
      const bool prim0 = is_primitive(n.child[0]), prim1 = is_primitive(n.child[1]);
      if (prim0) test_lanes(prims, primitive_of(n.child[0]), rays, l, active, s, k);
      if (prim1) test_lanes(prims, primitive_of(n.child[1]), rays, l, active, s, k);
      if (!(prim0 && prim1)) {
        const __m256 tmax = _mm256_load_ps(s.t);
        __m256 near0 = tmax, near1 = tmax;
        const unsigned hit0 = prim0 ? 0u : child_box<kOctant>(n, 0, l, tmax, near0) & active;
        const unsigned hit1 = prim1 ? 0u : child_box<kOctant>(n, 1, l, tmax, near1) & active;
        if (!prim0) count(k.boxes, active);
        if (!prim1) count(k.boxes, active);
        const unsigned both = hit0 & hit1, only0 = hit0 & ~both, only1 = hit1 & ~both;
        count(k.sorts, both);
        // traverse_ordered visits child 0 first only when its entry is strictly nearer.
        const unsigned first0 = both & unsigned(_mm256_movemask_ps(_mm256_cmp_ps(near0, near1, _CMP_LT_OQ)));
        const unsigned first1 = both & ~first0;
        const NodeRef c0 = n.child[0], c1 = n.child[1];
        // Popped: the last of the three first, so it is not pushed at all.
        const bool c0_first = std::popcount(first0) >= std::popcount(first1);  // c0, c1, then c0 again
        const bool ok = c0_first ? push(stack, top, c0, first1, near0) && push(stack, top, c1, both | only1, near1)
                                 : push(stack, top, c1, first0, near1) && push(stack, top, c0, both | only0, near0);
        if (!ok) return false;
        const unsigned last = c0_first ? first0 | only0 : first1 | only1;
        if (last) {
          if (top >= kPacketStackSize) return false;  // where its push would have failed
          node = c0_first ? c0 : c1;
          node_lanes = last;
          node_entry = c0_first ? near0 : near1;
          continue;
        }
      }
    }
    if (top == 0) break;
    const Entry& e = stack[--top];
    node = e.node;
    node_lanes = e.lanes;
    node_entry = _mm256_load_ps(e.entry);
  }
  write_back(s, k, lanes, hits, tallies);
  return true;
}

// The walk compiled for the packet's octant when all lanes share one.
GCSIM_AVX2 bool walk_packet(const PrimitiveArrays& prims, const PackedTree& tree, const Ray rays[], unsigned lanes,
                            Hit hits[], TestTally tallies[]) {
  Lanes l;
  prepare_lanes(prims, tree.root_box, rays, lanes, l);
  int octant = 0;
  for (int a = 0; a < 3; ++a) {
    const unsigned negative = lanes & unsigned(_mm256_movemask_ps(_mm256_castsi256_ps(
                                          _mm256_load_si256(reinterpret_cast<const __m256i*>(l.negative[a])))));
    if (negative != 0 && negative != lanes) octant = -1;
    if (octant >= 0 && negative) octant |= 1 << a;
  }
  switch (octant) {
    case 0: return walk<0>(prims, tree, rays, lanes, l, hits, tallies);
    case 1: return walk<1>(prims, tree, rays, lanes, l, hits, tallies);
    case 2: return walk<2>(prims, tree, rays, lanes, l, hits, tallies);
    case 3: return walk<3>(prims, tree, rays, lanes, l, hits, tallies);
    case 4: return walk<4>(prims, tree, rays, lanes, l, hits, tallies);
    case 5: return walk<5>(prims, tree, rays, lanes, l, hits, tallies);
    case 6: return walk<6>(prims, tree, rays, lanes, l, hits, tallies);
    case 7: return walk<7>(prims, tree, rays, lanes, l, hits, tallies);
    default: return walk<-1>(prims, tree, rays, lanes, l, hits, tallies);
  }
}

bool host_has_avx2() {
  static const bool yes = __builtin_cpu_supports("avx2");
  return yes;
}

#endif

}  // namespace

bool packet_kernel_vectorized() {
#if defined(GCSIM_PACKET_AVX2)
  return host_has_avx2();
#else
  return false;
#endif
}

void traverse_ordered_packet(const PrimitiveArrays& prims, const PackedTree& tree, const Ray rays[kPacketLanes],
                             unsigned lanes, Hit hits[kPacketLanes], TestTally tallies[kPacketLanes]) {
  lanes &= (1u << kPacketLanes) - 1;
  if (!lanes) return;
#if defined(GCSIM_PACKET_AVX2)
  // An empty tree or a lone primitive: nothing to share between the lanes.
  if (!tree.empty && !is_primitive(tree.root) && host_has_avx2() &&
      walk_packet(prims, tree, rays, lanes, hits, tallies))
    return;
#endif
  one_by_one(prims, tree, rays, lanes, hits, tallies);
}

}  // namespace gcsim::geometry
