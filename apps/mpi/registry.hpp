#pragma once
// The objects behind one rank's handles. Predefined datatypes, ops and MPI_GROUP_EMPTY are fixed
// and shared; objects a rank creates live in its Registry under handles from first_user_handle
// up, never reused, so a freed handle stays invalid. The C entry points use the calling rank's
// registry: the one a RegistryScope installed on this host thread (the runtime will install each
// rank's as its fiber runs), else this thread's own default one, as for a single process.
#include <unordered_map>

#include "apps/mpi/datatype.hpp"
#include "apps/mpi/error_handling.hpp"
#include "apps/mpi/group.hpp"
#include "apps/mpi/reduction.hpp"

namespace gcsim::mpi_layer {

inline constexpr int first_user_handle = 1000;

template <class T>
class HandleTable {
 public:
  int insert(T object) {
    const int handle = next_++;
    objects_.emplace(handle, std::move(object));
    return handle;
  }
  T* find(int handle) {
    const auto it = objects_.find(handle);
    return it == objects_.end() ? nullptr : &it->second;
  }
  bool erase(int handle) { return objects_.erase(handle) == 1; }
  std::size_t live() const { return objects_.size(); }

 private:
  std::unordered_map<int, T> objects_;
  int next_ = first_user_handle;
};

struct Registry {
  HandleTable<Datatype> datatypes;
  HandleTable<Op> ops;
  HandleTable<Group> groups;
  int world_rank = 0;  // this rank in MPI_COMM_WORLD (MPI_Group_rank)
  HandleTable<UserErrhandler> errhandlers;
  CallInProgress call;             // the entry point this rank is in (error_handling.hpp)
  ErrorRouter* errors = nullptr;   // the runtime's; null: every error is returned
};

Registry& current_registry();
// The runtime switches ranks on one host thread (fibers): it installs the running rank's registry
// each time that rank's fiber resumes (null: this thread's own again).
void install_registry(Registry* r);

class RegistryScope {
 public:
  explicit RegistryScope(Registry& r);
  ~RegistryScope();
  RegistryScope(const RegistryScope&) = delete;
  RegistryScope& operator=(const RegistryScope&) = delete;

 private:
  Registry* previous_;
};

inline bool is_predefined_datatype(MPI_Datatype handle) { return handle >= MPI_CHAR && handle <= MPI_LONG_DOUBLE_INT; }
// The predefined datatypes, indexed by handle (made as the program loads; they live for the process).
extern const Datatype* const predefined_datatype_table;

// The object a handle names, predefined or the registry's; null for an invalid handle. In line:
// every send and receive asks for its type.
inline const Datatype* find_datatype(Registry& r, MPI_Datatype handle) {
  if (is_predefined_datatype(handle)) return predefined_datatype_table + handle;
  return r.datatypes.find(handle);
}
Datatype* find_user_datatype(Registry& r, MPI_Datatype handle);
const Op* find_op(Registry& r, MPI_Op handle);
const Group* find_group(Registry& r, MPI_Group handle);
// Whether type is one of the predefined objects find_datatype returns (they live for the process).
bool is_predefined(const Datatype& type);

}  // namespace gcsim::mpi_layer
