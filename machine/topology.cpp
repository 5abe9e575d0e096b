#include "machine/topology.hpp"

#include <algorithm>
#include <deque>
#include <limits>
#include <stdexcept>
#include <string>

#include "machine/registry.hpp"

namespace gcsim::machine {

// ---- registry ------------------------------------------------------------------------------------

namespace {

// Each file of machine/topologies/ adds its family with a TopologyRegistrar.
struct TopologyEntry {
  std::string_view name;
  const TopologyFamily* family;
  int order;
};
Registry<TopologyEntry>& topology_registry() { return Registry<TopologyEntry>::instance(); }

}  // namespace

TopologyRegistrar::TopologyRegistrar(const TopologyFamily& family, int order) {
  topology_registry().add({family.name(), &family, order});
}

std::vector<const TopologyFamily*> topology_families() {
  std::vector<const TopologyFamily*> families;
  for (const TopologyEntry& e : topology_registry().entries()) families.push_back(e.family);
  return families;
}

std::vector<std::string> topology_names() { return topology_registry().names(); }

std::string topology_name_list() { return topology_registry().list(); }

const TopologyFamily& topology_family(std::string_view name) {
  if (const TopologyEntry* e = topology_registry().find(name)) return *e->family;
  throw std::invalid_argument("unknown topology '" + std::string(name) + "' (expected one of: " + topology_name_list() + ")");
}

TopologyKind parse_topology_kind(std::string_view s) { return topology_family(s).name(); }

TopologyMetrics TopologyFamily::thesis_formulas(int) const {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return {nan, nan, nan, nan, nan, nan};
}

VirtualTopology make_topology(TopologyKind kind, int n) {
  const TopologyFamily& family = topology_family(kind);
  if (n < 1) throw std::invalid_argument("a topology needs at least one processor");
  return family.graph(n);
}

TopologyMetrics thesis_formulas(TopologyKind kind, int n) { return topology_family(kind).thesis_formulas(n); }

void VirtualTopology::add_edge(int a, int b) {
  if (a == b) return;
  neighbours[a].push_back(b);
  neighbours[b].push_back(a);
}

void VirtualTopology::finish() {
  for (auto& nb : neighbours) {
    std::sort(nb.begin(), nb.end());
    nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
  }
}

// ---- parameters ----------------------------------------------------------------------------------

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

// ---- mapping -------------------------------------------------------------------------------------

PhysicalMapping map_onto(const VirtualTopology& t, const Interconnect& net) {
  const int n = t.size();
  if (n > net.nodes()) throw std::invalid_argument("topology has more processors than the " + std::string(net.name()) + " has nodes");
  PhysicalMapping m;
  m.node_of = topology_family(t.kind).placement(t, net);
  for (int node : m.node_of) {
    if (node < 0 || node >= net.nodes()) {
      throw std::invalid_argument("the " + std::string(t.kind) + " placement does not fit the " + std::to_string(net.width()) +
                                  "x" + std::to_string(net.height()) + " " + std::string(net.name()));
    }
  }
  std::vector<int> load(net.channel_count(), 0);
  std::vector<int> route;
  double hop_sum = 0;
  int edges = 0;
  for (int v = 0; v < n; ++v) {
    for (int w : t.neighbours[v]) {
      net.route(m.node_of[v], m.node_of[w], route);
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
