#pragma once
// How fast the host runs a rank's computation compared with the simulated node: host seconds times
// this ratio are node seconds (--compute measured, and the sampled bodies of <gcsim/mpi_ext.h>).
// `gcsim mpirun --host-speed` gives it as a ratio ("4"), as the host's rate ("2Gf": the ratio is
// that rate over the node's rate on the kernel, clock / [ops] daxpy_flop), or "auto": the kernel is
// timed once on this host, the first time the ratio is needed, and the figure kept for the run.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace gcsim::mpi_layer {

struct HostSpeedChoice {
  enum class Kind { automatic, ratio, rate };
  Kind kind = Kind::automatic;
  double value = 0;  // the ratio, or the host's rate in flop/s
  std::string text = "auto";
};

// "auto", a positive ratio, or a rate: a number with f, kf, Mf or Gf (flop/s, as SimGrid writes
// speeds; "flops" may replace "f"). Throws std::invalid_argument saying what was expected.
HostSpeedChoice parse_host_speed(const std::string& text);

// The host's rate on `kernel` in flop/s, timed on the calling thread's CPU time (best of three
// runs of at least 20 ms each). Throws std::invalid_argument for an unknown kernel.
double measure_host_flops(const std::string& kernel);

class HostSpeed {
 public:
  HostSpeed(HostSpeedChoice choice, std::string kernel, double node_flops);
  double ratio();  // measures the kernel on the first call under "auto"
  bool known() const { return ratio_.has_value(); }
  double node_flops() const { return node_flops_; }
  std::string summary() const;  // for the run's summary line
  nlohmann::json to_json() const;

 private:
  HostSpeedChoice choice_;
  std::string kernel_;
  double node_flops_;
  std::optional<double> host_flops_;
  std::optional<double> ratio_;
};

}  // namespace gcsim::mpi_layer
