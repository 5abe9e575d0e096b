// Trace runs beyond the small one's exact times: repeatability, trace levels, spawned threads,
// interrupted traces, and the CSV reader's errors.
#include "tests/trace/trace_test_support.hpp"
#include "machine/mesh.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim {
namespace {

using namespace trace_test;

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
  const machine::Mesh row(2, 1);
  machine::TraceWriter writer(options, 2, row);
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
