#include "apps/pipeline/option_vocabulary.hpp"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "machine/machine_config.hpp"
#include "machine/network_registry.hpp"
#include "machine/topology.hpp"
#include "parix/backend.hpp"

namespace gcsim::pipeline {

namespace {

// "1..64 on the built-in GC-PowerPlus": the built-in machine's range, read once from its file.
const std::string& builtin_node_range() {
  static const std::string range = [] {
    const machine::MachineConfig c = machine::default_machine_config();
    return fmt::format("1..{} on the built-in GC-PowerPlus", c.nodes);
  }();
  return range;
}

std::string in_words(const std::vector<std::string>& names, std::string_view last) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += i + 1 == names.size() ? last : ", ";
    out += names[i];
  }
  return out;
}

}  // namespace

std::string or_list(const std::vector<std::string>& names) { return in_words(names, " or "); }
std::string and_list(const std::vector<std::string>& names) { return in_words(names, " and "); }

std::string network_model_summaries() {
  std::string out;
  for (const machine::NetworkModelEntry& m : machine::network_models())
    out += fmt::format("{}{}: {}", out.empty() ? "" : "; ", m.name, m.summary);
  return out;
}

std::string topology_choices() { return or_list(machine::topology_names()); }

CLI::Validator each_network_model() {
  return CLI::Validator(
      [](std::string& v) -> std::string {
        std::size_t start = 0;
        for (;;) {
          const std::size_t comma = v.find(',', start);
          const std::string item = v.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
          if (!machine::is_network_model(item))
            return fmt::format("'{}' is not a network model (expected a comma-separated list of {})", item,
                               machine::network_model_list());
          if (comma == std::string::npos) return "";
          start = comma + 1;
        }
      },
      "", "NETWORK_MODELS");
}

CLI::Validator decimal_integer() {
  return CLI::Validator(
      [](std::string& v) -> std::string {
        const std::size_t sign = !v.empty() && (v[0] == '+' || v[0] == '-') ? 1 : 0;
        const bool digits = v.size() > sign && std::all_of(v.begin() + long(sign), v.end(),
                                                           [](unsigned char c) { return std::isdigit(c) != 0; });
        if (!digits) return "'" + v + "' is not a whole decimal number";
        const std::size_t first = std::min(v.find_first_not_of('0', sign), v.size() - 1);
        v.erase(sign, first - sign);  // CLI11 reads a leading 0 as octal
        return "";
      },
      "", "DECIMAL");
}

CLI::Option* add_config_option(CLI::App* cmd, std::string& path, std::string_view what) {
  return cmd->add_option("--config", path, fmt::format("{}; default: the built-in GC-PowerPlus as measured (configs/gc-powerplus-calibrated.toml; "
                                                      "configs/gc-powerplus.toml: as published)", what))
      ->check(CLI::ExistingFile);
}

CLI::Option* add_model_option(CLI::App* cmd, std::string& model, std::string_view what, std::string_view unset) {
  return cmd->add_option("--model", model, fmt::format("{}: {}; default: {}", what, network_model_summaries(), unset))
      ->check(CLI::IsMember(machine::network_model_names()));
}

CLI::Option* add_nodes_option(CLI::App* cmd, int& nodes, std::string_view what_default, int max) {
  return cmd
      ->add_option("--nodes", nodes,
                   fmt::format("Use the first N nodes of the machine ({}; a --config file sets its own), in the GC's mesh "
                               "shape (2=2x1, 4=2x2, 8=4x2, ...); default: {}",
                               builtin_node_range(), what_default))
      ->transform(decimal_integer())
      ->check(CLI::Range(1, max));
}

CLI::Option* add_json_option(CLI::App* cmd, std::string& path, std::string_view what) {
  return cmd->add_option("--json", path, fmt::format("Write {} as JSON", what));
}

CLI::Option* add_trace_option(CLI::App* cmd, std::string& path) {
  return cmd->add_option("--trace", path,
                         "Write a trace of simulated events: FILE.json (Chrome trace-event JSON, opens in Perfetto) with "
                         "FILE.csv and FILE.paje (ViTE) beside it; `gcsim plot FILE.json` draws it");
}

CLI::Option* add_backend_option(CLI::App* cmd, std::string& backend) {
  // Written from the registry, so a backend added (or left out of this build) is described as it is.
  std::string help = "Where the program runs:";
  for (const parix::Backend& b : parix::backends()) help += fmt::format(" {}: {};", b.name, b.summary);
  help.back() = '.';
  return cmd->add_option("--backend", backend, help)->check(CLI::IsMember(parix::backend_names()))->capture_default_str();
}

}  // namespace gcsim::pipeline
