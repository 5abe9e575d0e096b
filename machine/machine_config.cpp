#include "machine/machine_config.hpp"

#include <cmath>
#include <fstream>
#include <set>
#include <tuple>
#include <utility>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "machine/builtin_machines.hpp"
#include "machine/config_inheritance.hpp"
#include "machine/input_file.hpp"
#include "machine/interconnect.hpp"
#include "machine/interconnect_registry.hpp"
#include "machine/network_registry.hpp"

namespace gcsim::machine {

namespace {
// "file:line: what" built by appending: GCC 12 warns falsely (-Wrestrict) on ":" + std::string&&.
std::string located(const std::string& f, int l, const std::string& what) {
  std::string s = f;
  if (l > 0) s.append(":").append(std::to_string(l));
  return s.append(": ").append(what);
}
}  // namespace

ConfigError::ConfigError(const std::string& f, int l, const std::string& what)
    : std::runtime_error(located(f, l, what)), file(f), line(l) {}

namespace {

class Reader {
 public:
  Reader(const toml::table& root, std::string source) : root_(root), source_(std::move(source)) {}

  int line_of(const toml::node& n) const { return static_cast<int>(n.source().begin.line); }

  // Names the file the node came from: after inheritance (config_inheritance.hpp) a key may come
  // from the file or from one of its bases.
  [[noreturn]] void fail(const toml::node* n, const std::string& what) const {
    const auto& path = n ? n->source().path : nullptr;
    throw ConfigError(path ? *path : source_, n ? line_of(*n) : 0, what);
  }

  const toml::table& table(const toml::table& parent, std::string_view key, bool required = true) const {
    static const toml::table empty;
    const toml::node* n = parent.get(key);
    if (!n) {
      if (required) fail(&parent, "missing table [" + std::string(key) + "]");
      return empty;
    }
    if (!n->is_table()) fail(n, "'" + std::string(key) + "' must be a table");
    return *n->as_table();
  }

  // Rejects keys the format does not know, so a typo cannot silently fall back to a default.
  void only_keys(const toml::table& t, const std::string& where, std::initializer_list<std::string_view> keys) const {
    const std::set<std::string_view> known(keys);
    for (const auto& [k, v] : t) {
      if (!known.count(k.str())) {
        std::string list;
        for (auto key : keys) list += (list.empty() ? "" : ", ") + std::string(key);
        fail(&v, "unknown key '" + std::string(k.str()) + "' in " + where + " (expected one of: " + list + ")");
      }
    }
  }

  double number(const toml::table& t, std::string_view key, const std::string& where, double lo, double hi,
                std::optional<double> fallback = std::nullopt) const {
    const toml::node* n = t.get(key);
    if (!n) {
      if (fallback) return *fallback;
      fail(&t, "missing key '" + std::string(key) + "' in " + where);
    }
    double v;
    if (auto i = n->as_integer()) v = static_cast<double>(i->get());
    else if (auto f = n->as_floating_point()) v = f->get();
    else fail(n, "'" + std::string(key) + "' in " + where + " must be a number");
    if (!std::isfinite(v) || v < lo || v > hi) {
      std::ostringstream os;
      os << "'" << key << "' in " << where << " is " << v << "; expected a value in [" << lo << ", " << hi << "]";
      fail(n, os.str());
    }
    return v;
  }

  int integer(const toml::table& t, std::string_view key, const std::string& where, int lo, int hi) const {
    const toml::node* n = t.get(key);
    if (!n) fail(&t, "missing key '" + std::string(key) + "' in " + where);
    auto i = n->as_integer();
    if (!i) fail(n, "'" + std::string(key) + "' in " + where + " must be an integer");
    if (i->get() < lo || i->get() > hi) {
      fail(n, "'" + std::string(key) + "' in " + where + " is " + std::to_string(i->get()) + "; expected an integer in [" +
                  std::to_string(lo) + ", " + std::to_string(hi) + "]");
    }
    return static_cast<int>(i->get());
  }

