#include "apps/mpi/error_handling.hpp"

#include <cstring>

#include "apps/mpi/registry.hpp"

namespace gcsim::mpi_layer {

std::string entry_point_name(const char* signature) {
  const char* open = std::strchr(signature, '(');
  if (!open) return signature;  // named by the caller
  const char* start = open;
  while (start > signature && start[-1] != ' ' && start[-1] != ':') --start;
  std::string name(start, open);
  // The entry points' link names are gcsim_MPI_* (include/mpi_names.h); the program wrote MPI_*.
  if (name.starts_with("gcsim_MPI_")) name.erase(0, 6);
  return name;
}

CallScope::CallScope(Registry& r, const char* signature) : registry_(r) {
  if (++registry_.call.depth == 1) registry_.call = {1, signature, MPI_COMM_WORLD, false};
}

CallScope::~CallScope() { --registry_.call.depth; }

int CallScope::raise(const Error& e) {
  const CallInProgress& call = registry_.call;
  if (call.depth > 1 || !registry_.errors) return e.code();
  return registry_.errors->raise(call.signature, call.target, e);
}

}  // namespace gcsim::mpi_layer
