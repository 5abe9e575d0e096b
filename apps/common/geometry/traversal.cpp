#include "apps/common/geometry/traversal.hpp"

#include "apps/common/geometry/slab_lanes.hpp"
#include "apps/common/geometry/triangle_finish.hpp"
#include "apps/common/geometry/triangle_reject.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace gcsim::geometry {
namespace {

using slab::both_children;
using slab::SlabLanes;
using slab::SlabRay;

constexpr int kStackSize = 256;  // clustered trees of the built-in scenes are < 64 deep

// What the primitive tests need of a ray, prepared once per ray.
struct QuickRay {
  TriangleRejectRay reject;
  SphereRay sphere;  // set only when there are spheres: its conversion to double is not free
  // Without the range check's shortcut (reject.in_range false: every triangle is checked).
  QuickRay(const Ray& r, const PrimitiveArrays& prims) : reject(r) {
    if (!prims.spheres.empty()) sphere = SphereRay(r);
  }
  // Every primitive tested lies in `box` (the tree's root box); only triangles use it.
  QuickRay(const Ray& r, const Bounds3& box, const PrimitiveArrays& prims) : QuickRay(r, prims) {
    if (!prims.triangles.empty()) reject.assume_within(box);
  }
};

#if defined(__SSE2__)
template <int kLane>
inline float lane(__m128 v) { return _mm_cvtss_f32(_mm_shuffle_ps(v, v, _MM_SHUFFLE(kLane, kLane, kLane, kLane))); }

// watertight_finish with the rejection's rows taken from the registers they arrive in (stored
// and reloaded as floats, they would wait for store forwarding).
inline bool finish_from_lanes(const Ray& ray, __m128 x, __m128 y, __m128 z, __m128 e, float tmax, float* t, float* b1,
                              float* b2) {
  // Only after an "inside" verdict: the edge functions agree in sign.
  return watertight_finish<float, true>(lane<0>(x), lane<0>(y), lane<0>(z), lane<1>(x), lane<1>(y), lane<1>(z),
                                        lane<2>(x), lane<2>(y), lane<2>(z), lane<0>(e), lane<1>(e), lane<2>(e), ray, tmax,
                                        t, b1, b2);
}
#endif

// intersect_triangle's answer with the SSE rejection in front, finished from the rejection's
// own sheared vertices and edge functions when it finds the ray inside all three edges.
inline bool triangle_test_quickly(const Triangle& tri, const Ray& ray, const TriangleRejectRay& reject, float tmax,
                                  float* t, float* b1, float* b2) {
#if defined(__SSE2__)
  __m128 s[4];
  const RejectVerdict v = triangle_verdict(tri, reject, s);
  if (v == RejectVerdict::missed) return false;
  if (v == RejectVerdict::inside) return finish_from_lanes(ray, s[0], s[1], s[2], s[3], tmax, t, b1, b2);
#endif
  return intersect_triangle(tri, ray, tmax, t, b1, b2);
}

// test_primitive and occludes with the ray prepared and the triangle test above: the same tally
// and the same hits, fewer instructions.
inline void test_quickly(const PrimitiveArrays& prims, int prim, const Ray& ray, const QuickRay& quick, Hit& hit,
                         TestTally& tally) {
  if (prims.is_sphere(prim)) {
    ++tally.spheres;
    float t;
    if (intersect_sphere(prims.spheres[prim], quick.sphere, hit.t, &t)) hit.offer(t, prim);
    return;
  }
  ++tally.triangles;
  float t, b1 = 0, b2 = 0;
  if (triangle_test_quickly(prims.triangle(prim), ray, quick.reject, hit.t, &t, &b1, &b2)) hit.offer(t, prim, b1, b2);
}

inline bool occludes_quickly(const PrimitiveArrays& prims, int prim, const Ray& ray, const QuickRay& quick, float tmax,
                             TestTally& tally) {
  if (prims.is_sphere(prim)) {
    ++tally.spheres;
    float t;
    return intersect_sphere(prims.spheres[prim], quick.sphere, tmax, &t) && t < tmax;
  }
  ++tally.triangles;
  float t, b1, b2;
  return triangle_test_quickly(prims.triangle(prim), ray, quick.reject, tmax, &t, &b1, &b2) && t < tmax;
}

}  // namespace

