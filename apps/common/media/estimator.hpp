#pragma once
// The distance estimators a user picks (`--estimator`): the paper's three (uniform marching, eq. 6;
// transmittance IS, eq. 9; radiance IS, eq. 20), two beyond it (equiangular for a point light and
// their MIS), and the direct visualisation of the grid (corrected eqs. 17–18).
#include <optional>
#include <string>
#include <string_view>

namespace gcsim::media {

enum class Estimator { uniform, transmittance, radiance, equiangular, mis, grid };

inline constexpr Estimator kAllEstimators[] = {Estimator::uniform, Estimator::transmittance, Estimator::radiance,
                                               Estimator::equiangular, Estimator::mis, Estimator::grid};

inline std::string_view estimator_name(Estimator e) {
  switch (e) {
    case Estimator::uniform: return "uniform";
    case Estimator::transmittance: return "transmittance";
    case Estimator::radiance: return "radiance";
    case Estimator::equiangular: return "equiangular";
    case Estimator::mis: return "mis";
    case Estimator::grid: return "grid";
  }
  return "?";
}

inline std::optional<Estimator> parse_estimator(std::string_view name) {
  for (Estimator e : kAllEstimators)
    if (estimator_name(e) == name) return e;
  return std::nullopt;
}

}  // namespace gcsim::media
