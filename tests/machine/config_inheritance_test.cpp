// Machine files that inherit: a child names a base and overrides only the keys it names.
#include "machine/config_inheritance.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "machine/builtin_machines.hpp"
#include "machine/machine_config.hpp"
#include "tests/support/scratch_path.hpp"

namespace gcsim::machine {
namespace {

namespace fs = std::filesystem;

// A fresh directory per test, for files that name each other.
class Inheritance : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const std::string& text) {
    return scratch_.write(name, text);
  }
  std::string error_loading(const std::string& file) {
    try {
      load_machine_config(file);
    } catch (const ConfigError& e) {
      return e.what();
    }
    return "(no error)";
  }
  test_support::ScratchDir scratch_{"gcsim_inherit_"};
  const fs::path& dir_ = scratch_.path();
};

// Every field a file can set, so "same values" means the same machine.
void expect_same_machine(const MachineConfig& a, const MachineConfig& b) {
  EXPECT_EQ(a.nodes, b.nodes);
  EXPECT_EQ(a.mesh_width, b.mesh_width);
  EXPECT_EQ(a.mesh_height, b.mesh_height);
  EXPECT_EQ(a.cpus_per_node, b.cpus_per_node);
  EXPECT_EQ(a.clock_hz, b.clock_hz);
  EXPECT_EQ(a.memory_bytes, b.memory_bytes);
  EXPECT_EQ(a.comm_processors, b.comm_processors);
  EXPECT_EQ(a.links_per_comm_processor, b.links_per_comm_processor);
  EXPECT_EQ(a.cycles_per_op, b.cycles_per_op);
  EXPECT_EQ(a.network_model, b.network_model);
  EXPECT_EQ(a.link_bandwidth, b.link_bandwidth);
  EXPECT_EQ(a.message_setup, b.message_setup);
  EXPECT_EQ(a.network_latency, b.network_latency);
  EXPECT_EQ(a.hop_latency, b.hop_latency);
  EXPECT_EQ(a.connect_base, b.connect_base);
  EXPECT_EQ(a.connect_per_hop, b.connect_per_hop);
  EXPECT_EQ(a.connect_model, b.connect_model);
  EXPECT_EQ(a.connect_block_width, b.connect_block_width);
  EXPECT_EQ(a.connect_block_height, b.connect_block_height);
  EXPECT_EQ(a.packet_bytes, b.packet_bytes);
  EXPECT_EQ(a.shapes.size(), b.shapes.size());
  for (const auto& [n, s] : b.shapes) {
    ASSERT_TRUE(a.shapes.count(n)) << n;
    EXPECT_EQ(a.shapes.at(n).width, s.width);
    EXPECT_EQ(a.shapes.at(n).height, s.height);
  }
}

TEST_F(Inheritance, ChildOverridesOnlyTheKeysItNames) {
  write("gc.toml", std::string(published_machine_config_text()));
  const auto child = write("child.toml", "base = \"gc.toml\"\nname = \"slow\"\n[network]\nlink_bandwidth_mbps = 1.0\n"
                                         "[ops]\nflop = 3\n");
  const MachineConfig c = load_machine_config(child);
  MachineConfig expected = published_machine_config();
  expected.link_bandwidth = 1e6;
  expected.cycles_per_op["flop"] = 3;
  expect_same_machine(c, expected);
  EXPECT_EQ(c.name, "slow");
  EXPECT_EQ(c.source, child);
  EXPECT_GT(c.cycles_per_op.size(), 10u);  // the [ops] table came from the base
}

TEST_F(Inheritance, BuiltinBaseIsTheEmbeddedPublishedFile) {
  const auto child = write("child.toml", "base = \"builtin:gc-powerplus\"\n[topology]\nnodes = 16\nmesh = [4, 4]\n");
  const MachineConfig c = load_machine_config(child);
  MachineConfig expected = published_machine_config();
  expected.nodes = 16;
  expected.mesh_width = expected.mesh_height = 4;
  expect_same_machine(c, expected);
  EXPECT_EQ(c.name, published_machine_config().name);  // not named: inherited
}

