// The C entry points of attributes on communicators (MPI 3.1 section 6.7, and MPI-1's names for
// them): keys with copy and delete callbacks, set, get, delete, the predefined callbacks, and the
// predefined attributes, which every communicator answers (MPI_COMM_WORLD's, as the standard
// defines them): MPI_TAG_UB is INT_MAX; MPI_HOST is MPI_PROC_NULL (there is no host process);
// MPI_IO is MPI_ANY_SOURCE (every rank may do I/O: what it prints is kept); MPI_WTIME_IS_GLOBAL
// is 1 (the ranks read one simulated clock).
#include <climits>
#include <utility>
#include <vector>

#include "apps/mpi/c_call.hpp"
#include "apps/mpi/runtime/attributes.hpp"

using namespace gcsim::mpi_layer;

namespace {

const int tag_upper_bound = INT_MAX;
const int host_rank = MPI_PROC_NULL;
const int io_rank = MPI_ANY_SOURCE;
const int wtime_is_global = 1;

const int* predefined_value(int keyval) {
  switch (keyval) {
    case MPI_TAG_UB: return &tag_upper_bound;
    case MPI_HOST: return &host_rank;
    case MPI_IO: return &io_rank;
    case MPI_WTIME_IS_GLOBAL: return &wtime_is_global;
    default: return nullptr;
  }
}

// Calls the key's delete callback on the attribute (comm, keyval) and removes it.
void delete_one(Rank& rank, MPI_Comm comm, int keyval) {
  const Keyval& k = rank.keyvals.of_attribute(keyval);
  void* value = rank.comm(comm).attributes.at(keyval);
  if (k.erase) {
    const int code = k.erase(comm, keyval, value, k.extra_state);
    if (code != MPI_SUCCESS) fail(code, "an attribute's delete callback failed");
  }
  rank.comm(comm).attributes.erase(keyval);  // the callback may have freed other communicators
  rank.keyvals.unused(keyval);
}

void set_attribute(MPI_Comm comm, int keyval, void* value) {
  Rank& rank = Rank::current();
  rank.comm(comm);
  rank.keyvals.live(keyval);
  if (rank.comm(comm).attributes.contains(keyval)) delete_one(rank, comm, keyval);
  rank.comm(comm).attributes[keyval] = value;
  rank.keyvals.used(keyval);
}

}  // namespace

namespace gcsim::mpi_layer {

void copy_attributes(Rank& rank, MPI_Comm from, MPI_Comm to) {
  const std::vector<std::pair<int, void*>> attributes(rank.comm(from).attributes.begin(), rank.comm(from).attributes.end());
  for (const auto& [keyval, value] : attributes) {
    const Keyval k = rank.keyvals.of_attribute(keyval);
    if (!k.copy) continue;
    void* copied = nullptr;
    int flag = 0;
    const int code = k.copy(from, keyval, k.extra_state, value, &copied, &flag);
    if (code != MPI_SUCCESS) fail(code, "MPI_Comm_dup: an attribute's copy callback failed");
    if (!flag) continue;
    rank.comm(to).attributes[keyval] = copied;
    rank.keyvals.used(keyval);
  }
}

void delete_attributes(Rank& rank, MPI_Comm comm) {
  std::vector<int> keys;
  for (const auto& [keyval, value] : rank.comm(comm).attributes) keys.push_back(keyval);
  for (int keyval : keys) {
    if (rank.comm(comm).attributes.contains(keyval)) delete_one(rank, comm, keyval);
  }
}

}  // namespace gcsim::mpi_layer

extern "C" {

int MPI_Comm_create_keyval(MPI_Comm_copy_attr_function* comm_copy_attr_fn,
                           MPI_Comm_delete_attr_function* comm_delete_attr_fn, int* comm_keyval, void* extra_state) {
  return runtime_call([&](Rank& rank) {
    out_arg(comm_keyval) = rank.keyvals.create(Keyval{comm_copy_attr_fn, comm_delete_attr_fn, extra_state});
  });
}

int MPI_Comm_free_keyval(int* comm_keyval) {
  return runtime_call([&](Rank& rank) {
    int& k = out_arg(comm_keyval);
    rank.keyvals.free(k);
    k = MPI_KEYVAL_INVALID;
  });
}

int MPI_Comm_set_attr(MPI_Comm comm, int comm_keyval, void* attribute_val) {
  return runtime_call([&](Rank&) { set_attribute(comm, comm_keyval, attribute_val); });
}

int MPI_Comm_get_attr(MPI_Comm comm, int comm_keyval, void* attribute_val, int* flag) {
  return runtime_call([&](Rank& rank) {
    const Communicator& c = rank.comm(comm);
    int& found = out_arg(flag);
    if (!attribute_val) fail(MPI_ERR_ARG, "null attribute_val");
    found = 0;
    if (const int* value = predefined_value(comm_keyval)) {
      *static_cast<const int**>(attribute_val) = value;
      found = 1;
      return;
    }
    rank.keyvals.of_attribute(comm_keyval);  // MPI_ERR_KEYVAL for a key that never was
    const auto it = c.attributes.find(comm_keyval);
    if (it == c.attributes.end()) return;
    *static_cast<void**>(attribute_val) = it->second;
    found = 1;
  });
}

int MPI_Comm_delete_attr(MPI_Comm comm, int comm_keyval) {
  return runtime_call([&](Rank& rank) {
    rank.keyvals.of_attribute(comm_keyval);
    if (!rank.comm(comm).attributes.contains(comm_keyval)) fail(MPI_ERR_KEYVAL, "the communicator has no such attribute");
    delete_one(rank, comm, comm_keyval);
  });
}

int MPI_Keyval_create(MPI_Copy_function* copy_fn, MPI_Delete_function* delete_fn, int* keyval, void* extra_state) {
  return MPI_Comm_create_keyval(copy_fn, delete_fn, keyval, extra_state);
}
int MPI_Keyval_free(int* keyval) { return MPI_Comm_free_keyval(keyval); }
int MPI_Attr_put(MPI_Comm comm, int keyval, void* attribute_val) { return MPI_Comm_set_attr(comm, keyval, attribute_val); }
int MPI_Attr_get(MPI_Comm comm, int keyval, void* attribute_val, int* flag) {
  return MPI_Comm_get_attr(comm, keyval, attribute_val, flag);
}
int MPI_Attr_delete(MPI_Comm comm, int keyval) { return MPI_Comm_delete_attr(comm, keyval); }

int MPI_COMM_DUP_FN(MPI_Comm oldcomm, int comm_keyval, void* extra_state, void* attribute_val_in,
                    void* attribute_val_out, int* flag) {
  (void)oldcomm, (void)comm_keyval, (void)extra_state;
  *static_cast<void**>(attribute_val_out) = attribute_val_in;
  *flag = 1;
  return MPI_SUCCESS;
}
int MPI_DUP_FN(MPI_Comm oldcomm, int keyval, void* extra_state, void* attribute_val_in, void* attribute_val_out, int* flag) {
  return MPI_COMM_DUP_FN(oldcomm, keyval, extra_state, attribute_val_in, attribute_val_out, flag);
}

}  // extern "C"
