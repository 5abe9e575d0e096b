#include "apps/calibration/config_overrides.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "machine/builtin_machines.hpp"
#include "machine/input_file.hpp"

namespace gcsim::calibration {
namespace {

// The numeric keys of [node] and [network] a machine file may hold; [ops] keys are the file's own.
const std::vector<std::string> kNodeKeys = {"clock_mhz", "memory_mb"};
const std::vector<std::string> kNetworkKeys = {"link_bandwidth_mbps", "message_setup_us", "network_latency_us",
                                               "hop_latency_us",      "connect_base_us",  "connect_per_hop_us",
                                               "packet_bytes"};
const std::vector<std::string> kCommCpuKeys = {"send_us", "recv_us", "connect_us", "copy_ns_per_byte"};

std::pair<std::string, std::string> split_key(const std::string& key) {
  const auto dot = key.find('.');
  if (dot == std::string::npos) return {"", key};
  return {key.substr(0, dot), key.substr(dot + 1)};
}

}  // namespace

MachineFile::MachineFile(const std::filesystem::path& file) {
  if (file.empty()) {
    text_ = std::string(machine::builtin_machine_file(machine::kDefaultMachineFile));
    source_ = machine::builtin_source(machine::kDefaultMachineFile);
    base_ = machine::default_machine_config();
    return;
  }
  base_ = machine::load_machine_config(file);  // first: it refuses what is not a regular file or too deep
  machine::InputFile in = machine::read_input_file(file, machine::kMaxTomlFileBytes);
  if (!in.ok()) throw machine::ConfigError(file.string(), 0, "cannot open the machine file: it " + in.error);
  text_ = std::move(in.text);
  source_ = file.string();
}

std::vector<std::string> MachineFile::free_keys() const {
  std::vector<std::string> keys;
  for (const auto& k : kNodeKeys) keys.push_back("node." + k);
  for (const auto& k : kNetworkKeys) keys.push_back("network." + k);
  for (const auto& k : kCommCpuKeys) keys.push_back("comm_cpu." + k);
  for (const auto& [op, cycles] : base_.cycles_per_op) keys.push_back("ops." + op);
  return keys;
}

void MachineFile::check_free_key(const std::string& key) const {
  for (const auto& k : free_keys())
    if (k == key) return;
  std::string list;
  for (const auto& k : free_keys()) list += (list.empty() ? "" : ", ") + k;
  throw std::invalid_argument(fmt::format("--free: '{}' is not a numeric key of {} (expected one of: {})", key, source_, list));
}

double MachineFile::value(const std::string& key) const {
  check_free_key(key);
  const auto [table, name] = split_key(key);
  const machine::MachineConfig& c = base_;
  if (table == "ops") return c.cycles_per_op.at(name);
  if (table == "comm_cpu") {
    if (name == "copy_ns_per_byte") return c.comm_cpu.seconds_per_byte * 1e9;
    return machine::to_microseconds(name == "send_us" ? c.comm_cpu.send
                                    : name == "recv_us" ? c.comm_cpu.recv
                                                        : c.comm_cpu.connect);
  }
  if (name == "clock_mhz") return c.clock_hz / 1e6;
  if (name == "memory_mb") return static_cast<double>(c.memory_bytes) / (1024.0 * 1024.0);
  if (name == "link_bandwidth_mbps") return c.link_bandwidth / 1e6;
  if (name == "packet_bytes") return static_cast<double>(c.packet_bytes);
  const machine::SimTime t = name == "message_setup_us"     ? c.message_setup
                             : name == "network_latency_us" ? c.network_latency
                             : name == "hop_latency_us"     ? c.hop_latency
                             : name == "connect_base_us"    ? c.connect_base
                                                            : c.connect_per_hop;
  return machine::to_microseconds(t);
}

machine::MachineConfig MachineFile::with(const std::map<std::string, double>& values) const {
  toml::table root = toml::parse(text_, source_);
  for (const auto& [key, v] : values) {
    check_free_key(key);
    const auto [table, name] = split_key(key);
    if (!root.contains(table)) root.insert(table, toml::table{});
    toml::table* t = root[table].as_table();
    if (!t) throw std::invalid_argument(fmt::format("{}: '{}' is not a table", source_, table));
    if (name == "packet_bytes") t->insert_or_assign(name, static_cast<std::int64_t>(std::llround(v)));
    else t->insert_or_assign(name, v);
  }
  std::stringstream out;
  out << root;
  return machine::parse_machine_config(out.str(), source_);
}

}  // namespace gcsim::calibration
