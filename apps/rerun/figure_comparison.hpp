#pragma once
// Whether two run JSONs of the same command report the same simulated figures: every value of the
// documents but the host's (wall-clock times and the host threads beside them, the provenance block).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gcsim::rerun {

struct FigureComparison {
  int compared = 0;                  // simulated figures (leaf values) compared
  std::vector<std::string> differ;  // "/simulated/total_s: 0.1 -> 0.2", one per figure that differs
};

// Whether a key names a host figure rather than a simulated one: "provenance", and every key with
// "wall" in it ("wall", "wall_s", "messages_per_wall_s").
bool is_host_key(const std::string& key);

// recorded and rerun compared leaf by leaf, host keys left out.
FigureComparison compare_figures(const nlohmann::json& recorded, const nlohmann::json& rerun);

}  // namespace gcsim::rerun
