#pragma once
// What the kernel runs at an event: a move-only callable stored inline. std::function would
// allocate for any capture over 16 bytes and copy-construct through an indirect call; most of the
// kernel's actions capture a few pointers and integers, which are stored here in place and moved
// by memcpy. A larger or non-trivially-movable callable still works: it is moved through a small
// manager function, and one that does not fit at all lives on the heap.
#include <cstddef>
#include <cstring>
#include <new>
#include <type_traits>
#include <utility>

namespace gcsim::machine {

class KernelAction {
 public:
  static constexpr std::size_t kInlineBytes = 48;

  KernelAction() = default;
  template <class F, class = std::enable_if_t<!std::is_same_v<std::decay_t<F>, KernelAction>>>
  KernelAction(F&& f) {  // NOLINT(google-explicit-constructor): lambdas convert implicitly
    using Fn = std::decay_t<F>;
    if constexpr (fits_inline<Fn>()) {
      ::new (static_cast<void*>(buffer_)) Fn(std::forward<F>(f));
      invoke_ = [](void* b) { (*std::launder(static_cast<Fn*>(b)))(); };
      if constexpr (!std::is_trivially_copyable_v<Fn> || !std::is_trivially_destructible_v<Fn>) {
        manage_ = [](void* dst, void* src) {
          Fn* from = std::launder(static_cast<Fn*>(src));
          if (dst) ::new (dst) Fn(std::move(*from));
          from->~Fn();
        };
      }
    } else {
      Fn* heap = new Fn(std::forward<F>(f));
      std::memcpy(buffer_, &heap, sizeof heap);
      invoke_ = [](void* b) { (**static_cast<Fn**>(b))(); };
      manage_ = [](void* dst, void* src) {
        if (dst) std::memcpy(dst, src, sizeof(Fn*));
        else delete *static_cast<Fn**>(src);
      };
    }
  }
  KernelAction(KernelAction&& o) noexcept { take(o); }
  KernelAction& operator=(KernelAction&& o) noexcept {
    if (this != &o) {
      reset();
      take(o);
    }
    return *this;
  }
  KernelAction(const KernelAction&) = delete;
  KernelAction& operator=(const KernelAction&) = delete;
  ~KernelAction() { reset(); }

  // Moves o's callable into this action, which must be empty (o is left empty): assignment
  // without first destroying what is known to be nothing (the kernel's free slots).
  void fill(KernelAction&& o) noexcept { take(o); }

  explicit operator bool() const { return invoke_ != nullptr; }
  // const, as std::function's: a lambda that is not mutable calls its captured actions.
  void operator()() const { invoke_(const_cast<unsigned char*>(buffer_)); }
  void reset() {
    if (manage_) manage_(nullptr, buffer_);
    invoke_ = nullptr;
    manage_ = nullptr;
  }

 private:
  template <class Fn>
  static constexpr bool fits_inline() {
    return sizeof(Fn) <= kInlineBytes && alignof(Fn) <= alignof(std::max_align_t) &&
           std::is_nothrow_move_constructible_v<Fn>;
  }
  // Moves o's callable here (o must be empty-able: it is left empty).
  void take(KernelAction& o) noexcept {
    invoke_ = o.invoke_;
    manage_ = o.manage_;
    if (manage_) manage_(buffer_, o.buffer_);
    else std::memcpy(buffer_, o.buffer_, kInlineBytes);
    o.invoke_ = nullptr;
    o.manage_ = nullptr;
  }

  alignas(std::max_align_t) unsigned char buffer_[kInlineBytes];
  void (*invoke_)(void*) = nullptr;
  // Moves the callable from src to dst and destroys it at src (dst null: destroys only).
  // Null for trivially copyable callables, which are moved by memcpy.
  void (*manage_)(void* dst, void* src) = nullptr;
};

}  // namespace gcsim::machine
