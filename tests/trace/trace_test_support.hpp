#pragma once
// What the trace-export suites share: a small run whose every event time is known (3 processors in
// a row; P0 computes 1 ms, opens a link to P1, which has waited since 0, and sends it 1000 bytes;
// P2 does nothing), written into a fresh folder, and the checks of Perfetto's rules.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <unistd.h>

#include "machine/paje_writer.hpp"
#include "machine/trace_csv.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::trace_test {

namespace fs = std::filesystem;
using machine::kMicrosecond;
using machine::kMillisecond;
using machine::SimTime;
using nlohmann::json;

// Round numbers: 1 cycle = 1 us, a mesh channel carries 1 byte per us.
inline machine::MachineConfig small_machine() {
  machine::MachineConfig c;
  c.name = "test row of 3";
  c.nodes = 3;
  c.mesh_width = 3;
  c.mesh_height = 1;
  c.cpus_per_node = 1;
  c.clock_hz = 1e6;
  c.cycles_per_op = {{"work", 10.0}};
  c.link_bandwidth = 0.25e6;  // 4 links per direction: 1e6 bytes/s per channel
  c.message_setup = 10 * kMicrosecond;
  c.network_latency = 40 * kMicrosecond;
  c.hop_latency = 0;
  c.connect_base = 100 * kMicrosecond;
  c.connect_per_hop = 100 * kMicrosecond;
  return c;
}

// Known times (picoseconds).
constexpr SimTime kComputeEnd = 1 * kMillisecond;       // 100 x 10 cycles at 1 MHz
constexpr SimTime kLinkUp = 1200 * kMicrosecond;        // + 100 us + 1 hop x 100 us
constexpr SimTime kOnWire = 1250 * kMicrosecond;        // + 10 us set-up + 40 us latency
constexpr SimTime kArrival = 2250 * kMicrosecond;       // + 1000 bytes at 1 byte/us

inline fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("gcsim_trace_test_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// Runs the small program with tracing into dir/t.json (+ .csv, .paje).
inline void run_small_program(const fs::path& dir, machine::TraceLevel level = machine::TraceLevel::full) {
  parix::SimulationOptions o;
  o.config = small_machine();
  o.config.network_model = "analytic";
  o.trace.path = (dir / "t.json").string();
  o.trace.level = level;
  parix::run_simulated(o, [](parix::Processor& p) {
    if (p.id() == 0) {
      p.compute("work", 100);
      parix::Link l = p.connect(1);
      std::vector<std::byte> data(1000, std::byte{7});
      p.send(l, data);
    } else if (p.id() == 1) {
      parix::Link l = p.connect(0);
      EXPECT_EQ(p.recv(l).size(), 1000u);
    }
  });
}

// What Perfetto's JSON importer needs to show every event: the slices of one track nest (a slice
// that starts inside another ends inside it too), each message's flow has one start and one end,
// each async begin has its end; and only the phases gcsim writes appear.
inline void expect_perfetto_rules(const json& events) {
  ASSERT_TRUE(events.is_array());
  // (pid, tid) -> (start, end) in picoseconds: the six decimals of a microsecond, exactly.
  std::map<std::pair<int, int>, std::vector<std::pair<std::int64_t, std::int64_t>>> tracks;
  auto ps = [](const json& us) { return std::llround(us.get<double>() * 1e6); };
  std::map<std::int64_t, std::pair<int, int>> flow_ends;                           // bind_id -> (outs, ins)
  std::map<std::pair<std::string, std::int64_t>, int> async_open;
  for (const json& e : events) {
    const std::string ph = e["ph"];
    ASSERT_TRUE(ph == "M" || ph == "X" || ph == "b" || ph == "e") << e.dump();
    if (ph == "X") {
      const std::int64_t ts = ps(e["ts"]), dur = ps(e["dur"]);
      ASSERT_GE(dur, 0) << e.dump();
      tracks[{e["pid"], e["tid"]}].push_back({ts, ts + dur});
      if (e.contains("bind_id")) {
        auto& [outs, ins] = flow_ends[e["bind_id"].get<std::int64_t>()];
        if (e.value("flow_out", false)) ++outs;
        if (e.value("flow_in", false)) ++ins;
      }
    } else if (ph == "b") {
      ++async_open[{e["name"], e["id"].get<std::int64_t>()}];
    } else if (ph == "e") {
      --async_open[{e["name"], e["id"].get<std::int64_t>()}];
    }
  }
  for (auto& [track, slices] : tracks) {
    // Longer first at equal starts, as a parent precedes its children.
    std::sort(slices.begin(), slices.end(), [](auto& a, auto& b) { return a.first != b.first ? a.first < b.first : a.second > b.second; });
    std::vector<std::int64_t> open_ends;
    for (const auto& [ts, end] : slices) {
      while (!open_ends.empty() && open_ends.back() <= ts && !(open_ends.back() == ts && end == ts)) open_ends.pop_back();
      if (!open_ends.empty()) {
        EXPECT_LE(end, open_ends.back()) << "slices overlap without nesting on pid " << track.first << " tid " << track.second
                                         << " at ts " << ts;
      }
      open_ends.push_back(end);
    }
  }
  for (const auto& [id, ends] : flow_ends) {
    EXPECT_EQ(ends, std::make_pair(1, 1)) << "message flow " << id;
  }
  for (const auto& [key, open] : async_open) EXPECT_EQ(open, 0) << "async " << key.first << " id " << key.second;
}

}  // namespace gcsim::trace_test
