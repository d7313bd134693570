// The touch gesture recogniser (app/touch.h) driven by made-up touches: a drag looks, a
// pinch and a two-finger pan, taps, double taps, and what must not be a tap.
#include <catch2/catch.hpp>

#include <cmath>

#include "app/touch.h"

using namespace pt;

namespace {

constexpr float kDpr = 3.0f;  // a phone: the slops are CSS pixels, the touches device pixels

TouchRecognizer phone() {
  TouchRecognizer r;
  r.set_scale(kDpr);
  return r;
}

}  // namespace

TEST_CASE("touch: one finger drags to look, past the tap's slop only", "[touch]") {
  TouchRecognizer r = phone();
  r.down(1, {100, 100}, 0);
  r.move(1, {100 + 5 * kDpr, 100}, 16);  // inside the slop: nothing yet
  CHECK(!r.take().any());
  r.move(1, {100 + 12 * kDpr, 100}, 32);  // leaves the slop: from here on it looks
  r.move(1, {100 + 12 * kDpr + 30, 100 - 20}, 48);
  TouchGestures g = r.take();
  CHECK(g.look.x == Approx(30));
  CHECK(g.look.y == Approx(-20));
  CHECK(g.pinch == 0.0f);
  r.move(1, {100 + 12 * kDpr + 40, 100 - 20}, 64);
  r.up(1, {100 + 12 * kDpr + 40, 100 - 20}, 80);
  g = r.take();
  CHECK(g.look.x == Approx(10));
  CHECK(!g.tap);  // a drag is not a tap
  CHECK(!g.double_tap);
}

TEST_CASE("touch: a tap without movement, at its start", "[touch]") {
  TouchRecognizer r = phone();
  r.down(7, {200, 300}, 1000);
  r.move(7, {200 + 4 * kDpr, 300 + 3 * kDpr}, 1050);  // a trembling finger
  r.up(7, {200 + 4 * kDpr, 300 + 3 * kDpr}, 1100);
  const TouchGestures g = r.take();
  REQUIRE(g.tap);
  CHECK(g.tap->x == 200);
  CHECK(g.tap->y == 300);
  CHECK(g.look == glm::vec2(0.0f));
  CHECK(!g.double_tap);
}

TEST_CASE("touch: a long press is not a tap", "[touch]") {
  TouchRecognizer r = phone();
  r.down(1, {200, 300}, 0);
  r.up(1, {200, 300}, TouchRecognizer::kTapMs + 100);
  CHECK(!r.take().tap);
}

TEST_CASE("touch: a double tap resets, a slow or distant second tap is a tap", "[touch]") {
  TouchRecognizer r = phone();
  r.down(1, {200, 300}, 0);
  r.up(1, {200, 300}, 60);
  CHECK(r.take().tap);
  r.down(2, {210, 305}, 200);
  r.up(2, {210, 305}, 260);
  TouchGestures g = r.take();
  CHECK(g.double_tap);
  CHECK(!g.tap);  // the second tap resets only
  // A third tap soon after starts a new pair (a triple tap is a double tap and a tap).
  r.down(3, {210, 305}, 400);
  r.up(3, {210, 305}, 450);
  g = r.take();
  CHECK(g.tap);
  CHECK(!g.double_tap);
  // Too late: two taps.
  r.down(4, {210, 305}, 450 + TouchRecognizer::kDoubleTapMs + 50);
  r.up(4, {210, 305}, 450 + TouchRecognizer::kDoubleTapMs + 100);
  g = r.take();
  CHECK(g.tap);
  CHECK(!g.double_tap);
  // Too far: two taps.
  r.down(5, {210 + 60 * kDpr, 305}, 1000);
  r.up(5, {210 + 60 * kDpr, 305}, 1050);
  g = r.take();
  CHECK(g.tap);
  CHECK(!g.double_tap);
}

TEST_CASE("touch: two fingers pinch and pan, never look nor tap", "[touch]") {
  TouchRecognizer r = phone();
  r.down(1, {100, 500}, 0);
  r.down(2, {300, 500}, 10);  // 200 apart, midpoint (200, 500)
  r.move(1, {50, 500}, 30);
  r.move(2, {350, 500}, 30);  // 300 apart: spread by 1.5, the midpoint stays
  TouchGestures g = r.take();
  CHECK(g.pinch == Approx(std::log(1.5f)));
  CHECK(g.pan.x == Approx(0.0f).margin(1e-4));
  CHECK(g.look == glm::vec2(0.0f));
  // Both move right by 40 and down by 10: a pan, no pinch.
  r.move(1, {90, 510}, 50);
  r.move(2, {390, 510}, 50);
  g = r.take();
  CHECK(g.pan.x == Approx(40.0f));
  CHECK(g.pan.y == Approx(10.0f));
  CHECK(g.pinch == Approx(0.0f).margin(1e-5));
  // Pinched back to 150 apart.
  r.move(1, {165, 510}, 70);
  r.move(2, {315, 510}, 70);
  CHECK(r.take().pinch == Approx(std::log(0.5f)));
  // One finger lifted: the other goes on looking from where it is, without a jump.
  r.up(2, {315, 510}, 90);
  r.move(1, {175, 510}, 100);
  g = r.take();
  CHECK(g.look.x == Approx(10.0f));
  CHECK(g.pinch == 0.0f);
  r.up(1, {175, 510}, 110);
  g = r.take();
  CHECK(!g.tap);
  CHECK(!g.double_tap);
}

TEST_CASE("touch: two-finger taps and cancelled touches are no taps", "[touch]") {
  TouchRecognizer r = phone();
  r.down(1, {100, 100}, 0);
  r.down(2, {140, 100}, 5);
  r.up(1, {100, 100}, 40);
  r.up(2, {140, 100}, 45);
  CHECK(!r.take().tap);
  r.down(3, {100, 100}, 100);
  r.cancel(3);
  CHECK(!r.take().tap);
  CHECK(r.fingers() == 0);
  r.down(4, {100, 100}, 200);
  r.up(4, {100, 100}, 240);
  CHECK(r.take().tap);  // the next one is a tap again
}