  // [width, height]: two integers in [1, 2^24], checked as 64-bit before narrowing (4294967298
  // would wrap to 2). `message` says what was expected.
  std::pair<int, int> positive_pair(const toml::node* n, const std::string& message) const {
    constexpr std::int64_t kMax = std::int64_t(1) << 24;
    const toml::array* a = n ? n->as_array() : nullptr;
    if (!a || a->size() != 2 || !a->get(0)->is_integer() || !a->get(1)->is_integer()) fail(n, message);
    const std::int64_t w = a->get(0)->as_integer()->get(), h = a->get(1)->as_integer()->get();
    if (w < 1 || h < 1 || w > kMax || h > kMax)
      fail(n, message + fmt::format(" (found [{}, {}]; each at most {})", w, h, kMax));
    return {int(w), int(h)};
  }

  std::string string(const toml::table& t, std::string_view key, const std::string& where,
                     std::optional<std::string> fallback = std::nullopt) const {
    const toml::node* n = t.get(key);
    if (!n) {
      if (fallback) return *fallback;
      fail(&t, "missing key '" + std::string(key) + "' in " + where);
    }
    auto s = n->as_string();
    if (!s) fail(n, "'" + std::string(key) + "' in " + where + " must be a string");
    return s->get();
  }

  const toml::table& root() const { return root_; }
  const std::string& source() const { return source_; }

