#include "machine/topology.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <stdexcept>
#include <string>

#include "machine/machine_config.hpp"

namespace gcsim::machine {

TopologyKind parse_topology_kind(std::string_view s) {
  if (s == "mesh") return TopologyKind::mesh;
  if (s == "torus") return TopologyKind::torus;
  if (s == "ring") return TopologyKind::ring;
  if (s == "tree") return TopologyKind::tree;
  if (s == "hypercube") return TopologyKind::hypercube;
  throw std::invalid_argument("unknown topology '" + std::string(s) + "' (expected one of: " + std::string(kTopologyNames) + ")");
}

std::string_view to_string(TopologyKind k) {
  switch (k) {
    case TopologyKind::mesh: return "mesh";
    case TopologyKind::torus: return "torus";
    case TopologyKind::ring: return "ring";
    case TopologyKind::tree: return "tree";
    case TopologyKind::hypercube: return "hypercube";
  }
  return "?";
}

namespace {

void add_edge(VirtualTopology& t, int a, int b) {
  if (a == b) return;
  t.neighbours[a].push_back(b);
  t.neighbours[b].push_back(a);
}

bool is_power_of_two(int n) { return n > 0 && (n & (n - 1)) == 0; }

}  // namespace

VirtualTopology make_topology(TopologyKind kind, int n) {
  if (n < 1) throw std::invalid_argument("a topology needs at least one processor");
  VirtualTopology t{kind};
  t.neighbours.resize(n);
  switch (kind) {
    case TopologyKind::mesh:
    case TopologyKind::torus: {
      const MeshShape s = gc_mesh_shape(n);
      t.width = s.width;
      t.height = s.height;
      for (int y = 0; y < s.height; ++y) {
        for (int x = 0; x < s.width; ++x) {
          const int v = y * s.width + x;
          if (x + 1 < s.width) add_edge(t, v, v + 1);
          if (y + 1 < s.height) add_edge(t, v, v + s.width);
          if (kind == TopologyKind::torus) {
            if (x == s.width - 1 && s.width > 2) add_edge(t, v, y * s.width);
            if (y == s.height - 1 && s.height > 2) add_edge(t, v, x);
          }
        }
      }
      break;
    }
    case TopologyKind::ring:
      for (int v = 0; v + 1 < n; ++v) add_edge(t, v, v + 1);
      if (n > 2) add_edge(t, n - 1, 0);
      break;
    case TopologyKind::tree:
      for (int v = 1; v < n; ++v) add_edge(t, v, (v - 1) / 2);
      break;
    case TopologyKind::hypercube:
      if (!is_power_of_two(n)) {
        throw std::invalid_argument("a hypercube needs a power-of-two processor count, not " + std::to_string(n));
      }
      for (int v = 0; v < n; ++v) {
        for (int bit = 1; bit < n; bit <<= 1) {
          if ((v ^ bit) > v) add_edge(t, v, v ^ bit);
        }
      }
      break;
  }
  for (auto& nb : t.neighbours) {
    std::sort(nb.begin(), nb.end());
    nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
  }
  return t;
}

TopologyMetrics exact_metrics(const VirtualTopology& t) {
  const int n = t.size();
  TopologyMetrics m;
  if (n < 2) return m;
  // Brandes: BFS from every source gives distances and shortest-path counts; the dependency
  // accumulation gives each vertex's betweenness over ordered pairs (halved below).
  std::vector<double> betweenness(n, 0.0);
  double distance_sum = 0;
  int diameter = 0;
  int radius = std::numeric_limits<int>::max();
  std::vector<int> dist(n), order;
  std::vector<double> sigma(n), delta(n);
  order.reserve(n);
  for (int s = 0; s < n; ++s) {
    std::fill(dist.begin(), dist.end(), -1);
    std::fill(sigma.begin(), sigma.end(), 0.0);
    std::fill(delta.begin(), delta.end(), 0.0);
    order.clear();
    dist[s] = 0;
    sigma[s] = 1;
    std::deque<int> queue{s};
    while (!queue.empty()) {
      const int v = queue.front();
      queue.pop_front();
      order.push_back(v);
      for (int w : t.neighbours[v]) {
        if (dist[w] < 0) {
          dist[w] = dist[v] + 1;
          queue.push_back(w);
        }
        if (dist[w] == dist[v] + 1) sigma[w] += sigma[v];
      }
    }
    if (static_cast<int>(order.size()) != n) throw std::logic_error("topology graph is not connected");
    int eccentricity = 0;
    for (int v = 0; v < n; ++v) {
      distance_sum += dist[v];
      eccentricity = std::max(eccentricity, dist[v]);
    }
    diameter = std::max(diameter, eccentricity);
    radius = std::min(radius, eccentricity);
    for (auto it = order.rbegin(); it != order.rend(); ++it) {
      const int w = *it;
      for (int v : t.neighbours[w]) {
        if (dist[v] == dist[w] - 1) delta[v] += sigma[v] / sigma[w] * (1.0 + delta[w]);
      }
      if (w != s) betweenness[w] += delta[w];
    }
  }
  double edges = 0;
  for (const auto& nb : t.neighbours) edges += static_cast<double>(nb.size());
  m.D = diameter;
  m.d = distance_sum / (double(n) * (n - 1));
  m.R = 0;
  m.r = 0;
  for (double b : betweenness) {
    m.R = std::max(m.R, b / 2);
    m.r += b / 2;
  }
  m.r /= n;
  m.k = edges / n;
  m.B = radius;
  return m;
}

TopologyMetrics thesis_formulas(TopologyKind kind, int n) {
  const double N = n;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  switch (kind) {
    case TopologyKind::mesh:  // eqs. 2.1-2.6
      return {2 * std::sqrt(N), 2.0 / 3.0 * std::sqrt(N), std::sqrt(N * N * N) / 2, std::sqrt(N * N * N) / 3, 4,
              std::sqrt(N)};
    case TopologyKind::tree:  // eqs. 2.8-2.12
      return {2 * std::log2(N), 2 * std::log2(N), 5.0 / 16.0 * N * N, N * std::log2(N), 2, 2 * std::log2(N)};
    case TopologyKind::hypercube:  // eqs. 2.13-2.17
      return {std::log2(N), std::log2(N) / 2, N * std::log2(N) / 4, N * std::log2(N) / 4, std::log2(N), std::log2(N)};
    case TopologyKind::torus:
    case TopologyKind::ring:
      return {nan, nan, nan, nan, nan, nan};
  }
  return {};
}

namespace {

// Position i of a ring of length len folded so that neighbours, including the wrap, are <= 2 apart.
int fold(int i, int len) { return i < (len + 1) / 2 ? 2 * i : 2 * (len - 1 - i) + 1; }

// Mesh nodes in the order of a Hamiltonian cycle (height even, or width even by symmetry), or of a
// boustrophedon path when neither dimension is even.
std::vector<int> ring_order(const Mesh& mesh, int n) {
  const int w = mesh.width(), h = mesh.height();
  std::vector<int> order;
  if (n != w * h) {
    for (int v = 0; v < n; ++v) order.push_back(v);
    return order;
  }
  auto walk = [&](bool transpose) {
    const int W = transpose ? h : w, H = transpose ? w : h;
    auto at = [&](int x, int y) { return transpose ? mesh.node_at(y, x) : mesh.node_at(x, y); };
    std::vector<int> o;
    for (int y = 0; y < H; ++y) {
      if (y % 2 == 0) {
        for (int x = (y == 0 ? 0 : 1); x < W; ++x) o.push_back(at(x, y));
      } else {
        for (int x = W - 1; x >= 1; --x) o.push_back(at(x, y));
      }
    }
    for (int y = H - 1; y >= 1; --y) o.push_back(at(0, y));
    return o;
  };
  if (w >= 2 && h >= 2 && h % 2 == 0) return walk(false);
  if (w >= 2 && h >= 2 && w % 2 == 0) return walk(true);
  for (int y = 0; y < h; ++y) {
    for (int i = 0; i < w; ++i) order.push_back(mesh.node_at(y % 2 == 0 ? i : w - 1 - i, y));
  }
  return order;
}

}  // namespace

MeshMapping map_onto_mesh(const VirtualTopology& t, const Mesh& mesh) {
  const int n = t.size();
  if (n > mesh.nodes()) throw std::invalid_argument("topology has more processors than the mesh has nodes");
  MeshMapping m;
  m.node_of.resize(n);
  switch (t.kind) {
    case TopologyKind::mesh:
    case TopologyKind::torus:
      for (int v = 0; v < n; ++v) {
        int x = v % t.width, y = v / t.width;
        if (t.kind == TopologyKind::torus) {
          x = fold(x, t.width);
          y = fold(y, t.height);
        }
        if (t.width <= mesh.width() && t.height <= mesh.height()) m.node_of[v] = mesh.node_at(x, y);
        else m.node_of[v] = mesh.node_at(y, x);  // the virtual grid is the turned physical one
      }
      break;
    case TopologyKind::ring: {
      const std::vector<int> order = ring_order(mesh, n);
      for (int v = 0; v < n; ++v) m.node_of[v] = order[v];
      break;
    }
    case TopologyKind::tree:
      for (int v = 0; v < n; ++v) m.node_of[v] = v;
      break;
    case TopologyKind::hypercube: {
      int xbits = 0;
      while ((1 << (xbits + 1)) <= mesh.width() && (1 << (xbits + 1)) <= n) ++xbits;
      const int xmask = (1 << xbits) - 1;
      for (int v = 0; v < n; ++v) m.node_of[v] = mesh.node_at(v & xmask, v >> xbits);
      break;
    }
  }
  std::vector<int> load(mesh.channel_count(), 0);
  std::vector<int> route;
  double hop_sum = 0;
  int edges = 0;
  for (int v = 0; v < n; ++v) {
    for (int w : t.neighbours[v]) {
      mesh.route(m.node_of[v], m.node_of[w], route);
      for (int ch : route) m.congestion = std::max(m.congestion, ++load[ch]);
      m.dilation = std::max(m.dilation, static_cast<int>(route.size()));
      hop_sum += static_cast<double>(route.size());
      ++edges;
    }
  }
  m.mean_dilation = edges ? hop_sum / edges : 0;
  return m;
}

}  // namespace gcsim::machine
