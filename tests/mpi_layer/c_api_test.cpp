// The C entry points over the core: handles per rank's registry, errors as return values, groups
// as the runtime will hand them out, and MPI-1's removed names.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "apps/mpi/error.hpp"
#include "apps/mpi/registry.hpp"

namespace gcsim::mpi_layer {
namespace {

TEST(MpiCApi, EachRegistryHoldsItsOwnRanksObjects) {
  Registry rank0, rank1;
  MPI_Datatype t0 = MPI_DATATYPE_NULL, t1 = MPI_DATATYPE_NULL;
  {
    RegistryScope scope(rank0);
    ASSERT_EQ(MPI_Type_contiguous(3, MPI_INT, &t0), MPI_SUCCESS);
    EXPECT_GE(t0, first_user_handle);
    {
      RegistryScope inner(rank1);
      ASSERT_EQ(MPI_Type_vector(2, 1, 2, MPI_DOUBLE, &t1), MPI_SUCCESS);
      int size = 0;
      EXPECT_EQ(MPI_Type_size(t1, &size), MPI_SUCCESS);
      EXPECT_EQ(size, 16);
    }
    int size = 0;  // back in rank 0: its own type of the same handle number
    EXPECT_EQ(MPI_Type_size(t0, &size), MPI_SUCCESS);
    EXPECT_EQ(size, 12);
  }
  EXPECT_EQ(rank0.datatypes.live(), 1u);
  EXPECT_EQ(rank1.datatypes.live(), 1u);
}

TEST(MpiCApi, FreedHandlesStayInvalid) {
  Registry r;
  RegistryScope scope(r);
  MPI_Datatype t = MPI_DATATYPE_NULL;
  ASSERT_EQ(MPI_Type_contiguous(2, MPI_INT, &t), MPI_SUCCESS);
  const MPI_Datatype freed = t;
  ASSERT_EQ(MPI_Type_free(&t), MPI_SUCCESS);
  EXPECT_EQ(t, MPI_DATATYPE_NULL);
  MPI_Datatype again = MPI_DATATYPE_NULL;
  ASSERT_EQ(MPI_Type_contiguous(2, MPI_INT, &again), MPI_SUCCESS);
  EXPECT_NE(again, freed);
  int size = 0;
  EXPECT_EQ(MPI_Type_size(freed, &size), MPI_ERR_TYPE);
  EXPECT_EQ(MPI_Type_contiguous(-1, MPI_INT, &t), MPI_ERR_COUNT);
  EXPECT_EQ(MPI_Type_contiguous(1, MPI_DATATYPE_NULL, &t), MPI_ERR_TYPE);
  EXPECT_EQ(MPI_Type_contiguous(1, MPI_INT, nullptr), MPI_ERR_ARG);
  MPI_Op sum = MPI_SUM;
  EXPECT_EQ(MPI_Op_free(&sum), MPI_ERR_OP);
  EXPECT_EQ(sum, MPI_SUM);
}

TEST(MpiCApi, MpiOnesRemovedNamesStillWork) {
  Registry r;
  RegistryScope scope(r);
  int lengths[2] = {1, 1};
  MPI_Aint displacements[2] = {-4, 8};
  MPI_Datatype types[2] = {MPI_INT, MPI_DOUBLE}, t = MPI_DATATYPE_NULL;
  ASSERT_EQ(MPI_Type_struct(2, lengths, displacements, types, &t), MPI_SUCCESS);
  MPI_Aint extent = 0, lb = 0, ub = 0;
  MPI_Type_extent(t, &extent);
  MPI_Type_lb(t, &lb);
  MPI_Type_ub(t, &ub);
  EXPECT_EQ(lb, -4);
  EXPECT_EQ(extent, 24);  // 16 - (-4) = 20, rounded up to double's alignment
  EXPECT_EQ(ub, lb + extent);
  MPI_Aint address = 0;
  EXPECT_EQ(MPI_Address(&extent, &address), MPI_SUCCESS);
  EXPECT_EQ(address, reinterpret_cast<MPI_Aint>(&extent));
}

TEST(MpiCApi, GroupsAsTheRuntimeWillHandThemOut) {
  Registry r;
  r.world_rank = 2;
  RegistryScope scope(r);
  const MPI_Group world = r.groups.insert(Group::world(6));
  int rank = -1, size = -1;
  EXPECT_EQ(MPI_Group_rank(world, &rank), MPI_SUCCESS);
  EXPECT_EQ(rank, 2);
  int ranges[1][3] = {{5, 1, -2}};  // 5 3 1
  MPI_Group odd = MPI_GROUP_NULL;
  ASSERT_EQ(MPI_Group_range_incl(world, 1, ranges, &odd), MPI_SUCCESS);
  MPI_Group_size(odd, &size);
  EXPECT_EQ(size, 3);
  EXPECT_EQ(MPI_Group_rank(odd, &rank), MPI_SUCCESS);
  EXPECT_EQ(rank, MPI_UNDEFINED);  // world rank 2 is not in it
  const int from[3] = {0, 1, 2};
  int to[3] = {};
  ASSERT_EQ(MPI_Group_translate_ranks(odd, 3, from, world, to), MPI_SUCCESS);
  EXPECT_EQ(to[0], 5);
  EXPECT_EQ(to[2], 1);
  MPI_Group none = MPI_GROUP_NULL;
  ASSERT_EQ(MPI_Group_difference(odd, world, &none), MPI_SUCCESS);
  EXPECT_EQ(none, MPI_GROUP_EMPTY);
  const int twice[2] = {1, 1};
  EXPECT_EQ(MPI_Group_incl(world, 2, twice, &none), MPI_ERR_RANK);
  int result = -1;
  MPI_Group_compare(odd, world, &result);
  EXPECT_EQ(result, MPI_UNEQUAL);
  ASSERT_EQ(MPI_Group_free(&odd), MPI_SUCCESS);
  EXPECT_EQ(odd, MPI_GROUP_NULL);
  EXPECT_EQ(MPI_Group_size(odd, &size), MPI_ERR_GROUP);
}

TEST(MpiCApi, EveryErrorClassHasAText) {
  for (int code = MPI_SUCCESS; code <= MPI_ERR_LASTCODE; ++code) {
    char text[MPI_MAX_ERROR_STRING];
    int length = 0, error_class = -1;
    ASSERT_EQ(MPI_Error_string(code, text, &length), MPI_SUCCESS);
    EXPECT_GT(length, 10);
    EXPECT_EQ(length, static_cast<int>(std::strlen(text)));
    EXPECT_EQ(MPI_Error_class(code, &error_class), MPI_SUCCESS);
    EXPECT_EQ(error_class, code);
    EXPECT_EQ(std::string(text).rfind("MPI_", 0), 0u);
  }
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  EXPECT_EQ(MPI_Error_string(MPI_ERR_LASTCODE + 1, text, &length), MPI_ERR_ARG);
  EXPECT_EQ(error_text(MPI_ERR_TRUNCATE), "MPI_ERR_TRUNCATE: message truncated");
}

TEST(MpiCApi, StatusCountsForAPartialReceive) {
  Registry r;
  RegistryScope scope(r);
  MPI_Datatype t = MPI_DATATYPE_NULL;
  int lengths[2] = {1, 1};
  MPI_Aint displacements[2] = {0, 8};
  MPI_Datatype types[2] = {MPI_INT, MPI_DOUBLE};
  MPI_Type_create_struct(2, lengths, displacements, types, &t);
  MPI_Type_commit(&t);
  MPI_Status status{};
  status.gcsim_bytes = 12 + 4;  // one struct and an int arrived
  int count = 0;
  EXPECT_EQ(MPI_Get_count(&status, t, &count), MPI_SUCCESS);
  EXPECT_EQ(count, MPI_UNDEFINED);
  EXPECT_EQ(MPI_Get_elements(&status, t, &count), MPI_SUCCESS);
  EXPECT_EQ(count, 3);
  MPI_Count big = 0;
  EXPECT_EQ(MPI_Get_elements_x(&status, t, &big), MPI_SUCCESS);
  EXPECT_EQ(big, 3);
  EXPECT_EQ(MPI_Get_count(MPI_STATUS_IGNORE, t, &count), MPI_ERR_ARG);
}

}  // namespace
}  // namespace gcsim::mpi_layer
