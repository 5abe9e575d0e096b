#include "apps/render/plan_check.hpp"

#include <cmath>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

namespace gcsim::render {

namespace {

const nlohmann::json& field(const nlohmann::json& j, const char* key, const char* which) {
  if (!j.is_object() || !j.contains(key)) throw std::invalid_argument(fmt::format("the {} JSON has no '{}'", which, key));
  return j.at(key);
}

struct PlanPass {
  bool on = false;
  double seconds = 0, uncertainty = 0;
  const nlohmann::json* entry = nullptr;
};

// Uncertainties of a sum: the parts' absolute ones added (their errors are not independent).
void add(PlanCheckRow& row, double seconds, double relative) {
  const double before = row.predicted * row.uncertainty;
  row.predicted += seconds;
  row.uncertainty = row.predicted > 0 ? (before + seconds * relative) / row.predicted : 0.0;
}

}  // namespace

std::vector<PlanCheckRow> compare_plan_render(const nlohmann::json& plan, const nlohmann::json& render) {
  std::map<std::string, PlanPass> pass;
  for (const nlohmann::json& p : field(plan, "passes", "plan"))
    pass[p.at("name").get<std::string>()] = {p.at("on").get<bool>(), p.at("estimated_seconds_per_node").get<double>(),
                                             p.value("relative_uncertainty", 0.0), &p};
  const double total_s = field(field(render, "simulated", "render"), "total_s", "render").get<double>();
  const nlohmann::json& media = render.contains("media") ? render.at("media") : nlohmann::json::object();
  const double photons_end = media.value("simulated_end_s", 0.0);
  const nlohmann::json& rad = field(render, "radiosity", "render");
  const bool rad_ran = rad.value("ran", false);
  std::vector<PlanCheckRow> rows;
  PlanCheckRow view{"view"}, total{"total"};
  if (pass["media"].on) {
    const PlanPass& m = pass["media"];
    const double photons = m.entry->contains("parts_s") ? m.entry->at("parts_s").at("photons").get<double>() : 0.0;
    if (photons > 0) rows.push_back({"media photons", photons, photons_end, m.uncertainty});
    add(view, m.seconds - photons, m.uncertainty);
  }
  if (pass["radiosity"].on && rad_ran) {
    const double end = rad.at("simulated_end_s").get<double>();
    rows.push_back({"radiosity", pass["radiosity"].seconds, end - photons_end, pass["radiosity"].uncertainty});
  }
  for (const char* name : {"view", "specular", "shadows"})
    if (pass[name].on) add(view, pass[name].seconds, pass[name].uncertainty);
  view.measured = total_s - (rad_ran ? rad.at("simulated_end_s").get<double>() : photons_end);
  rows.push_back(view);
  for (const auto& [name, p] : pass)
    if (p.on) add(total, p.seconds, p.uncertainty);
  total.measured = total_s;
  rows.push_back(total);
  rows.push_back({"memory", field(plan, "memory_peak_bytes", "plan").get<double>(),
                  field(field(render, "memory_peak", "render"), "bytes", "render").get<double>(),
                  plan.value("memory_peak_relative_uncertainty", 0.0)});
  return rows;
}

}  // namespace gcsim::render
