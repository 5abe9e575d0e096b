#include "apps/raytrace/traversal.hpp"

#include <algorithm>

namespace gcsim::raytrace {
namespace {

constexpr int kStackSize = 256;  // clustered trees of the built-in scenes are < 64 deep

// Slab test of child c of n (see intersect_box for the conservative rounding and NaN handling:
// the comparisons below drop a NaN from 0 * inf, counting a slab plane the ray lies in as inside).
inline bool child_box(const PairNode& n, int c, const Ray& r, float tmax, float* entry) {
  float t0 = r.tmin, t1 = tmax;
  for (int a = 0; a < 3; ++a) {
    const float tn = (n.bounds[r.near_plane[a]][c] - r.origin[a]) * r.inv_direction[a];
    const float tf = (n.bounds[r.far_plane[a]][c] - r.origin[a]) * r.inv_direction[a] * (1.0f + 2.0f * gamma(3));
    t0 = tn > t0 ? tn : t0;
    t1 = tf < t1 ? tf : t1;
  }
  *entry = t0 * (1.0f - 2.0f * gamma(3));
  return t0 <= t1;
}

}  // namespace

void traverse_unordered(const Scene& scene, const PackedTree& tree, const Ray& ray, Hit& hit, TestTally& tally) {
  if (tree.empty) return;
  if (is_primitive(tree.root)) {
    test_primitive(scene, primitive_of(tree.root), ray, hit, tally);
    return;
  }
  float entry;
  ++tally.boxes;
  if (!intersect_box(tree.root_box, ray, kInfinity, &entry)) return;
  NodeRef stack[kStackSize];
  int top = 0;
  stack[top++] = tree.root;
  while (top > 0) {
    const PairNode& n = tree.nodes[stack[--top]];
    for (int i = 1; i >= 0; --i) {  // push the second child first: the first is visited first
      const NodeRef c = n.child[i];
      if (is_primitive(c)) {
        test_primitive(scene, primitive_of(c), ray, hit, tally);
      } else {
        ++tally.boxes;
        if (child_box(n, i, ray, kInfinity, &entry) && top < kStackSize) stack[top++] = c;
      }
    }
  }
}

void traverse_ordered(const Scene& scene, const PackedTree& tree, const Ray& ray, Hit& hit, TestTally& tally) {
  if (tree.empty) return;
  if (is_primitive(tree.root)) {
    test_primitive(scene, primitive_of(tree.root), ray, hit, tally);
    return;
  }
  struct Entry { NodeRef node; float entry; };
  Entry stack[kStackSize];
  int top = 0;
  float entry;
  ++tally.boxes;
  if (!intersect_box(tree.root_box, ray, hit.t, &entry)) return;
  stack[top++] = {tree.root, entry};
  while (top > 0) {
    const Entry e = stack[--top];
    if (e.entry > hit.t) continue;  // figure 3: a nearer primitive was found meanwhile
    const PairNode& n = tree.nodes[e.node];
    Entry found[2];
    int count = 0;
    for (int i = 0; i < 2; ++i) {
      const NodeRef c = n.child[i];
      if (is_primitive(c)) {
        test_primitive(scene, primitive_of(c), ray, hit, tally);
      } else {
        ++tally.boxes;
        if (child_box(n, i, ray, hit.t, &entry)) found[count++] = {c, entry};
      }
    }
    if (count == 2) {
      ++tally.sorts;  // a binary tree sorts its children with one comparison (2.2.2)
      if (found[0].entry < found[1].entry) std::swap(found[0], found[1]);
      if (top + 2 <= kStackSize) {
        stack[top++] = found[0];  // farther, visited second
        stack[top++] = found[1];
      }
    } else if (count == 1 && top < kStackSize) {
      stack[top++] = found[0];
    }
  }
}

bool traverse_any_hit(const Scene& scene, const PackedTree& tree, const Ray& ray, float tmax, TestTally& tally) {
  if (tree.empty) return false;
  if (is_primitive(tree.root)) return occludes(scene, primitive_of(tree.root), ray, tmax, tally);
  float entry;
  ++tally.boxes;
  if (!intersect_box(tree.root_box, ray, tmax, &entry)) return false;
  NodeRef stack[kStackSize];
  int top = 0;
  stack[top++] = tree.root;
  while (top > 0) {
    const PairNode& n = tree.nodes[stack[--top]];
    for (int i = 1; i >= 0; --i) {
      const NodeRef c = n.child[i];
      if (is_primitive(c)) {
        if (occludes(scene, primitive_of(c), ray, tmax, tally)) return true;
      } else {
        ++tally.boxes;
        if (child_box(n, i, ray, tmax, &entry) && top < kStackSize) stack[top++] = c;
      }
    }
  }
  return false;
}

void intersect_brute_force(const Scene& scene, const Ray& ray, Hit& hit, TestTally& tally) {
  for (int p = 0; p < scene.prim_count(); ++p) test_primitive(scene, p, ray, hit, tally);
}

}  // namespace gcsim::raytrace
