#include "machine/machine_config.hpp"

#include <gtest/gtest.h>

#include <string>

namespace gcsim::machine {
namespace {

const std::string kValid = R"(name = "tiny"
[topology]
nodes = 4
mesh = [2, 2]
[node]
cpus = 1
clock_mhz = 100
memory_mb = 8
comm_processors = 1
links_per_comm_processor = 4
[network]
model = "flow"
link_bandwidth_mbps = 1.0
message_setup_us = 1
network_latency_us = 10
hop_latency_us = 1
connect_base_us = 100
connect_per_hop_us = 10
[ops]
cycle = 1
)";

// Replaces the first occurrence of `from` in the valid file.
std::string with(const std::string& from, const std::string& to) {
  std::string s = kValid;
  s.replace(s.find(from), from.size(), to);
  return s;
}

// The error message, which must name the file and a line.
std::string error_of(const std::string& text) {
  try {
    parse_machine_config(text, "bad.toml");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(MachineConfig, PublishedGCIsCompiledIn) {
  const MachineConfig c = published_machine_config();
  EXPECT_EQ(c.nodes, 64);
  EXPECT_EQ(c.mesh_width, 8);
  EXPECT_EQ(c.mesh_height, 8);
  EXPECT_EQ(c.cpus_per_node, 2);
  EXPECT_DOUBLE_EQ(c.clock_hz, 80e6);
  EXPECT_EQ(c.memory_bytes, 32LL << 20);
  EXPECT_EQ(c.links_per_node(), 16);
  EXPECT_NEAR(c.node_bandwidth(), 35e6, 1);
  EXPECT_EQ(c.message_setup, 5 * kMicrosecond);
  EXPECT_EQ(c.network_latency, 60 * kMicrosecond);
}

TEST(MachineConfig, ShippedFilesLoad) {
  const std::string dir = GCSIM_SOURCE_DIR "/configs/";
  for (const char* f : {"gc-powerplus.toml", "gc-powerplus-calibrated.toml", "whatif-1024-nodes.toml",
                        "whatif-fast-links.toml", "whatif-4096-nodes.toml", "whatif-16384-nodes.toml",
                        "whatif-65536-nodes.toml"}) {
    EXPECT_NO_THROW(load_machine_config(dir + f)) << f;
  }
  EXPECT_EQ(load_machine_config(dir + "whatif-1024-nodes.toml").nodes, 1024);
  const MachineConfig huge = load_machine_config(dir + "whatif-65536-nodes.toml");
  EXPECT_EQ(huge.nodes, 65536);
  EXPECT_EQ(huge.mesh_width, 256);
  EXPECT_EQ(huge.link_bandwidth, published_machine_config().link_bandwidth);  // inherited from the GC
}

TEST(MachineConfig, FiberStackSizeComesFromTheRuntimeTable) {
  EXPECT_EQ(parse_machine_config(kValid, "tiny.toml").fiber_stack_bytes, 64 << 10);  // the default
  EXPECT_EQ(parse_machine_config(kValid + "[runtime]\nfiber_stack_kib = 256\n", "t.toml").fiber_stack_bytes, 256 << 10);
  const std::string small = error_of(kValid + "[runtime]\nfiber_stack_kib = 4\n");
  EXPECT_NE(small.find("bad.toml:22"), std::string::npos) << small;
  EXPECT_NE(small.find("fiber_stack_kib"), std::string::npos) << small;
  const std::string unknown = error_of(kValid + "[runtime]\nstack = 4\n");
  EXPECT_NE(unknown.find("unknown key 'stack' in [runtime]"), std::string::npos) << unknown;
}

TEST(MachineConfig, LinksMustSpreadEvenlyOverTheInterconnectsDirections) {
  // The mesh spreads a node's links over 4 directions: 6 links do not divide, 8 do (2 per channel).
  std::string six = kValid;
  six.replace(six.find("links_per_comm_processor = 4"), 28, "links_per_comm_processor = 6");
  const std::string e = error_of(six);
  EXPECT_NE(e.find("bad.toml:10"), std::string::npos) << e;
  EXPECT_NE(e.find("multiple of 4 (the mesh spreads"), std::string::npos) << e;
  std::string eight = kValid;
  eight.replace(eight.find("links_per_comm_processor = 4"), 28, "links_per_comm_processor = 8");
  EXPECT_DOUBLE_EQ(parse_machine_config(eight, "eight.toml").channel_bandwidth(4), 2e6);
}

TEST(MachineConfig, ParsesAValidFile) {
  const MachineConfig c = parse_machine_config(kValid, "tiny.toml");
  EXPECT_EQ(c.name, "tiny");
  EXPECT_EQ(c.network_model, "flow");
  EXPECT_DOUBLE_EQ(c.channel_bandwidth(4), 1e6);
  EXPECT_EQ(op_time(c, "cycle", 100), 1 * kMicrosecond);
}

TEST(MachineConfig, UnknownKeyNamesFileLineAndExpectedKeys) {
  const std::string e = error_of(with("cpus = 1", "cpus = 1\nclock_ghz = 1"));
  EXPECT_NE(e.find("bad.toml:7"), std::string::npos) << e;
  EXPECT_NE(e.find("unknown key 'clock_ghz'"), std::string::npos) << e;
  EXPECT_NE(e.find("clock_mhz"), std::string::npos) << e;
}

TEST(MachineConfig, WrongTypeIsRejected) {
  const std::string e = error_of(with("cpus = 1", "cpus = \"two\""));
  EXPECT_NE(e.find("bad.toml:6"), std::string::npos) << e;
  EXPECT_NE(e.find("must be an integer"), std::string::npos) << e;
}

TEST(MachineConfig, NegativeBandwidthIsRejected) {
  const std::string e = error_of(with("link_bandwidth_mbps = 1.0", "link_bandwidth_mbps = -35"));
  EXPECT_NE(e.find("bad.toml:13"), std::string::npos) << e;
  EXPECT_NE(e.find("expected a value in"), std::string::npos) << e;
}

TEST(MachineConfig, MeshMustMatchNodeCount) {
  const std::string e = error_of(with("mesh = [2, 2]", "mesh = [3, 2]"));
  EXPECT_NE(e.find("bad.toml:4"), std::string::npos) << e;
  EXPECT_NE(e.find("width * height == nodes"), std::string::npos) << e;
}

TEST(MachineConfig, MissingSectionAndSyntaxErrorsAreReported) {
  EXPECT_NE(error_of("name = \"x\"\n").find("missing table [topology]"), std::string::npos);
  const std::string e = error_of(with("cpus = 1", "cpus = = 1"));
  EXPECT_NE(e.find("bad.toml:6"), std::string::npos) << e;
}

TEST(MachineConfig, UnknownNetworkModelIsRejected) {
  EXPECT_NE(error_of(with("model = \"flow\"", "model = \"packet-ish\"")).find("expected one of: analytic, flow, packet"),
            std::string::npos);
}

// [topology] interconnect names a registered physical interconnect; the GC's mesh without it.
TEST(MachineConfig, InterconnectDefaultsToTheMeshAndIsCheckedAgainstTheRegistry) {
  EXPECT_EQ(parse_machine_config(kValid, "tiny.toml").interconnect, "mesh");
  EXPECT_EQ(default_machine_config().interconnect, "mesh");
  EXPECT_EQ(parse_machine_config(with("nodes = 4", "nodes = 4\ninterconnect = \"mesh\""), "tiny.toml").interconnect, "mesh");
  const std::string e = error_of(with("nodes = 4", "nodes = 4\ninterconnect = \"hypercube\""));
  EXPECT_NE(e.find("bad.toml:4: 'interconnect' in [topology] is 'hypercube'; expected one of: mesh"), std::string::npos) << e;
  const std::string t = error_of(with("nodes = 4", "nodes = 4\ninterconnect = 3"));
  EXPECT_NE(t.find("bad.toml:4: 'interconnect' in [topology] must be a string"), std::string::npos) << t;
}

TEST(MachineConfig, MissingFileIsAClearError) {
  try {
    load_machine_config("no/such/machine.toml");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("no/such/machine.toml"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos);
  }
}

TEST(MachineConfig, GcMeshShapes) {
  const std::pair<int, std::pair<int, int>> expected[] = {
      {1, {1, 1}}, {2, {2, 1}}, {4, {2, 2}}, {8, {4, 2}}, {16, {4, 4}}, {32, {8, 4}}, {64, {8, 8}}, {1024, {32, 32}}, {6, {3, 2}}};
  for (auto [n, wh] : expected) {
    const MeshShape s = gc_mesh_shape(n);
    EXPECT_EQ(s.width, wh.first) << n;
    EXPECT_EQ(s.height, wh.second) << n;
  }
}

TEST(MachineConfig, WithNodesRestrictsTheMesh) {
  const MachineConfig c = with_nodes(published_machine_config(), 32);
  EXPECT_EQ(c.nodes, 32);
  EXPECT_EQ(c.mesh_width, 8);
  EXPECT_EQ(c.mesh_height, 4);
  EXPECT_THROW(with_nodes(published_machine_config(), 65), ConfigError);
  EXPECT_THROW(with_nodes(published_machine_config(), 0), ConfigError);
  EXPECT_THROW(with_nodes(published_machine_config(), 13), ConfigError);  // 13x1 does not fit in 8x8
}

TEST(MachineConfig, UnknownOperationIsNamed) {
  try {
    op_time(published_machine_config(), "warp_drive", 1);
    FAIL();
  } catch (const std::out_of_range& e) {
    EXPECT_NE(std::string(e.what()).find("warp_drive"), std::string::npos);
  }
}

}  // namespace
}  // namespace gcsim::machine

namespace gcsim::machine {
namespace {

TEST(MeshShapes, ChosenShapeReplacesTheDefault) {
  const MachineConfig gc = published_machine_config();
  const MachineConfig row = with_nodes(gc, 8, MeshShape{8, 1});
  EXPECT_EQ(row.mesh_width, 8);
  EXPECT_EQ(row.mesh_height, 1);
  const MachineConfig block = with_nodes(gc, 8);
  EXPECT_EQ(block.mesh_width, 4);
  EXPECT_EQ(block.mesh_height, 2);
  EXPECT_THROW(with_nodes(gc, 8, MeshShape{3, 3}), ConfigError);   // 9 nodes, not 8
  EXPECT_THROW(with_nodes(gc, 16, MeshShape{16, 1}), ConfigError);  // wider than the 8x8 mesh
}

TEST(MeshShapes, MachineFileNamesShapesPerNodeCount) {
  std::string text(published_machine_config_text());
  text.replace(text.find("[node]"), 6, "[topology.shapes]\n8 = [8, 1]\n\n[node]");
  const MachineConfig c = parse_machine_config(text, "rows.toml");
  EXPECT_EQ(with_nodes(c, 8).mesh_height, 1);
  EXPECT_EQ(with_nodes(c, 16).mesh_height, 4);  // no entry: the default shape
  std::string bad(published_machine_config_text());
  bad.replace(bad.find("[node]"), 6, "[topology.shapes]\n8 = [3, 3]\n\n[node]");
  try {
    parse_machine_config(bad, "bad.toml");
    FAIL() << "a 9-node shape for 8 nodes was accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.toml:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("width * height == 8"), std::string::npos) << e.what();
  }
}

TEST(MeshShapes, ParsesWxH) {
  EXPECT_EQ(parse_mesh_shape("8x1").width, 8);
  EXPECT_EQ(parse_mesh_shape("8x1").height, 1);
  EXPECT_THROW(parse_mesh_shape("8"), std::invalid_argument);
  EXPECT_THROW(parse_mesh_shape("x4"), std::invalid_argument);
  EXPECT_THROW(parse_mesh_shape("0x4"), std::invalid_argument);
  EXPECT_THROW(parse_mesh_shape("-2x4"), std::invalid_argument);
}

}  // namespace
}  // namespace gcsim::machine