namespace {

// Depth-first walk in child order, without sorting: what A1 and shadow rays share. Boxes are
// tested against tmax; visit(primitive) tests one primitive and returns true to stop the walk.
template <class Visit>
bool walk_depth_first(const PackedTree& tree, const Ray& ray, float tmax, TestTally& tally, Visit&& visit) {
  if (tree.empty) return false;
  if (is_primitive(tree.root)) return visit(primitive_of(tree.root));
  float entry;
  ++tally.boxes;
  if (!intersect_box(tree.root_box, ray, tmax, &entry)) return false;
  const SlabRay slab(ray);
  const SlabLanes lanes(slab, ray.tmin);
  NodeRef stack[kStackSize];
  int top = 0;
  NodeRef node = tree.root;  // in registers: the first child, pushed last, is taken at once
  for (;;) {
    const PairNode& n = tree.nodes[node];
    float entries[2];
    const unsigned mask = both_children<-1>(n, lanes, tmax, entries);
    bool next = false;
    for (int i = 1; i >= 0; --i) {  // the second child first on the stack: the first is visited first
      const NodeRef c = n.child[i];
      if (is_primitive(c)) {
        if (visit(primitive_of(c))) return true;
      } else {
        ++tally.boxes;
        if ((mask >> i & 1u) && top < kStackSize) {
          if (i == 0) node = c, next = true;
          else stack[top++] = c;
        }
      }
    }
    if (next) continue;
    if (top == 0) break;
    node = stack[--top];
  }
  return false;
}

}  // namespace

void traverse_unordered(const PrimitiveArrays& prims, const PackedTree& tree, const Ray& ray, Hit& hit, TestTally& tally) {
  const QuickRay quick(ray, tree.root_box, prims);
  walk_depth_first(tree, ray, kInfinity, tally, [&](int p) {
    test_quickly(prims, p, ray, quick, hit, tally);
    return false;
  });
}

