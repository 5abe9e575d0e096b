#pragma once
// What `gcsim plan` predicted against what `gcsim render` then took, pass by pass, from their JSON
// (plan_report.hpp's plan_json, the render's --json). The rows are the stages the render reports:
//   media photons  the photon pass (the render's media.simulated_end_s; the plan's photons part)
//   radiosity      the radiosity pass (its end less the photons')
//   view           everything after: the SH grid, the view with its specular and shadow rays and
//                  the media's marching (the plan's view, specular and shadows rows, SH grid, marching)
//   total          the render's simulated time, the plan's rows summed
//   memory         the most one node held (the render's memory_peak.bytes; the plan's memory_peak_bytes)
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gcsim::render {

struct PlanCheckRow {
  std::string stage;
  double predicted = 0, measured = 0;
  double uncertainty = 0;  // the plan's relative uncertainty of the prediction
  double error() const { return measured != 0 ? predicted / measured - 1 : 0.0; }
};

// Throws std::invalid_argument naming the field either JSON lacks.
std::vector<PlanCheckRow> compare_plan_render(const nlohmann::json& plan, const nlohmann::json& render);

}  // namespace gcsim::render
