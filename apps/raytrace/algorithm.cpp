#include "apps/raytrace/algorithm.hpp"

#include <array>
#include <cctype>

namespace gcsim::raytrace {

std::span<const Algorithm> paper_algorithms() {
  static constexpr std::array<Algorithm, 6> all{Algorithm::A1, Algorithm::A2, Algorithm::A2p,
                                                Algorithm::A3, Algorithm::A4, Algorithm::B1};
  return all;
}

std::string_view name_of(Algorithm a) {
  switch (a) {
    case Algorithm::A1: return "A1";
    case Algorithm::A2: return "A2";
    case Algorithm::A2p: return "A2p";
    case Algorithm::A3: return "A3";
    case Algorithm::A4: return "A4";
    case Algorithm::B1: return "B1";
    case Algorithm::brute: return "brute";
  }
  return "?";
}

std::string_view paper_name_of(Algorithm a) { return a == Algorithm::A2p ? "A2'" : name_of(a); }

std::string_view description_of(Algorithm a) {
  switch (a) {
    case Algorithm::A1: return "bounding-volume tree only";
    case Algorithm::A2: return "tree + front-to-back child sorting with pruning";
    case Algorithm::A2p: return "per-subregion dynamic subtree";
    case Algorithm::A3: return "subtree + sorting";
    case Algorithm::A4: return "subtree + sorting + subregion uniformity test";
    case Algorithm::B1: return "Arvo-Kirk ray classification (primary rays)";
    case Algorithm::brute: return "every primitive for every ray";
  }
  return "";
}

std::optional<Algorithm> parse_algorithm(std::string_view s) {
  std::string k;
  for (char c : s) k += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (k == "A1") return Algorithm::A1;
  if (k == "A2") return Algorithm::A2;
  if (k == "A2P" || k == "A2'") return Algorithm::A2p;
  if (k == "A3") return Algorithm::A3;
  if (k == "A4") return Algorithm::A4;
  if (k == "B1") return Algorithm::B1;
  if (k == "BRUTE") return Algorithm::brute;
  return std::nullopt;
}

bool uses_subtree(Algorithm a) { return a == Algorithm::A2p || a == Algorithm::A3 || a == Algorithm::A4; }

}  // namespace gcsim::raytrace
