// Resumable (core/resumable.h): work stops when the units run out and goes on where it
// stopped; inner coroutines share the units; errors reach run(); slicing changes nothing.
#include <catch2/catch.hpp>

#include <stdexcept>
#include <vector>

#include "core/resumable.h"

using namespace pt;

namespace {

// Appends 0..n-1, one unit each.
Resumable count(int n, std::vector<int>& out) {
  for (int i = 0; i < n; ++i) {
    out.push_back(i);
    co_await Work{1};
  }
}

// Two inner counts around a marker; throws after them when asked to.
Resumable outer(std::vector<int>& out, bool fail) {
  Resumable a = count(5, out);
  while (!co_await a) {
  }
  out.push_back(-1);
  co_await Work{1};
  Resumable b = count(3, out);
  while (!co_await b) {
  }
  if (fail) throw std::runtime_error("planted");
  out.push_back(-2);
}

}  // namespace

TEST_CASE("a Resumable does about the units it is given, and resumes where it stopped", "[resumable]") {
  std::vector<int> out;
  Resumable r = count(10, out);
  CHECK(out.empty());  // nothing runs before run()
  CHECK_FALSE(r.run(3));
  CHECK(out == std::vector<int>{0, 1, 2});
  CHECK_FALSE(r.run(4));
  CHECK(out.size() == 7);
  CHECK(r.run(100));
  CHECK(out.size() == 10);
  CHECK(r.done());
  CHECK(r.run(1));  // done stays done
}

TEST_CASE("inner Resumables share the outer's units; any slicing gives the same result", "[resumable]") {
  std::vector<int> whole;
  outer(whole, false).finish();
  CHECK(whole == std::vector<int>{0, 1, 2, 3, 4, -1, 0, 1, 2, -2});
  for (long units : {1L, 2L, 3L, 7L}) {
    std::vector<int> sliced;
    Resumable r = outer(sliced, false);
    int runs = 0;
    while (!r.run(units)) {
      ++runs;
      REQUIRE(sliced.size() <= size_t(runs) * size_t(units));  // never more than the units given
    }
    CHECK(sliced == whole);
    if (units == 1) CHECK(runs >= 8);
  }
}

TEST_CASE("an exception inside an inner Resumable reaches run(), after the work before it", "[resumable]") {
  std::vector<int> out;
  Resumable r = outer(out, true);
  CHECK_FALSE(r.run(4));
  CHECK_THROWS_WITH(r.finish(), "planted");
  CHECK(out == std::vector<int>{0, 1, 2, 3, 4, -1, 0, 1, 2});
  CHECK(r.done());
}

TEST_CASE("EndSlice ends the current run there; finish goes on through it", "[resumable]") {
  auto two_steps = [](std::vector<int>& out) -> Resumable {
    out.push_back(1);
    co_await EndSlice{};
    out.push_back(2);
  };
  std::vector<int> out;
  Resumable r = two_steps(out);
  CHECK_FALSE(r.run(1000000));  // plenty of units: stopped by EndSlice, not by them
  CHECK(out == std::vector<int>{1});
  CHECK(r.run(1));
  CHECK(out == std::vector<int>{1, 2});
  std::vector<int> all;
  Resumable f = two_steps(all);
  f.finish();
  CHECK(all == std::vector<int>{1, 2});
}
