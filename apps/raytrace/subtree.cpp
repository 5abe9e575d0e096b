#include "apps/raytrace/subtree.hpp"

#include "apps/raytrace/plane_classification4.hpp"

namespace gcsim::raytrace {
namespace {

// Counts the tests of a box by the planes `inside` does not yet hold it in, from its bits of a
// two-plane classification; false if it lies outside one. Plane 1 is not tested after plane 0
// drops the box, as one scalar classify() after another would not.
constexpr bool survives_planes(unsigned in, unsigned out_bits, std::uint8_t& inside, std::int64_t& tests) {
  for (int i = 0; i < 2; ++i) {
    if (inside & (1u << i)) continue;
    ++tests;
    if (out_bits >> i & 1u) return false;
    if (in >> i & 1u) inside |= (1u << i);
  }
  return true;
}

// survives_planes for every inside mask and two-plane classification of a child, looked up where
// the subtree pass would branch on each plane: index inside | in << 2 | out << 4; the verdict holds
// the child's new inside mask in bits 0-1, its count of tests in bits 2-3 and "survives" in bit 4.
struct PlaneVerdicts {
  std::uint8_t of[64] = {};
  constexpr PlaneVerdicts() {
    for (unsigned i = 0; i < 64; ++i) {
      std::uint8_t inside = std::uint8_t(i & 3u);
      std::int64_t tests = 0;
      const bool survives = survives_planes(i >> 2 & 3u, i >> 4 & 3u, inside, tests);
      of[i] = std::uint8_t(inside | tests << 2 | unsigned(survives) << 4);
    }
  }
};
constexpr PlaneVerdicts kVerdicts;

// The box of a BVH node or of a primitive.
const Bounds3& box_of(const Bvh& bvh, NodeRef r) {
  return is_primitive(r) ? bvh.prim_bounds[primitive_of(r)] : bvh.nodes[r].box;
}

PlaneFilteredTree::ChildPair child_pair_of(const Bvh& bvh, const BvhNode& node) {
  const Bounds3& a = box_of(bvh, node.child[0]);
  const Bounds3& b = box_of(bvh, node.child[1]);
  return {BoxLanes(BoxCentre(a), BoxCentre(b)), {a, b}, {node.child[0], node.child[1]},
          {PlaneFilteredTree::kDropped, PlaneFilteredTree::kDropped}};
}

struct FilterPass {
  using Entry = PlaneFilteredTree::Entry;
  const Bvh& bvh;
  PlaneFilteredTree& out;
  const PreparedChildPairs* prepared;  // null: each node's pair worked out here
  // Both children of a node classified in one pass (lanes 2 and 3 repeat the planes).
  FourPlanes both;
  std::int64_t tests = 0;

  // The entry of r, which survives with flags `inside` and has box `bounds`; -1 when nothing
  // below it does. A node's children are classified here, both at once, in the lanes the row
  // keeps for them; a primitive child's entry is written here too, without a call.
  int visit(NodeRef r, std::uint8_t inside, const Bounds3& bounds) {
    const int at = static_cast<int>(out.entries.size());
    out.entries.push_back({r, inside, {-1, -1}, -1, bounds});
    if (is_primitive(r)) return at;
    PlaneFilteredTree::ChildPair pair = prepared ? prepared->of(r) : child_pair_of(bvh, bvh.nodes[r]);
    unsigned in = 0, out_bits = 0;  // not read when the node is inside both planes
    if ((inside & 3u) != 3u) both.sides(pair.lanes, in, out_bits);
    const std::size_t lanes_before = out.children.size();
    int c[2];
    for (int k = 0; k < 2; ++k) {
      std::uint8_t child_inside = inside;
      c[k] = -1;
      if (!survives_planes(in >> (2 * k) & 3u, out_bits >> (2 * k) & 3u, child_inside, tests)) continue;
      if (is_primitive(pair.ref[k])) {
        c[k] = static_cast<int>(out.entries.size());
        out.entries.push_back({pair.ref[k], child_inside, {-1, -1}, -1, pair.box[k]});
      } else {
        c[k] = visit(pair.ref[k], child_inside, pair.box[k]);
      }
    }
    if (c[0] < 0 && c[1] < 0) {
      out.entries.resize(at);  // nothing below survives: drop the node too
      out.children.erase(out.children.begin() + std::ptrdiff_t(lanes_before), out.children.end());
      return -1;
    }
    Entry& e = out.entries[at];
    e.child[0] = c[0];
    e.child[1] = c[1];
    e.children = static_cast<int>(out.children.size());
    for (int k = 0; k < 2; ++k)
      if (c[k] >= 0) pair.pair[k] = is_primitive(pair.ref[k]) ? PlaneFilteredTree::kPrimitive : out.entries[c[k]].children;
    out.children.push_back(pair);  // a dropped child's lanes are classified, never read
    return at;
  }
};

struct SubtreePass {
  using ChildPair = PlaneFilteredTree::ChildPair;
  const PlaneFilteredTree& row;
  const Plane* planes;  // two
  PackedTree& out;
  std::int64_t tests = 0;
  // Both planes classified in one pass (lanes 2 and 3 repeat them); counted as one at a time.
  FourPlanes both{{planes[0], planes[1], planes[0], planes[1]}};

