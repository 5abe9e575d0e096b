#pragma once
// One rank's attribute keys (MPI 3.1 section 6.7.2): the copy and delete callbacks and extra state
// each key was created with. A freed key stays behind its attributes until the last is deleted, as
// the standard asks ("the key is freed when no attribute uses it"); the handle is invalid for new
// uses at once. User keys are numbered from 1000 up, never reused; the predefined ones (MPI_TAG_UB
// ... MPI_WTIME_IS_GLOBAL) are 1-4.
#include <map>

#include "apps/mpi/include/mpi.h"

namespace gcsim::mpi_layer {

struct Keyval {
  MPI_Comm_copy_attr_function* copy = nullptr;      // null: not copied by MPI_Comm_dup
  MPI_Comm_delete_attr_function* erase = nullptr;   // null: nothing to call
  void* extra_state = nullptr;
  int uses = 0;        // attributes set with it
  bool freed = false;  // MPI_Comm_free_keyval called
};

class Keyvals {
 public:
  int create(Keyval k);
  // The key a user handle names, not freed; MPI_ERR_KEYVAL otherwise (predefined ones included).
  Keyval& live(int keyval);
  // The key behind an attribute, freed or not (its callbacks still run).
  Keyval& of_attribute(int keyval);
  void free(int keyval);  // MPI_ERR_KEYVAL for a predefined or invalid one
  void used(int keyval) { ++of_attribute(keyval).uses; }
  void unused(int keyval);  // an attribute is gone; drops a freed key with no more uses
  static bool predefined(int keyval) { return keyval >= MPI_TAG_UB && keyval <= MPI_WTIME_IS_GLOBAL; }

 private:
  std::map<int, Keyval> keys_;
  int next_ = 1000;
};

}  // namespace gcsim::mpi_layer
