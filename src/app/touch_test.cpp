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

namespace {

// A two-finger gesture from (a0, b0) to (a1, b1) (CSS pixels, on the phone), as `steps`
// touchmove events of both fingers (straight lines; finger b reaches its end `lag` of the
// way behind finger a, catching up in the last event), with a frame (take) after every
// `per_frame` events (0: one frame at the end), the fingers then lifted. What the frames
// added up to.
struct Sum {
  glm::vec2 pan{0.0f};
  float pinch = 0.0f;
  glm::vec2 look{0.0f};
  bool tap = false;
  int frames_pinching = 0;  // frames whose pinch was not 0
};
Sum two_fingers(glm::vec2 a0, glm::vec2 b0, glm::vec2 a1, glm::vec2 b1, int steps, int per_frame, float lag = 0.0f) {
  TouchRecognizer r = phone();
  Sum sum;
  const auto frame = [&] {
    const TouchGestures g = r.take();
    sum.pan += g.pan / kDpr;
    sum.pinch += g.pinch;
    sum.look += g.look;
    sum.tap = sum.tap || g.tap.has_value();
    sum.frames_pinching += g.pinch != 0.0f;
  };
  double t = 1000;
  r.down(1, a0 * kDpr, t);
  r.down(2, b0 * kDpr, t);
  for (int k = 1; k <= steps; ++k) {
    t += 16;
    const float u = float(k) / float(steps), v = k == steps ? 1.0f : std::max(0.0f, u - lag);
    r.move(1, (a0 + (a1 - a0) * u) * kDpr, t);  // one event: both fingers, the same time
    r.move(2, (b0 + (b1 - b0) * v) * kDpr, t);
    if (per_frame > 0 && k % per_frame == 0) frame();
  }
  t += 16;
  r.up(1, a1 * kDpr, t);
  r.up(2, b1 * kDpr, t);
  frame();
  return sum;
}

// Few big steps (a slow page: the browser coalesces the moves) and many small ones, a
// frame after each event, after every few or only at the end.
const int kGroupings[][2] = {{1, 1}, {2, 1}, {3, 0}, {8, 1}, {8, 3}, {40, 1}, {40, 7}, {40, 0}, {200, 1}};

}  // namespace

TEST_CASE("touch: a pinch moves from its dead zone's edge and never pans, however the moves are grouped", "[touch]") {
  const float slop = TouchRecognizer::kPinchSlop;
  for (const auto& [steps, per_frame] : kGroupings) {
    CAPTURE(steps, per_frame);
    // Spread from 200 to 300 apart about a fixed midpoint.
    Sum s = two_fingers({100, 500}, {300, 500}, {50, 500}, {350, 500}, steps, per_frame);
    CHECK(s.pinch == Approx(std::log(300.0f / (200.0f + slop))));
    CHECK(s.pan == glm::vec2(0.0f));
    CHECK(s.look == glm::vec2(0.0f));
    CHECK(!s.tap);
    // Together from 220 to 80 apart (phone_test's pinch).
    s = two_fingers({85, 500}, {305, 500}, {155, 500}, {235, 500}, steps, per_frame);
    CHECK(s.pinch == Approx(std::log(80.0f / (220.0f - slop))));
    CHECK(s.pan == glm::vec2(0.0f));
    // One finger still, the other spreads by 150: the midpoint travels half that, and
    // the image stays where it is (a pinch, not a pan).
    s = two_fingers({100, 500}, {200, 500}, {100, 500}, {350, 500}, steps, per_frame);
    CHECK(s.pinch == Approx(std::log(250.0f / (100.0f + slop))));
    CHECK(s.pan == glm::vec2(0.0f));
  }
}