  // What survives of a node: the root of its part of the subtree (a node of `out` or a
  // primitive) and the box that bounds that part; box null when nothing does.
  struct Part {
    NodeRef ref;
    const Bounds3* box;
  };

  // The part of the node whose children are pair p and whose box is `box`, the node surviving with
  // flags `inside`. Both
  // children are classified here at once, so that a child outside a plane, or a primitive, costs
  // no call; what the pass needs of a child is in the pair, so it reads no entry.
  Part visit(int p, std::uint8_t inside, const Bounds3* box) {
    const ChildPair& pair = row.children[p];
    unsigned in = 0, out_bits = 0;  // not read when the node is inside both planes
    if ((inside & 3u) != 3u) both.sides(pair.lanes, in, out_bits);
    Part c[2] = {{0, nullptr}, {0, nullptr}};
    for (int k = 0; k < 2; ++k) {
      const std::int32_t below = pair.pair[k];
      if (below == PlaneFilteredTree::kDropped) continue;
      const unsigned verdict = kVerdicts.of[(inside & 3u) | (in >> (2 * k) & 3u) << 2 | (out_bits >> (2 * k) & 3u) << 4];
      tests += verdict >> 2 & 3u;
      if (!(verdict & 16u)) continue;
      c[k] = below == PlaneFilteredTree::kPrimitive ? Part{pair.ref[k], &pair.box[k]}
                                                    : visit(below, std::uint8_t(verdict & 3u), &pair.box[k]);
    }
    const Part& c0 = c[0];
    const Part& c1 = c[1];
    // Figure 2: a node left with one child is replaced by the child.
    if (!c0.box) return c1;
    if (!c1.box) return c0;
    PairNode& n = out.nodes.emplace_back();
    set_child_boxes(n, *c0.box, *c1.box);
    n.child[0] = c0.ref;
    n.child[1] = c1.ref;
    return {static_cast<NodeRef>(out.nodes.size() - 1), box};
  }
};

}  // namespace

PreparedChildPairs::PreparedChildPairs(const Bvh& bvh) {
  pairs_.reserve(bvh.nodes.size());
  for (const BvhNode& node : bvh.nodes) pairs_.push_back(child_pair_of(bvh, node));
}

void filter_by_two_planes(const Bvh& bvh, const Plane& a, const Plane& b, PlaneFilteredTree& out, TraceCounters& counters,
                          const PreparedChildPairs* prepared) {
  out.entries.clear();
  out.children.clear();
  FilterPass pass{bvh, out, prepared, FourPlanes({a, b, a, b})};
  out.root_box = BoxCentre(box_of(bvh, bvh.root));
  std::uint8_t inside = 0;
  unsigned in, out_bits;
  pass.both.sides(out.root_box, in, out_bits);
  out.root = survives_planes(in, out_bits, inside, pass.tests) ? pass.visit(bvh.root, inside, box_of(bvh, bvh.root)) : -1;
  counters.plane_tests += pass.tests;
  counters.subtree_nodes += static_cast<std::int64_t>(out.entries.size());
}

void subtree_from_filtered(const PlaneFilteredTree& row, const Plane& c, const Plane& d, Subtree& out,
                           TraceCounters& counters) {
  out.packed.nodes.clear();
  out.empty = out.packed.empty = true;
  out.root = out.packed.root = 0;
  if (row.root < 0) return;
  const Plane planes[2] = {c, d};
  SubtreePass pass{row, planes, out.packed};
  std::uint8_t inside = 0;
  unsigned in, out_bits;
  pass.both.sides(row.root_box, in, out_bits);
  SubtreePass::Part root{0, nullptr};
  if (survives_planes(in, out_bits, inside, pass.tests)) {
    const PlaneFilteredTree::Entry& top = row.entries[row.root];
    root = is_primitive(top.ref) ? SubtreePass::Part{top.ref, &top.bounds} : pass.visit(top.children, inside, &top.bounds);
  }
  if (root.box) {
    out.root = out.packed.root = root.ref;
    out.empty = out.packed.empty = false;
    out.packed.root_box = *root.box;
  }
  counters.plane_tests += pass.tests;
  counters.subtree_nodes += static_cast<std::int64_t>(out.packed.nodes.size());
}

void build_subtree(const Bvh& bvh, const std::array<Plane, 4>& planes, Subtree& out, TraceCounters& counters) {
  PlaneFilteredTree filtered;
  filter_by_two_planes(bvh, planes[0], planes[1], filtered, counters);
  subtree_from_filtered(filtered, planes[2], planes[3], out, counters);
}

std::array<Plane, 4> pyramid_planes(const Camera& camera, int x0, int y0, int x1, int y1) {
  return {camera.row_plane(y0), flipped(camera.row_plane(y1)), camera.column_plane(x0), flipped(camera.column_plane(x1))};
}

}  // namespace gcsim::raytrace
