// Pack, unpack, receive-side copies between type maps, signatures and counts from bytes.
#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <cstring>
#include <numeric>
#include <vector>

#include "apps/mpi/error.hpp"
#include "tests/mpi_layer/mpi_test_support.hpp"
#include "apps/mpi/type_constructors.hpp"
#include "apps/mpi/type_transfer.hpp"

namespace gcsim::mpi_layer {
namespace {


struct IntDouble {
  int i;
  double d;
};

Datatype int_double() {
  const std::vector<int> lengths{1, 1};
  const std::vector<MPI_Aint> displacements{offsetof(IntDouble, i), offsetof(IntDouble, d)};
  const Datatype* types[] = {&int_type, &double_type};
  return type_struct(lengths, displacements, types);
}

std::vector<std::byte> iota_bytes(std::size_t n) {
  std::vector<std::byte> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<std::byte>(i * 7 + 1);
  return v;
}

TEST(MpiTypeTransfer, PackTakesTheElementsInTypeMapOrder) {
  const std::array<int, 8> a{0, 1, 2, 3, 4, 5, 6, 7};
  const Datatype every_other = type_vector(4, 1, 2, int_type);
  std::array<int, 4> packed{};
  MPI_Count position = 0;
  pack(a.data(), 1, every_other, std::as_writable_bytes(std::span(packed)), position);
  EXPECT_EQ(position, 16);
  EXPECT_EQ(packed, (std::array<int, 4>{0, 2, 4, 6}));
}

TEST(MpiTypeTransfer, PackAppendsAtThePositionAndRefusesOverflow) {
  const std::array<double, 2> d{1.5, -2.5};
  const int i = 42;
  std::vector<std::byte> out(20);
  MPI_Count position = 0;
  pack(&i, 1, int_type, out, position);
  pack(d.data(), 2, double_type, out, position);
  EXPECT_EQ(position, 20);
  EXPECT_THROW(pack(&i, 1, int_type, out, position), Error);
  MPI_Count read = 0;
  int i2 = 0;
  std::array<double, 2> d2{};
  unpack(out, read, &i2, 1, int_type);
  unpack(out, read, d2.data(), 2, double_type);
  EXPECT_EQ(i2, 42);
  EXPECT_EQ(d2, d);
  EXPECT_EQ(pack_size(3, int_double()), 36);
  try {
    unpack(out, read, &i2, 1, int_type);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), MPI_ERR_TRUNCATE);
  }
}

// For a type with holes, negative displacements and a resized extent: packing then unpacking
// writes exactly the data bytes, as a direct typed copy does, and leaves the holes alone.
TEST(MpiTypeTransfer, PackUnpackRoundTripEqualsDirectCopy) {
  const std::vector<int> lengths{2, 1};
  const std::vector<MPI_Aint> displacements{-8, 12};
  const Datatype holes = type_resized(type_hindexed(lengths, displacements, int_type), -8, 32);
  const Datatype nested = type_vector(3, 2, 3, holes);
  const MPI_Count count = 2;
  const std::size_t span = static_cast<std::size_t>(nested.extent() * count + 64);
  const std::vector<std::byte> source = iota_bytes(span);
  const std::byte* origin = source.data() + 16;  // room for the negative displacement

  std::vector<std::byte> packed(static_cast<std::size_t>(pack_size(count, nested)));
  MPI_Count position = 0;
  pack(origin, count, nested, packed, position);
  ASSERT_EQ(position, static_cast<MPI_Count>(packed.size()));

  std::vector<std::byte> unpacked(span), direct(span);
  position = 0;
  unpack(packed, position, unpacked.data() + 16, count, nested);
  const MPI_Count copied = copy_typed(origin, count, nested, direct.data() + 16, count, nested);
  EXPECT_EQ(copied, nested.size() * count);
  EXPECT_EQ(unpacked, direct);
  // Exactly the type map's bytes were written: the same as walking its runs by hand.
  std::vector<std::byte> expected(span);
  for (MPI_Count k = 0; k < count; ++k)
    for (const mpi_layer::Run& r : nested.runs()) {
      const MPI_Aint at = 16 + k * nested.extent() + r.offset;
      std::memcpy(expected.data() + at, source.data() + at, static_cast<std::size_t>(r.count) * sizeof(int));
    }
  EXPECT_EQ(unpacked, expected);
}

TEST(MpiTypeTransfer, ZeroCountsMoveNothing) {
  std::vector<std::byte> out(4);
  MPI_Count position = 2;
  pack(nullptr, 0, int_type, out, position);
  EXPECT_EQ(position, 2);
  const Datatype empty = type_contiguous(0, double_type);
  pack(nullptr, 5, empty, out, position);
  EXPECT_EQ(position, 2);
  EXPECT_EQ(copy_typed(nullptr, 3, empty, nullptr, 3, int_type), 0);
  EXPECT_EQ(match_signatures(int_type, 0, double_type, 4), SignatureMatch::Match);
}

// A receive into a different type map with the same signature: a matrix column arrives as a row.
TEST(MpiTypeTransfer, CopyBetweenDifferentMapsWithTheSameSignature) {
  std::array<int, 16> matrix{};
  std::iota(matrix.begin(), matrix.end(), 0);
  const Datatype column = type_vector(4, 1, 4, int_type);
  std::array<int, 4> row{};
  ASSERT_EQ(match_signatures(column, 1, int_type, 4), SignatureMatch::Match);
  EXPECT_EQ(copy_typed(matrix.data() + 1, 1, column, row.data(), 4, int_type), 16);
  EXPECT_EQ(row, (std::array<int, 4>{1, 5, 9, 13}));
  // The transpose: every column of a into the rows of b, column-by-column type to contiguous.
  std::array<int, 16> transposed{};
  const Datatype columns = type_resized(column, 0, sizeof(int));
  copy_typed(matrix.data(), 4, columns, transposed.data(), 16, int_type);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_EQ(transposed[r * 4 + c], matrix[c * 4 + r]);
}

