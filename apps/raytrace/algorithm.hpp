#pragma once
// The primary-ray algorithms compared in section 3 of the paper, and brute force as reference.
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace gcsim::raytrace {

enum class Algorithm {
  A1,     // BVH only
  A2,     // BVH with front-to-back child sorting and pruning (2.2.2)
  A2p,    // A2' in the paper: per-subregion dynamic subtree (2.2.1), no sorting
  A3,     // subtree and sorting
  A4,     // A3 with the subregion uniformity test and recursive halving (2.2.3)
  B1,     // Arvo-Kirk ray classification for primary rays
  brute,  // every primitive for every ray (tests only)
};

std::span<const Algorithm> paper_algorithms();  // A1 A2 A2p A3 A4 B1
std::string_view name_of(Algorithm a);           // "A2'" is written A2p on the command line
std::string_view paper_name_of(Algorithm a);     // as in the paper's tables: A2'
std::string_view description_of(Algorithm a);
std::optional<Algorithm> parse_algorithm(std::string_view s);  // accepts A2p, A2', a2p, ...
bool uses_subtree(Algorithm a);

}  // namespace gcsim::raytrace
