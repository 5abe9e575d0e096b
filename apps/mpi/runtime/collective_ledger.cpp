#include "apps/mpi/runtime/collective_ledger.hpp"

#include <array>

#include "apps/mpi/error.hpp"
#include "apps/mpi/type_transfer.hpp"

namespace gcsim::mpi_layer {
namespace {

std::string op_name(MPI_Op op) {
  static constexpr std::array<const char*, 15> names = {"MPI_OP_NULL", "MPI_MAX",  "MPI_MIN",  "MPI_SUM",    "MPI_PROD",
                                                        "MPI_LAND",    "MPI_BAND", "MPI_LOR",  "MPI_BOR",    "MPI_LXOR",
                                                        "MPI_BXOR",    "MPI_MINLOC", "MPI_MAXLOC", "MPI_REPLACE", "MPI_NO_OP"};
  if (op >= 0 && op < static_cast<MPI_Op>(names.size())) return names[static_cast<std::size_t>(op)];
  return "a user op";
}

bool same_op(MPI_Op a, MPI_Op b) {
  const bool user_a = a > MPI_NO_OP, user_b = b > MPI_NO_OP;
  return user_a && user_b ? true : a == b;
}

// The class of the first difference between two calls; MPI_SUCCESS if they agree.
int difference(const CollectiveSignature& mine, const CollectiveSignature& first) {
  if (mine.call != first.call) return MPI_ERR_OTHER;
  if (mine.root != first.root) return MPI_ERR_ROOT;
  if (!same_op(mine.op, first.op)) return MPI_ERR_OP;
  if (!mine.type || !first.type) return MPI_SUCCESS;
  // Equal signatures: each a prefix of the other. A prefix only: more or fewer of the same.
  if (match_signatures(*mine.type, mine.count, *first.type, first.count) == SignatureMatch::Mismatch) return MPI_ERR_TYPE;
  return mine.count * mine.type->size() == first.count * first.type->size() ? MPI_SUCCESS : MPI_ERR_COUNT;
}

}  // namespace

std::string CollectiveSignature::text() const {
  std::string args;
  auto add = [&args](const std::string& a) { args += (args.empty() ? "" : ", ") + a; };
  if (root >= 0) add("root=" + std::to_string(root));
  if (op != MPI_OP_NULL) add("op=" + op_name(op));
  if (type) add(data_text);
  return call + "(" + args + ")";
}

void CollectiveLedger::arrive(std::int64_t context, int first_member, std::uint32_t sequence, int comm_size,
                              int comm_rank, const std::string& comm_name, const CollectiveSignature& mine) {
  const auto key = std::make_tuple(context, first_member, sequence);
  auto it = entries_.find(key);
  if (it == entries_.end()) it = entries_.emplace(key, Entry{mine, comm_rank, 0}).first;
  const Entry& e = it->second;
  if (const int code = difference(mine, e.first); code != MPI_SUCCESS) {
    const std::string where = comm_name == "MPI_COMM_WORLD" ? "" : " of " + comm_name;
    throw Error(code, (mine.text() + " but rank " + std::to_string(e.first_rank) + where + " called " + e.first.text()).c_str());
  }
  if (++it->second.arrived == comm_size) entries_.erase(it);
}

}  // namespace gcsim::mpi_layer
