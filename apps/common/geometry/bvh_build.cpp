#include "apps/common/geometry/bvh.hpp"

#include <algorithm>
#include <numeric>
#include <functional>

#include "apps/common/geometry/primitive_arrays.hpp"

namespace gcsim::geometry {
namespace {

constexpr std::size_t kClusterGroupSize = 2048;
// Clustering ties on coincident primitives (one face repeated) and then chains them into a tree
// as deep as the group is large; the subtree walks recurse on fiber stacks. A group clustered
// deeper than this is split at medians instead (depth log2 of the group), so every tree is at
// most this plus log2(n / kClusterGroupSize) deep. The built-in scenes' groups stay below it.
constexpr int kMaxClusterDepth = 64;

// 2 (xy + yz + zx) of the box's extent, in double. Float extents of finite boxes are at most
// 2 * FLT_MAX (finite in double), their products at most ~1e77 and at least ~1e-90: neither
// overflows nor underflows, so the clustering compares real areas on any finite geometry.
double surface_area_in_double(const Bounds3& b) {
  if (b.empty()) return 0.0;
  const double x = double(b.hi.x) - double(b.lo.x), y = double(b.hi.y) - double(b.lo.y),
               z = double(b.hi.z) - double(b.lo.z);
  return 2.0 * (x * y + y * z + z * x);
}

struct Builder {
  std::vector<BvhNode> nodes;  // in creation order
  const std::vector<Bounds3>* prim_bounds = nullptr;
  bool areas_in_double = false;  // see float_areas_suffice

  Bounds3 bounds_of(NodeRef r) const {
    return is_primitive(r) ? (*prim_bounds)[primitive_of(r)] : nodes[r].box;
  }
  NodeRef make_node(NodeRef a, NodeRef b) {
    nodes.push_back({union_of(bounds_of(a), bounds_of(b)), {a, b}});
    return static_cast<NodeRef>(nodes.size() - 1);
  }

  // Agglomerative clustering of the given subtrees with nearest-neighbour chains.
  NodeRef cluster(std::vector<NodeRef> refs) {
    struct Cluster { Bounds3 box; NodeRef ref; };
    std::vector<Cluster> pool;
    pool.reserve(refs.size() * 2);
    std::vector<int> active;
    for (NodeRef r : refs) {
      active.push_back(static_cast<int>(pool.size()));
      pool.push_back({bounds_of(r), r});
    }
    std::vector<int> position(pool.capacity(), -1);
    for (std::size_t i = 0; i < active.size(); ++i) position[active[i]] = static_cast<int>(i);
    auto remove = [&](int c) {
      const int at = position[c];
      active[at] = active.back();
      position[active[at]] = at;
      active.pop_back();
      position[c] = -1;
    };
    auto cost = [&](int a, int b) {
      const Bounds3 u = union_of(pool[a].box, pool[b].box);
      return areas_in_double ? surface_area_in_double(u) : double(u.surface_area());
    };

    std::vector<int> chain;
    while (active.size() > 1) {
      if (chain.empty()) chain.push_back(active.front());
      const int a = chain.back();
      const int prev = chain.size() >= 2 ? chain[chain.size() - 2] : -1;
      // Keeping prev on ties guarantees the chain ends in a reciprocal pair. A chain of one
      // always takes a neighbour, whatever the costs, so it can never pop what it does not hold.
      int best = prev;
      double best_cost = prev >= 0 ? cost(a, prev) : 0.0;
      for (int c : active) {
        if (c == a || c == prev) continue;
        const double d = cost(a, c);
        if (best < 0 || d < best_cost) { best_cost = d; best = c; }
      }
      if (best == prev) {
        chain.pop_back();
        chain.pop_back();
        remove(a);
        remove(prev);
        const NodeRef merged = make_node(pool[prev].ref, pool[a].ref);
        const int c = static_cast<int>(pool.size());
        pool.push_back({nodes[merged].box, merged});
        position[c] = static_cast<int>(active.size());
        active.push_back(c);
      } else {
        chain.push_back(best);
      }
    }
    return pool[active.front()].ref;
  }

  // Top-down median splits until groups are small enough to cluster.
  NodeRef build(std::vector<int>& prims, std::size_t begin, std::size_t end, const std::vector<glm::vec3>& centroid) {
    if (end - begin <= kClusterGroupSize) {
      std::vector<NodeRef> refs;
      for (std::size_t i = begin; i < end; ++i) refs.push_back(primitive_ref(prims[i]));
      const std::size_t first_node = nodes.size();
      const NodeRef clustered = cluster(std::move(refs));
      if (depth_of_new_nodes(first_node) <= kMaxClusterDepth) return clustered;
      nodes.resize(first_node);
      return split_at_medians(prims, begin, end, centroid, 1);
    }
    return split_at_medians(prims, begin, end, centroid, kClusterGroupSize);
  }

