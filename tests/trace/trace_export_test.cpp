// The three trace exports (Chrome JSON, CSV, Paje) of a small run whose every event time is known
// (tests/trace/trace_test_support.hpp).
#include "tests/trace/trace_test_support.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim {
namespace {

using namespace trace_test;

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
  o.config = machine::published_machine_config();
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
  for (const char* p : {"p0", "p1", "p2"}) EXPECT_TRUE(containers.count(p)) << p;
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

}  // namespace
}  // namespace gcsim