 private:
  const toml::table& root_;
  std::string source_;
};

constexpr double kMaxMicroseconds = 1e9;

// [calibration] fitted = ["4.6", ...]: written by `gcsim calibrate`, read by `gcsim validate`.
void read_calibration(const Reader& r, const toml::table& root, MachineConfig& c) {
  const toml::table& cal = r.table(root, "calibration", false);
  r.only_keys(cal, "[calibration]", {"fitted"});
  if (const toml::node* n = cal.get("fitted")) {
    const toml::array* a = n->as_array();
    if (!a) r.fail(n, "'fitted' in [calibration] must be a list of table names, e.g. [\"4.6\"]");
    for (const auto& item : *a) {
      if (!item.is_string()) r.fail(&item, "'fitted' in [calibration] must be a list of table names, e.g. [\"4.6\"]");
      c.calibrated_on.push_back(item.as_string()->get());
    }
  }
}

// [topology.shapes]: N = [w, h], the sub-mesh `--nodes N` uses instead of the GC's default.
void read_shapes(const Reader& r, const toml::table& topo, MachineConfig& c) {
  const toml::table& shapes = r.table(topo, "shapes", false);
  for (const auto& [k, v] : shapes) {
    int n = 0;
    try {
      std::size_t used = 0;
      n = std::stoi(std::string(k.str()), &used);
      if (used != k.str().size()) n = 0;
    } catch (const std::exception&) {
    }
    const std::string expected = "[topology.shapes] entries are N = [width, height], e.g. 8 = [8, 1]";
    if (n < 1) r.fail(&v, expected);
    const auto [width, height] = r.positive_pair(&v, expected);
    const MeshShape s{width, height};
    if (s.width < 1 || s.height < 1 || std::int64_t(s.width) * s.height != n || s.width > c.mesh_width ||
        s.height > c.mesh_height) {
      r.fail(&v, "[topology.shapes] " + std::to_string(n) + " = [" + std::to_string(s.width) + ", " +
                     std::to_string(s.height) + "]: expected width * height == " + std::to_string(n) +
                     " and a shape that fits in the " + std::to_string(c.mesh_width) + "x" +
                     std::to_string(c.mesh_height) + " mesh");
    }
    c.shapes[n] = s;
  }
}

// [network] connect_model = "parallel" | "serialized" | "servers" | "route", with connect_server_block =
// [w, h] for "servers". The older connect_serialized = true means "serialized".
void read_connect_model(const Reader& r, const toml::table& net, MachineConfig& c) {
  if (const toml::node* n = net.get("connect_serialized")) {
    auto b = n->as_boolean();
    if (!b) r.fail(n, "'connect_serialized' in [network] must be true or false");
    if (net.get("connect_model")) r.fail(n, "give either 'connect_model' or the older 'connect_serialized' in [network], not both");
    c.connect_model = b->get() ? ConnectModel::serialized : ConnectModel::parallel;
  }
  const std::string model = r.string(net, "connect_model", "[network]", std::string("parallel"));
  if (model == "serialized") c.connect_model = ConnectModel::serialized;
  else if (model == "servers") c.connect_model = ConnectModel::servers;
  else if (model == "route") c.connect_model = ConnectModel::route;
  else if (model != "parallel")
    r.fail(net.get("connect_model"), "'connect_model' in [network] is '" + model + "'; expected \"parallel\", \"serialized\", \"servers\" or \"route\"");
  if (const toml::node* n = net.get("connect_server_block")) {
    const auto [width, height] =
        r.positive_pair(n, "'connect_server_block' in [network] must be [width, height], two positive integers");
    if (c.connect_model != ConnectModel::servers) r.fail(n, "'connect_server_block' needs connect_model = \"servers\"");
    c.connect_block_width = width;
    c.connect_block_height = height;
  }
}

// [comm_cpu]: send_us, recv_us, connect_us, copy_ns_per_byte, each optional (0).
void read_comm_cpu(const Reader& r, const toml::table& root, MachineConfig& c) {
  const toml::table& t = r.table(root, "comm_cpu", false);
  r.only_keys(t, "[comm_cpu]", {"send_us", "recv_us", "connect_us", "copy_ns_per_byte"});
  auto us = [&](std::string_view key) {
    return from_seconds(r.number(t, key, "[comm_cpu]", 0.0, kMaxMicroseconds, 0.0) * 1e-6);
  };
  c.comm_cpu.send = us("send_us");
  c.comm_cpu.recv = us("recv_us");
  c.comm_cpu.connect = us("connect_us");
  c.comm_cpu.seconds_per_byte = r.number(t, "copy_ns_per_byte", "[comm_cpu]", 0.0, 1e9, 0.0) * 1e-9;
}

// [mpi], each key optional: call_overhead_us (5), ns_per_byte (0), reduce_ns_per_byte (5), eager_limit_bytes (16384).
void read_mpi(const Reader& r, const toml::table& root, MachineConfig& c) {
  const toml::table& t = r.table(root, "mpi", false);
  r.only_keys(t, "[mpi]", {"call_overhead_us", "ns_per_byte", "reduce_ns_per_byte", "eager_limit_bytes"});
  c.mpi.call_overhead = from_seconds(r.number(t, "call_overhead_us", "[mpi]", 0.0, kMaxMicroseconds, 5.0) * 1e-6);
  c.mpi.seconds_per_byte = r.number(t, "ns_per_byte", "[mpi]", 0.0, 1e9, 0.0) * 1e-9;
  c.mpi.reduce_seconds_per_byte = r.number(t, "reduce_ns_per_byte", "[mpi]", 0.0, 1e9, 5.0) * 1e-9;
  c.mpi.eager_limit_bytes = static_cast<std::int64_t>(r.number(t, "eager_limit_bytes", "[mpi]", 0.0, 1e15, 16384.0));
}

}  // namespace

MachineConfig parse_machine_config(std::string_view text, const std::string& source) {
  const toml::table root = parse_with_bases(text, source);
  Reader r(root, source);
  r.only_keys(root, "the file", {"name", "topology", "node", "network", "comm_cpu", "ops", "calibration", "runtime", "mpi"});

  MachineConfig c;
  c.source = source;
  c.name = r.string(root, "name", "the file", std::string("unnamed machine"));

  const toml::table& topo = r.table(root, "topology");
  r.only_keys(topo, "[topology]", {"nodes", "interconnect", "mesh", "shapes"});
  c.nodes = r.integer(topo, "nodes", "[topology]", 1, 1 << 20);
  c.interconnect = r.string(topo, "interconnect", "[topology]", std::string("mesh"));
  if (!is_interconnect(c.interconnect)) {
    r.fail(topo.get("interconnect"), "'interconnect' in [topology] is '" + c.interconnect + "'; expected one of: " + interconnect_list());
  }
  const toml::node* mesh = topo.get("mesh");
  if (!mesh) r.fail(&topo, "missing key 'mesh' in [topology] (expected mesh = [width, height])");
  std::tie(c.mesh_width, c.mesh_height) =
      r.positive_pair(mesh, "'mesh' in [topology] must be [width, height], two positive integers");
  if (c.mesh_width < 1 || c.mesh_height < 1) r.fail(mesh, "'mesh' in [topology] must be [width, height], two positive integers");
  if (std::int64_t(c.mesh_width) * c.mesh_height != c.nodes) {
    r.fail(mesh, "mesh " + std::to_string(c.mesh_width) + "x" + std::to_string(c.mesh_height) + " has " +
                     std::to_string(std::int64_t(c.mesh_width) * c.mesh_height) + " nodes but [topology] nodes = " +
                     std::to_string(c.nodes) + "; expected width * height == nodes");
  }

  read_shapes(r, topo, c);

  const toml::table& node = r.table(root, "node");
  r.only_keys(node, "[node]", {"cpus", "clock_mhz", "memory_mb", "comm_processors", "links_per_comm_processor"});
  c.cpus_per_node = r.integer(node, "cpus", "[node]", 1, 1024);
  c.clock_hz = r.number(node, "clock_mhz", "[node]", 1e-3, 1e7) * 1e6;
  c.memory_bytes = static_cast<std::int64_t>(r.number(node, "memory_mb", "[node]", 1e-3, 1e9) * 1024 * 1024);
  c.comm_processors = r.integer(node, "comm_processors", "[node]", 1, 64);
  c.links_per_comm_processor = r.integer(node, "links_per_comm_processor", "[node]", 1, 64);
  const int directions = make_interconnect(c)->directions();
  if (c.links_per_node() % directions != 0) {
    r.fail(node.get("links_per_comm_processor"),
           fmt::format("comm_processors * links_per_comm_processor = {}; expected a multiple of {} (the {} spreads a "
                       "node's links evenly over its {} directions)",
                       c.links_per_node(), directions, c.interconnect, directions));
  }

  const toml::table& net = r.table(root, "network");
  r.only_keys(net, "[network]", {"model", "link_bandwidth_mbps", "message_setup_us", "network_latency_us",
                                 "hop_latency_us", "connect_base_us", "connect_per_hop_us",
                                 "connect_serialized", "connect_model", "connect_server_block", "packet_bytes"});
  c.network_model = r.string(net, "model", "[network]", std::string("analytic"));
  if (!is_network_model(c.network_model)) {
    r.fail(net.get("model"), "'model' in [network] is '" + c.network_model + "'; expected one of: " + network_model_list());
  }
  c.link_bandwidth = r.number(net, "link_bandwidth_mbps", "[network]", 1e-9, 1e9) * 1e6;
  auto us = [&](std::string_view key) {
    return from_seconds(r.number(net, key, "[network]", 0.0, kMaxMicroseconds) * 1e-6);
  };
  c.message_setup = us("message_setup_us");
  c.network_latency = us("network_latency_us");
  c.hop_latency = us("hop_latency_us");
  c.connect_base = us("connect_base_us");
  c.connect_per_hop = us("connect_per_hop_us");
  read_connect_model(r, net, c);
  c.packet_bytes = static_cast<std::int64_t>(r.number(net, "packet_bytes", "[network]", 1, 1 << 30, 1024.0));

  read_comm_cpu(r, root, c);
  read_mpi(r, root, c);
  read_calibration(r, root, c);

  const toml::table& runtime = r.table(root, "runtime", false);
  r.only_keys(runtime, "[runtime]", {"fiber_stack_kib"});
  c.fiber_stack_bytes = std::int64_t(r.number(runtime, "fiber_stack_kib", "[runtime]", 16, 1 << 20, 64.0)) << 10;

  const toml::table& ops = r.table(root, "ops", false);
  for (const auto& [k, v] : ops) {
    c.cycles_per_op[std::string(k.str())] = r.number(ops, k.str(), "[ops]", 0.0, 1e15);
  }
  return c;
}

MachineConfig load_machine_config(const std::filesystem::path& file) {
  InputFile in = read_input_file(file, kMaxTomlFileBytes);
  if (!in.ok()) throw ConfigError(file.string(), 0, "cannot open the machine file: it " + in.error);
  return parse_machine_config(in.text, file.string());
}

std::string builtin_source(std::string_view file_name) { return "<built-in configs/" + std::string(file_name) + ">"; }

MachineConfig default_machine_config() {
  return parse_machine_config(builtin_machine_file(kDefaultMachineFile), builtin_source(kDefaultMachineFile));
}

MachineConfig published_machine_config() {
  return parse_machine_config(published_machine_config_text(), builtin_source(kPublishedMachineFile));
}

std::string_view published_machine_config_text() { return builtin_machine_file(kPublishedMachineFile); }

MeshShape gc_mesh_shape(int n) {
  if (n < 1) throw std::invalid_argument("node count must be positive");
  int h = 1;
  for (int d = 1; std::int64_t(d) * d <= n; ++d) {
    if (n % d == 0) h = d;
  }
  return {n / h, h};
}

MachineConfig with_nodes(const MachineConfig& c, int n, std::optional<MeshShape> shape) {
  if (n == c.nodes && !shape) return c;
  if (n < 1 || n > c.nodes) {
    throw ConfigError(c.source, 0, "--nodes " + std::to_string(n) + " does not fit: the machine has " +
                                       std::to_string(c.nodes) + " nodes (expected 1.." + std::to_string(c.nodes) + ")");
  }
  const auto configured = c.shapes.find(n);
  const bool chosen = shape || configured != c.shapes.end();
  const MeshShape s = shape ? *shape : configured != c.shapes.end() ? configured->second : gc_mesh_shape(n);
  const std::string name = std::to_string(s.width) + "x" + std::to_string(s.height);
  if (std::int64_t(s.width) * s.height != n) {
    throw ConfigError(c.source, 0, "shape " + name + " has " + std::to_string(std::int64_t(s.width) * s.height) +
                                       " nodes, not " + std::to_string(n) + " (expected width * height == nodes)");
  }
  const bool fits = s.width <= c.mesh_width && s.height <= c.mesh_height;
  // The default shape may be turned to fit; a shape the user chose is taken as given.
  const bool fits_turned = !chosen && s.height <= c.mesh_width && s.width <= c.mesh_height;
  if (!fits && !fits_turned) {
    throw ConfigError(c.source, 0, "--nodes " + std::to_string(n) + " in a " + name + " mesh does not fit in the machine's " +
                                       std::to_string(c.mesh_width) + "x" + std::to_string(c.mesh_height) + " mesh");
  }
  MachineConfig out = c;
  out.nodes = n;
  out.mesh_width = fits ? s.width : s.height;
  out.mesh_height = fits ? s.height : s.width;
  return out;
}

MeshShape parse_mesh_shape(std::string_view text) {
  const auto x = text.find('x');
  auto number = [&](std::string_view part) {
    int v = 0;
    if (part.empty() || part.size() > 7) return -1;
    for (char ch : part) {
      if (ch < '0' || ch > '9') return -1;
      v = v * 10 + (ch - '0');
    }
    return v;
  };
  const int w = x == std::string_view::npos ? -1 : number(text.substr(0, x));
  const int h = x == std::string_view::npos ? -1 : number(text.substr(x + 1));
  if (w < 1 || h < 1) throw std::invalid_argument("shape '" + std::string(text) + "': expected WxH, e.g. 8x1");
  return {w, h};
}

SimTime op_time(const MachineConfig& c, std::string_view op, std::int64_t count) {
  auto it = c.cycles_per_op.find(op);
  if (it == c.cycles_per_op.end()) {
    throw std::out_of_range("operation '" + std::string(op) + "' has no cost in the [ops] table of " + c.source);
  }
  return from_seconds(it->second * static_cast<double>(count) / c.clock_hz);
}

}  // namespace gcsim::machine