namespace {

// The rare and long parts of a primitive test, out of line so that the walk's loop keeps its
// registers: a sphere, and a triangle the SSE rejection could not rule out. The caller counts.
[[gnu::noinline]] void sphere_test(const PrimitiveArrays& prims, int prim, const SphereRay& ray, Hit& hit) {
  float t;
  if (intersect_sphere(prims.spheres[prim], ray, hit.t, &t)) hit.offer(t, prim);
}

[[gnu::noinline]] void full_triangle_test(const PrimitiveArrays& prims, int prim, const Ray& ray, Hit& hit) {
  float t, b1 = 0, b2 = 0;
  if (intersect_triangle(prims.triangle(prim), ray, hit.t, &t, &b1, &b2)) hit.offer(t, prim, b1, b2);
}

#if defined(__SSE2__)
// The rest of the watertight test for a triangle the rejection found inside all three edges,
// from the rejection's own sheared vertices and edge functions (the full test would compute
// them again).
[[gnu::noinline]] void finish_triangle(const Ray& ray, int prim, __m128 x, __m128 y, __m128 z, __m128 e, Hit& hit) {
  float t, b1 = 0, b2 = 0;
  if (finish_from_lanes(ray, x, y, z, e, hit.t, &t, &b1, &b2)) hit.offer(t, prim, b1, b2);
}
#endif

// test_quickly with the counts in the walk's own locals and only the rejection inline.
struct OrderedTally {
  std::int64_t boxes = 0, spheres = 0, triangles = 0, sorts = 0;
};

// The ray's triangle axes (Ray::prepare) for octant kSigns when kZ is the dominant axis; -1 for
// the generic walk, which reads them from the ray.
template <int kSigns, int kZ>
constexpr int kx_of() { return kZ < 0 ? -1 : ((kSigns >> kZ) & 1) ? (kZ + 2) % 3 : (kZ + 1) % 3; }
template <int kSigns, int kZ>
constexpr int ky_of() { return kZ < 0 ? -1 : ((kSigns >> kZ) & 1) ? (kZ + 1) % 3 : (kZ + 2) % 3; }

// The arrays' pointers read once per ray: the out-of-line tests might, for all the compiler
// knows, change the vectors.
struct PrimView {
  const PrimitiveArrays& prims;
  const Triangle* triangles;
  int sphere_count;
  explicit PrimView(const PrimitiveArrays& p)
      : prims(p), triangles(p.triangles.data()), sphere_count(p.sphere_count()) {}
};

template <int kSigns, int kZ>
[[gnu::always_inline]] inline void test_in_walk(const PrimView& view, int prim, const Ray& ray, const QuickRay& quick,
                                                Hit& hit, OrderedTally& tally) {
  if (prim < view.sphere_count) {
    ++tally.spheres;
    sphere_test(view.prims, prim, quick.sphere, hit);
    return;
  }
  ++tally.triangles;
#if defined(__SSE2__)
  __m128 s[4];
  const RejectVerdict v = triangle_verdict<kx_of<kSigns, kZ>(), ky_of<kSigns, kZ>(), kZ>(
      view.triangles[prim - view.sphere_count], quick.reject, s);
  if (v == RejectVerdict::inside) finish_triangle(ray, prim, s[0], s[1], s[2], s[3], hit);
  else if (v == RejectVerdict::unsure) full_triangle_test(view.prims, prim, ray, hit);
#else
  if (!triangle_surely_missed<kx_of<kSigns, kZ>(), ky_of<kSigns, kZ>(), kZ>(view.triangles[prim - view.sphere_count], quick.reject))
    full_triangle_test(view.prims, prim, ray, hit);
#endif
}

// Both children of a node are primitives: as test_in_walk on each in turn, with both triangles'
// rejections done at once when the host has AVX (a triangle's verdict does not depend on the hit
// distance, which the first may shorten; the second is finished after the first).
template <int kSigns, int kZ>
[[gnu::always_inline]] inline void test_two_in_walk(const PrimView& view, int p0, int p1, const Ray& ray,
                                                    const QuickRay& quick, Hit& hit, OrderedTally& tally) {
#if defined(__AVX__)
  if (p0 >= view.sphere_count && p1 >= view.sphere_count) {
    tally.triangles += 2;
    const RejectPair pair = triangle_verdicts2<kx_of<kSigns, kZ>(), ky_of<kSigns, kZ>(), kZ>(
        view.triangles[p0 - view.sphere_count], view.triangles[p1 - view.sphere_count], quick.reject);
    const int prims[2] = {p0, p1};
    for (int k = 0; k < 2; ++k) {
      if (pair.verdict[k] == RejectVerdict::inside) {
        __m128 s[4];
        pair.rows(k, s);
        finish_triangle(ray, prims[k], s[0], s[1], s[2], s[3], hit);
      } else if (pair.verdict[k] == RejectVerdict::unsure) {
        full_triangle_test(view.prims, prims[k], ray, hit);
      }
    }
    return;
  }
#endif
  test_in_walk<kSigns, kZ>(view, p0, ray, quick, hit, tally);
  test_in_walk<kSigns, kZ>(view, p1, ray, quick, hit, tally);
}

// The triangle rejection's range check of the tree's root box (TriangleRejectRay::assume_within)
// for one origin at a time: the rays of a run mostly share their origin (a tile's primary rays).
class RootRange {
 public:
  RootRange(const PackedTree& tree, const PrimitiveArrays& prims) : prims_(prims), box_(tree.root_box), triangles_(!prims.triangles.empty()) {}
  QuickRay quick_ray(const Ray& ray) {
    QuickRay quick(ray, prims_);
    if (!triangles_) return quick;
    if (!known_ || std::memcmp(&origin_, &ray.origin, sizeof origin_) != 0) {
      quick.reject.assume_within(box_);
      origin_ = ray.origin, in_range_ = quick.reject.in_range, known_ = true;
    }
    quick.reject.in_range = in_range_;
    return quick;
  }

