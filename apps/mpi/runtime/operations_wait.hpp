#pragma once
// A blocked call's text for a deadlock report, made of its operations' calls only when a report
// asks for it: "MPI_Recv(source=1, ...)", "MPI_Wait on MPI_Irecv(...)", "MPI_Sendrecv(source=...)
// and MPI_Sendrecv(dest=...)". The operations stay while the call waits.
#include <string>

#include "apps/mpi/runtime/rank.hpp"

namespace gcsim::mpi_layer {

class OperationsWait final : public parix::WaitDescription {
 public:
  // done_second: the call of a second operation complete without a request (an eager send of
  // MPI_Sendrecv), named in second's place.
  OperationsWait(const Rank& rank, const char* prefix, MPI_Request first, MPI_Request second = MPI_REQUEST_NULL,
                 const CallText* done_second = nullptr)
      : rank_(rank), prefix_(prefix), first_(first), second_(second), done_second_(done_second) {}

  std::string text() const override {
    std::string out = prefix_;
    append(out, first_);
    if (second_ != MPI_REQUEST_NULL || done_second_) {
      out.append(" and ");
      if (done_second_) done_second_->append_to(out);
      else append(out, second_);
    }
    return out;
  }

 private:
  void append(std::string& out, MPI_Request h) const {
    if (const Operation* op = rank_.find_operation(h)) op->call.append_to(out);
  }
  const Rank& rank_;
  const char* prefix_;
  MPI_Request first_, second_;
  const CallText* done_second_;
};

}  // namespace gcsim::mpi_layer
