#include "apps/radiosity/app/solve_options.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "apps/pipeline/list_parsing.hpp"
#include "apps/radiosity/hemicube.hpp"
#include "apps/radiosity/program_preset.hpp"

namespace gcsim::radiosity::app {

namespace {

// --energy: a fraction in [0, 1), with the reason 1 can never be reached.
CLI::Validator shot_fraction() {
  return CLI::Validator(
      [](std::string& v) -> std::string {
        double x = -1;
        try {
          std::size_t used = 0;
          x = std::stod(v, &used);
          if (used != v.size()) return "'" + v + "' is not a number";
        } catch (const std::exception&) {
          return "'" + v + "' is not a number";
        }
        return x >= 0 && x < 1 ? "" : "must be in [0, 1): reflected light keeps some energy unshot forever";
      },
      "in [0, 1)");
}

// Which program runs: a preset, and the two settings of it that are not the solver's.
void add_program_options(CLI::App* cmd, SolveFlags& f) {
  cmd->add_option("--preset", f.preset,
                  "The program: gcsim (gcsim's own: cells dealt cyclically, half side faces, each part merged over "
                  "its own cells, each shooter exchanged alone, the scenes as built) or thesis (the thesis's program, "
                  "the one the default machine was fitted with and `gcsim validate` runs: --cell-assignment block "
                  "--side-faces full --ff-merge fixed-arrays --ff-exchange together --workload thesis-loops "
                  "--comm-time root, K = 2, hemicube 256, 99.9 %; docs/calibration.md). Options given override it")
      ->check(CLI::IsMember(program_preset_names()))
      ->capture_default_str();
  cmd->add_option("--workload", f.workload,
                  "as-built (the scene as built) or thesis-loops (a built-in scene's reflectances times the one "
                  "factor that makes it take table 4.2's loops at --energy, found by bisection on the host, about a "
                  "minute: CORNELL as built takes 254 loops to 99.9 %, the thesis's 302; apps/radiosity/thesis_workload.hpp)")
      ->check(CLI::IsMember({"as-built", "thesis-loops"}))
      ->capture_default_str();
  cmd->add_option("--comm-time", f.comm_time,
                  "Whose communication time the radiosity report and the sweep put next to table 4.5: mean (over "
                  "the processors) or root (processor 0, which every exchange gathers to and scatters from)")
      ->check(CLI::IsMember({"mean", "root"}))
      ->capture_default_str();
}

// What is solved: the scene, the hemicube, the shooters and when to stop.
void add_problem_options(CLI::App* cmd, SolveFlags& f) {
  cmd->add_option("--scene", f.scene, "room, picroom, cornell (thesis table 4.1) or the path of a TOML scene file or a WORLD file")
      ->capture_default_str();
  cmd->add_option("--hemicube", f.hemicube,
                  "Hemicube resolution: pixels across the top face (side faces are half as high). Cost and "
                  "accuracy of the form factors grow with it")
      ->check(CLI::Range(8, 4096))
      ->capture_default_str();
  cmd->add_option("--shooters", f.shooters, "K: patches that shoot per loop, those with the most unshot energy (thesis: 2)")
      ->check(CLI::Range(1, 1 << 20))
      ->capture_default_str();
  cmd->add_option("--energy", f.energy, "Stop once this fraction of the energy has been shot (thesis: 0.999)")
      ->check(shot_fraction())
      ->capture_default_str();
}

// How the nodes share the work and exchange its results.
void add_parallel_options(CLI::App* cmd, SolveFlags& f) {
  cmd->add_option("--parallel", f.parallel,
                  "hemicube-fixed (4.3: hemicube cells spread over the nodes), hemicube-hierarchical (4.5: "
                  "border cells split into four, recursively), patch (4.2.2: each shooter's owner computes "
                  "its whole hemicube)")
      ->check(CLI::IsMember({"hemicube-fixed", "hemicube-hierarchical", "patch"}))
      ->capture_default_str();
  cmd->add_option("--bcast", f.bcast,
                  "All-node broadcast: sequential (everyone to the root in turn and back, table 4.6) or tree "
                  "(leaves to root and back, table 4.7)")
      ->check(CLI::IsMember({"sequential", "tree"}))
      ->capture_default_str();
  cmd->add_flag("--aggregate", f.aggregate,
                "4.4.3: one larger exchange per loop (the replicas choose the shooters themselves and every "
                "shooter's form factors travel together) instead of K + 1 exchanges");
  cmd->add_flag("--keep-links", f.keep_links,
                "Open each link once and reuse it (the thesis opened a connection for every message)");
  cmd->add_option("--levels", f.levels, "hemicube-hierarchical: levels of subdivision below the coarse cells")
      ->check(CLI::Range(1, 6))
      ->capture_default_str();
  cmd->add_option("--cells", f.cells,
                  "Hemicube partition: T x T cells on the top face, T x T/2 per side face (even)")
      ->check(CLI::Range(2, 512))
      ->capture_default_str();
  cmd->add_option("--cell-assignment", f.cell_assignment,
                  "Which cells each node computes: cyclic (node r: cells r, r + N, ...; nearly even work) or block "
                  "(one contiguous region of the hemicube per node, as the thesis's figure 4.1 draws it: the node "
                  "whose region sees most of the scene sets the pace). Same radiosities either way")
      ->check(CLI::IsMember({"cyclic", "block"}))
      ->capture_default_str();
  cmd->add_option("--side-faces", f.side_faces,
                  "The mesh those shares are cut from: half (each side face is its T x T/2 cells above the "
                  "horizon) or full (each side face a whole T x T square whose lower half, below the horizon, "
                  "is empty: five equal faces; apps/radiosity/cell_assignment.hpp). Same radiosities either way")
      ->check(CLI::IsMember({"half", "full"}))
      ->capture_default_str();
  cmd->add_option("--ff-merge", f.merge,
                  "How a node adds up the form factors the exchange brought: own-cells (each part over the cells it "
                  "holds), whole-hemicube (each of the N parts over every cell and element, inside the exchange, "
                  "so it counts as communication: the reading of the thesis's tables 4.5 and 4.8) or fixed-arrays "
                  "(as whole-hemicube over 256 element slots per cell, whatever the scene: tables 4.2 and 4.5; "
                  "apps/radiosity/form_factor_merge.hpp). Same radiosities either way")
      ->check(CLI::IsMember({"own-cells", "whole-hemicube", "fixed-arrays"}))
      ->capture_default_str();
  cmd->add_option("--ff-exchange", f.ff_exchange,
                  "How a loop's form factors travel: per-shooter (one all-node exchange per shooter after the "
                  "proposals: K + 1 per loop) or together (one exchange carries every shooter's: 2 per loop, the "
                  "thesis's 4.4.1 reading, apps/radiosity/form_factor_exchange.hpp). Same radiosities either way")
      ->check(CLI::IsMember({"per-shooter", "together"}))
      ->capture_default_str();
}

// The near field, the shooters' order and the loop limit.
void add_shooting_options(CLI::App* cmd, SolveFlags& f) {
  cmd->add_option("--near-field-ratio", f.near_field_ratio,
                  "Near field: a shooter splits into n x n parts (each shooting its own hemicube of resolution / n) "
                  "until each part is at most this times its centre's distance to the nearest receiver. At the "
                  "defaults two facing unit squares are +4% off their closed form and a closed furnace box within 2% "
                  "(one point, the thesis's: +20% and -8%); 0.5 with --near-field-samples 4 brings both within 1% "
                  "for +22% of CORNELL's time (`gcsim accuracy radiosity`, table 4)")
      ->check(CLI::Range(1e-6, 1e6))
      ->capture_default_str();
  cmd->add_option("--near-field-samples", f.near_field_samples,
                  "Most parts per side a near shooter splits into (a power of two; 1: the thesis's one hemicube at "
                  "the patch centre; fewer where resolution / n would fall below 16 pixels)")
      ->check(CLI::IsMember({1, 2, 4, 8, 16, 32}))
      ->capture_default_str();
  cmd->add_flag("--each-node-projects", f.each_node_projects,
                "Every simulated node projects the shooters on the host itself. By default the first node to "
                "need a shooter's projection computes it and the others reuse it and charge its cost as their "
                "own (computation sampling, as SMPI's): identical results and simulated times, less wall time");
  cmd->add_option("--order", f.order,
                  "How shooters are chosen: energy (the K largest unshot energies, 3.5.2), index (patch order "
                  "without sorting, 4.4.1: saves the proposal exchange but converges more slowly), "
                  "energy-then-index (sort until --sort-until, then index order, 4.4.1)")
      ->check(CLI::IsMember({"energy", "index", "energy-then-index"}))
      ->capture_default_str();
  cmd->add_option("--sort-until", f.sort_until, "energy-then-index: shot fraction at which sorting stops")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--max-steps", f.max_steps, "Give up after this many loops")
      ->check(CLI::Range(1, 1 << 30))
      ->capture_default_str();
}

}  // namespace

void add_solve_options(CLI::App* cmd, SolveFlags& f) {
  add_program_options(cmd, f);
  add_problem_options(cmd, f);
  add_parallel_options(cmd, f);
  add_shooting_options(cmd, f);
}

void apply_preset(const CLI::App& cmd, SolveFlags& f) {
  f.preset_overridden = apply_program_preset(program_preset(f.preset), f, [&cmd](const char* option) { return cmd.count(option) > 0; });
}

ParallelOptions parallel_options(const SolveFlags& f) {
  ParallelOptions o;
  o.solver.hemicube.resolution = f.hemicube;
  o.solver.hemicube.cells_per_side = f.cells;
  o.solver.hemicube.max_shooter_samples = f.near_field_samples;
  o.solver.hemicube.near_field_ratio = f.near_field_ratio;
  o.share_projections = !f.each_node_projects;
  o.solver.shooters = f.shooters;
  o.solver.energy = f.energy;
  o.solver.max_steps = f.max_steps;
  o.solver.order = parse_shooting_order(f.order);
  o.solver.sort_until = f.sort_until;
  o.algorithm = parse_parallel_algorithm(f.parallel);
  o.bcast = f.bcast == "tree" ? parix::BcastAlgo::tree : parix::BcastAlgo::sequential;
  o.aggregate = f.aggregate;
  o.keep_links = f.keep_links;
  o.hierarchical_levels = f.levels;
  o.cell_assignment = parse_cell_assignment(f.cell_assignment);
  o.side_faces = parse_side_faces(f.side_faces);
  o.merge = parse_form_factor_merge(f.merge);
  o.ff_exchange = parse_form_factor_exchange(f.ff_exchange);
  // Fail early, with the reason, on an impossible hemicube / partition combination.
  HemicubeOptions check = o.solver.hemicube;
  if (o.algorithm == ParallelAlgorithm::hemicube_hierarchical) check.hierarchical_levels = f.levels;
  check_hemicube_options(check);
  return o;
}

// "ex,ey,ez,tx,ty,tz[,fov]"
Camera parse_camera(const std::string& s) {
  const std::vector<double> v = pipeline::parse_number_list(s, "--camera", "a number (expected ex,ey,ez,tx,ty,tz[,fov])");
  if (v.size() != 6 && v.size() != 7)
    throw std::invalid_argument(fmt::format("--camera: expected 6 or 7 numbers (ex,ey,ez,tx,ty,tz[,fov]), got {}", v.size()));
  Camera c;
  c.eye = {v[0], v[1], v[2]};
  c.look_at = {v[3], v[4], v[5]};
  if (v.size() == 7) c.fov_y_degrees = v[6];
  if (!(c.fov_y_degrees > 0.01 && c.fov_y_degrees < 179)) throw std::invalid_argument("--camera: field of view must be in (0.01, 179) degrees");
  const double distance = glm::length(c.look_at - c.eye);
  if (!std::isfinite(distance)) throw std::invalid_argument("--camera: eye or target too far out (the distance between them overflows)");
  if (distance == 0) throw std::invalid_argument("--camera: eye and target coincide");
  // The image's vertical is `up` made orthogonal to the view: looking straight along it leaves no vertical.
  const double sine = glm::length(glm::cross((c.look_at - c.eye) / distance, glm::normalize(c.up)));
  if (!(sine > 1e-6))
    throw std::invalid_argument(fmt::format("--camera: the view direction is parallel to the up direction ({},{},{}); "
                                            "look from a point not straight above or below the target",
                                            c.up.x, c.up.y, c.up.z));
  return c;
}

}  // namespace gcsim::radiosity::app
