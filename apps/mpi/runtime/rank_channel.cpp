#include "apps/mpi/runtime/rank_channel.hpp"

namespace gcsim::mpi_layer {

RankChannel::RankChannel(Rank& rank, MPI_Comm comm, std::string call)
    : rank_(rank), comm_(rank.comm(comm)), call_(std::make_shared<const std::string>(std::move(call))) {}

CollectiveChannel::Handle RankChannel::start_send(int peer, int tag, std::span<const std::byte> data) {
  return rank_.start_send(comm_, comm_.collective_context(), peer, tag, data, SendMode::buffered, CallText::shared(call_));
}

CollectiveChannel::Handle RankChannel::start_recv(int peer, int tag, std::span<std::byte> into) {
  return rank_.start_raw_recv(comm_, comm_.collective_context(), peer, tag, into);
}

void RankChannel::wait_all(std::span<const Handle> handles) {
  const auto all_done = [&] {
    for (Handle h : handles) {
      if (!rank_.test(h)) return false;
    }
    return true;
  };
  if (CollectiveProgress* schedule = rank_.running_schedule()) {  // a non-blocking one: yield, never block
    const std::vector<MPI_Request> waiting(handles.begin(), handles.end());
    while (!all_done()) schedule->yield(waiting);
  } else {
    rank_.wait_until(all_done, *call_);
  }
  std::string mismatch;
  int error = MPI_SUCCESS;
  for (Handle h : handles) {
    MPI_Request r = h;
    const std::size_t expected = rank_.operation(r).raw.size();
    MPI_Status status{};
    const int code = rank_.finish(r, &status);
    if (code == MPI_SUCCESS || error != MPI_SUCCESS) continue;
    error = code;
    mismatch = *call_ + ": a block of " + std::to_string(status.gcsim_bytes) + " bytes from rank " +
               std::to_string(status.MPI_SOURCE) + " where this rank expects " + std::to_string(expected) +
               " (the ranks' counts or datatypes disagree)";
  }
  if (error != MPI_SUCCESS) fail(error, mismatch.c_str());
}

}  // namespace gcsim::mpi_layer
