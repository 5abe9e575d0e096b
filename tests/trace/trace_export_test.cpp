// The three trace exports (Chrome JSON, CSV, Paje) of a small run whose every event time is known:
// 3 processors in a row; P0 computes 1 ms, opens a link to P1 (which has waited since 0) and sends
// it 1000 bytes; P2 does nothing.
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
#include "parix/simulated_runtime.hpp"

namespace gcsim {
namespace {

namespace fs = std::filesystem;
using machine::kMicrosecond;
using machine::kMillisecond;
using machine::SimTime;
using nlohmann::json;

// Round numbers: 1 cycle = 1 us, a mesh channel carries 1 byte per us.
machine::MachineConfig small_machine() {
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

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("gcsim_trace_test_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// Runs the small program with tracing into dir/t.json (+ .csv, .paje).
void run_small_program(const fs::path& dir, machine::TraceLevel level = machine::TraceLevel::full) {
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
void expect_perfetto_rules(const json& events) {
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

class SmallRunTrace : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(fresh_dir("small"));
    run_small_program(*dir_);
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
  }
  static fs::path file(const char* ext) { return *dir_ / (std::string("t") + ext); }
  static fs::path* dir_;
};
fs::path* SmallRunTrace::dir_ = nullptr;

TEST_F(SmallRunTrace, ChromeJsonParsesWithOneTrackPerProcessor) {
  const json events = json::parse(slurp(file(".json")));
  ASSERT_TRUE(events.is_array());
  std::map<int, std::string> tracks;
  for (const json& e : events) {
    if (e["ph"] == "M" && e["pid"] == 0 && e["name"] == "thread_name") {
      EXPECT_FALSE(tracks.count(e["tid"].get<int>())) << "two names for one track";
      tracks[e["tid"].get<int>()] = e["args"]["name"].get<std::string>();
    }
  }
  ASSERT_EQ(tracks.size(), 3u);
  EXPECT_EQ(tracks[0], "P0 node (0,0)");
  EXPECT_EQ(tracks[1], "P1 node (1,0)");
  EXPECT_EQ(tracks[2], "P2 node (2,0)");
}

TEST_F(SmallRunTrace, ChromeJsonHasTheExpectedEventsAtExactTimes) {
  const json events = json::parse(slurp(file(".json")));
  // (pid, tid, category) -> [(ts, dur)] in microseconds.
  std::map<std::tuple<int, int, std::string>, std::vector<std::pair<double, double>>> slices;
  std::vector<json> flows;
  std::vector<json> channel;  // async begin/end of the channel's occupancy
  for (const json& e : events) {
    if (e["pid"] == 1 && (e["ph"] == "b" || e["ph"] == "e")) channel.push_back(e);
    if (e["ph"] != "X") continue;
    slices[{e["pid"].get<int>(), e["tid"].get<int>(), e["cat"].get<std::string>()}].push_back(
        {e["ts"].get<double>(), e["dur"].get<double>()});
    if (e.contains("bind_id")) flows.push_back(e);
  }
  using Slices = std::vector<std::pair<double, double>>;
  EXPECT_EQ((slices[{0, 0, "compute"}]), (Slices{{0.0, 1000.0}}));
  EXPECT_EQ((slices[{0, 0, "connect"}]), (Slices{{1000.0, 200.0}}));
  EXPECT_EQ((slices[{0, 1, "connect"}]), (Slices{{0.0, 1200.0}}));
  EXPECT_EQ((slices[{0, 0, "send"}]), (Slices{{1200.0, 1050.0}}));
  EXPECT_EQ((slices[{0, 1, "recv"}]), (Slices{{1200.0, 1050.0}}));
  EXPECT_EQ(slices.size(), 7u);  // and the two message marks below; nothing on P2
  // Channel 0 (node 0 east) carries the 1000 bytes from the end of the latency to the arrival.
  ASSERT_EQ(channel.size(), 2u);
  EXPECT_EQ(channel[0]["ph"], "b");
  EXPECT_EQ(channel[0]["name"], "ch 0 P0->P1 east");
  EXPECT_EQ(channel[0]["ts"].get<double>(), 1250.0);
  EXPECT_EQ(channel[0]["args"]["bytes"], 1000);
  EXPECT_EQ(channel[1]["ph"], "e");
  EXPECT_EQ(channel[1]["ts"].get<double>(), 2250.0);
  EXPECT_EQ(channel[1]["id"], channel[0]["id"]);
  // The message arrow: out of P0 when sent, into P1 on arrival, bound by the message id.
  ASSERT_EQ(flows.size(), 2u);
  const json& out = flows[0]["flow_out"] == true ? flows[0] : flows[1];
  const json& in = flows[0]["flow_out"] == true ? flows[1] : flows[0];
  EXPECT_EQ(out["tid"], 0);
  EXPECT_EQ(out["ts"].get<double>(), 1200.0);
  EXPECT_EQ(in["tid"], 1);
  EXPECT_EQ(in["flow_in"], true);
  EXPECT_EQ(in["ts"].get<double>(), 2250.0);
  EXPECT_EQ(in["bind_id"], out["bind_id"]);
  EXPECT_EQ(out["args"]["bytes"], 1000);
}

TEST_F(SmallRunTrace, ChromeJsonFollowsPerfettosRules) { expect_perfetto_rules(json::parse(slurp(file(".json")))); }

// Many messages at once on shared channels (flow model: they overlap on the links), a node that
// opens links from many threads at once (as the ray tracer's master does), and collectives.
TEST(TraceExport, BusyRunsFollowPerfettosRules) {
  const fs::path d = fresh_dir("busy");
  parix::SimulationOptions o;
  o.config = machine::default_machine_config();
  o.config = machine::with_nodes(o.config, 16);
  o.config.network_model = "flow";
  o.trace.path = (d / "t.json").string();
  parix::run_simulated(o, [](parix::Processor& p) {
    if (p.id() == 0) {
      std::vector<parix::Link> links(p.count());
      {
        std::vector<parix::Thread> openers;
        for (int w = 1; w < p.count(); ++w) openers.push_back(p.spawn([&links, w](parix::Processor& q) { links[w] = q.connect(w); }));
      }
      for (int w = 1; w < p.count(); ++w) EXPECT_EQ(p.recv(links[w]).size(), 5000u);
    } else {
      parix::Link l = p.connect(0);
      p.compute("cycle", 1000 * p.id());
      parix::Request r = p.isend(l, std::vector<std::byte>(5000));
      p.compute("cycle", 500);
      p.wait(r);
    }
  });
  const json events = json::parse(slurp(d / "t.json"));
  expect_perfetto_rules(events);
  std::set<int> thread_tracks;
  for (const json& e : events) {
    if (e["ph"] == "M" && e["name"] == "thread_name" && e["tid"].get<int>() >= 16) thread_tracks.insert(e["tid"].get<int>());
  }
  EXPECT_EQ(thread_tracks.size(), 15u) << "one track per connecting thread of P0";
  fs::remove_all(d);
}

TEST_F(SmallRunTrace, CsvRowsMatchTheRun) {
  const std::vector<std::string> lines = lines_of(slurp(file(".csv")));
  ASSERT_GE(lines.size(), 2u);
  EXPECT_EQ(lines[0], "# gcsim trace; level full; 3 processors; mesh 3x1; times in picoseconds");
  EXPECT_EQ(lines[1], "kind,proc,peer,start_ps,end_ps,bytes,id,label,thread");
  std::vector<std::string> rows(lines.begin() + 2, lines.end());
  std::sort(rows.begin(), rows.end());
  const std::vector<std::string> expected{
      "compute,0,-1,0,1000000000,0,-1,work,0",
      "connect,0,1,1000000000,1200000000,0,-1,connect,0",
      "connect,1,0,0,1200000000,0,-1,connect,0",
      "link,0,1,1250000000,2250000000,1000,0,link,0",
      "message,0,1,1200000000,2250000000,1000,0,message,0",
      "recv,1,0,1200000000,2250000000,1000,-1,recv,0",
      "send,0,1,1200000000,2250000000,0,-1,send,0",
  };
  EXPECT_EQ(rows, expected);
  EXPECT_EQ(kComputeEnd, 1000000000);
  EXPECT_EQ(kLinkUp, 1200000000);
  EXPECT_EQ(kOnWire, 1250000000);
  EXPECT_EQ(kArrival, 2250000000);
}

TEST_F(SmallRunTrace, CsvReadsBack) {
  const machine::TraceCsv t = machine::read_trace_csv(file(".csv").string());
  EXPECT_EQ(t.level, "full");
  EXPECT_EQ(t.processors, 3);
  EXPECT_EQ(t.mesh_width, 3);
  EXPECT_EQ(t.mesh_height, 1);
  ASSERT_EQ(t.records.size(), 7u);
  const auto message = std::find_if(t.records.begin(), t.records.end(),
                                    [](const auto& r) { return r.kind == machine::TraceKind::message; });
  ASSERT_NE(message, t.records.end());
  EXPECT_EQ(message->start, kLinkUp);
  EXPECT_EQ(message->end, kArrival);
  EXPECT_EQ(message->bytes, 1000);
  EXPECT_EQ(t.labels[message->label], "message");
}

// The Paje file: %EventDef blocks first, then type and value definitions, then containers,
// then timed events in non-decreasing time, balanced pushes and pops, and the known events.
TEST_F(SmallRunTrace, PajeFollowsTheFormat) {
  const std::vector<std::string> lines = lines_of(slurp(file(".paje")));
  std::map<int, std::string> defined;  // event id -> Paje event name
  std::map<int, int> field_count;
  std::size_t i = 0;
  for (; i < lines.size() && lines[i].rfind("%", 0) == 0; ++i) {
    std::istringstream in(lines[i]);
    std::string word, name;
    int id = -1;
    in >> word;
    if (word == "%EventDef") {
      in >> name >> id;
      ASSERT_FALSE(defined.count(id)) << lines[i];
      defined[id] = name;
      field_count[id] = 0;
    } else if (word == "%") {
      std::string field, type;
      in >> field >> type;
      ASSERT_TRUE(type == "string" || type == "date" || type == "double" || type == "int" || type == "color") << lines[i];
      ++field_count[std::prev(defined.end())->first];
    } else {
      ASSERT_EQ(word, "%EndEventDef") << lines[i];
    }
  }
  for (const char* needed : {"PajeDefineContainerType", "PajeDefineStateType", "PajeDefineLinkType",
                             "PajeDefineEntityValue", "PajeCreateContainer", "PajeDestroyContainer", "PajePushState",
                             "PajePopState", "PajeStartLink", "PajeEndLink"}) {
    EXPECT_TRUE(std::any_of(defined.begin(), defined.end(), [&](const auto& d) { return d.second == needed; })) << needed;
  }
  // Phases in order: 0 definitions, 1 containers, 2 timed events, 3 destruction.
  auto phase_of = [&](const std::string& name) {
    if (name.rfind("PajeDefine", 0) == 0) return 0;
    if (name == "PajeCreateContainer") return 1;
    if (name == "PajeDestroyContainer") return 3;
    return 2;
  };
  int phase = 0;
  double last_time = 0;
  std::map<std::string, int> depth;  // container -> pushed states
  std::set<std::string> containers{"0"};
  std::vector<std::string> events;
  for (; i < lines.size(); ++i) {
    std::istringstream in(lines[i]);
    int id = -1;
    in >> id;
    ASSERT_TRUE(defined.count(id)) << "undefined event id in: " << lines[i];
    const std::string& name = defined[id];
    const int p = phase_of(name);
    if (name != "PajeSetVariable") {
      EXPECT_GE(p, phase) << "out of order: " << lines[i];
      phase = std::max(phase, p);
    }
    // Fields on the line: quoted names count as one.
    std::vector<std::string> fields;
    for (std::string w; in >> w;) {
      if (w.front() == '"' && (w.size() == 1 || w.back() != '"')) {
        std::string rest;
        std::getline(in, rest, '"');
        w += rest + '"';
      }
      fields.push_back(w);
    }
    ASSERT_EQ(static_cast<int>(fields.size()), field_count[id]) << lines[i];
    if (p == 0) continue;
    const double t = std::stod(fields[0]);
    EXPECT_GE(t, last_time) << "time goes back: " << lines[i];
    last_time = t;
    if (name == "PajeCreateContainer") {
      EXPECT_TRUE(containers.count(fields[3])) << "parent not created yet: " << lines[i];
      containers.insert(fields[1]);
    } else if (name == "PajePushState") {
      EXPECT_TRUE(containers.count(fields[2])) << lines[i];
      ++depth[fields[2]];
      events.push_back(lines[i]);
    } else if (name == "PajePopState") {
      EXPECT_GT(depth[fields[2]]--, 0) << "pop without push: " << lines[i];
      events.push_back(lines[i]);
    } else if (name == "PajeStartLink" || name == "PajeEndLink") {
      EXPECT_TRUE(containers.count(fields[4])) << lines[i];
      events.push_back(lines[i]);
    }
  }
  EXPECT_EQ(phase, 3) << "containers are destroyed at the end";
  for (const auto& [c, d] : depth) EXPECT_EQ(d, 0) << "unbalanced states on " << c;
  for (const std::string& p : {"p0", "p1", "p2"}) EXPECT_TRUE(containers.count(p)) << p;
  EXPECT_TRUE(containers.count("c0")) << "the channel P0->P1 east carried the message";

  const std::vector<std::string> expected{
      "7 0.000000000 S p0 compute",       "7 0.000000000 S p1 connect", "8 1.000000000 S p0",
      "7 1.000000000 S p0 connect",       "8 1.200000000 S p1",         "8 1.200000000 S p0",
      "9 1.200000000 L gc msg p0 m0",     "7 1.200000000 S p1 recv",    "7 1.200000000 S p0 send",
      "8 2.250000000 S p1",               "8 2.250000000 S p0",         "10 2.250000000 L gc msg p1 m0",
  };
  // Same multiset; order is checked by time above (ties keep the run's record order).
  std::vector<std::string> got = events, want = expected;
  std::sort(got.begin(), got.end());
  std::sort(want.begin(), want.end());
  EXPECT_EQ(got, want);
}

TEST(TraceExport, IdenticalRunsWriteByteIdenticalFiles) {
  const fs::path a = fresh_dir("repeat_a"), b = fresh_dir("repeat_b");
  run_small_program(a);
  run_small_program(b);
  for (const char* ext : {".json", ".csv", ".paje"}) {
    const std::string fa = slurp(a / (std::string("t") + ext));
    EXPECT_FALSE(fa.empty()) << ext;
    EXPECT_EQ(fa, slurp(b / (std::string("t") + ext))) << ext << " differs between identical runs";
  }
  fs::remove_all(a);
  fs::remove_all(b);
}

TEST(TraceExport, SummaryLevelKeepsOnlyTheFrames) {
  const fs::path d = fresh_dir("summary");
  run_small_program(d, machine::TraceLevel::summary);
  EXPECT_EQ(json::parse(slurp(d / "t.json")).size(), 8u);  // process name/sort + 3 x (thread name, sort index)
  EXPECT_EQ(lines_of(slurp(d / "t.csv")).size(), 2u);
  EXPECT_EQ(machine::read_trace_csv((d / "t.csv").string()).level, "summary");
  const std::string paje = slurp(d / "t.paje");
  EXPECT_NE(paje.find("p2 N gc"), std::string::npos);
  EXPECT_EQ(paje.find("S p0 compute"), std::string::npos);
  fs::remove_all(d);
}

TEST(TraceExport, MessagesLevelHasNoLinkRecords) {
  const fs::path d = fresh_dir("messages");
  run_small_program(d, machine::TraceLevel::messages);
  const std::string csv = slurp(d / "t.csv");
  EXPECT_EQ(csv.find("\nlink,"), std::string::npos);
  EXPECT_NE(csv.find("\nmessage,0,1,"), std::string::npos);
  fs::remove_all(d);
}

TEST(TraceCsv, BadFilesAreNamedWithWhatWasExpected) {
  const fs::path d = fresh_dir("bad");
  auto message_for = [&](const std::string& text) {
    std::ofstream(d / "bad.csv") << text;
    try {
      machine::read_trace_csv((d / "bad.csv").string());
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message_for("").find("bad.csv:1: empty file"), std::string::npos);
  EXPECT_NE(message_for("hello\n").find("bad.csv:1: not a gcsim trace CSV"), std::string::npos);
  const std::string header = "# gcsim trace; level full; 2 processors; mesh 2x1; times in picoseconds\n";
  EXPECT_NE(message_for(header + "a,b\n").find("bad.csv:2: expected the column line"), std::string::npos);
  // Found by fuzz_trace_csv: a header of 1e17 processors had the Paje writer loop for ever.
  EXPECT_NE(message_for("# gcsim trace; level full; 100000000000000006 processors; mesh 4x4; t\n")
                .find("bad.csv:1: 100000000000000006 processors in the header; expected 1..1048576"),
            std::string::npos);
  EXPECT_NE(message_for("# gcsim trace; level full; 4 processors; mesh 99999999x2; t\n").find("bad.csv:1: mesh 99999999x2"),
            std::string::npos);
  const std::string columns = "kind,proc,peer,start_ps,end_ps,bytes,id,label,thread\n";
  EXPECT_NE(message_for(header + columns + "teleport,0,1,0,1,0,-1,x,0\n").find("bad.csv:3: unknown record kind"),
            std::string::npos);
  EXPECT_NE(message_for(header + columns + "send,0,1,zero,1,0,-1,x,0\n").find("bad.csv:3: expected integers"),
            std::string::npos);
  EXPECT_NE(message_for(header + columns + "send,0,1\n").find("bad.csv:3: expected 9"), std::string::npos);
  EXPECT_NE(message_for(header + columns + "send,0,1,0,1,0,-1,x,two\n").find("bad.csv:3: expected a thread"),
            std::string::npos);
  // Traces written before the thread column read as thread 0.
  EXPECT_EQ(message_for(header + "kind,proc,peer,start_ps,end_ps,bytes,id,label\nsend,0,1,0,1,0,-1,x\n"), "no error");
  EXPECT_THROW(machine::read_trace_csv((d / "missing.csv").string()), std::runtime_error);
  fs::remove_all(d);
}

// P0 spawns a thread that computes while P0 itself computes: the overlapping intervals go to
// separate tracks (Chrome JSON) and containers (Paje), so that each stays properly nested.
TEST(TraceExport, SpawnedThreadsGetTheirOwnTrack) {
  const fs::path d = fresh_dir("threads");
  parix::SimulationOptions o;
  o.config = small_machine();
  o.config.cpus_per_node = 2;
  o.trace.path = (d / "t.json").string();
  parix::run_simulated(o, [](parix::Processor& p) {
    if (p.id() != 0) return;
    parix::Thread t = p.spawn([](parix::Processor& q) { q.compute("work", 300); });
    p.compute("work", 100);
    t.join();
  });
  std::map<int, std::string> names;
  std::vector<std::tuple<int, double, double>> computes;  // tid, ts, dur
  for (const json& e : json::parse(slurp(d / "t.json"))) {
    if (e["ph"] == "M" && e["name"] == "thread_name") names[e["tid"].get<int>()] = e["args"]["name"];
    if (e["ph"] == "X" && e["cat"] == "compute") computes.emplace_back(e["tid"], e["ts"], e["dur"]);
  }
  EXPECT_EQ(names[3], "P0 thread 1");  // tid = thread x processors + processor
  std::sort(computes.begin(), computes.end());
  EXPECT_EQ(computes, (std::vector<std::tuple<int, double, double>>{{0, 0.0, 1000.0}, {3, 0.0, 3000.0}}));
  const std::string csv = slurp(d / "t.csv");
  EXPECT_NE(csv.find("compute,0,-1,0,3000000000,0,-1,work,1\n"), std::string::npos) << csv;
  const std::string paje = slurp(d / "t.paje");
  EXPECT_NE(paje.find("p0t1 T p0 \"P0 thread 1\""), std::string::npos) << paje;
  EXPECT_NE(paje.find("7 0.000000000 TS p0t1 t_compute"), std::string::npos);
  EXPECT_NE(paje.find("8 3.000000000 TS p0t1"), std::string::npos);
  EXPECT_NE(paje.find("8 1.000000000 S p0\n"), std::string::npos);
  fs::remove_all(d);
}

// A run killed mid-way leaves what has been flushed: whole records only, so the JSON parses once
// its closing bracket is added (Perfetto does without it) and the CSV reads back.
TEST(TraceExport, AnInterruptedTraceEndsOnARecordBoundary) {
  const fs::path d = fresh_dir("interrupted");
  machine::TraceOptions options;
  options.path = (d / "t.json").string();
  machine::TraceWriter writer(options, 2, 2, 1);
  for (int i = 0; i < 5000; ++i) {  // well past one flush of the buffers
    writer.record({machine::TraceKind::compute, i % 2, -1, SimTime(i) * kMicrosecond, SimTime(i + 1) * kMicrosecond, 0,
                   -1, "work"});
  }
  const std::string json_so_far = slurp(d / "t.json");
  const std::string csv_so_far = slurp(d / "t.csv");
  ASSERT_GT(json_so_far.size(), 1u << 16);
  EXPECT_EQ(json_so_far.back(), '}');
  EXPECT_EQ(csv_so_far.back(), '\n');
  const json events = json::parse(json_so_far + "\n]");
  const machine::TraceCsv csv = machine::read_trace_csv((d / "t.csv").string());
  EXPECT_GT(csv.records.size(), 100u);
  // Two processes (processors; mesh channels at level full) with name and order, two named tracks,
  // then one event per record.
  EXPECT_EQ(events.size(), 2 + 2 + 2 * 2 + csv.records.size());
  writer.close();
  EXPECT_EQ(machine::read_trace_csv((d / "t.csv").string()).records.size(), 5000u);
  fs::remove_all(d);
}

TEST(TraceCsv, SiblingPaths) {
  EXPECT_EQ(machine::trace_sibling_path("run/t.json", ".csv"), "run/t.csv");
  EXPECT_EQ(machine::trace_sibling_path("run.d/trace", ".paje"), "run.d/trace.paje");
  EXPECT_EQ(machine::trace_sibling_path("t", ".csv"), "t.csv");
}

}  // namespace
}  // namespace gcsim
