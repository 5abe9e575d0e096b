#pragma once
// A blocked call's text for a deadlock report, made of its operations' calls only when a report
// asks for it: "MPI_Recv(source=1, ...)", "MPI_Wait on MPI_Irecv(...)", "MPI_Sendrecv(source=...)
// and MPI_Sendrecv(dest=...)". The operations stay while the call waits.
#include <string>

#include "apps/mpi/runtime/rank.hpp"

namespace gcsim::mpi_layer {

class OperationsWait final : public parix::WaitDescription {
 public:
  OperationsWait(const Rank& rank, const char* prefix, MPI_Request first, MPI_Request second = MPI_REQUEST_NULL)
      : rank_(rank), prefix_(prefix), first_(first), second_(second) {}

  std::string text() const override {
    std::string out = prefix_;
    append(out, first_);
    if (second_ != MPI_REQUEST_NULL) {
      out.append(" and ");
      append(out, second_);
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
};

}  // namespace gcsim::mpi_layer
