// The C entry points that move or count typed data without communicating: MPI_Pack and
// MPI_Unpack, and the counts of a status.
#include <climits>
#include <span>

#include "apps/mpi/c_call.hpp"
#include "apps/mpi/type_transfer.hpp"

using namespace gcsim::mpi_layer;

namespace {

// The runtime will check communicators; the core needs none and only refuses MPI_COMM_NULL.
void check_comm_arg(MPI_Comm comm) {
  if (comm == MPI_COMM_NULL) fail(MPI_ERR_COMM, "MPI_COMM_NULL");
}

const MPI_Status& status_arg(const MPI_Status* status) {
  if (!status) fail(MPI_ERR_ARG, "MPI_STATUS_IGNORE has no counts");
  return *status;
}

}  // namespace

extern "C" {

int MPI_Pack(const void* inbuf, int incount, MPI_Datatype datatype, void* outbuf, int outsize, int* position,
             MPI_Comm comm) {
  return c_call([&](Registry& r) {
    check_comm_arg(comm);
    check_count_arg(incount);
    check_count_arg(outsize);
    int& at = out_arg(position);
    MPI_Count p = at;
    pack(inbuf, incount, datatype_arg(r, datatype, true),
         std::span(static_cast<std::byte*>(outbuf), static_cast<std::size_t>(outsize)), p);
    at = static_cast<int>(p);  // within outsize
  });
}

int MPI_Unpack(const void* inbuf, int insize, int* position, void* outbuf, int outcount, MPI_Datatype datatype,
               MPI_Comm comm) {
  return c_call([&](Registry& r) {
    check_comm_arg(comm);
    check_count_arg(insize);
    check_count_arg(outcount);
    int& at = out_arg(position);
    MPI_Count p = at;
    unpack(std::span(static_cast<const std::byte*>(inbuf), static_cast<std::size_t>(insize)), p, outbuf, outcount,
           datatype_arg(r, datatype, true));
    at = static_cast<int>(p);
  });
}

int MPI_Pack_size(int incount, MPI_Datatype datatype, MPI_Comm comm, int* size) {
  return c_call([&](Registry& r) {
    check_comm_arg(comm);
    const MPI_Count bytes = pack_size(incount, datatype_arg(r, datatype, true));
    if (bytes > INT_MAX) fail(MPI_ERR_COUNT, "packed size exceeds an int");
    out_arg(size) = static_cast<int>(bytes);
  });
}

int MPI_Get_count(const MPI_Status* status, MPI_Datatype datatype, int* count) {
  return c_call([&](Registry& r) {
    out_arg(count) = int_or_undefined(count_of(status_arg(status).gcsim_bytes, datatype_arg(r, datatype, false)));
  });
}

int MPI_Get_elements_x(const MPI_Status* status, MPI_Datatype datatype, MPI_Count* count) {
  return c_call([&](Registry& r) {
    out_arg(count) = elements_of(status_arg(status).gcsim_bytes, datatype_arg(r, datatype, false));
  });
}

int MPI_Get_elements(const MPI_Status* status, MPI_Datatype datatype, int* count) {
  return c_call([&](Registry& r) {
    out_arg(count) = int_or_undefined(elements_of(status_arg(status).gcsim_bytes, datatype_arg(r, datatype, false)));
  });
}

int MPI_Status_set_elements(MPI_Status* status, MPI_Datatype datatype, int count) {
  return c_call([&](Registry& r) {
    MPI_Status& s = out_arg(status);
    s.gcsim_bytes = bytes_of_elements(count, datatype_arg(r, datatype, false));
  });
}

int MPI_Status_set_cancelled(MPI_Status* status, int flag) {
  return c_call([&](Registry&) { out_arg(status).gcsim_cancelled = flag != 0; });
}

int MPI_Test_cancelled(const MPI_Status* status, int* flag) {
  return c_call([&](Registry&) { out_arg(flag) = status_arg(status).gcsim_cancelled != 0; });
}

}  // extern "C"
