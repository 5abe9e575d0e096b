#include "apps/mpi/error.hpp"

#include <array>

namespace gcsim::mpi_layer {
namespace {

constexpr std::array<std::string_view, MPI_ERR_LASTCODE + 1> error_texts = {
    "MPI_SUCCESS: no errors",
    "MPI_ERR_BUFFER: invalid buffer pointer",
    "MPI_ERR_COUNT: invalid count argument",
    "MPI_ERR_TYPE: invalid datatype",
    "MPI_ERR_TAG: invalid tag",
    "MPI_ERR_COMM: invalid communicator",
    "MPI_ERR_RANK: invalid rank",
    "MPI_ERR_REQUEST: invalid request",
    "MPI_ERR_ROOT: invalid root",
    "MPI_ERR_GROUP: invalid group",
    "MPI_ERR_OP: invalid reduce operation",
    "MPI_ERR_TOPOLOGY: invalid communicator topology",
    "MPI_ERR_DIMS: invalid topology dimension",
    "MPI_ERR_ARG: invalid argument of some other kind",
    "MPI_ERR_UNKNOWN: unknown error",
    "MPI_ERR_TRUNCATE: message truncated",
    "MPI_ERR_OTHER: known error not in this list",
    "MPI_ERR_INTERN: internal error",
    "MPI_ERR_IN_STATUS: error code is in status",
    "MPI_ERR_PENDING: pending request",
    "MPI_ERR_KEYVAL: invalid keyval",
    "MPI_ERR_NO_MEM: out of memory",
    "MPI_ERR_INFO: invalid info object",
    "MPI_ERR_UNSUPPORTED_OPERATION: operation not supported",
};

}  // namespace

bool is_error_code(int code) { return code >= MPI_SUCCESS && code <= MPI_ERR_LASTCODE; }

std::string_view error_text(int code) { return is_error_code(code) ? error_texts[code] : std::string_view(); }

}  // namespace gcsim::mpi_layer
