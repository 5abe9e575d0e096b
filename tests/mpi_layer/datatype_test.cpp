// Derived datatypes: type maps, bounds and extents as the standard defines them.
#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

#include "apps/mpi/error.hpp"
#include "tests/mpi_layer/mpi_test_support.hpp"
#include "apps/mpi/type_constructors.hpp"

namespace gcsim::mpi_layer {
namespace {


TEST(MpiDatatype, BasicTypesHaveTheirCSizes) {
  EXPECT_EQ(Datatype::of_basic(Basic::Int).size(), static_cast<MPI_Count>(sizeof(int)));
  EXPECT_EQ(Datatype::of_basic(Basic::LongDouble).extent(), static_cast<MPI_Aint>(sizeof(long double)));
  EXPECT_EQ(Datatype::of_basic(Basic::Bool).size(), static_cast<MPI_Count>(sizeof(bool)));
  EXPECT_EQ(Datatype::of_basic(Basic::DoubleComplex).size(), 16);
  EXPECT_EQ(basic_of_handle(MPI_INT), Basic::Int);
  EXPECT_EQ(basic_of_handle(MPI_PACKED), Basic::Packed);
  EXPECT_EQ(handle_of_basic(Basic::UInt64), MPI_UINT64_T);
  EXPECT_FALSE(basic_of_handle(MPI_2INT).has_value());
}

TEST(MpiDatatype, ContiguousMergesIntoOneRun) {
  const Datatype t = type_contiguous(5, int_type);
  ASSERT_EQ(t.runs().size(), 1u);
  EXPECT_EQ(t.runs()[0], (mpi_layer::Run{0, Basic::Int, 5}));
  EXPECT_EQ(t.size(), 20);
  EXPECT_EQ(t.extent(), 20);
  EXPECT_EQ(t.elements(), 5);
  EXPECT_TRUE(t.is_dense());
}

TEST(MpiDatatype, VectorHasHolesBetweenBlocks) {
  // 3 blocks of 2 doubles, 4 doubles apart: the standard's extent ends at the last block.
  const Datatype t = type_vector(3, 2, 4, double_type);
  ASSERT_EQ(t.runs().size(), 3u);
  EXPECT_EQ(t.runs()[1], (mpi_layer::Run{32, Basic::Double, 2}));
  EXPECT_EQ(t.size(), 48);
  EXPECT_EQ(t.lb(), 0);
  EXPECT_EQ(t.extent(), 80);
  EXPECT_EQ(t.true_extent(), 80);
  EXPECT_FALSE(t.is_dense());
  // A stride equal to the block length is contiguous: the runs merge.
  EXPECT_EQ(type_vector(3, 2, 2, double_type).runs().size(), 1u);
}

TEST(MpiDatatype, HvectorStrideIsInBytes) {
  const Datatype t = type_hvector(2, 1, 6, int_type);
  EXPECT_EQ(t.runs()[1].offset, 6);
  EXPECT_EQ(t.extent(), 12);  // 6 + 4 = 10, rounded up to int's alignment
  EXPECT_EQ(t.true_extent(), 10);
}

TEST(MpiDatatype, NegativeDisplacementsMoveTheLowerBound) {
  const std::vector<int> lengths{1, 2};
  const std::vector<MPI_Aint> displacements{16, -8};
  const Datatype t = type_hindexed(lengths, displacements, int_type);
  EXPECT_EQ(t.lb(), -8);
  EXPECT_EQ(t.ub(), 20);
  EXPECT_EQ(t.extent(), 28);
  EXPECT_EQ(t.true_lb(), -8);
  EXPECT_EQ(t.size(), 12);
  // Type-map order is the constructor's, not address order.
  EXPECT_EQ(t.runs()[0].offset, 16);
  EXPECT_EQ(t.runs()[1], (mpi_layer::Run{-8, Basic::Int, 2}));
}

TEST(MpiDatatype, IndexedDisplacementsAreInExtents) {
  const std::vector<int> lengths{2, 1}, displacements{0, 5};
  const Datatype t = type_indexed(lengths, displacements, double_type);
  EXPECT_EQ(t.runs()[1].offset, 40);
  EXPECT_EQ(t.extent(), 48);
  const Datatype b = type_indexed_block(2, displacements, double_type);
  EXPECT_EQ(b.size(), 32);
  EXPECT_EQ(b.runs()[1], (mpi_layer::Run{40, Basic::Double, 2}));
  const std::vector<MPI_Aint> bytes{3, 11};
  EXPECT_EQ(type_hindexed_block(1, bytes, char_type).extent(), 9);
}

struct CharDoubleInt {
  char c;
  double d;
  int i;
};

Datatype char_double_int() {
  const std::vector<int> lengths{1, 1, 1};
  const std::vector<MPI_Aint> displacements{offsetof(CharDoubleInt, c), offsetof(CharDoubleInt, d),
                                            offsetof(CharDoubleInt, i)};
  const std::vector<const Datatype*> types{&char_type, &double_type, &int_type};
  return type_struct(lengths, displacements, types);
}

TEST(MpiDatatype, StructExtentIsPaddedToTheCStruct) {
  const Datatype t = char_double_int();
  EXPECT_EQ(t.size(), 13);
  EXPECT_EQ(t.extent(), static_cast<MPI_Aint>(sizeof(CharDoubleInt)));
  EXPECT_EQ(t.true_extent(), static_cast<MPI_Aint>(offsetof(CharDoubleInt, i) + sizeof(int)));
  EXPECT_EQ(t.elements(), 3);
  // An int followed by a char rounds up to int alignment too.
  const std::vector<int> lengths{1, 1};
  const std::vector<MPI_Aint> displacements{0, 4};
  const std::vector<const Datatype*> types{&int_type, &char_type};
  EXPECT_EQ(type_struct(lengths, displacements, types).extent(), 8);
}

TEST(MpiDatatype, PairTypesAreTheirCStructs) {
  struct DoubleInt { double v; int i; };
  struct ShortInt { short v; int i; };
  struct LongDoubleInt { long double v; int i; };
  EXPECT_EQ(pair_type(MPI_DOUBLE_INT).size(), 12);
  EXPECT_EQ(pair_type(MPI_DOUBLE_INT).extent(), static_cast<MPI_Aint>(sizeof(DoubleInt)));
  EXPECT_EQ(pair_type(MPI_SHORT_INT).size(), 6);
  EXPECT_EQ(pair_type(MPI_SHORT_INT).extent(), static_cast<MPI_Aint>(sizeof(ShortInt)));
  EXPECT_EQ(pair_type(MPI_LONG_DOUBLE_INT).extent(), static_cast<MPI_Aint>(sizeof(LongDoubleInt)));
  EXPECT_EQ(pair_type(MPI_2INT).runs().size(), 1u);  // two adjacent ints merge
  EXPECT_EQ(pair_type(MPI_2INT).elements(), 2);
  EXPECT_TRUE(pair_type(MPI_FLOAT_INT).committed());
}

TEST(MpiDatatype, ResizedSetsBoundsAndCopiesStepByTheNewExtent) {
  const Datatype r = type_resized(int_type, -4, 12);
  EXPECT_EQ(r.lb(), -4);
  EXPECT_EQ(r.extent(), 12);
  EXPECT_EQ(r.true_lb(), 0);
  EXPECT_EQ(r.true_extent(), 4);
  const Datatype c = type_contiguous(3, r);
  EXPECT_EQ(c.lb(), -4);
  EXPECT_EQ(c.extent(), 36);
  ASSERT_EQ(c.runs().size(), 3u);
  EXPECT_EQ(c.runs()[2].offset, 24);
  EXPECT_EQ(c.true_extent(), 28);
  // Shrinking the extent makes copies overlap in steps of one byte.
  const Datatype narrow = type_contiguous(4, type_resized(int_type, 0, 1));
  EXPECT_EQ(narrow.extent(), 4);
  EXPECT_EQ(narrow.true_extent(), 7);
  // Markers win over data: a struct with a resized member takes its bounds from the markers.
  const std::vector<int> lengths{1, 1};
  const std::vector<MPI_Aint> displacements{0, 100};
  const std::vector<const Datatype*> types{&r, &int_type};
  const Datatype s = type_struct(lengths, displacements, types);
  EXPECT_EQ(s.lb(), -4);
  EXPECT_EQ(s.ub(), 8);
  EXPECT_EQ(s.true_extent(), 104);
}

TEST(MpiDatatype, NestedVectorsOfStructs) {
  const Datatype s = char_double_int();
  const Datatype row = type_vector(2, 1, 3, s);   // structs 0 and 3 of a row of structs
  const Datatype grid = type_vector(2, 1, 2, row);  // rows 0 and 2, each row's extent apart
  EXPECT_EQ(row.extent(), 4 * s.extent());
  EXPECT_EQ(grid.size(), 4 * s.size());
  EXPECT_EQ(grid.elements(), 12);
  EXPECT_EQ(grid.extent(), 3 * row.extent());
  EXPECT_EQ(grid.runs().back().offset, 2 * row.extent() + 3 * s.extent() + static_cast<MPI_Aint>(offsetof(CharDoubleInt, i)));
}

TEST(MpiDatatype, ZeroCountsMakeEmptyTypes) {
  for (const Datatype& t : {type_contiguous(0, int_type), type_vector(0, 3, 4, int_type), type_vector(3, 0, 4, int_type)}) {
    EXPECT_EQ(t.size(), 0);
    EXPECT_EQ(t.extent(), 0);
    EXPECT_FALSE(t.has_data());
  }
  const std::vector<int> lengths{0, 1};
  const std::vector<MPI_Aint> displacements{-100, 8};
  const std::vector<const Datatype*> types{&double_type, &int_type};
  const Datatype s = type_struct(lengths, displacements, types);
  EXPECT_EQ(s.lb(), 8);  // a zero-length block adds nothing, bounds included
  EXPECT_EQ(s.extent(), 4);
}

TEST(MpiDatatype, ConstructorsCheckTheirArguments) {
  EXPECT_EQ(error_of([] { type_contiguous(-1, int_type); }), MPI_ERR_COUNT);
  EXPECT_EQ(error_of([] { type_vector(2, -1, 1, int_type); }), MPI_ERR_ARG);
  const std::vector<int> lengths{1, -2};
  const std::vector<MPI_Aint> displacements{0, 4};
  EXPECT_EQ(error_of([&] { type_hindexed(lengths, displacements, int_type); }), MPI_ERR_ARG);
  EXPECT_EQ(error_of([] { type_hvector(3, 1, MPI_Aint{1} << 62, int_type); }), MPI_ERR_ARG);  // overflow
  EXPECT_EQ(error_of([] { pair_type(MPI_INT); }), MPI_ERR_TYPE);
}

TEST(MpiDatatype, DupKeepsTheMapAndTheCommittedState) {
  Datatype v = type_vector(2, 1, 3, int_type);
  EXPECT_FALSE(type_dup(v).committed());
  v.commit();
  const Datatype d = type_dup(v);
  EXPECT_TRUE(d.committed());
  EXPECT_TRUE(std::ranges::equal(d.runs(), v.runs()));
  EXPECT_EQ(d.extent(), v.extent());
}

}  // namespace
}  // namespace gcsim::mpi_layer