  // Depth of the subtree the nodes from `first` on form; children precede their parents.
  int depth_of_new_nodes(std::size_t first) const {
    std::vector<int> depth(nodes.size() - first, 1);
    int deepest = 0;
    for (std::size_t i = first; i < nodes.size(); ++i) {
      for (NodeRef c : nodes[i].child)
        if (!is_primitive(c)) depth[i - first] = std::max(depth[i - first], depth[c - first] + 1);
      deepest = std::max(deepest, depth[i - first]);
    }
    return deepest;
  }

  // Median split on the centroids' widest axis (ties by index, so coincident primitives halve
  // too); groups of at most `leaf_group` are clustered, or become a primitive when it is 1.
  NodeRef split_at_medians(std::vector<int>& prims, std::size_t begin, std::size_t end,
                           const std::vector<glm::vec3>& centroid, std::size_t leaf_group) {
    if (leaf_group == 1 && end - begin == 1) return primitive_ref(prims[begin]);
    Bounds3 cb;
    for (std::size_t i = begin; i < end; ++i) cb.extend(centroid[prims[i]]);
    const glm::vec3 e = cb.extent();
    const int axis = e.x > e.y ? (e.x > e.z ? 0 : 2) : (e.y > e.z ? 1 : 2);
    const std::size_t mid = (begin + end) / 2;
    std::nth_element(prims.begin() + begin, prims.begin() + mid, prims.begin() + end, [&](int a, int b) {
      return centroid[a][axis] < centroid[b][axis] || (centroid[a][axis] == centroid[b][axis] && a < b);
    });
    const auto half = [&](std::size_t b, std::size_t e) {
      return leaf_group == 1 ? split_at_medians(prims, b, e, centroid, 1) : build(prims, b, e, centroid);
    };
    const NodeRef l = half(begin, mid);
    const NodeRef r = half(mid, end);
    return make_node(l, r);
  }
};

int depth_of(const Bvh& bvh, NodeRef r) {
  if (is_primitive(r)) return 0;
  return 1 + std::max(depth_of(bvh, bvh.nodes[r].child[0]), depth_of(bvh, bvh.nodes[r].child[1]));
}

// Float areas of every union box stay finite and normal when the scene's extent is within these
// bounds (areas up to ~1e37, down to ~1e-30): then the clustering keeps float areas, the trees
// the figures were recorded with. Outside them (a vertex at 1e23, a scene 1e-30 across) float
// areas overflow to infinity or underflow to zero and tie everything, so they are taken in double.
bool float_areas_suffice(const std::vector<Bounds3>& prim_bounds) {
  Bounds3 all;
  for (const Bounds3& b : prim_bounds) all.extend(b);
  const double x = double(all.hi.x) - double(all.lo.x), y = double(all.hi.y) - double(all.lo.y),
               z = double(all.hi.z) - double(all.lo.z);
  const double extent = std::max({x, y, z});
  return extent >= 1e-15 && extent <= 1e18;
}

}  // namespace

int Bvh::depth() const { return depth_of(*this, root); }

Bvh build_bvh_by_clustering(const PrimitiveArrays& primitives) {
  Bvh bvh;
  const int n = primitives.prim_count();
  bvh.prim_bounds.resize(n);
  std::vector<glm::vec3> centroid(n);
  for (int i = 0; i < n; ++i) {
    bvh.prim_bounds[i] = primitives.prim_bounds(i);
    // Halves first: lo + hi overflows for boxes near FLT_MAX; halving is exact otherwise.
    centroid[i] = 0.5f * bvh.prim_bounds[i].lo + 0.5f * bvh.prim_bounds[i].hi;
  }
  Builder b;
  b.prim_bounds = &bvh.prim_bounds;
  b.areas_in_double = n > 0 && !float_areas_suffice(bvh.prim_bounds);
  std::vector<int> prims(n);
  std::iota(prims.begin(), prims.end(), 0);
  const NodeRef root = n == 0 ? primitive_ref(0) : b.build(prims, 0, prims.size(), centroid);
  if (is_primitive(root)) {
    bvh.root = root;
    pack_tree(bvh.nodes, bvh.root, false, bvh.prim_bounds, bvh.packed);
    return bvh;
  }
  // Lay the nodes out depth-first, so a descent walks forward through memory.
  bvh.nodes.reserve(b.nodes.size());
  std::function<NodeRef(NodeRef)> copy = [&](NodeRef r) -> NodeRef {
    if (is_primitive(r)) return r;
    const NodeRef at = static_cast<NodeRef>(bvh.nodes.size());
    bvh.nodes.push_back(b.nodes[r]);
    const NodeRef c0 = copy(b.nodes[r].child[0]);
    const NodeRef c1 = copy(b.nodes[r].child[1]);
    bvh.nodes[at].child[0] = c0;
    bvh.nodes[at].child[1] = c1;
    return at;
  };
  bvh.root = copy(root);
  pack_tree(bvh.nodes, bvh.root, false, bvh.prim_bounds, bvh.packed);
  return bvh;
}

}  // namespace gcsim::geometry
