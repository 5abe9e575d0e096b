// Reduction operations: the predefined ones on every type they are defined for, the pair types'
// MINLOC/MAXLOC, derived types, and user functions in rank order.
#include <gtest/gtest.h>

#include <array>
#include <climits>
#include <complex>
#include <cstdint>
#include <cstring>
#include <vector>

#include "apps/mpi/basic_dispatch.hpp"
#include "apps/mpi/error.hpp"
#include "tests/mpi_layer/mpi_test_support.hpp"
#include "apps/mpi/reduction.hpp"
#include "apps/mpi/type_constructors.hpp"

namespace gcsim::mpi_layer {
namespace {

template <class T>
T reduce_one(PredefinedOp op, T in, T inout, Basic b) {
  apply_op(Op::predefined(op), &in, &inout, 1, Datatype::of_basic(b), handle_of_basic(b));
  return inout;
}

int op_error(PredefinedOp op, Basic b) {
  std::array<std::byte, 32> in{}, inout{};
  try {
    apply_op(Op::predefined(op), in.data(), inout.data(), 1, Datatype::of_basic(b), handle_of_basic(b));
  } catch (const Error& e) {
    return e.code();
  }
  return MPI_SUCCESS;
}

constexpr PredefinedOp element_ops[] = {PredefinedOp::Max, PredefinedOp::Min, PredefinedOp::Sum, PredefinedOp::Prod,
                                        PredefinedOp::Land, PredefinedOp::Band, PredefinedOp::Lor, PredefinedOp::Bor,
                                        PredefinedOp::Lxor, PredefinedOp::Bxor};

// 2 op 3 as the op's class defines it.
double expected_2_op_3(PredefinedOp op) {
  switch (op) {
    case PredefinedOp::Max: return 3;
    case PredefinedOp::Min: return 2;
    case PredefinedOp::Sum: return 5;
    case PredefinedOp::Prod: return 6;
    case PredefinedOp::Land: case PredefinedOp::Lor: return 1;
    case PredefinedOp::Lxor: return 0;
    case PredefinedOp::Band: return 2;
    case PredefinedOp::Bor: return 3;
    default: return 1;  // Bxor
  }
}

TEST(MpiReduction, EveryPredefinedOpOnEveryTypeItIsDefinedFor) {
  int defined = 0;
  for (int i = 0; i < basic_type_count; ++i) {
    const auto b = static_cast<Basic>(i);
    for (PredefinedOp op : element_ops) {
      SCOPED_TRACE(std::string(basic_name(b)) + " op " + std::to_string(static_cast<int>(op)));
      if (!op_defined_on(op, b)) {
        EXPECT_EQ(op_error(op, b), MPI_ERR_OP);
        continue;
      }
      ++defined;
      visit_basic(b, [&]<class T>(BasicTag<T>) {
        if constexpr (std::is_same_v<T, bool>) {
          const bool expected = op == PredefinedOp::Land ? false : true;  // true op false
          EXPECT_EQ(reduce_one<T>(op, true, false, b), expected);
        } else {
          EXPECT_EQ(reduce_one<T>(op, T(2), T(3), b), T(static_cast<decltype(std::real(T{}))>(expected_2_op_3(op))));
        }
      });
    }
  }
  // 21 integer types x 10 ops, 3 floating x 4, 3 complex x 2, bool x 3, byte x 3.
  EXPECT_EQ(defined, 21 * 10 + 3 * 4 + 3 * 2 + 3 + 3);
}

TEST(MpiReduction, TheStandardsTableOfUndefinedPairs) {
  EXPECT_EQ(op_error(PredefinedOp::Sum, Basic::Char), MPI_ERR_OP);  // text, not a number
  EXPECT_EQ(op_error(PredefinedOp::Max, Basic::FloatComplex), MPI_ERR_OP);
  EXPECT_EQ(op_error(PredefinedOp::Land, Basic::Double), MPI_ERR_OP);
  EXPECT_EQ(op_error(PredefinedOp::Bor, Basic::Float), MPI_ERR_OP);
  EXPECT_EQ(op_error(PredefinedOp::Max, Basic::Bool), MPI_ERR_OP);
  EXPECT_EQ(op_error(PredefinedOp::Sum, Basic::Byte), MPI_ERR_OP);
  EXPECT_EQ(op_error(PredefinedOp::Minloc, Basic::Int), MPI_ERR_OP);
  EXPECT_EQ(op_error(PredefinedOp::Replace, Basic::WChar), MPI_SUCCESS);
}

TEST(MpiReduction, IntegerSumAndProductWrapAsTwosComplement) {
  EXPECT_EQ(reduce_one<int>(PredefinedOp::Sum, INT_MAX, 1, Basic::Int), INT_MIN);
  EXPECT_EQ(reduce_one<long long>(PredefinedOp::Sum, LLONG_MIN, -1, Basic::LongLong), LLONG_MAX);
  EXPECT_EQ(reduce_one<std::int8_t>(PredefinedOp::Prod, 100, 3, Basic::Int8), std::int8_t{44});
  EXPECT_EQ(reduce_one<int>(PredefinedOp::Prod, INT_MIN, -1, Basic::Int), INT_MIN);
  // unsigned short * unsigned short would promote to int and overflow: computed unsigned instead.
  EXPECT_EQ(reduce_one<unsigned short>(PredefinedOp::Prod, 65535, 65535, Basic::UnsignedShort), 1);
  EXPECT_EQ(reduce_one<unsigned>(PredefinedOp::Sum, UINT_MAX, 2, Basic::Unsigned), 1u);
}

TEST(MpiReduction, FloatingAndComplexArithmetic) {
  EXPECT_FLOAT_EQ(reduce_one<float>(PredefinedOp::Sum, 0.1f, 0.2f, Basic::Float), 0.1f + 0.2f);
  EXPECT_EQ(reduce_one<double>(PredefinedOp::Min, -0.5, 2.0, Basic::Double), -0.5);
  EXPECT_EQ(reduce_one<long double>(PredefinedOp::Prod, 1.5L, 4.0L, Basic::LongDouble), 6.0L);
  const std::complex<double> i(0, 1);
  EXPECT_EQ(reduce_one<std::complex<double>>(PredefinedOp::Prod, i, i, Basic::DoubleComplex), std::complex<double>(-1, 0));
}

TEST(MpiReduction, LogicalAndBitwiseOps) {
  EXPECT_EQ(reduce_one<int>(PredefinedOp::Land, 2, 7, Basic::Int), 1);
  EXPECT_EQ(reduce_one<int>(PredefinedOp::Lor, 0, 0, Basic::Int), 0);
  EXPECT_EQ(reduce_one<long>(PredefinedOp::Lxor, 5, 0, Basic::Long), 1);
  EXPECT_EQ(reduce_one<std::uint64_t>(PredefinedOp::Bxor, 0xF0F0, 0xFF00, Basic::UInt64), 0x0FF0u);
  EXPECT_EQ(reduce_one<unsigned char>(PredefinedOp::Band, 0xAC, 0x0F, Basic::Byte), 0x0C);
  EXPECT_EQ(reduce_one<bool>(PredefinedOp::Lxor, true, true, Basic::Bool), false);
}

TEST(MpiReduction, MinlocAndMaxlocTakeTheLowerIndexOnTies) {
  struct DoubleInt { double v; int i; };
  std::array<DoubleInt, 3> in{{{1.0, 4}, {5.0, 2}, {3.0, 9}}};
  std::array<DoubleInt, 3> inout{{{1.0, 1}, {2.0, 0}, {7.0, 3}}};
  const Datatype t = pair_type(MPI_DOUBLE_INT);
  auto minimum = inout;
  apply_op(Op::predefined(PredefinedOp::Minloc), in.data(), minimum.data(), 3, t, MPI_DOUBLE_INT);
  EXPECT_EQ(minimum[0].i, 1);  // tie: the lower index
  EXPECT_EQ(minimum[1].v, 2.0);
  EXPECT_EQ(minimum[1].i, 0);
  EXPECT_EQ(minimum[2].v, 3.0);
  EXPECT_EQ(minimum[2].i, 9);
  auto maximum = inout;
  apply_op(Op::predefined(PredefinedOp::Maxloc), in.data(), maximum.data(), 3, t, MPI_DOUBLE_INT);
  EXPECT_EQ(maximum[0].i, 1);
  EXPECT_EQ(maximum[1].i, 2);
  EXPECT_EQ(maximum[2].v, 7.0);

  std::array<int, 4> a{3, 8, -1, 5}, b{3, 2, -1, 4};  // two MPI_2INT pairs
  apply_op(Op::predefined(PredefinedOp::Maxloc), a.data(), b.data(), 2, pair_type(MPI_2INT), MPI_2INT);
  EXPECT_EQ(b, (std::array<int, 4>{3, 2, -1, 4}));
  struct ShortInt { short v; int i; } s_in{-3, 7}, s_inout{2, 1};
  apply_op(Op::predefined(PredefinedOp::Minloc), &s_in, &s_inout, 1, pair_type(MPI_SHORT_INT), MPI_SHORT_INT);
  EXPECT_EQ(s_inout.v, -3);
  EXPECT_EQ(s_inout.i, 7);
}

TEST(MpiReduction, LocOpsOnDerivedTypesOfPairs) {
  struct FloatInt { float v; int i; };
  std::array<FloatInt, 2> in{{{1.0f, 0}, {9.0f, 0}}}, inout{{{2.0f, 1}, {3.0f, 1}}};
  const Datatype t = type_contiguous(2, pair_type(MPI_FLOAT_INT));
  apply_op(Op::predefined(PredefinedOp::Minloc), in.data(), inout.data(), 1, t, 0);
  EXPECT_EQ(inout[0].i, 0);
  EXPECT_EQ(inout[1].i, 1);
  // A pair whose index is not an int is no pair type.
  const Datatype d = Datatype::of_basic(Basic::Double);
  EXPECT_THROW(apply_op(Op::predefined(PredefinedOp::Minloc), in.data(), inout.data(), 1, type_contiguous(2, d), 0), Error);
}

TEST(MpiReduction, PredefinedOpsWalkADerivedTypesElementsAndSkipItsHoles) {
  std::array<int, 6> in{1, 100, 2, 100, 3, 100}, inout{10, -7, 20, -7, 30, -7};
  const Datatype every_other = type_vector(3, 1, 2, Datatype::of_basic(Basic::Int));
  apply_op(Op::predefined(PredefinedOp::Sum), in.data(), inout.data(), 1, every_other, 0);
  EXPECT_EQ(inout, (std::array<int, 6>{11, -7, 22, -7, 33, -7}));

  struct IntDouble { int i; double d; };
  const std::vector<int> ones{1, 1};
  const std::vector<MPI_Aint> displacements{offsetof(IntDouble, i), offsetof(IntDouble, d)};
  const Datatype* types[] = {&int_type, &double_type};
  const Datatype s = type_struct(ones, displacements, types);
  std::array<IntDouble, 2> a{{{1, 0.5}, {2, 1.5}}}, b{{{3, 0.25}, {4, 2.0}}};
  apply_op(Op::predefined(PredefinedOp::Prod), a.data(), b.data(), 2, s, 0);
  EXPECT_EQ(b[1].i, 8);
  EXPECT_EQ(b[1].d, 3.0);
  const Datatype* with_char[] = {&int_type, &char_type};
  EXPECT_THROW(apply_op(Op::predefined(PredefinedOp::Sum), a.data(), b.data(), 1, type_struct(ones, displacements, with_char), 0), Error);
}

TEST(MpiReduction, ReplaceCopiesAndNoOpKeeps) {
  std::array<int, 2> in{1, 2}, inout{5, 6};
  const Datatype t = Datatype::of_basic(Basic::Int);
  apply_op(Op::predefined(PredefinedOp::NoOp), in.data(), inout.data(), 2, t, MPI_INT);
  EXPECT_EQ(inout, (std::array<int, 2>{5, 6}));
  apply_op(Op::predefined(PredefinedOp::Replace), in.data(), inout.data(), 2, t, MPI_INT);
  EXPECT_EQ(inout, in);
}

// A non-commutative user op: 2x2 matrix product, inout = in * inout.
int user_calls = 0;
MPI_Datatype user_seen_type = MPI_DATATYPE_NULL;
void matrix_product(void* invec, void* inoutvec, int* len, MPI_Datatype* type) {
  ++user_calls;
  user_seen_type = *type;
  for (int k = 0; k < *len; ++k) {
    double a[4], b[4], c[4];
    std::memcpy(a, static_cast<double*>(invec) + 4 * k, sizeof a);
    std::memcpy(b, static_cast<double*>(inoutvec) + 4 * k, sizeof b);
    c[0] = a[0] * b[0] + a[1] * b[2];
    c[1] = a[0] * b[1] + a[1] * b[3];
    c[2] = a[2] * b[0] + a[3] * b[2];
    c[3] = a[2] * b[1] + a[3] * b[3];
    std::memcpy(static_cast<double*>(inoutvec) + 4 * k, c, sizeof c);
  }
}

TEST(MpiReduction, NonCommutativeUserOpsApplyInRankOrder) {
  const Op op = Op::user(&matrix_product, false);
  EXPECT_FALSE(op.commutative());
  EXPECT_FALSE(op.is_predefined());
  const Datatype matrix = type_contiguous(4, Datatype::of_basic(Basic::Double));
  const MPI_Datatype handle = 300;  // as registered
  // Ranks 0..3 hold M_r; the reduction is M_0 * M_1 * M_2 * M_3, folded from the highest rank down.
  const std::array<std::array<double, 4>, 4> ranks{{{1, 1, 0, 1}, {2, 0, 0, 1}, {0, 1, 1, 0}, {1, 0, 3, 1}}};
  std::array<double, 4> acc = ranks[3];
  for (int r = 2; r >= 0; --r) apply_op(op, ranks[r].data(), acc.data(), 1, matrix, handle);
  // By hand: M0*M1 = [2 1; 0 1]; *M2 = [1 2; 1 0]; *M3 = [7 2; 1 0].
  EXPECT_EQ(acc, (std::array<double, 4>{7, 2, 1, 0}));
  EXPECT_EQ(user_calls, 3);
  EXPECT_EQ(user_seen_type, handle);
  // The other order gives another product: the op really is order-sensitive.
  std::array<double, 4> reversed = ranks[0];
  for (int r = 1; r < 4; ++r) apply_op(op, ranks[r].data(), reversed.data(), 1, matrix, handle);
  EXPECT_NE(reversed, acc);
}

void add_ints(void* invec, void* inoutvec, int* len, MPI_Datatype*) {
  for (int k = 0; k < *len; ++k) {
    int a, b;
    std::memcpy(&a, static_cast<char*>(invec) + 4 * k, 4);
    std::memcpy(&b, static_cast<char*>(inoutvec) + 4 * k, 4);
    b = static_cast<int>(static_cast<unsigned>(a) + static_cast<unsigned>(b));
    std::memcpy(static_cast<char*>(inoutvec) + 4 * k, &b, 4);
  }
}

TEST(MpiReduction, UserFunctionsGetTheWholeCount) {
  std::vector<int> in(1000, 2), inout(1000, 5);
  apply_op(Op::user(&add_ints, true), in.data(), inout.data(), 1000, Datatype::of_basic(Basic::Int), MPI_INT);
  EXPECT_EQ(inout.front(), 7);
  EXPECT_EQ(inout.back(), 7);
}

}  // namespace
}  // namespace gcsim::mpi_layer
