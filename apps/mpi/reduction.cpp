#include "apps/mpi/reduction.hpp"

#include <algorithm>
#include <climits>
#include <vector>

#include "apps/mpi/address.hpp"
#include "apps/mpi/basic_dispatch.hpp"
#include "apps/mpi/error.hpp"
#include "apps/mpi/reduction_kernels.hpp"

namespace gcsim::mpi_layer {
namespace {

bool is_bitwise(PredefinedOp op) { return op == PredefinedOp::Band || op == PredefinedOp::Bor || op == PredefinedOp::Bxor; }
bool is_logical(PredefinedOp op) { return op == PredefinedOp::Land || op == PredefinedOp::Lor || op == PredefinedOp::Lxor; }
bool is_loc(PredefinedOp op) { return op == PredefinedOp::Minloc || op == PredefinedOp::Maxloc; }

// One basic element of one instance of a type map.
struct Element {
  MPI_Aint offset;
  Basic basic;
};

std::vector<Element> elements_of_instance(const Datatype& type) {
  std::vector<Element> out;
  for (const Run& r : type.runs()) {
    const auto size = static_cast<MPI_Aint>(basic_size(r.basic));
    for (MPI_Count i = 0; i < r.count; ++i) out.push_back({r.offset + size * i, r.basic});
  }
  return out;
}

void apply_loc(PredefinedOp op, const void* in, void* inout, MPI_Count count, const Datatype& type) {
  const std::vector<Element> elements = elements_of_instance(type);
  if (elements.size() % 2 != 0) fail(MPI_ERR_OP, "MINLOC/MAXLOC need (value, index) pairs");
  for (std::size_t i = 0; i < elements.size(); i += 2)
    if (!loc_pair_allowed(elements[i].basic, elements[i + 1].basic))
      fail(MPI_ERR_OP, "MINLOC/MAXLOC are defined on the pair types only");
  for (MPI_Count k = 0; k < count; ++k) {
    const MPI_Aint base = type.extent() * k;
    for (std::size_t i = 0; i < elements.size(); i += 2) {
      const MPI_Aint value = base + elements[i].offset, index = base + elements[i + 1].offset;
      visit_basic(elements[i].basic, [&]<class T>(BasicTag<T>) {
        if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>)
          combine_loc<T>(op == PredefinedOp::Minloc, address_at(in, value), address_at(in, index),
                         address_at(inout, value), address_at(inout, index));
      });
    }
  }
}

void apply_predefined(PredefinedOp op, const void* in, void* inout, MPI_Count count, const Datatype& type) {
  if (op == PredefinedOp::NoOp) return;
  if (is_loc(op)) return apply_loc(op, in, inout, count, type);
  for (const Run& r : type.runs())
    if (!op_defined_on(op, r.basic)) fail(MPI_ERR_OP, "the operation is not defined on this datatype");
  if (type.is_dense() && count > 0) {  // all elements are one run
    const Run& r = type.runs().front();
    visit_basic(r.basic, [&]<class T>(BasicTag<T>) {
      combine_run<T>(op, address_at(in, r.offset), address_at(inout, r.offset), r.count * count);
    });
    return;
  }
  for (MPI_Count k = 0; k < count; ++k) {
    const MPI_Aint base = type.extent() * k;
    for (const Run& r : type.runs())
      visit_basic(r.basic, [&]<class T>(BasicTag<T>) {
        combine_run<T>(op, address_at(in, base + r.offset), address_at(inout, base + r.offset), r.count);
      });
  }
}

}  // namespace

bool loc_pair_allowed(Basic value, Basic index) {
  if (index != Basic::Int) return false;
  switch (value) {
    case Basic::Float: case Basic::Double: case Basic::LongDouble:
    case Basic::Long: case Basic::Int: case Basic::Short: return true;
    default: return false;
  }
}

bool op_defined_on(PredefinedOp op, Basic b) {
  const TypeClass c = basic_class(b);
  switch (op) {
    case PredefinedOp::Replace: case PredefinedOp::NoOp: return true;
    case PredefinedOp::Minloc: case PredefinedOp::Maxloc: return false;
    case PredefinedOp::Max: case PredefinedOp::Min: return c == TypeClass::Integer || c == TypeClass::Floating;
    case PredefinedOp::Sum: case PredefinedOp::Prod:
      return c == TypeClass::Integer || c == TypeClass::Floating || c == TypeClass::Complex;
    default:
      if (is_logical(op)) return c == TypeClass::Integer || c == TypeClass::Logical;
      if (is_bitwise(op)) return c == TypeClass::Integer || c == TypeClass::Byte;
      return false;
  }
}

void apply_op(const Op& op, const void* in, void* inout, MPI_Count count, const Datatype& type, MPI_Datatype handle) {
  if (count < 0) fail(MPI_ERR_COUNT, "negative count");
  if (op.is_predefined()) return apply_predefined(op.which(), in, inout, count, type);
  // A user function takes an int count: longer reductions go in slices.
  for (MPI_Count done = 0; done < count;) {
    int len = static_cast<int>(std::min<MPI_Count>(count - done, INT_MAX));
    const MPI_Aint shift = type.extent() * done;
    MPI_Datatype t = handle;
    op.function()(const_cast<std::byte*>(address_at(in, shift)), address_at(inout, shift), &len, &t);
    done += len;
  }
}

}  // namespace gcsim::mpi_layer