 private:
  const PrimitiveArrays& prims_;
  const Bounds3& box_;
  bool triangles_, known_ = false, in_range_ = false;
  glm::vec3 origin_{0.0f};
};

// Section 2.2.2's ordered walk for one ray.
template <int kSigns, int kZ>
[[gnu::always_inline]] inline void ordered_one(const PrimView& view, const PackedTree& tree, const Ray& ray, Hit& hit,
                                               RootRange& range, OrderedTally& tally) {
  struct Entry { NodeRef node; float entry; };
  Entry stack[kStackSize];
  int top = 0;
  float entry;
  ++tally.boxes;
  if (!intersect_box(tree.root_box, ray, hit.t, &entry)) return;
  const QuickRay quick = range.quick_ray(ray);
  const SlabRay slab(ray);
  const SlabLanes lanes(slab, ray.tmin, std::integral_constant<int, kSigns>{});
  // The node to expand next stays in registers: the child the binary walk would push last, and
  // so pop at once, is taken without the trip through the stack (same order, same checks).
  Entry e{tree.root, entry};
  for (;;) {
    if (e.entry > hit.t) {  // figure 3: a nearer primitive was found meanwhile
      if (top == 0) break;
      e = stack[--top];
      continue;
    }
    const PairNode& n = tree.nodes[e.node];
    const NodeRef c0 = n.child[0], c1 = n.child[1];
    // Primitive children first: their hits tighten the distance the boxes are tested against.
    const bool prim0 = is_primitive(c0), prim1 = is_primitive(c1);
    if (prim0 && prim1) {
      test_two_in_walk<kSigns, kZ>(view, primitive_of(c0), primitive_of(c1), ray, quick, hit, tally);
    } else {
      if (prim0) test_in_walk<kSigns, kZ>(view, primitive_of(c0), ray, quick, hit, tally);
      if (prim1) test_in_walk<kSigns, kZ>(view, primitive_of(c1), ray, quick, hit, tally);
      // The hit children by name, not in an array: an array went through memory.
      float entries[2];
      const unsigned mask = both_children<kSigns>(n, lanes, hit.t, entries);
      tally.boxes += int(!prim0) + int(!prim1);
      const bool in0 = !prim0 && (mask & 1u), in1 = !prim1 && (mask & 2u);
      if (in0 && in1) {
        ++tally.sorts;  // a binary tree sorts its children with one comparison (2.2.2)
        if (top + 2 <= kStackSize) {  // else both are dropped, as the binary walk drops them
          if (entries[0] < entries[1]) {  // the farther below, the nearer next
            stack[top++] = {c1, entries[1]};
            e = {c0, entries[0]};
          } else {
            stack[top++] = {c0, entries[0]};
            e = {c1, entries[1]};
          }
          continue;
        }
      } else if ((in0 || in1) && top < kStackSize) {
        e = in0 ? Entry{c0, entries[0]} : Entry{c1, entries[1]};
        continue;
      }
    }
    if (top == 0) break;
    e = stack[--top];
  }
}

// ordered_one for each of `count` rays of one octant and dominant axis, the per-tree work (the
// counts' locals, the arrays' pointers, the root box's range check per origin) done once.
template <int kSigns, int kZ>
void ordered(const PrimitiveArrays& prims, const PackedTree& tree, const Ray* rays, int count, Hit* hits,
             TestTally& counts) {
  if (tree.empty) return;
  if (is_primitive(tree.root)) {
    for (int i = 0; i < count; ++i) test_primitive(prims, primitive_of(tree.root), rays[i], hits[i], counts);
    return;
  }
  OrderedTally tally;  // locals: the primitive tests cannot alias them
  const PrimView view(prims);
  RootRange range(tree, prims);
  for (int i = 0; i < count; ++i) ordered_one<kSigns, kZ>(view, tree, rays[i], hits[i], range, tally);
  counts.boxes += tally.boxes;
  counts.spheres += tally.spheres;
  counts.triangles += tally.triangles;
  counts.sorts += tally.sorts;
}

using Walk = void (*)(const PrimitiveArrays&, const PackedTree&, const Ray*, int, Hit*, TestTally&);

// One walk per ray octant and dominant axis, so that neither the slab test's near/far choice nor
// the triangle rejection's axis permutation is read at run time.
Walk walk_for(const PrimitiveArrays& prims, const Ray& ray) {
#define GCSIM_OCTANT(s) ordered<s, 0>, ordered<s, 1>, ordered<s, 2>
  static constexpr Walk kByOctantAndAxis[8][3] = {{GCSIM_OCTANT(0)}, {GCSIM_OCTANT(1)}, {GCSIM_OCTANT(2)},
                                                  {GCSIM_OCTANT(3)}, {GCSIM_OCTANT(4)}, {GCSIM_OCTANT(5)},
                                                  {GCSIM_OCTANT(6)}, {GCSIM_OCTANT(7)}};
#undef GCSIM_OCTANT
  const glm::vec3& inv = ray.inv_direction;  // SlabRay's signs
  const int octant = int(std::signbit(inv.x)) | int(std::signbit(inv.y)) << 1 | int(std::signbit(inv.z)) << 2;
  // Without triangles the axes are never read: one walk per octant keeps fewer walks warm.
  if (prims.triangles.empty()) return kByOctantAndAxis[octant][2];
  // The octant's sign of the dominant axis decides kx and ky as Ray::prepare does, except for a
  // direction of -0 or NaN there: such a ray takes the generic walk.
  static constexpr int kAxes[2][3][2] = {{{1, 2}, {2, 0}, {0, 1}}, {{2, 1}, {0, 2}, {1, 0}}};  // [negative][kz]: kx, ky
  const int kz = ray.kz;
  const int* axes = kAxes[(octant >> kz) & 1][kz];
  return axes[0] == ray.kx && axes[1] == ray.ky ? kByOctantAndAxis[octant][kz] : ordered<-1, -1>;
}

// Whether walk_for gives two rays the same walk, from all it reads of them (the inverse
// direction's signs, kx, ky, kz), in one test of their bits: cheaper than asking it.
bool same_walk(const Ray& a, const Ray& b) {
  std::uint32_t p[3], q[3];
  std::memcpy(p, &a.inv_direction, sizeof p);
  std::memcpy(q, &b.inv_direction, sizeof q);
  const std::uint32_t signs = ((p[0] ^ q[0]) | (p[1] ^ q[1]) | (p[2] ^ q[2])) >> 31;
  const std::uint32_t axes = std::uint32_t(a.kx ^ b.kx) | std::uint32_t(a.ky ^ b.ky) | std::uint32_t(a.kz ^ b.kz);
  return (signs | axes) == 0;
}

}  // namespace

