#pragma once
// The collective channel (apps/mpi/collective_channel.hpp) of one communicator over the rank's
// point-to-point, on the communicator's collective context: always eager, so a collective's
// schedule never waits for a receive to be posted before its data can leave.
#include <vector>

#include "apps/mpi/collective_channel.hpp"
#include "apps/mpi/runtime/rank.hpp"

namespace gcsim::mpi_layer {

class RankChannel final : public CollectiveChannel {
 public:
  // call: the collective, named in deadlock reports ("MPI_Bcast(root=0, comm=MPI_COMM_WORLD)").
  RankChannel(Rank& rank, MPI_Comm comm, std::string call);
  int rank() const override { return comm_.rank; }
  int size() const override { return comm_.size(); }
  Handle start_send(int peer, int tag, std::span<const std::byte> data) override;
  Handle start_recv(int peer, int tag, std::span<std::byte> into) override;
  void wait_all(std::span<const Handle> handles) override;
  void charge_reduction(std::size_t bytes) override { rank_.charge_reduction(bytes); }

 private:
  Rank& rank_;
  const Communicator& comm_;
  std::shared_ptr<const std::string> call_;  // shared: every send of the collective names it
};

}  // namespace gcsim::mpi_layer
