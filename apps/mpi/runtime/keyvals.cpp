// One rank's attribute keys: creation, lookup, and freeing once no attribute uses a freed key.
#include "apps/mpi/runtime/keyvals.hpp"

#include "apps/mpi/error.hpp"

namespace gcsim::mpi_layer {

int Keyvals::create(Keyval k) {
  const int handle = next_++;
  keys_.emplace(handle, k);
  return handle;
}

Keyval& Keyvals::live(int keyval) {
  Keyval& k = of_attribute(keyval);
  if (k.freed) fail(MPI_ERR_KEYVAL, "the attribute key was freed");
  return k;
}

Keyval& Keyvals::of_attribute(int keyval) {
  const auto it = keys_.find(keyval);
  if (it == keys_.end()) {
    fail(MPI_ERR_KEYVAL, predefined(keyval) ? "a predefined attribute key cannot be set, deleted or freed" : "invalid attribute key");
  }
  return it->second;
}

void Keyvals::free(int keyval) {
  Keyval& k = live(keyval);
  k.freed = true;
  if (k.uses == 0) keys_.erase(keyval);
}

void Keyvals::unused(int keyval) {
  Keyval& k = of_attribute(keyval);
  if (--k.uses == 0 && k.freed) keys_.erase(keyval);
}

}  // namespace gcsim::mpi_layer
