#pragma once
// A rank's live operations by request handle, without a heap allocation per request: handles are
// given in increasing order and never reused (a freed handle stays invalid), the live ones are kept
// in a vector in handle order (a rank rarely has more than a few; a lookup is a binary search,
// the newest first), and finished operations go back to a free list to be reset and reused.
#include <algorithm>
#include <memory>
#include <utility>
#include <vector>

#include "apps/mpi/runtime/operation.hpp"

namespace gcsim::mpi_layer {

class OperationTable {
 public:
  struct Entry {
    MPI_Request handle;
    Operation* op;
  };

  OperationTable() = default;
  OperationTable(const OperationTable&) = delete;
  OperationTable& operator=(const OperationTable&) = delete;
  ~OperationTable() {
    for (const Entry& e : live_) delete e.op;
  }

  // A fresh operation (fields at their defaults) and its handle.
  std::pair<MPI_Request, Operation&> add();
  // The handle the next add() gives.
  MPI_Request next_handle() const { return next_; }

  Operation* find(MPI_Request handle) const {
    if (!live_.empty() && live_.back().handle == handle) return live_.back().op;
    const auto it = std::lower_bound(live_.begin(), live_.end(), handle,
                                     [](const Entry& e, MPI_Request h) { return e.handle < h; });
    return it != live_.end() && it->handle == handle ? it->op : nullptr;
  }
  Operation& at(MPI_Request handle) const { return *find(handle); }  // handle must be live
  bool erase(MPI_Request handle);
  template <class Pred>
  std::size_t erase_if(Pred pred) {
    std::size_t erased = 0;
    for (std::size_t i = live_.size(); i-- > 0;) {
      if (pred(*live_[i].op)) erase_at(i), ++erased;
    }
    return erased;
  }

  // In handle order, as the map this replaces iterated.
  auto begin() const { return live_.begin(); }
  auto end() const { return live_.end(); }

 private:
  void erase_at(std::size_t index);
  std::vector<Entry> live_;
  std::vector<std::unique_ptr<Operation>> spare_;  // reset, ready for add()
  MPI_Request next_ = 1;
};

}  // namespace gcsim::mpi_layer
