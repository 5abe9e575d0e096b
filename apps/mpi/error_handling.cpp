#include "apps/mpi/error_handling.hpp"

#include <cstring>

#include "apps/mpi/registry.hpp"

namespace gcsim::mpi_layer {

std::string entry_point_name(const char* signature) {
  const char* open = std::strchr(signature, '(');
  if (!open) return signature;
  const char* start = open;
  while (start > signature && start[-1] != ' ' && start[-1] != ':') --start;
  return std::string(start, open);
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
