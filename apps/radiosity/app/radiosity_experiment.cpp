#include "apps/radiosity/app/radiosity_experiment.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "apps/common/scene/scene_catalogue.hpp"
#include "apps/pipeline/failure.hpp"
#include "apps/pipeline/list_parsing.hpp"
#include "apps/pipeline/option_checks.hpp"
#include "apps/radiosity/builtin_scenes.hpp"
#include "apps/radiosity/convergence.hpp"
#include "apps/radiosity/radiosity_output.hpp"

namespace gcsim::radiosity::app {

namespace {

// A scene name that looks like a path must name an existing file (before "unknown scene").
const std::string& checked_scene_name(const std::string& name) {
  pipeline::check_scene_file(name, scene::builtin_scene_names());
  return name;
}

// The preset (and the options that override it) and, when matched, the workload.
void print_program_lines(const SolveFlags& f, const std::optional<LoopMatch>& m, double energy) {
  std::string given;
  for (const std::string& o : f.preset_overridden) given += (given.empty() ? "; given: " : ", ") + o;
  fmt::print("program   --preset {}: {}{}\n", f.preset, program_preset(f.preset).summary, given);
  if (m)
    fmt::print("workload  every reflectance x{:.4f}: {} loops to {:g} % (table 4.2: {}; as built: {})\n", m->scale, m->loops,
               100 * energy, m->thesis_loops, m->loops_as_built);
  else if (f.workload == to_string(Workload::thesis_loops))
    fmt::print("workload  the scene as built (table 4.2 gives no loops for '{}' at {:g} %)\n", f.scene, 100 * energy);
}

}  // namespace

RadiosityExperiment::RadiosityExperiment(const SolveFlags& solve, const RunOutputs& outputs)
    : solve_(solve),
      outputs_(outputs),
      scene_(flatten(load_scene_world(checked_scene_name(solve.scene)))),
      options_(parallel_options(solve)) {
  // Checked before the run, so that a typo does not cost a whole simulation.
  if (!outputs_.camera.empty()) camera_ = parse_camera(outputs_.camera);
  if (!pipeline::list_is_empty(outputs_.snapshots)) {
    if (outputs_.image.empty()) throw std::invalid_argument("--snapshots needs --image (the snapshots are named after it)");
    options_.snapshot_loops = pipeline::parse_int_list(outputs_.snapshots, "--snapshots");
  }
  workload_ = parse_workload(solve_.workload);
  comm_time_ = parse_comm_time_of(solve_.comm_time);
  match_workload();
}

// A built-in scene whose loops table 4.2 gives at this energy is matched to them, as `gcsim
// validate` matches it (same solver options, so the same factor); any other scene runs as built.
void RadiosityExperiment::match_workload() {
  if (workload_ != Workload::thesis_loops) return;
  const std::optional<int> target = thesis_loops(solve_.scene, options_.solver.energy);
  if (!target) return;
  pipeline::ProgressLine progress("workload", 0);
  progress.update(0, fmt::format("matching {} to table 4.2's {} loops", scene_.name, *target));
  match_ = match_loops(scene_, options_.solver, *target);
  scene_ = with_reflectances_scaled(std::move(scene_), match_->scale);
}

nlohmann::json RadiosityExperiment::program_json() const {
  nlohmann::json j = {{"preset", solve_.preset}, {"preset_overridden", solve_.preset_overridden},
                      {"workload", to_string(workload_)}, {"comm_time_of", to_string(comm_time_)}};
  if (match_)
    j["workload_match"] = {{"reflectance_scale", match_->scale}, {"loops", match_->loops},
                           {"thesis_loops", match_->thesis_loops}, {"loops_as_built", match_->loops_as_built}};
  return j;
}

pipeline::RunInputs RadiosityExperiment::run_inputs() const {
  pipeline::RunInputs in;
  in.scene = solve_.scene;
  for (const std::string* f : {&outputs_.image, &outputs_.steps_csv, &outputs_.radiosities})
    if (!f->empty()) in.outputs.push_back(*f);
  for (const int loop : options_.snapshot_loops) in.outputs.push_back(snapshot_path(outputs_.image, loop));
  return in;
}

void RadiosityExperiment::check_outputs() const {
  pipeline::check_writable(outputs_.image, "--image");  // the snapshots go beside it
  pipeline::check_writable(outputs_.steps_csv, "--steps-csv");
  pipeline::check_writable(outputs_.radiosities, "--radiosities");
}

std::optional<std::string> RadiosityExperiment::goal_missed(const pipeline::Outcome& out) const {
  const ParallelOutcome& r = pipeline::outcome_as<RadiosityOutcome>(out).result;
  return convergence_failure(r.converged, r.steps.empty() ? 1.0 : r.steps.back().shot_fraction, options_.solver.energy,
                             int(r.steps.size()), options_.solver.max_steps);
}

std::unique_ptr<pipeline::Outcome> RadiosityExperiment::new_outcome(int) const {
  return std::make_unique<RadiosityOutcome>();
}

parix::Program RadiosityExperiment::program(pipeline::Outcome& out) const {
  RadiosityOutcome& o = pipeline::outcome_as<RadiosityOutcome>(out);
  ParallelOutcome* result = &o.result;
  if (outputs_.progress && pipeline::progress_wanted()) o.progress = std::make_unique<pipeline::ProgressLine>("radiosity", 0);
  ParallelOptions shown = with_shared_projections(options_, o.options);
  // Unshot energy falls about geometrically per loop, so the loops done are log(unshot) over
  // log(unshot at the threshold): a fraction that grows about linearly with the loops.
  shown.on_loop = [&o, goal = std::log(1 - options_.solver.energy)](int loop, double shot) {
    o.loops_done = loop, o.shot_fraction = shot;
    if (!o.progress) return;
    const double fraction = goal < 0 ? std::clamp(std::log(std::max(1 - shot, 1e-300)) / goal, 0.0, 1.0) : 1.0;
    o.progress->update_fraction(fraction, fmt::format("loop {}, {:.4f}% of the energy shot", loop, 100 * shot));
  };
  return [this, result, shown](parix::Processor& p) { radiosity_program(p, scene_, shown, result); };
}

void RadiosityExperiment::report_interrupted(const pipeline::Outcome& out, nlohmann::json& reached) const {
  const RadiosityOutcome& o = pipeline::outcome_as<RadiosityOutcome>(out);
  reached["loops"] = o.loops_done;
  reached["shot_fraction"] = o.shot_fraction;
}

void RadiosityExperiment::after_run(pipeline::Outcome& out) const {
  pipeline::outcome_as<RadiosityOutcome>(out).progress.reset();  // erases the line before the report
}

std::vector<pipeline::MemoryNeed> RadiosityExperiment::node_memory(int, int* processor) const {
  *processor = 0;  // every node holds the same
  return {{"scene replica", replica_bytes(scene_)}, {"hemicube", hemicube_buffer_bytes(hemicube_of(options_))}};
}

std::int64_t RadiosityExperiment::host_memory(int nodes) const {
  // Every replica holds its scene and solver state; the delta form factor tables are built once
  // and shared (shared_delta_form_factors). Measured with whatif-4096-nodes.toml: CORNELL on 2048
  // nodes holds about 127 KB a node more than on 1024 (fiber stacks included), 98 KB counted here.
  return hemicube_host_bytes(hemicube_of(options_)) + pipeline::saturating_product(nodes, 2 * replica_bytes(scene_));
}

void RadiosityExperiment::print_setup(int nodes) const {
  const auto c = scene_.counts();
  const ParallelOptions& o = options_;
  fmt::print("scene     {}: {} instances, {} surfaces, {} patches, {} elements, {} vertices\n", scene_.name, c.instances,
             c.surfaces, c.patches, c.elements, c.vertices);
  fmt::print("solver    {} on {} nodes, bcast {}{}{}{}{}{}{}{}, hemicube {}, {} shooters per loop, energy {}\n",
             to_string(o.algorithm), nodes, solve_.bcast, o.aggregate ? ", aggregated" : "", o.keep_links ? ", links kept" : "",
             o.solver.order == ShootingOrder::energy ? "" : fmt::format(", order {}", to_string(o.solver.order)),
             o.cell_assignment == CellAssignment::cyclic ? "" : ", cells in blocks",
             o.side_faces == SideFaces::half ? "" : ", full side faces",
             o.merge == FormFactorMerge::own_cells        ? ""
             : o.merge == FormFactorMerge::whole_hemicube ? ", parts merged over the whole hemicube"
                                                          : ", parts merged over the whole hemicube in fixed arrays",
             o.ff_exchange == FormFactorExchange::per_shooter ? "" : ", form factors exchanged together",
             o.solver.hemicube.resolution, o.solver.shooters, o.solver.energy);
  const HemicubeOptions& hc = o.solver.hemicube;
  fmt::print("near      a patch wider than {} x its distance to the nearest receiver shoots from up to {} x {} points\n",
             hc.near_field_ratio, hc.max_shooter_samples, hc.max_shooter_samples);
  print_program_lines(solve_, match_, options_.solver.energy);
}

namespace {

nlohmann::json run_json(const Scene& scene, const ParallelOptions& o, const std::string& bcast, const ParallelOutcome& r) {
  const auto c = scene.counts();
  return {{"scene", scene.name},
          {"counts", {{"instances", c.instances}, {"surfaces", c.surfaces}, {"patches", c.patches},
                      {"elements", c.elements}, {"vertices", c.vertices}}},
          {"parallel", to_string(o.algorithm)},
          {"bcast", bcast},
          {"aggregate", o.aggregate},
          {"keep_links", o.keep_links},
          {"cell_assignment", to_string(o.cell_assignment)},
          {"side_faces", to_string(o.side_faces)},
          {"ff_merge", to_string(o.merge)},
          {"ff_exchange", to_string(o.ff_exchange)},
          {"order", to_string(o.solver.order)},
          {"hemicube", o.solver.hemicube.resolution},
          {"near_field", {{"max_samples_per_side", o.solver.hemicube.max_shooter_samples},
                          {"ratio", o.solver.hemicube.near_field_ratio}}},
          {"shooters", o.solver.shooters},
          {"energy_threshold", o.solver.energy},
          {"loops", r.steps.size()},
          {"shot_fraction", r.steps.empty() ? 1.0 : r.steps.back().shot_fraction},
          {"converged", r.converged}};
}

void print_convergence(const ParallelOutcome& r) {
  fmt::print("loops     {} (shot fraction {:.6f}{})\n", r.steps.size(), r.steps.empty() ? 1.0 : r.steps.back().shot_fraction,
             r.converged ? "" : ", threshold NOT reached");
  const Rgb bal = r.energy.emitted + r.energy.injected - r.energy.unshot - r.energy.absorbed - r.energy.escaped - r.energy.in_media;
  fmt::print("energy    emitted {:.6g}, absorbed {:.6g}, unshot {:.6g}, escaped {:.6g}, imbalance {:.3g}\n",
             channel_sum(r.energy.emitted), channel_sum(r.energy.absorbed), channel_sum(r.energy.unshot),
             channel_sum(r.energy.escaped), channel_sum(bal));
}

}  // namespace

void RadiosityExperiment::report(const pipeline::Outcome& out, nlohmann::json& extra) const {
  const ParallelOutcome& r = pipeline::outcome_as<RadiosityOutcome>(out).result;
  print_convergence(r);
  extra["radiosity"] = run_json(scene_, options_, solve_.bcast, r);
  extra["radiosity"].update(program_json());
  if (comm_time_ == CommTimeOf::root) {
    const double root = comm_seconds(out.run, comm_time_);
    fmt::print("comm      {:.6f} s on the root, processor 0 (--comm-time root: table 4.5's reading)\n", root);
    extra["radiosity"]["root_comm_s"] = root;
  }
  if (outputs_.gauss_seidel)
    extra["radiosity"]["gauss_seidel_max_difference"] = compare_with_gauss_seidel(scene_, options_.solver.hemicube, r);
  print_loops_table(r, scene_.name, options_.solver.shooters);
  fmt::print("\n");
  if (!outputs_.steps_csv.empty()) {
    write_steps_csv(outputs_.steps_csv, r);
    fmt::print("csv       {}\n", outputs_.steps_csv);
  }
  if (!outputs_.radiosities.empty()) {
    write_radiosities(outputs_.radiosities, scene_, r.element_radiosity);
    fmt::print("elements  {} (per-element radiosities)\n", outputs_.radiosities);
  }
  if (!outputs_.image.empty()) {
    write_images(scene_, r, outputs_, camera_ ? *camera_ : (scene_.camera ? *scene_.camera : default_camera(scene_)));
    extra["radiosity"]["image"] = outputs_.image;
  }
}

void RadiosityExperiment::print_sweep_setup() const {
  const ParallelOptions& o = options_;
  fmt::print("{}: {} / bcast {}{}{} / hemicube {} / K {} / energy {}\n", scene_.name, to_string(o.algorithm), solve_.bcast,
             o.aggregate ? " aggregated" : "", o.keep_links ? " links kept" : "", o.solver.hemicube.resolution,
             o.solver.shooters, o.solver.energy);
  print_program_lines(solve_, match_, o.solver.energy);
}

std::unique_ptr<pipeline::SweepTable> RadiosityExperiment::sweep_table() const {
  return thesis_sweep_table(scene_, options_, comm_time_, program_json());
}

}  // namespace gcsim::radiosity::app
