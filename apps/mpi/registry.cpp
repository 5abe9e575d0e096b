#include "apps/mpi/registry.hpp"

#include <functional>
#include <vector>

#include "apps/mpi/type_constructors.hpp"

namespace gcsim::mpi_layer {
namespace {

static_assert(static_cast<int>(PredefinedOp::Max) == MPI_MAX && static_cast<int>(PredefinedOp::NoOp) == MPI_NO_OP &&
              static_cast<int>(PredefinedOp::Minloc) == MPI_MINLOC);

thread_local Registry* installed = nullptr;

// Indexed by handle: MPI_CHAR..MPI_PACKED, then the pair types.
const std::vector<Datatype>& predefined_datatypes() {
  static const std::vector<Datatype> types = [] {
    std::vector<Datatype> v(MPI_LONG_DOUBLE_INT + 1);
    for (int i = 0; i < basic_type_count; ++i) v[handle_of_basic(static_cast<Basic>(i))] = Datatype::of_basic(static_cast<Basic>(i));
    for (MPI_Datatype pair = MPI_FLOAT_INT; pair <= MPI_LONG_DOUBLE_INT; ++pair) v[pair] = pair_type(pair);
    return v;
  }();
  return types;
}

const std::vector<Op>& predefined_ops() {
  static const std::vector<Op> ops = [] {
    std::vector<Op> v{Op::predefined(PredefinedOp::NoOp)};  // slot 0 is MPI_OP_NULL, never found
    for (int op = MPI_MAX; op <= MPI_NO_OP; ++op) v.push_back(Op::predefined(static_cast<PredefinedOp>(op)));
    return v;
  }();
  return ops;
}

const Group empty_group;

}  // namespace

Registry& current_registry() {
  thread_local Registry own;
  return installed ? *installed : own;
}

void install_registry(Registry* r) { installed = r; }

RegistryScope::RegistryScope(Registry& r) : previous_(installed) { installed = &r; }
RegistryScope::~RegistryScope() { installed = previous_; }

const Datatype* const predefined_datatype_table = predefined_datatypes().data();

bool is_predefined(const Datatype& type) {
  const Datatype* const all = predefined_datatype_table;
  return std::less_equal<>()(all, &type) && std::less<>()(&type, all + MPI_LONG_DOUBLE_INT + 1);
}

Datatype* find_user_datatype(Registry& r, MPI_Datatype handle) { return r.datatypes.find(handle); }

const Op* find_op(Registry& r, MPI_Op handle) {
  if (handle >= MPI_MAX && handle <= MPI_NO_OP) return &predefined_ops()[handle];
  return r.ops.find(handle);
}

const Group* find_group(Registry& r, MPI_Group handle) {
  if (handle == MPI_GROUP_EMPTY) return &empty_group;
  return r.groups.find(handle);
}

}  // namespace gcsim::mpi_layer
