// Touch gestures on the image (issue 16), as 3D viewers have them (model-viewer,
// Sketchfab): one finger drags to look, two fingers pinch to move forward and back and pan
// to strafe, a tap without movement picks, a double tap resets the view. Plain logic over
// touch points (no GL, no ImGui, no browser): the platform feeds it the touches that
// started on the image (src/platform/web_touch.cpp; touches on the panel go to ImGui as a
// mouse), the app takes what they add up to once per frame (app_interaction.cpp), and a
// native unit test (touch_test.cpp) drives it with made-up touches.
#pragma once
#include <optional>
#include <vector>

#include <glm/glm.hpp>

namespace pt {

// What the touches since the last take() add up to. Positions and movements are in the
// platform's pixels (device pixels on the page: the canvas's drawing buffer, y down).
struct TouchGestures {
  glm::vec2 look{0.0f};     // one finger's drag (as the mouse's drag: x right, y down)
  glm::vec2 pan{0.0f};      // the midpoint of two fingers moved by this much (past the pan's dead zone)
  float pinch = 0.0f;       // log(distance now / distance before) of two fingers, past the pinch's dead zone: > 0 spreads them
  std::optional<glm::vec2> tap;  // a tap ended here (one finger, no movement, short)
  bool double_tap = false;  // a second tap close to the first, soon after it (no tap then)
  bool any() const { return look != glm::vec2(0.0f) || pan != glm::vec2(0.0f) || pinch != 0.0f || tap || double_tap; }
};

class TouchRecognizer {
 public:
  // A tap moves less than kTapSlop, lasts at most kTapMs; a double tap's second tap ends
  // within kDoubleTapMs of the first and within kDoubleTapDistance of it. Distances in CSS
  // pixels, times in milliseconds.
  static constexpr float kTapSlop = 10.0f;
  static constexpr double kTapMs = 500.0;
  static constexpr double kDoubleTapMs = 350.0;
  static constexpr float kDoubleTapDistance = 40.0f;
  // Two fingers: pinch or pan (or both) is decided from the whole gesture so far, never
  // from one event's or one frame's increments, so the outcome does not depend on how the
  // browser groups the touches into events or the events into frames (a slow frame
  // coalesces many moves into one; docs/reliability.md "The phone test in CI"). Measured
  // from where the two fingers went down: the spread, |distance now - distance then|, and
  // the travel of their midpoint, |midpoint now - midpoint then| (CSS pixels). A pinch
  // starts once the spread passes kPinchSlop and is at least kDominance times the travel;
  // a pan once the travel passes kPanSlop and is at least kDominance times the spread.
  // Once started, each goes on until the fingers lift (hysteresis: a pan that later
  // spreads the fingers a little stays a pan, a pinch whose midpoint drifts stays a
  // pinch) and from the point of its dead zone's edge (no jump when it starts: the dead
  // zone is swallowed, as the tap's slop is for one finger). Both can start in one
  // gesture, each when it dominates, as in model-viewer and Sketchfab, where two fingers
  // zoom and pan at once. A pan with one finger lagging the other (spread a fifth of the
  // travel) never zooms; a pinch with one finger still (travel half the spread) never pans.
  static constexpr float kPinchSlop = 20.0f;
  static constexpr float kPanSlop = 12.0f;
  static constexpr float kDominance = 1.0f;

  // Platform pixels per CSS pixel (the device pixel ratio on the page): scales the slops.
  void set_scale(float pixels_per_css) { scale_ = pixels_per_css > 0.0f ? pixels_per_css : 1.0f; }
  void down(int id, glm::vec2 p, double t_ms);
  void move(int id, glm::vec2 p, double t_ms);  // moves with the same t_ms are one event
  void up(int id, glm::vec2 p, double t_ms);
  void cancel(int id);  // the browser took the touch away: never a tap
  TouchGestures take();
  int fingers() const { return int(touches_.size()); }

 private:
  struct Touch {
    int id;
    glm::vec2 start, last;
  };
  Touch* find(int id);
  void two_finger_baseline();  // the pinch and pan measure from the fingers' positions now
  void two_finger_update();    // the first two fingers moved: what the pinch and pan add
  void flush();                // the event's moves are all in: update the two-finger gesture

  std::vector<Touch> touches_;
  TouchGestures pending_;
  float scale_ = 1.0f;
  // The gesture since the first finger went down until the last one is up.
  int most_fingers_ = 0;
  bool moved_ = false;  // beyond the tap slop, or more than one finger: not a tap
  double start_ms_ = 0.0;
  // The two-finger gesture: the first two fingers' distance and midpoint when it began,
  // whether the pinch and the pan have started, and what each has reported so far (both
  // as totals since the start: each report is the total now less the total before).
  float distance0_ = 1.0f;
  glm::vec2 mid0_{0.0f};
  bool pinching_ = false, panning_ = false;
  float pinch_from_ = 1.0f;      // the distance the pinch measures from (d0 +- kPinchSlop)
  glm::vec2 pan_from_{0.0f};     // the midpoint the pan measures from (mid0 + kPanSlop toward it)
  float pinch_sent_ = 0.0f;
  glm::vec2 pan_sent_{0.0f};
  // Moves with the same time are one event (a touchmove lists every finger that moved,
  // and the platform hands them over one by one): the gesture is updated once they are
  // all in, so a big step of both fingers is never seen half done (one finger moved, the
  // other not yet: a pinch).
  bool batch_open_ = false;
  double batch_ms_ = 0.0;
  // The last tap, for a double tap.
  std::optional<glm::vec2> last_tap_;
  double last_tap_ms_ = -1e30;
};

}  // namespace pt
