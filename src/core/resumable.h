// Long CPU work that a page runs a few milliseconds per animation frame, written as plain
// loops: a coroutine returning Resumable says how much work it has done with
// `co_await Work{n}` and stops there once the units given to the current run() are spent;
// the next run() goes on from that point. `while (!co_await inner) {}` runs another
// Resumable inside, on the same units. run() rethrows what the coroutine threw. The
// result does not depend on how the work was sliced (a coroutine only stops, it never
// skips), so finish() - one run without limit - is the synchronous version of the same code.
//
// Coroutine parameters that are references must outlive the Resumable (pass by value
// what the caller may destroy).
#pragma once
#include <climits>
#include <exception>
#include <utility>

// Debian's Emscripten (3.1.6, clang 14) has its libc++'s coroutines only as <experimental/coroutine>.
#if __has_include(<coroutine>)
#include <coroutine>
namespace pt::coro {
using std::coroutine_handle;
using std::suspend_always;
}  // namespace pt::coro
#else
#include <experimental/coroutine>
namespace pt::coro {
using std::experimental::coroutine_handle;
using std::experimental::suspend_always;
}  // namespace pt::coro
#endif

namespace pt {

struct Work {
  long units;
};
// `co_await EndSlice{}`: the current run() stops here (the next step is long enough to
// deserve a slice of its own); finish() goes on through it.
struct EndSlice {};

class Resumable {
 public:
  struct promise_type;
  using Handle = coro::coroutine_handle<promise_type>;

  struct promise_type {
    long* left = nullptr;  // the units left to the current run, shared with inner coroutines
    std::exception_ptr error;

    Resumable get_return_object() { return Resumable(Handle::from_promise(*this)); }
    coro::suspend_always initial_suspend() noexcept { return {}; }  // nothing runs before run()
    coro::suspend_always final_suspend() noexcept { return {}; }
    void return_void() noexcept {}
    void unhandled_exception() noexcept { error = std::current_exception(); }

    struct Spend {
      bool ready;
      bool await_ready() const noexcept { return ready; }
      void await_suspend(coro::coroutine_handle<>) const noexcept {}
      void await_resume() const noexcept {}
    };
    Spend await_transform(Work w) noexcept {
      *left -= w.units;
      return {*left > 0};
    }
    Spend await_transform(EndSlice) noexcept {
      *left = 0;
      return {false};
    }

    struct Inner {
      Resumable& inner;
      long* left;
      bool done = false;
      bool await_ready() { return done = inner.resume_within(left); }  // rethrows the inner error here
      void await_suspend(coro::coroutine_handle<>) const noexcept {}
      bool await_resume() const noexcept { return done; }
    };
    Inner await_transform(Resumable& inner) noexcept { return {inner, left}; }
  };

  Resumable() = default;
  Resumable(Resumable&& o) noexcept : h_(std::exchange(o.h_, {})) {}
  Resumable& operator=(Resumable&& o) noexcept {
    if (this != &o) {
      if (h_) h_.destroy();
      h_ = std::exchange(o.h_, {});
    }
    return *this;
  }
  Resumable(const Resumable&) = delete;
  Resumable& operator=(const Resumable&) = delete;
  ~Resumable() {
    if (h_) h_.destroy();
  }

  // Does about `units` of work (at least one step); true once the coroutine has finished.
  bool run(long units) {
    long left = units;
    return resume_within(&left);
  }
  void finish() {
    while (!run(LONG_MAX)) {
    }
  }
  bool done() const { return !h_ || h_.done(); }

 private:
  explicit Resumable(Handle h) : h_(h) {}

  bool resume_within(long* left) {
    if (done()) return true;
    h_.promise().left = left;
    h_.resume();
    if (h_.promise().error) std::rethrow_exception(std::exchange(h_.promise().error, nullptr));
    return h_.done();
  }

  Handle h_;
};

}  // namespace pt
