#include "apps/mpi/runtime/collective_site.hpp"

#include <cstring>
#include <utility>

#include "apps/mpi/type_transfer.hpp"

namespace gcsim::mpi_layer {

void fail_in(const std::string& call, int code, const std::string& what) {
  throw Error(code, (call + ": " + what).c_str());
}

namespace {
std::string described(const char* call, MPI_Comm comm, const std::string& details) {
  return std::string(call) + "(" + (details.empty() ? "" : details + ", ") + "comm=" + Rank::comm_name(comm) + ")";
}
std::optional<std::uint32_t> reserved_sequence;  // ranks switch only inside blocking calls
}  // namespace

Communicator& communicator_of(Rank& rank, const char* call, MPI_Comm comm) {
  try {
    return rank.comm(comm);
  } catch (const Error& e) {
    fail_in(call, e.code(), e.what());
  }
}

ReservedSequence::ReservedSequence(std::uint32_t sequence) { reserved_sequence = sequence; }
ReservedSequence::~ReservedSequence() { reserved_sequence.reset(); }

CollectiveSite::CollectiveSite(Rank& rank, const char* call, MPI_Comm comm, const std::string& details)
    : rank_(rank), call_(call), comm_(communicator_of(rank, call, comm)), channel_(rank, comm, described(call, comm, details)) {
  signature_.call = call;
}

CollectiveCall CollectiveSite::call() {
  const std::uint32_t sequence = reserved_sequence ? *reserved_sequence : comm_.collectives;
  if (rank_.collective_ledger) {
    rank_.collective_ledger->arrive(comm_.collective_context(), comm_.world_rank_of(0), sequence, size(), rank(),
                                    Rank::comm_name(comm_.handle), signature_);
  }
  if (reserved_sequence) reserved_sequence.reset();
  else ++comm_.collectives;
  return CollectiveCall{channel_, sequence};
}

void CollectiveSite::agree_on_data(long long count, const Datatype& type, MPI_Datatype handle) {
  signature_.type = type;
  signature_.count = count;
  const auto basic = basic_of_handle(handle);
  signature_.data_text = std::to_string(count) + " x " +
                         (basic ? std::string(basic_name(*basic)) : "a derived type of " + std::to_string(type.size()) + " bytes");
}

void CollectiveSite::check_root(int root) {
  if (root < 0 || root >= size()) {
    fail(MPI_ERR_ROOT, "root " + std::to_string(root) + " outside the communicator of " + std::to_string(size()) + " ranks");
  }
  signature_.root = root;
}

void CollectiveSite::check_count(long long count, const char* which) const {
  if (count < 0) fail(MPI_ERR_COUNT, std::string("negative ") + which + " " + std::to_string(count));
}

const Datatype& CollectiveSite::datatype(MPI_Datatype handle) const {
  try {
    return datatype_arg(rank_.registry(), handle, true);
  } catch (const Error& e) {
    fail(e.code(), e.what());
  }
}

const Op& CollectiveSite::op(MPI_Op handle) {
  try {
    const Op& found = op_arg(rank_.registry(), handle);
    signature_.op = handle;
    return found;
  } catch (const Error& e) {
    fail(e.code(), e.what());
  }
}

void CollectiveSite::check_buffer(const void* buf, long long count, bool in_place_allowed, const char* which) const {
  if (buf == MPI_IN_PLACE && !in_place_allowed) fail(MPI_ERR_BUFFER, std::string("MPI_IN_PLACE is not allowed as ") + which + " here");
  if (buf == nullptr && count > 0) fail(MPI_ERR_BUFFER, std::string("null ") + which + " for " + std::to_string(count) + " elements");
}

void CollectiveSite::check_counts(const int* counts, const char* which) const {
  if (!counts) fail(MPI_ERR_ARG, std::string("null ") + which);
  for (int r = 0; r < size(); ++r) check_count(counts[r], which);
}

CollectiveSite::Blocks CollectiveSite::blocks(const int* counts, const int* displs, int count, bool varying,
                                              const char* side) const {
  const auto n = static_cast<std::size_t>(size());
  if (varying) {
    check_counts(counts, (std::string(side) + "counts").c_str());
    if (!displs) fail(MPI_ERR_ARG, "null displs");
    return {std::vector<int>(counts, counts + n), std::vector<int>(displs, displs + n)};
  }
  check_count(count, (std::string(side) + "count").c_str());
  Blocks b{std::vector<int>(n, count), std::vector<int>(n)};
  for (std::size_t r = 0; r < n; ++r) b.displs[r] = static_cast<int>(r) * count;
  return b;
}

Bytes pack_of(const void* buf, long long count, const Datatype& type) {
  Bytes b(static_cast<std::size_t>(pack_size(count, type)));
  if (b.empty()) return b;
  MPI_Count position = 0;
  pack(buf, count, type, b, position);
  return b;
}

void unpack_into(std::span<const std::byte> bytes, void* buf, long long count, const Datatype& type) {
  if (count == 0) return;
  MPI_Count position = 0;
  unpack(bytes, position, buf, count, type);
}

const void* element_at(const void* buf, long long index, const Datatype& type) {
  return static_cast<const char*>(buf) + index * type.extent();
}

void* element_at(void* buf, long long index, const Datatype& type) {
  return static_cast<char*>(buf) + index * type.extent();
}

std::vector<std::size_t> end_to_end(const std::vector<std::size_t>& sizes) {
  std::vector<std::size_t> displacements(sizes.size());
  std::size_t at = 0;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    displacements[i] = at;
    at += sizes[i];
  }
  return displacements;
}

}  // namespace gcsim::mpi_layer