// The default is the calibrated file and its two bases, compiled in: the same machine as the
// shipped file, from any working directory, with no file read.
TEST_F(Inheritance, DefaultMachineIsTheCalibratedFileResolvedFromBuiltInCopies) {
  const std::string dir = GCSIM_SOURCE_DIR "/configs/";
  for (std::string_view name : builtin_machine_file_names()) {
    std::ifstream in(dir + std::string(name));
    const std::string shipped((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(builtin_machine_file(name), shipped) << name;
  }
  const MachineConfig shipped = load_machine_config(dir + "gc-powerplus-calibrated.toml");
  const fs::path before = fs::current_path();
  fs::current_path(dir_);  // holds no machine file: a base read from disk would fail
  const MachineConfig d = default_machine_config();
  fs::current_path(before);
  expect_same_machine(d, shipped);
  EXPECT_EQ(d.name, shipped.name);
  EXPECT_EQ(d.calibrated_on, shipped.calibrated_on);
  EXPECT_EQ(d.source, builtin_source("gc-powerplus-calibrated.toml"));
  EXPECT_NE(d.connect_base, published_machine_config().connect_base);
}

TEST_F(Inheritance, BuiltinBaseNamesAnyCompiledInFile) {
  const auto child = write("child.toml", "base = \"builtin:gc-powerplus-calibrated\"\nname = \"mine\"\n");
  expect_same_machine(load_machine_config(child), default_machine_config());
  const auto mech = write("mech.toml", "base = \"builtin:gc-powerplus-mechanisms\"\n");
  EXPECT_EQ(load_machine_config(mech).connect_model, ConnectModel::servers);
  const std::string e = error_loading(write("c.toml", "base = \"builtin:gc-powerplus-fast\"\n"));
  EXPECT_NE(e.find("builtin:gc-powerplus-calibrated"), std::string::npos) << e;  // lists what is built in
}

TEST_F(Inheritance, ChainsOfBasesApplyInOrder) {
  write("a.toml", std::string(published_machine_config_text()));
  write("b.toml", "base = \"a.toml\"\n[network]\nhop_latency_us = 7\nconnect_base_us = 9\n");
  const auto c = load_machine_config(write("c.toml", "base = \"b.toml\"\n[network]\nconnect_base_us = 11\n"));
  EXPECT_EQ(c.hop_latency, 7 * kMicrosecond);
  EXPECT_EQ(c.connect_base, 11 * kMicrosecond);
}

TEST_F(Inheritance, ShippedFilesEqualTheirOldFullCopies) {
  const std::string dir = GCSIM_SOURCE_DIR "/configs/";
  const MachineConfig gc = published_machine_config();
  // The mechanisms file changes only the connection model and the 8-node shape; the calibrated
  // file inherits it and overrides only the five keys gcsim calibrate fitted.
  MachineConfig mechanisms = gc;
  mechanisms.connect_model = ConnectModel::servers;
  mechanisms.connect_block_width = mechanisms.connect_block_height = 4;
  mechanisms.shapes[8] = MeshShape{8, 1};
  expect_same_machine(load_machine_config(dir + "gc-powerplus-mechanisms.toml"), mechanisms);
  const MachineConfig calibrated = load_machine_config(dir + "gc-powerplus-calibrated.toml");
  MachineConfig fitted = mechanisms;
  fitted.connect_base = calibrated.connect_base;
  fitted.connect_per_hop = calibrated.connect_per_hop;
  fitted.link_bandwidth = calibrated.link_bandwidth;
  for (const char* op : {"hemicube_pixel", "form_factor_merge"}) fitted.cycles_per_op[op] = calibrated.cycles_per_op.at(op);
  expect_same_machine(calibrated, fitted);
  EXPECT_EQ(calibrated.calibrated_on, (std::vector<std::string>{"4.6", "4.3@1+32+CORNELL+PICROOM"}));
  MachineConfig big = gc;
  big.nodes = 1024;
  big.mesh_width = big.mesh_height = 32;
  expect_same_machine(load_machine_config(dir + "whatif-1024-nodes.toml"), big);
  MachineConfig fast = gc;
  fast.link_bandwidth = 21.875e6;
  fast.connect_base = 55 * kMicrosecond;
  fast.connect_per_hop = 24 * kMicrosecond;
  expect_same_machine(load_machine_config(dir + "whatif-fast-links.toml"), fast);
}

TEST_F(Inheritance, BadKeyInTheChildNamesTheChildAndItsLine) {
  const auto child = write("child.toml", "base = \"builtin:gc-powerplus\"\n\n[network]\nlink_bandwith_mbps = 1.0\n");
  const std::string e = error_loading(child);
  EXPECT_NE(e.find(child + ":4:"), std::string::npos) << e;
  EXPECT_NE(e.find("link_bandwith_mbps"), std::string::npos) << e;
}

TEST_F(Inheritance, BadValueInTheBaseNamesTheBase) {
  std::string text(published_machine_config_text());
  text.replace(text.find("cpus = 2"), 8, "cpus = -2");
  const auto base = write("base.toml", text);
  const std::string e = error_loading(write("child.toml", "base = \"base.toml\"\n"));
  EXPECT_NE(e.find(base + ":"), std::string::npos) << e;
  EXPECT_NE(e.find("cpus"), std::string::npos) << e;
}

TEST_F(Inheritance, MissingBaseNamesTheLineOfBase) {
  const auto child = write("child.toml", "name = \"x\"\nbase = \"nowhere.toml\"\n");
  const std::string e = error_loading(child);
  EXPECT_NE(e.find(child + ":2:"), std::string::npos) << e;
  EXPECT_NE(e.find("nowhere.toml"), std::string::npos) << e;
  EXPECT_NE(error_loading(write("b.toml", "base = 3\n")).find("'base' must be a string"), std::string::npos);
  EXPECT_NE(error_loading(write("c.toml", "base = \"builtin:cray\"\n")).find("not built in"), std::string::npos);
}

TEST_F(Inheritance, ACycleOfBasesIsAnError) {
  const auto a = write("a.toml", "base = \"b.toml\"\n");
  write("b.toml", "\nbase = \"a.toml\"\n");
  const std::string e = error_loading(a);
  EXPECT_NE(e.find("name each other as base"), std::string::npos) << e;
  EXPECT_NE(error_loading(write("self.toml", "base = \"self.toml\"\n")).find("name each other"), std::string::npos);
}

TEST_F(Inheritance, ChildMaySwitchTheConnectModelOfItsBase) {
  std::string text(published_machine_config_text());
  text.replace(text.find("connect_model = \"parallel\""), 26, "connect_model = \"servers\"\nconnect_server_block = [2, 2]");
  write("servers.toml", text);
  EXPECT_EQ(load_machine_config(write("s.toml", "base = \"servers.toml\"\n")).connect_model, ConnectModel::servers);
  const auto c = load_machine_config(write("c.toml", "base = \"servers.toml\"\n[network]\nconnect_serialized = true\n"));
  EXPECT_EQ(c.connect_model, ConnectModel::serialized);
}

// A child that only resizes its base's connection-server blocks keeps the base's "servers" model
// (it used to drop it and fail with "'connect_server_block' needs connect_model = \"servers\"").
TEST_F(Inheritance, ChildMayResizeTheServerBlocksOfItsBase) {
  std::string text(published_machine_config_text());
  text.replace(text.find("connect_model = \"parallel\""), 26, "connect_model = \"servers\"\nconnect_server_block = [4, 4]");
  write("servers.toml", text);
  const auto c = load_machine_config(write("c.toml", "base = \"servers.toml\"\n[network]\nconnect_server_block = [4, 2]\n"));
  EXPECT_EQ(c.connect_model, ConnectModel::servers);
  EXPECT_EQ(c.connect_block_width, 4);
  EXPECT_EQ(c.connect_block_height, 2);
  // Switching the model still drops the base's block: a parallel child has none to complain about.
  const auto p = load_machine_config(write("p.toml", "base = \"servers.toml\"\n[network]\nconnect_model = \"parallel\"\n"));
  EXPECT_EQ(p.connect_model, ConnectModel::parallel);
  // A block under a base whose model is not "servers" is still refused, naming the child's line.
  const std::string e = error_loading(write("bad.toml", "base = \"builtin:gc-powerplus\"\n[network]\nconnect_server_block = [2, 2]\n"));
  EXPECT_NE(e.find("bad.toml:3:"), std::string::npos) << e;
  EXPECT_NE(e.find("needs connect_model"), std::string::npos) << e;
}

TEST_F(Inheritance, CalibratedFileAsGcsimCalibrateWritesItLoads) {
  write("gc.toml", std::string(published_machine_config_text()));
  const auto fitted = write("fitted.toml",
                            "# written by gcsim calibrate\nbase = \"gc.toml\"\nname = \"GC (calibrated on 4.6)\"\n\n"
                            "[calibration]\nfitted = [\"4.6\"]\n\n[network]\nlink_bandwidth_mbps = 1.71    # fitted\n"
                            "connect_base_us = 540\n");
  const MachineConfig c = load_machine_config(fitted);
  EXPECT_EQ(c.calibrated_on, std::vector<std::string>{"4.6"});
  EXPECT_EQ(c.link_bandwidth, 1.71e6);
  EXPECT_EQ(c.connect_base, 540 * kMicrosecond);
  EXPECT_EQ(c.cycles_per_op, published_machine_config().cycles_per_op);
}

}  // namespace
}  // namespace gcsim::machine
