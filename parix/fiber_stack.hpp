#pragma once
// Stacks for the simulated processors' fibers: guard-paged (an overflow faults instead of
// corrupting a neighbour) and registered with valgrind when its header is available, so that
// memcheck understands the stack switches instead of reporting every access to a fiber's locals.
// (Boost's own BOOST_USE_VALGRIND would change stack_context's layout and break the ABI of the
// distribution's compiled Boost.Fiber.)
#include <cstddef>
#include <unordered_map>

#include <boost/context/protected_fixedsize_stack.hpp>

#if __has_include(<valgrind/valgrind.h>)
#include <valgrind/valgrind.h>
#define GCSIM_VALGRIND_STACKS 1
#endif

namespace gcsim::parix {

class FiberStack {
 public:
  explicit FiberStack(std::size_t bytes) : inner_(bytes) {}

  boost::context::stack_context allocate() {
    boost::context::stack_context s = inner_.allocate();
#ifdef GCSIM_VALGRIND_STACKS
    registered()[s.sp] = VALGRIND_STACK_REGISTER(static_cast<char*>(s.sp) - s.size, s.sp);
#endif
    return s;
  }

  void deallocate(boost::context::stack_context& s) noexcept {
#ifdef GCSIM_VALGRIND_STACKS
    auto it = registered().find(s.sp);
    if (it != registered().end()) {
      VALGRIND_STACK_DEREGISTER(it->second);
      registered().erase(it);
    }
#endif
    inner_.deallocate(s);
  }

 private:
#ifdef GCSIM_VALGRIND_STACKS
  // Stack top -> valgrind's id; fibers are created and destroyed on one host thread.
  static std::unordered_map<void*, unsigned>& registered() {
    static thread_local std::unordered_map<void*, unsigned> ids;
    return ids;
  }
#endif
  boost::context::protected_fixedsize_stack inner_;
};

}  // namespace gcsim::parix
