#pragma once
// Reduction operations (MPI 3.1 section 5.9): the predefined ones on the types the standard
// defines them for, and user functions made by MPI_Op_create. Every op computes
// inout[i] = in[i] op inout[i]; a non-commutative op sees the lower rank's data as in.
#include "apps/mpi/datatype.hpp"

namespace gcsim::mpi_layer {

enum class PredefinedOp : std::uint8_t { Max = 1, Min, Sum, Prod, Land, Band, Lor, Bor, Lxor, Bxor, Minloc, Maxloc, Replace, NoOp };

class Op {
 public:
  static Op predefined(PredefinedOp op) { return Op(op, nullptr, true); }
  static Op user(MPI_User_function* function, bool commutative) { return Op({}, function, commutative); }
  bool is_predefined() const { return function_ == nullptr; }
  PredefinedOp which() const { return which_; }
  MPI_User_function* function() const { return function_; }
  bool commutative() const { return commutative_; }

 private:
  Op(PredefinedOp which, MPI_User_function* function, bool commutative)
      : which_(which), function_(function), commutative_(commutative) {}
  PredefinedOp which_;
  MPI_User_function* function_;
  bool commutative_;
};

// Whether a predefined op is defined on a basic type (the standard's table; MINLOC and MAXLOC are
// defined on pairs, see loc_pair_allowed).
bool op_defined_on(PredefinedOp op, Basic b);
// Whether (value, index) is one of the pair types' layouts: value float, double, long double,
// long, int or short, index int.
bool loc_pair_allowed(Basic value, Basic index);

// Applies op to count elements of type: inout = in op inout. handle is passed to a user function
// (its datatype argument). A predefined op walks the type map's basic elements and fails with
// MPI_ERR_OP if it is not defined on one of them.
void apply_op(const Op& op, const void* in, void* inout, MPI_Count count, const Datatype& type, MPI_Datatype handle);

}  // namespace gcsim::mpi_layer
