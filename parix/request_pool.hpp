#pragma once
// Request states for the simulated runtime without a malloc per send and receive: a free list of
// equal-sized blocks, handed to std::allocate_shared, which puts the shared_ptr's control block and
// the RequestState in one of them. The pool lives in the Simulation and must outlive every
// request of its run (they are held by the run's fibers and messages, all gone before it ends).
#include <cstddef>
#include <memory>
#include <new>
#include <vector>

#include "parix/processor.hpp"

namespace gcsim::parix::detail {

class BlockPool {
 public:
  BlockPool() = default;
  BlockPool(const BlockPool&) = delete;
  BlockPool& operator=(const BlockPool&) = delete;
  ~BlockPool() {
    for (void* chunk : chunks_) ::operator delete(chunk, std::align_val_t{kAlign});
  }

  // Every block has the size of the first request (allocate_shared asks for one type only).
  void* take(std::size_t bytes) {
    if (block_ == 0) block_ = (bytes + kAlign - 1) / kAlign * kAlign;
    if (bytes > block_) return ::operator new(bytes, std::align_val_t{kAlign});  // not expected
    if (free_.empty()) grow();
    void* b = free_.back();
    free_.pop_back();
    return b;
  }
  void give(void* p, std::size_t bytes) {
    if (bytes > block_) return ::operator delete(p, std::align_val_t{kAlign});
    free_.push_back(p);
  }

 private:
  static constexpr std::size_t kAlign = alignof(std::max_align_t);
  static constexpr std::size_t kBlocksPerChunk = 256;
  void grow() {
    auto* chunk = static_cast<char*>(::operator new(block_ * kBlocksPerChunk, std::align_val_t{kAlign}));
    chunks_.push_back(chunk);
    for (std::size_t i = kBlocksPerChunk; i-- > 0;) free_.push_back(chunk + i * block_);
  }
  std::size_t block_ = 0;
  std::vector<void*> free_;
  std::vector<void*> chunks_;
};

template <class T>
struct PoolAllocator {
  using value_type = T;
  BlockPool* pool;
  explicit PoolAllocator(BlockPool& p) : pool(&p) {}
  template <class U>
  PoolAllocator(const PoolAllocator<U>& o) : pool(o.pool) {}  // NOLINT: rebinding converts implicitly
  T* allocate(std::size_t n) { return static_cast<T*>(pool->take(n * sizeof(T))); }
  void deallocate(T* p, std::size_t n) { pool->give(p, n * sizeof(T)); }
  template <class U>
  bool operator==(const PoolAllocator<U>& o) const { return pool == o.pool; }
};

inline std::shared_ptr<RequestState> new_request(BlockPool& pool) {
  return std::allocate_shared<RequestState>(PoolAllocator<RequestState>(pool));
}

}  // namespace gcsim::parix::detail