std::vector<int> packed_ints(const void* buffer, const Datatype& t) {
  std::vector<int> out(static_cast<std::size_t>(t.size()) / sizeof(int));
  MPI_Count position = 0;
  pack(buffer, 1, t, std::as_writable_bytes(std::span(out)), position);
  return out;
}

TEST(MpiTypeTransfer, SubarraysInBothOrders) {
  std::array<int, 20> a{};
  std::iota(a.begin(), a.end(), 0);
  const std::array<int, 2> sizes{4, 5}, subsizes{2, 3}, starts{1, 1};
  const Datatype c = type_subarray(sizes, subsizes, starts, MPI_ORDER_C, int_type);
  EXPECT_EQ(c.lb(), 0);
  EXPECT_EQ(c.extent(), 80);  // the whole array
  EXPECT_EQ(c.size(), 24);
  EXPECT_EQ(packed_ints(a.data(), c), (std::vector<int>{6, 7, 8, 11, 12, 13}));
  const Datatype f = type_subarray(sizes, subsizes, starts, MPI_ORDER_FORTRAN, int_type);
  EXPECT_EQ(packed_ints(a.data(), f), (std::vector<int>{5, 6, 9, 10, 13, 14}));
  const std::array<int, 2> too_far{3, 1};
  EXPECT_EQ(error_of([&] { type_subarray(sizes, subsizes, too_far, MPI_ORDER_C, int_type); }), MPI_ERR_ARG);
  EXPECT_EQ(error_of([&] { type_subarray(sizes, subsizes, starts, 3, int_type); }), MPI_ERR_ARG);
}

TEST(MpiTypeTransfer, StructsArriveIntoPackedArrays) {
  const std::array<IntDouble, 2> s{{{1, 0.5}, {2, 0.25}}};
  const Datatype t = int_double();
  struct Out {
    int i[2];
    double d[2];
  } out{};
  // The receiver lays the same signature (int, double, int, double) out its own way.
  const std::vector<MPI_Aint> displacements{offsetof(Out, i), offsetof(Out, d), offsetof(Out, i) + 4,
                                            offsetof(Out, d) + 8};
  const std::vector<int> ones{1, 1, 1, 1};
  const Datatype* types[] = {&int_type, &double_type, &int_type, &double_type};
  const Datatype receiver = type_struct(ones, displacements, types);
  ASSERT_EQ(match_signatures(t, 2, receiver, 1), SignatureMatch::Match);
  copy_typed(s.data(), 2, t, &out, 1, receiver);
  EXPECT_EQ(out.i[1], 2);
  EXPECT_EQ(out.d[0], 0.5);
  EXPECT_EQ(out.d[1], 0.25);
}

TEST(MpiTypeTransfer, SignaturesDecideTruncationAndMismatch) {
  const Datatype three_ints = type_contiguous(3, int_type);
  EXPECT_EQ(match_signatures(int_type, 3, three_ints, 1), SignatureMatch::Match);
  EXPECT_EQ(match_signatures(int_type, 2, three_ints, 1), SignatureMatch::Match);  // a short message
  EXPECT_EQ(match_signatures(int_type, 4, three_ints, 1), SignatureMatch::Truncate);
  EXPECT_EQ(match_signatures(int_type, 1, float_type, 1), SignatureMatch::Mismatch);
  EXPECT_EQ(match_signatures(int_double(), 1, pair_type(MPI_DOUBLE_INT), 1), SignatureMatch::Mismatch);  // order
  EXPECT_EQ(match_signatures(pair_type(MPI_2INT), 2, int_type, 4), SignatureMatch::Match);
  EXPECT_EQ(match_signatures(Datatype::of_basic(Basic::Byte), 4, Datatype::of_basic(Basic::Char), 4),
            SignatureMatch::Mismatch);
  // MPI_PACKED matches anything, by bytes.
  EXPECT_EQ(match_signatures(int_double(), 1, packed_type, 12), SignatureMatch::Match);
  EXPECT_EQ(match_signatures(packed_type, 16, int_double(), 1), SignatureMatch::Truncate);
}

TEST(MpiTypeTransfer, CountsFromBytes) {
  const Datatype t = int_double();  // 12 bytes, 2 elements
  EXPECT_EQ(count_of(24, t), 2);
  EXPECT_EQ(count_of(16, t), MPI_UNDEFINED);
  EXPECT_EQ(elements_of(24, t), 4);
  EXPECT_EQ(elements_of(16, t), 3);  // a partial receive: one whole struct and an int
  EXPECT_EQ(elements_of(18, t), MPI_UNDEFINED);  // ends inside the double
  EXPECT_EQ(elements_of(0, t), 0);
  const Datatype v = type_vector(2, 3, 5, Datatype::of_basic(Basic::Short));
  EXPECT_EQ(elements_of(10, v), 5);
  EXPECT_EQ(count_of(0, type_contiguous(0, int_type)), 0);
  EXPECT_EQ(elements_of(0, type_contiguous(0, int_type)), 0);
}

}  // namespace
}  // namespace gcsim::mpi_layer
