#include "apps/calibration/app/prediction_flags.hpp"

#include <fmt/format.h>

#include "apps/pipeline/csv_comment.hpp"
#include "apps/pipeline/option_vocabulary.hpp"

namespace gcsim::calibration::app {

void add_predict_options(CLI::App* cmd, PredictFlags& f) {
  f.command = cmd;
  pipeline::add_model_option(cmd, f.model, "Network model for every run");
  cmd->add_option("--preset", f.preset,
                  "Radiosity tables: the program the runs simulate, as `gcsim run radiosity --preset` runs it: thesis "
                  "(the thesis's program, every default below) or gcsim (gcsim's own: cells cyclic, half side faces, "
                  "own-cells merge, per-shooter exchanges, scenes as built); options given override it")
      ->check(CLI::IsMember(radiosity::program_preset_names()))
      ->capture_default_str();
  cmd->add_option("--hemicube", f.hemicube, "Radiosity tables: hemicube resolution of the runs")
      ->check(CLI::Range(8, 4096))
      ->capture_default_str();
  cmd->add_option("--energy", f.energy, "Radiosity tables: shot fraction at which a run stops (the thesis: 0.999)")
      ->check(CLI::Range(0.5, 0.99999))
      ->capture_default_str();
  cmd->add_option("--cell-assignment", f.cell_assignment,
                  "Radiosity tables: which hemicube cells each node computes: block (one region of the hemicube per "
                  "node, as the thesis's figure 4.1 draws it; fitted on 4.6 and two rows of 4.3 it predicts the other "
                  "radiosity cells better than cyclic: docs/calibration.md) or cyclic (`gcsim run radiosity`'s default)")
      ->check(CLI::IsMember({"cyclic", "block"}))
      ->capture_default_str();
  cmd->add_option("--side-faces", f.side_faces,
                  "Radiosity tables: the mesh the blocks are cut from: full (each side face a whole square whose "
                  "lower half, below the horizon, is empty: five equal faces; what the thesis's 2-, 4- and 8-node "
                  "rows imply together: docs/calibration.md) or half (`gcsim run radiosity`'s default)")
      ->check(CLI::IsMember({"half", "full"}))
      ->capture_default_str();
  cmd->add_option("--ff-merge", f.merge,
                  "Radiosity tables: how each node adds up the exchanged form factors: fixed-arrays (each of the N "
                  "parts as an array over every cell and 256 element slots, whatever the scene, counted as "
                  "communication: what tables 4.5 and 4.8 imply together, and 4.2 with 4.5 that it does not grow with "
                  "the elements; docs/calibration.md), whole-hemicube (the same over the scene's elements) or "
                  "own-cells (`gcsim run radiosity`'s default)")
      ->check(CLI::IsMember({"own-cells", "whole-hemicube", "fixed-arrays"}))
      ->capture_default_str();
  cmd->add_option("--ff-exchange", f.ff_exchange,
                  "Radiosity tables: together (2 exchanges per loop: the proposals, then every shooter's form factors "
                  "in one, the thesis's 4.4.1 \"two synchronizations per loop\"; docs/calibration.md) or per-shooter "
                  "(K + 1: each shooter's form factors on their own, `gcsim run radiosity`'s default)")
      ->check(CLI::IsMember({"per-shooter", "together"}))
      ->capture_default_str();
  cmd->add_option("--workload", f.workload,
                  "Radiosity tables: thesis-loops (each scene's reflectances scaled by the one factor that makes it "
                  "take table 4.2's loops at --energy, since a run's time is its loops times the machine's time per "
                  "loop: CORNELL as built takes 254 loops to 99.9 % where the thesis's took 302; docs/calibration.md) "
                  "or as-built (the scenes as `gcsim run radiosity` builds them)")
      ->check(CLI::IsMember({"thesis-loops", "as-built"}))
      ->capture_default_str();
  cmd->add_option("--comm-time", f.comm_time,
                  "Radiosity tables: whose communication time table 4.5 reports: root (processor 0, which every "
                  "exchange gathers to and scatters from; the thesis does not say whose time it printed: README, "
                  "Calibration) or mean (over the processors, as `gcsim run radiosity` prints it)")
      ->check(CLI::IsMember({"root", "mean"}))
      ->capture_default_str();
  cmd->add_option("--jobs", f.jobs, "Simulations run side by side on this many host threads")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
}

void apply_preset(PredictFlags& f) {
  const CLI::App* cmd = f.command;
  radiosity::apply_program_preset(radiosity::program_preset(f.preset), f,
                                  [cmd](const char* option) { return cmd && cmd->count(option) > 0; });
}

std::string non_default_flags(const PredictFlags& f) {
  const PredictFlags d(radiosity::program_preset(f.preset));
  std::string out;
  if (f.preset != PredictFlags().preset) out += " --preset " + f.preset;
  if (f.model != d.model) out += " --model " + f.model;
  if (f.hemicube != d.hemicube) out += fmt::format(" --hemicube {}", f.hemicube);
  if (f.energy != d.energy) out += fmt::format(" --energy {}", f.energy);
  if (f.cell_assignment != d.cell_assignment) out += " --cell-assignment " + f.cell_assignment;
  if (f.side_faces != d.side_faces) out += " --side-faces " + f.side_faces;
  if (f.merge != d.merge) out += " --ff-merge " + f.merge;
  if (f.ff_exchange != d.ff_exchange) out += " --ff-exchange " + f.ff_exchange;
  if (f.workload != d.workload) out += " --workload " + f.workload;
  if (f.comm_time != d.comm_time) out += " --comm-time " + f.comm_time;
  return out;
}

cal::PredictionSettings settings(const PredictFlags& f) {
  cal::PredictionSettings s;
  s.model = f.model;
  s.hemicube = f.hemicube;
  s.energy = f.energy;
  s.cell_assignment = radiosity::parse_cell_assignment(f.cell_assignment);
  s.side_faces = radiosity::parse_side_faces(f.side_faces);
  s.merge = radiosity::parse_form_factor_merge(f.merge);
  s.ff_exchange = radiosity::parse_form_factor_exchange(f.ff_exchange);
  s.jobs = f.jobs;
  s.match_thesis_loops = f.workload == "thesis-loops";
  s.comm_time_of = cal::parse_comm_time_of(f.comm_time);
  return s;
}

std::string workload_lines(const cal::Predictor& p, double energy, const std::string& prefix) {
  std::string out;
  for (const auto& [scene, m] : p.loop_matches())
    out += fmt::format("{}{}: every reflectance x{:.4f}, {} loops to {:g} % (table 4.2: {}; as built: {})\n", prefix, scene,
                       m.scale, m.loops, 100 * energy, m.thesis_loops, m.loops_as_built);
  return out;
}

std::string cells_comment(const std::string& command, const machine::MachineConfig& c,
                          const std::vector<cal::CellComparison>& cells, const std::string& model) {
  int lo = 0, hi = 0;
  for (const cal::CellComparison& cell : cells) {
    lo = lo == 0 ? cell.nodes : std::min(lo, cell.nodes);
    hi = std::max(hi, cell.nodes);
  }
  const std::string nodes = lo == hi ? std::to_string(lo) : fmt::format("{}-{}", lo, hi);
  return pipeline::csv_comment(command, c.name, nodes, model.empty() ? c.network_model : model);
}

}  // namespace gcsim::calibration::app