void traverse_ordered(const PrimitiveArrays& prims, const PackedTree& tree, const Ray& ray, Hit& hit, TestTally& tally) {
  walk_for(prims, ray)(prims, tree, &ray, 1, &hit, tally);
}

void traverse_ordered_rays(const PrimitiveArrays& prims, const PackedTree& tree, const Ray* rays, int count, Hit* hits,
                           TestTally& tally) {
  if (count <= 0) return;
  // Runs of rays that take the same walk (a tile's rays mostly take one).
  int first = 0;
  Walk walk = walk_for(prims, rays[0]);
  for (int i = 1; i <= count; ++i) {
    if (i < count && same_walk(rays[i], rays[i - 1])) continue;
    const Walk next = i < count ? walk_for(prims, rays[i]) : nullptr;
    if (next == walk) continue;
    walk(prims, tree, rays + first, i - first, hits + first, tally);
    first = i;
    walk = next;
  }
}

void traverse_ordered_generic(const PrimitiveArrays& prims, const PackedTree& tree, const Ray& ray, Hit& hit,
                              TestTally& tally) {
  ordered<-1, -1>(prims, tree, &ray, 1, &hit, tally);
}

bool traverse_any_hit(const PrimitiveArrays& prims, const PackedTree& tree, const Ray& ray, float tmax, TestTally& tally) {
  const QuickRay quick(ray, tree.root_box, prims);
  return walk_depth_first(tree, ray, tmax, tally,
                          [&](int p) { return occludes_quickly(prims, p, ray, quick, tmax, tally); });
}

void test_primitive_quickly(const PrimitiveArrays& prims, int prim, const Ray& ray, Hit& hit, TestTally& tally) {
  if (prims.is_sphere(prim)) {
    test_primitive(prims, prim, ray, hit, tally);
    return;
  }
  ++tally.triangles;
  float t, b1 = 0, b2 = 0;
  if (triangle_test_quickly(prims.triangle(prim), ray, TriangleRejectRay(ray), hit.t, &t, &b1, &b2))
    hit.offer(t, prim, b1, b2);
}

void intersect_brute_force(const PrimitiveArrays& prims, const Ray& ray, Hit& hit, TestTally& tally) {
  for (int p = 0; p < prims.prim_count(); ++p) test_primitive(prims, p, ray, hit, tally);
}

}  // namespace gcsim::geometry
