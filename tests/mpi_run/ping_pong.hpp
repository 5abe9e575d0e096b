#pragma once
// A ping-pong between two ranks of a simulated run, timed with MPI_Wtime: the tests that check a
// round trip against the analytic model's formula share it.
#include <vector>

#include "apps/mpi/include/mpi.h"
#include "apps/mpi/runtime/rank.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::mpi_layer {

// Rank 0 and rank `peer` exchange `bytes` bytes `reps` times after one warm-up exchange.
inline double measured_round_trip(const parix::SimulationOptions& o, int peer, int bytes, int reps) {
  double round_trip = 0;
  parix::run_simulated(o, [&](parix::Processor& p) {
    Rank rank(p, o.config.mpi);
    rank.install();
    MPI_Init(nullptr, nullptr);
    std::vector<char> buffer(static_cast<std::size_t>(bytes) + 1);
    const int me = p.id();
    if (me == 0 || me == peer) {
      const int other = me == 0 ? peer : 0;
      double start = 0;
      for (int i = 0; i <= reps; ++i) {
        if (i == 1) start = MPI_Wtime();
        if (me == 0) {
          MPI_Send(buffer.data(), bytes, MPI_CHAR, other, 0, MPI_COMM_WORLD);
          MPI_Recv(buffer.data(), bytes, MPI_CHAR, other, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        } else {
          MPI_Recv(buffer.data(), bytes, MPI_CHAR, other, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
          MPI_Send(buffer.data(), bytes, MPI_CHAR, other, 0, MPI_COMM_WORLD);
        }
      }
      if (me == 0) round_trip = (MPI_Wtime() - start) / reps;
    }
    install_registry(nullptr);  // no MPI_Finalize: its barrier would involve the idle ranks' time only
  });
  return round_trip;
}

}  // namespace gcsim::mpi_layer
