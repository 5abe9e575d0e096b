// A Reduction over packed bytes from the layer's Op and Datatype. apply_op works on a type's
// layout in memory; packed elements of a dense type (one run of bytes with no gaps) already are
// that layout, shifted by the type's lb. Any other type is unpacked into scratch buffers laid out
// as the type, reduced there and packed back.
#include <vector>

#include "apps/mpi/address.hpp"
#include "apps/mpi/collective_algorithms.hpp"
#include "apps/mpi/type_transfer.hpp"

namespace gcsim::mpi_layer {
namespace {

// Scratch memory for count elements of type, and the buffer address whose type map lands in it.
struct Laid {
  std::vector<std::byte> memory;
  void* buffer;
  Laid(const Datatype& type, std::size_t count)
      : memory(count == 0 ? 0 : static_cast<std::size_t>(type.extent()) * (count - 1) +
                                    static_cast<std::size_t>(type.true_extent())),
        buffer(address_at(static_cast<void*>(memory.data()), -type.true_lb())) {}
};

void reduce_through_layout(const Op& op, const Datatype& type, MPI_Datatype handle, const std::byte* in,
                           std::byte* inout, std::size_t count) {
  const auto n = static_cast<MPI_Count>(count), bytes = n * type.size();
  Laid a(type, count), b(type, count);
  MPI_Count position = 0;
  unpack(std::span(in, static_cast<std::size_t>(bytes)), position, a.buffer, n, type);
  position = 0;
  unpack(std::span<const std::byte>(inout, static_cast<std::size_t>(bytes)), position, b.buffer, n, type);
  apply_op(op, a.buffer, b.buffer, n, type, handle);
  position = 0;
  pack(b.buffer, n, type, std::span(inout, static_cast<std::size_t>(bytes)), position);
}

}  // namespace

Reduction reduction_for(const Op& op, const Datatype& type, MPI_Datatype handle) {
  Reduction r{.element_size = static_cast<std::size_t>(type.size()), .commutative = op.commutative(), .combine = {}};
  if (type.is_dense()) {
    const MPI_Aint lb = type.lb();
    r.combine = [op, type, handle, lb](const std::byte* in, std::byte* inout, std::size_t count) {
      apply_op(op, address_at(static_cast<const void*>(in), -lb), address_at(static_cast<void*>(inout), -lb),
               static_cast<MPI_Count>(count), type, handle);
    };
  } else {
    r.combine = [op, type, handle](const std::byte* in, std::byte* inout, std::size_t count) {
      reduce_through_layout(op, type, handle, in, inout, count);
    };
  }
  return r;
}

}  // namespace gcsim::mpi_layer
