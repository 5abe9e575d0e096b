#pragma once
// Progressive refinement radiosity (thesis section 3.5.2, after Cohen et al. 1988) with
// substructuring: patches shoot, elements receive. Each step the K patches with the largest unshot
// energy (delta B times A, summed over r, g, b) shoot; for shooter i and element e
//     delta Rad_e = rho_e * delta B_i * F_ie * A_i / A_e,
// and the element's patch gains delta Rad_e * A_e / A_p of unshot radiosity.
// The state is plain data so that every node of a parallel run can hold a replica of it.
#include <cstdint>
#include <functional>
#include <string>
#include <span>
#include <vector>

#include "apps/radiosity/hemicube.hpp"
#include "apps/radiosity/op_counts.hpp"
#include "apps/radiosity/path_transmittance.hpp"
#include "apps/radiosity/scene.hpp"

namespace gcsim::radiosity {

// emitted + injected = unshot + absorbed + escaped + in_media at every step.
struct EnergyBalance {
  Rgb emitted{0.0};   // sum of E * A
  Rgb injected{0.0};  // power received before the solve (SolverOptions::received)
  Rgb unshot{0.0};    // sum of delta B * A still to shoot
  Rgb absorbed{0.0};  // (1 - rho) of what elements received
  Rgb escaped{0.0};   // shot energy no element caught (open scenes)
  Rgb in_media{0.0};  // caught energy that a participating medium took on the way (PathTransmittance)
};

class ProgressiveState {
 public:
  // media: what lies between patches and elements (null: nothing, the thesis's radiosity).
  // received: power per element arriving before the solve (null or all zero: none); each element
  // absorbs 1 - rho of it and starts with rho of it as radiosity and as its patch's unshot energy.
  explicit ProgressiveState(const Scene& scene, const PathTransmittance* media = nullptr,
                            const std::vector<Rgb>* received = nullptr);

  // The K patches with the largest unshot energy, largest first (ties: lower index); only patches
  // with unshot energy > 0.
  std::vector<int> select_shooters(int k, OpCounts& ops) const;
  // Thesis 4.4.1: the next K patches with unshot energy > 0 in index order, cycling, without
  // sorting (so that a parallel run needs no exchange to choose them). Advances the cursor.
  std::vector<int> select_in_index_order(int k, OpCounts& ops);
  // Unshot energy of a patch (delta B * A summed over channels): what selection sorts by.
  double unshot_energy(int patch) const { return channel_sum(unshot_[patch]) * scene_->patches[patch].area; }
  // Shoots every patch in `shooters` with the unshot radiosity it had before the step, using
  // rows[k][e] = F(shooters[k] -> e).
  void shoot(std::span<const int> shooters, std::span<const std::vector<double>> rows, OpCounts& ops);

  // 1 - unshot / (the unshot energy at the start) (channel sums): the fraction of the energy shot so
  // far (table 4.2); the start is the emitted energy plus what received power adds.
  double shot_fraction() const;
  const std::vector<Rgb>& element_radiosity() const { return element_b_; }
  const std::vector<Rgb>& patch_unshot() const { return unshot_; }
  std::vector<Rgb> patch_radiosity() const;  // area-weighted mean of its elements
  const EnergyBalance& energy() const { return energy_; }
  int steps() const { return steps_; }

 private:
  void receive(const std::vector<Rgb>& received);
  Rgb total_unshot() const;  // sum of delta B * A over the patches

  const Scene* scene_;
  const PathTransmittance* media_;
  std::vector<Rgb> element_b_;
  std::vector<Rgb> unshot_;  // per patch
  EnergyBalance energy_;
  double emitted_sum_ = 0;
  int steps_ = 0;
  int cursor_ = 0;  // next patch index for select_in_index_order
};

// How shooters are chosen (thesis 3.5.2 and 4.4.1).
enum class ShootingOrder {
  energy,            // the K largest unshot energies: sorting, the thesis's method
  index,             // patch index order, no sorting (4.4.1: converges more slowly)
  energy_then_index  // sort until the shot fraction reaches sort_until, then index order (4.4.1)
};
ShootingOrder parse_shooting_order(const std::string& s);  // throws std::invalid_argument
const char* to_string(ShootingOrder o);

struct SolverOptions {
  HemicubeOptions hemicube;
  int shooters = 2;          // K: patches shooting per step (the thesis uses 2)
  double energy = 0.999;     // stop once this fraction of the energy has been shot
  int max_steps = 1000000;   // safety net for reflectances near 1
  ShootingOrder order = ShootingOrder::energy;
  double sort_until = 0.9;   // energy_then_index: sort while the shot fraction is below this
  // Participating media between the surfaces (apps/render supplies them); null: none. Not owned.
  const PathTransmittance* media = nullptr;
  // Power (per channel, one per element) that reaches the elements by paths radiosity does not
  // transport, before the solve (apps/render: light the media scatter onto the walls); the solve
  // carries on what they reflect; the parallel solve charges an element_update per element for
  // taking it. Null: none. Not owned.
  const std::vector<Rgb>* received = nullptr;
  // The host solve (solve_progressive) keeps each shooter's form-factor row, with what computing it
  // counted, up to this many bytes, and shoots a patch again from its kept row: the row depends on
  // the shooter alone, so the solution and the counts are the same bit for bit. Progressive
  // radiosity shoots the same patches again and again (CORNELL at a 16-cell hemicube: 515 shots of
  // 111 patches). 0: every row computed. The parallel solve does not read it.
  std::int64_t row_memo_bytes = 64 << 20;
};

// Whether this step sorts by energy (true) or takes the index order.
inline bool sorts_this_step(const SolverOptions& o, double shot_fraction) {
  return o.order == ShootingOrder::energy || (o.order == ShootingOrder::energy_then_index && shot_fraction < o.sort_until);
}

struct StepRecord {
  int step;                  // 1-based
  double shot_fraction;      // after the step
  std::vector<int> shooters;
};

struct SolveResult {
  ProgressiveState state;
  std::vector<StepRecord> steps;
  bool converged = false;    // reached the energy threshold (false: max_steps or nothing left)
};

// The sequential solver: select, compute the hemicube rows, shoot, until the threshold.
SolveResult solve_progressive(const Scene& scene, const SolverOptions& options, OpCounts* ops = nullptr,
                              const std::function<void(const StepRecord&, const ProgressiveState&)>& on_step = {});

}  // namespace gcsim::radiosity
