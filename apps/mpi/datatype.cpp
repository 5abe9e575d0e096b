#include "apps/mpi/datatype.hpp"

#include <algorithm>

#include "apps/mpi/error.hpp"

namespace gcsim::mpi_layer {

MPI_Aint checked_multiply(MPI_Aint a, MPI_Aint b) {
  MPI_Aint r;
  if (__builtin_mul_overflow(a, b, &r)) fail(MPI_ERR_ARG, "datatype displacement overflows MPI_Aint");
  return r;
}

MPI_Aint checked_add(MPI_Aint a, MPI_Aint b) {
  MPI_Aint r;
  if (__builtin_add_overflow(a, b, &r)) fail(MPI_ERR_ARG, "datatype displacement overflows MPI_Aint");
  return r;
}

Datatype Datatype::of_basic(Basic b) {
  Datatype t;
  const auto size = static_cast<MPI_Count>(basic_size(b));
  t.runs_.push_back({0, b, 1});
  t.size_ = size;
  t.elements_ = 1;
  t.data_lb_ = 0;
  t.data_ub_ = size;
  t.alignment_ = basic_alignment(b);
  t.committed_ = true;
  t.dense_ = t.find_dense();
  return t;
}

MPI_Aint Datatype::lb() const {
  if (lb_marker_) return *lb_marker_;
  return has_data() ? data_lb_ : 0;
}

MPI_Aint Datatype::ub() const {
  if (ub_marker_) return *ub_marker_;
  const MPI_Aint low = lb();
  const MPI_Aint high = has_data() ? std::max(data_ub_, low) : low;
  // The standard's epsilon: the extent rounded up to a multiple of the largest alignment.
  const auto align = static_cast<MPI_Aint>(alignment_);
  const MPI_Aint rest = (high - low) % align;
  return rest == 0 ? high : high + (align - rest);
}

bool Datatype::find_dense() const {
  if (runs_.size() != 1) return false;
  const Run& r = runs_.front();
  return r.offset == lb() && r.count * static_cast<MPI_Count>(basic_size(r.basic)) == extent();
}

void TypeBuilder::append_run(Run r) {
  if (!type_.runs_.empty()) {
    Run& last = type_.runs_.back();
    const auto size = static_cast<MPI_Aint>(basic_size(last.basic));
    if (last.basic == r.basic && last.offset + last.count * size == r.offset) {
      last.count += r.count;
      return;
    }
  }
  type_.runs_.push_back(r);
}

// Data bounds and markers of one copy of t at displacement.
void TypeBuilder::add_bounds(const Datatype& t, MPI_Aint displacement) {
  Datatype& d = type_;
  if (t.has_data()) {
    const MPI_Aint low = checked_add(t.data_lb_, displacement), high = checked_add(t.data_ub_, displacement);
    d.data_lb_ = data_seen_ ? std::min(d.data_lb_, low) : low;
    d.data_ub_ = data_seen_ ? std::max(d.data_ub_, high) : high;
    data_seen_ = true;
  }
  if (t.lb_marker_) {
    const MPI_Aint m = checked_add(*t.lb_marker_, displacement);
    d.lb_marker_ = d.lb_marker_ ? std::min(*d.lb_marker_, m) : m;
  }
  if (t.ub_marker_) {
    const MPI_Aint m = checked_add(*t.ub_marker_, displacement);
    d.ub_marker_ = d.ub_marker_ ? std::max(*d.ub_marker_, m) : m;
  }
}

void TypeBuilder::add_copies(const Datatype& t, MPI_Aint displacement, MPI_Count n) {
  if (n <= 0) return;
  const MPI_Aint extent = t.extent();
  const MPI_Aint last = checked_add(displacement, checked_multiply(extent, n - 1));
  // Bounds are linear in the copy's index: the first and the last copy hold the extremes.
  add_bounds(t, displacement);
  if (n > 1) add_bounds(t, last);
  type_.alignment_ = std::max(type_.alignment_, t.alignment_);
  type_.size_ = checked_add(type_.size_, checked_multiply(t.size_, n));
  type_.elements_ = checked_add(type_.elements_, checked_multiply(t.elements_, n));
  if (t.is_dense()) {
    const Run& r = t.runs_.front();
    append_run({r.offset + displacement, r.basic, r.count * n});
    return;
  }
  for (MPI_Count i = 0; i < n; ++i) {
    const MPI_Aint shift = displacement + extent * i;  // between the two checked ends
    for (const Run& r : t.runs_) append_run({r.offset + shift, r.basic, r.count});
  }
}

void TypeBuilder::set_bounds(MPI_Aint lb, MPI_Aint ub) {
  type_.lb_marker_ = lb;
  type_.ub_marker_ = ub;
}

}  // namespace gcsim::mpi_layer
