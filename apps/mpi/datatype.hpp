#pragma once
// A datatype as the standard defines it (MPI 3.1 section 4.1): a type map, kept flattened to runs
// of one basic type at increasing addresses in type-map order (adjacent runs merged where they
// are contiguous), and its bounds. Bounds follow the standard's rule: lb and ub are the least and
// greatest lb/ub markers if the map has any (create_resized puts them), else the least
// displacement and the greatest end rounded up to the map's alignment.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "apps/mpi/basic_type.hpp"

namespace gcsim::mpi_layer {

// count consecutive elements of one basic type starting offset bytes from the buffer.
struct Run {
  MPI_Aint offset;
  Basic basic;
  MPI_Count count;
  friend bool operator==(const Run&, const Run&) = default;
};

class Datatype {
 public:
  static Datatype of_basic(Basic b);

  std::span<const Run> runs() const { return runs_; }
  MPI_Count size() const { return size_; }          // bytes of data in one element
  MPI_Count elements() const { return elements_; }  // basic elements in one element
  MPI_Aint lb() const;
  MPI_Aint ub() const;
  MPI_Aint extent() const { return ub() - lb(); }
  MPI_Aint true_lb() const { return has_data() ? data_lb_ : 0; }
  MPI_Aint true_extent() const { return has_data() ? data_ub_ - data_lb_ : 0; }
  std::size_t alignment() const { return alignment_; }
  bool has_data() const { return !runs_.empty(); }
  // One run covering [lb, ub) exactly: count elements are one block of bytes. Asked on every
  // send and receive, so found once, as the type is made.
  bool is_dense() const { return dense_; }

  bool committed() const { return committed_; }
  void commit() { committed_ = true; }

 private:
  friend class TypeBuilder;
  bool find_dense() const;
  std::vector<Run> runs_;
  MPI_Count size_ = 0;
  MPI_Count elements_ = 0;
  MPI_Aint data_lb_ = 0, data_ub_ = 0;  // of the data entries, when there are any
  std::optional<MPI_Aint> lb_marker_, ub_marker_;
  std::size_t alignment_ = 1;
  bool committed_ = false;
  bool dense_ = false;  // find_dense(), set where a type is finished
};

// Builds a type map from copies of other types, each displaced by some bytes.
class TypeBuilder {
 public:
  // n copies of t, the i-th displaced by displacement + i * extent(t).
  void add_copies(const Datatype& t, MPI_Aint displacement, MPI_Count n);
  void add(const Datatype& t, MPI_Aint displacement) { add_copies(t, displacement, 1); }
  // Erases every marker and puts lb and ub ones (create_resized).
  void set_bounds(MPI_Aint lb, MPI_Aint ub);
  Datatype finish() {
    type_.dense_ = type_.find_dense();
    return std::move(type_);
  }

 private:
  void append_run(Run r);
  void add_bounds(const Datatype& t, MPI_Aint displacement);
  Datatype type_;
  bool data_seen_ = false;
};

// Displacement arithmetic that reports overflow as MPI_ERR_ARG instead of wrapping.
MPI_Aint checked_multiply(MPI_Aint a, MPI_Aint b);
MPI_Aint checked_add(MPI_Aint a, MPI_Aint b);

}  // namespace gcsim::mpi_layer
