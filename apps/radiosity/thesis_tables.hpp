#pragma once
// The thesis's measured figures (tables 4.1 to 4.5 and 4.8), copied here so the project carries its
// own reference numbers. Seconds to shoot 99.9% of the energy on the GC-PowerPlus; -1 = not reported.
#include <array>
#include <string_view>

namespace gcsim::radiosity::thesis {

inline constexpr std::array<int, 7> kNodes = {1, 2, 4, 8, 16, 32, 64};

struct SceneFigures {
  std::string_view name;
  std::array<double, 7> time_sequential_bcast;  // table 4.3
  std::array<double, 7> speedup_percent;        // table 4.4 (the 1-node entry is 100 by definition)
  std::array<double, 7> comm_seconds;           // table 4.5 (no 1-node entry: 0)
  std::array<double, 7> time_tree_bcast;        // table 4.8
  std::array<int, 13> loops_for_energy;         // table 4.2 (2 shooters per loop), -1: not reported
};

inline constexpr std::array<double, 13> kEnergyPercent = {10, 20, 30, 40, 50, 60, 70, 80, 90, 95, 99, 99.5, 99.9};

inline constexpr std::array<SceneFigures, 3> kScenes = {{
    {"room", {320, 268, 221, 189, 257, 384, 633}, {100, 119, 145, 169, 125, 83.3, 50.6},
     {0, 25, 44, 73, 180, 357, 588}, {320, 267, 215, 178, 227, 329, 545},
     {4, 7, 10, 12, 16, 19, 25, 33, 41, 44, 54, 59, 73}},
    {"picroom", {398, 280, 232, 203, 296, 429, 721}, {100, 142, 172, 196, 134, 92.8, 55.2},
     {0, 27, 48, 80, 192, 389, 630}, {398, 279, 224, 191, 264, 362, 594},
     {3, 5, 7, 10, 13, 30, 53, 81, 123, 166, 274, 307, 394}},
    {"cornell", {289, 237, 186, 144, 209, 336, 582}, {100, 122, 155, 201, 138, 86.0, 49.7},
     {0, 25, 40, 66, 147, 297, 442}, {289, 236, 180, 122, 177, 289, 490},
     {-1, -1, -1, -1, 1, 4, 13, 30, 71, 104, 183, 216, 302}},
}};

// The figures of a built-in scene (case-insensitive), or nullptr.
inline const SceneFigures* figures_for(std::string_view scene) {
  for (const auto& s : kScenes) {
    if (s.name.size() != scene.size()) continue;
    bool same = true;
    for (std::size_t i = 0; i < scene.size(); ++i)
      same = same && (s.name[i] == (scene[i] >= 'A' && scene[i] <= 'Z' ? char(scene[i] - 'A' + 'a') : scene[i]));
    if (same) return &s;
  }
  return nullptr;
}
inline int node_index(int nodes) {
  for (std::size_t i = 0; i < kNodes.size(); ++i)
    if (kNodes[i] == nodes) return int(i);
  return -1;
}

}  // namespace gcsim::radiosity::thesis