TEST_CASE("touch: a pan moves from its dead zone's edge and never zooms, a lagging finger neither, however grouped", "[touch]") {
  const float slop = TouchRecognizer::kPanSlop;
  for (const auto& [steps, per_frame] : kGroupings) {
    CAPTURE(steps, per_frame);
    // Both right by 100 (phone_test's pan): the midpoint travels 100.
    Sum s = two_fingers({135, 500}, {255, 500}, {235, 500}, {355, 500}, steps, per_frame);
    CHECK(s.pan.x == Approx(100.0f - slop));
    CHECK(s.pan.y == Approx(0.0f).margin(1e-3));
    CHECK(s.pinch == 0.0f);
    CHECK(s.frames_pinching == 0);
    // Right and down, the second finger lagging 15% of the way behind (up to 32 px of
    // spread on the way) and ending 20 px short: still a pan only.
    s = two_fingers({135, 500}, {255, 500}, {235, 550}, {335, 540}, steps, per_frame, 0.15f);
    const glm::vec2 travel = 0.5f * (glm::vec2(235, 550) + glm::vec2(335, 540)) - glm::vec2(195, 500);
    CHECK(s.pan.x == Approx(travel.x * (1.0f - slop / glm::length(travel))).epsilon(1e-3));
    CHECK(s.pan.y == Approx(travel.y * (1.0f - slop / glm::length(travel))).epsilon(1e-3));
    CHECK(s.pinch == 0.0f);
    CHECK(s.frames_pinching == 0);
  }
}

TEST_CASE("touch: two fingers trembling in place neither pinch nor pan; both once each dominates", "[touch]") {
  for (const auto& [steps, per_frame] : kGroupings) {
    CAPTURE(steps, per_frame);
    // Inside both dead zones: nothing, and no tap.
    Sum s = two_fingers({100, 500}, {300, 500}, {95, 506}, {310, 497}, steps, per_frame);
    CHECK(s.pinch == 0.0f);
    CHECK(s.pan == glm::vec2(0.0f));
    CHECK(!s.tap);
  }
  // A pinch, then (the same fingers still down) a pan: the pan starts once it dominates
  // and the pinch goes on (model-viewer and Sketchfab zoom and pan at once).
  TouchRecognizer r = phone();
  r.down(1, glm::vec2(100, 500) * kDpr, 0);
  r.down(2, glm::vec2(300, 500) * kDpr, 0);
  r.move(1, glm::vec2(50, 500) * kDpr, 16);
  r.move(2, glm::vec2(350, 500) * kDpr, 16);  // 300 apart
  TouchGestures g = r.take();
  CHECK(g.pinch == Approx(std::log(300.0f / (200.0f + TouchRecognizer::kPinchSlop))));
  CHECK(g.pan == glm::vec2(0.0f));
  r.move(1, glm::vec2(90, 500) * kDpr, 32);
  r.move(2, glm::vec2(390, 500) * kDpr, 32);  // right by 40: travel 40 < spread 100, not yet
  CHECK(r.take().pan == glm::vec2(0.0f));
  r.move(1, glm::vec2(200, 500) * kDpr, 48);
  r.move(2, glm::vec2(500, 500) * kDpr, 48);  // travel 150 > spread 100: a pan, from its edge
  g = r.take();
  CHECK(g.pan.x / kDpr == Approx(150.0f - TouchRecognizer::kPanSlop));
  CHECK(g.pinch == 0.0f);
  r.move(1, glm::vec2(175, 500) * kDpr, 64);
  r.move(2, glm::vec2(525, 500) * kDpr, 64);  // spread again: the pinch goes on from where it was
  g = r.take();
  CHECK(g.pinch == Approx(std::log(350.0f / 300.0f)));
  CHECK(g.pan.x == Approx(0.0f).margin(1e-3));
  // One finger lifted: the other goes on looking from where it is, without a jump.
  r.up(2, glm::vec2(525, 500) * kDpr, 80);
  r.move(1, glm::vec2(175, 500) * kDpr + glm::vec2(10, 0), 96);
  g = r.take();
  CHECK(g.look.x == Approx(10.0f));
  CHECK(g.pinch == 0.0f);
  CHECK(g.pan == glm::vec2(0.0f));
  r.up(1, glm::vec2(175, 500) * kDpr + glm::vec2(10, 0), 110);
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
