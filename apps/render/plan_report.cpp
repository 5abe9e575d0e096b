#include "apps/render/plan_report.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace gcsim::render {

namespace {

std::string mib(std::int64_t bytes) { return fmt::format("{:.2f} MiB", double(bytes) / (1 << 20)); }

// "~80.0 s ± 6 %" for a measured figure, "~80.0 s" for a counted one (it has no spread to give).
std::string with_uncertainty(double seconds, double relative, bool measured) {
  if (!measured) return fmt::format("~{:.3g} s", seconds);
  return fmt::format("~{:.3g} s ± {:.0f} %", seconds, std::max(relative * 100, 1.0));
}

std::string needs(const PassPlan& p) {
  std::string out;
  for (PassId d : p.depends_on) out += (out.empty() ? "" : ", ") + std::string(pass_name(d));
  return out.empty() ? "-" : out;
}

// Whether the pass's estimate came from a sample run on the simulated machine, not from counts.
bool is_measured(const PassPlan& p, const CostModel& model) {
  return (p.id == PassId::radiosity && model.radiosity_seconds_per_loop > 0) ||
         (p.id == PassId::media && model.media_seconds > 0) || (measured_by_view_sample(p.id) && model.view_sampled);
}

// Which figures ran on the simulated machine and which are operation counts.
std::string describe_estimate(const Plan& plan, const CostModel& model) {
  const SceneFacts& f = plan.facts;
  std::string out;
  if (model.radiosity_seconds_per_loop > 0)
    out += fmt::format("measured  radiosity: its first loops ran on the simulated machine{}, {:.4g} s each\n"
                       "          (communication and waiting included; each loop priced by the hemicubes its shooters project),\n"
                       "          times ~{:.0f} loops forecast by solving the mesh on the host with a 16-cell hemicube.\n",
                       model.radiosity_deposits ? " from the photons' wall deposits" : "",
                       model.radiosity_seconds_per_loop, expected_loops(f, model));
  if (model.media_seconds > 0) out += "measured  media: " + model.media_measured + "\n";
  if (model.view_sampled) out += "measured  " + model.view_measured + "\n";
  std::string counted;
  for (const PassPlan& p : plan.passes) {
    if (p.on && !is_measured(p, model)) counted += (counted.empty() ? "" : ", ") + std::string(pass_name(p.id));
  }
  if (counted.empty()) return out;
  out += "modeled   " + counted + ": work split evenly over the nodes from the counts above and the machine's [ops]\n"
         "          cycles; communication not counted";
  if (plan.pass(PassId::radiosity).on && model.radiosity_seconds_per_loop <= 0)
    out += fmt::format("; radiosity assumes {:g} shots per patch (~{:.0f} loops of {}) and a {} hemicube",
                       model.shots_per_patch, expected_loops(f, model), model.shooters_per_loop, model.hemicube_resolution);
  if (plan.pass(PassId::media).on && model.media_seconds <= 0)
    out += fmt::format("; media assume {} photons and {} march samples per free path", model.photons, model.march_samples);
  return out + ".\n";
}

}  // namespace

std::string format_plan(const Plan& plan, const machine::MachineConfig& machine, int nodes, const CostModel& model) {
  const SceneFacts& f = plan.facts;
  std::string out = fmt::format("plan      {} on {} ({} nodes)\n", plan.scene_name, machine.name, nodes);
  out += fmt::format("scene     {} shapes in {} objects; radiosity mesh {} patches, {} elements; {} ray-tracing "
                     "primitives; {} emissive surfaces, {} point/spot lights; {} pixels x {} spp\n\n",
                     f.shapes, f.objects, f.patches, f.elements, f.primitives, f.emitters, f.point_lights, f.pixels,
                     f.samples_per_pixel);
  out += fmt::format("{:<10} {:<4} {:>18} {:>12}  {}\n", "pass", "", "time/node", "memory/node", "needs");
  double total = 0;
  std::int64_t peak = 0;
  for (const PassPlan& p : plan.passes) {
    const PassCost c = estimate_pass(p, f, machine, nodes, model);
    const std::int64_t bytes = pass_bytes_per_node(p, f, machine, nodes, model);
    total += c.seconds_per_node;
    peak = std::max(peak, bytes);
    const std::string time = with_uncertainty(c.seconds_per_node, pass_uncertainty(p.id, model), is_measured(p, model));
    out += fmt::format("{:<10} {:<4} {:>18} {:>12}  {}\n", pass_name(p.id), p.on ? "ON" : "off", p.on ? time : "-",
                       p.on ? mib(bytes) : "-",
                       needs(p));
    out += "           " + p.reason + "\n";
    if (!p.detail.empty() && (p.on || p.id == PassId::media)) out += "           " + p.detail + "\n";
  }
  const PeakMemory held = predicted_peak(plan, machine, nodes, model);
  out += fmt::format("\ntotal     ~{:.3g} s per node (largest pass ~{} per node)\n", total, mib(peak));
  out += fmt::format("memory    ~{} ± {:.0f} % at the peak on one node (the photon map with the larger of the\n"
                     "          radiosity pass's replica and hemicube and the view's scene and image)\n",
                     mib(held.bytes), std::max(held.uncertainty * 100, 1.0));
  out += describe_estimate(plan, model);
  return out;
}

nlohmann::json plan_json(const Plan& plan, const machine::MachineConfig& machine, int nodes, const CostModel& model) {
  const SceneFacts& f = plan.facts;
  nlohmann::json j;
  j["scene"] = plan.scene_name;
  j["machine"] = machine.name;
  j["nodes"] = nodes;
  j["counts"] = {{"shapes", f.shapes},         {"objects", f.objects},           {"patches", f.patches},
                 {"elements", f.elements},     {"primitives", f.primitives},     {"emitters", f.emitters},
                 {"point_lights", f.point_lights}, {"pixels", f.pixels},         {"spp", f.samples_per_pixel}};
  j["passes"] = nlohmann::json::array();
  for (const PassPlan& p : plan.passes) {
    const PassCost c = estimate_pass(p, f, machine, nodes, model);
    nlohmann::json needs_list = nlohmann::json::array();
    for (PassId d : p.depends_on) needs_list.push_back(pass_name(d));
    j["passes"].push_back({{"name", pass_name(p.id)}, {"on", p.on}, {"reason", p.reason}, {"detail", p.detail},
                           {"estimate", !p.on ? "none" : is_measured(p, model) ? "measured" : "modeled"},
                           {"needs", needs_list}, {"estimated_seconds_per_node", c.seconds_per_node},
                           {"estimated_bytes_per_node", pass_bytes_per_node(p, f, machine, nodes, model)},
                           {"relative_uncertainty", p.on && is_measured(p, model) ? pass_uncertainty(p.id, model) : 0.0}});
    if (p.id == PassId::media && p.on && model.media_seconds > 0)
      j["passes"].back()["parts_s"] = {{"photons", model.media_photon_seconds}, {"sh_grid", model.media_grid_seconds},
                                       {"marching", model.media_march_seconds}};
  }
  const PeakMemory held = predicted_peak(plan, machine, nodes, model);
  j["memory_peak_bytes"] = held.bytes;
  j["memory_peak_relative_uncertainty"] = held.uncertainty;
  return j;
}

}  // namespace gcsim::render
