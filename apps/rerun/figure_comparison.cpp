#include "apps/rerun/figure_comparison.hpp"

#include <array>
#include <string_view>

#include <fmt/format.h>

namespace gcsim::rerun {

namespace {

// The provenance block differs by design (command line, cwd, output paths); the paths the run
// reports elsewhere are mapped back to the recorded ones before comparing (recorded_run.hpp).
constexpr std::array<std::string_view, 1> kHostKeys = {"provenance"};

void compare(const nlohmann::json& a, const nlohmann::json& b, const std::string& path, FigureComparison& out) {
  if (a.is_object() && b.is_object()) {
    for (const auto& [key, value] : a.items()) {
      if (is_host_key(key)) continue;
      if (!b.contains(key)) {
        out.differ.push_back(fmt::format("{}/{}: {} -> missing", path, key, value.dump()));
        continue;
      }
      compare(value, b.at(key), path + "/" + key, out);
    }
    for (const auto& [key, value] : b.items())
      if (!is_host_key(key) && !a.contains(key)) out.differ.push_back(fmt::format("{}/{}: missing -> {}", path, key, value.dump()));
    return;
  }
  if (a.is_array() && b.is_array() && a.size() == b.size()) {
    for (std::size_t i = 0; i < a.size(); ++i) compare(a[i], b[i], fmt::format("{}[{}]", path, i), out);
    return;
  }
  ++out.compared;
  if (a != b) out.differ.push_back(fmt::format("{}: {} -> {}", path.empty() ? "/" : path, a.dump(), b.dump()));
}

}  // namespace

bool is_host_key(const std::string& key) {
  for (std::string_view host : kHostKeys)
    if (key == host) return true;
  return key.find("wall") != std::string::npos;  // wall, wall_s, messages_per_wall_s, ...
}

FigureComparison compare_figures(const nlohmann::json& recorded, const nlohmann::json& rerun) {
  FigureComparison out;
  compare(recorded, rerun, "", out);
  return out;
}

}  // namespace gcsim::rerun
