#include "apps/raytrace/subtree.hpp"

#include "apps/raytrace/plane_classification4.hpp"

namespace gcsim::raytrace {
namespace {

struct FilterPass {
  const Bvh& bvh;
  const Plane* planes;  // two
  PlaneFilteredTree& out;
  std::int64_t tests = 0;

  const Bounds3& box(NodeRef r) const { return is_primitive(r) ? bvh.prim_bounds[primitive_of(r)] : bvh.nodes[r].box; }

  // Returns the entry index, or -1 when r lies outside a plane.
  int visit(NodeRef r, std::uint8_t inside) {
    const BoxCentre b(box(r));
    for (int i = 0; i < 2; ++i) {
      if (inside & (1u << i)) continue;
      ++tests;
      const Side s = classify(b, planes[i], abs_components(planes[i].normal));
      if (s == Side::outside) return -1;
      if (s == Side::inside) inside |= (1u << i);
    }
    const int at = static_cast<int>(out.entries.size());
    out.entries.push_back({r, inside, {-1, -1}, b});
    if (!is_primitive(r)) {
      const int c0 = visit(bvh.nodes[r].child[0], inside);
      const int c1 = visit(bvh.nodes[r].child[1], inside);
      if (c0 < 0 && c1 < 0) {
        out.entries.resize(at);  // nothing below survives: drop the node too
        return -1;
      }
      out.entries[at].child[0] = c0;
      out.entries[at].child[1] = c1;
    }
    return at;
  }
};

struct SubtreePass {
  const Bvh& bvh;
  const PlaneFilteredTree& row;
  const Plane* planes;  // two
  Subtree& out;
  std::int64_t tests = 0;
  // Both planes classified in one pass (lanes 2 and 3 repeat them); counted as one at a time.
  FourPlanes both{{planes[0], planes[1], planes[0], planes[1]}};

  // Returns true and sets *ref when something of entry e lies inside both planes.
  bool visit(int e, std::uint8_t inside, NodeRef* ref) {
    const auto& entry = row.entries[e];
    if ((inside & 3u) != 3u) {
      unsigned in, out_bits;
      both.sides(entry.box, in, out_bits);
      for (int i = 0; i < 2; ++i) {
        if (inside & (1u << i)) continue;
        ++tests;
        if (out_bits >> i & 1u) return false;  // plane 1 is not tested after plane 0 drops the box
        if (in >> i & 1u) inside |= (1u << i);
      }
    }
    if (is_primitive(entry.ref)) {
      *ref = entry.ref;
      ++out.primitive_count;
      return true;
    }
    NodeRef c[2];
    bool has[2] = {false, false};
    for (int i = 0; i < 2; ++i)
      if (entry.child[i] >= 0) has[i] = visit(entry.child[i], inside, &c[i]);
    if (!has[0] && !has[1]) return false;
    if (!has[0] || !has[1]) {  // figure 2: a node with one child is replaced by the child
      *ref = has[0] ? c[0] : c[1];
      return true;
    }
    out.nodes.push_back({bvh.nodes[entry.ref].box, {c[0], c[1]}});
    *ref = static_cast<NodeRef>(out.nodes.size() - 1);
    return true;
  }
};

}  // namespace

void filter_by_two_planes(const Bvh& bvh, const Plane& a, const Plane& b, PlaneFilteredTree& out, TraceCounters& counters) {
  out.entries.clear();
  const Plane planes[2] = {a, b};
  FilterPass pass{bvh, planes, out};
  out.root = pass.visit(bvh.root, 0);
  counters.plane_tests += pass.tests;
  counters.subtree_nodes += static_cast<std::int64_t>(out.entries.size());
}

void subtree_from_filtered(const Bvh& bvh, const PlaneFilteredTree& row, const Plane& c, const Plane& d, Subtree& out,
                           TraceCounters& counters) {
  out.nodes.clear();
  out.empty = true;
  out.primitive_count = 0;
  out.packed.empty = true;
  if (row.root < 0) return;
  const Plane planes[2] = {c, d};
  SubtreePass pass{bvh, row, planes, out};
  NodeRef root;
  if (pass.visit(row.root, 0, &root)) {
    out.root = root;
    out.empty = false;
  }
  counters.plane_tests += pass.tests;
  counters.subtree_nodes += static_cast<std::int64_t>(out.nodes.size());
  pack_tree(out.nodes, out.root, out.empty, bvh.prim_bounds, out.packed);
}

void build_subtree(const Bvh& bvh, const std::array<Plane, 4>& planes, Subtree& out, TraceCounters& counters) {
  PlaneFilteredTree filtered;
  filter_by_two_planes(bvh, planes[0], planes[1], filtered, counters);
  subtree_from_filtered(bvh, filtered, planes[2], planes[3], out, counters);
}

std::array<Plane, 4> pyramid_planes(const Camera& camera, int x0, int y0, int x1, int y1) {
  return {camera.row_plane(y0), flipped(camera.row_plane(y1)), camera.column_plane(x0), flipped(camera.column_plane(x1))};
}

}  // namespace gcsim::raytrace
