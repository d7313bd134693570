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
  glm::vec2 pan{0.0f};      // the midpoint of two fingers moved by this much
  float pinch = 0.0f;       // log(distance now / distance before) of two fingers: > 0 spreads them
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

  // Platform pixels per CSS pixel (the device pixel ratio on the page): scales the slops.
  void set_scale(float pixels_per_css) { scale_ = pixels_per_css > 0.0f ? pixels_per_css : 1.0f; }
  void down(int id, glm::vec2 p, double t_ms);
  void move(int id, glm::vec2 p, double t_ms);
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

  std::vector<Touch> touches_;
  TouchGestures pending_;
  float scale_ = 1.0f;
  // The gesture since the first finger went down until the last one is up.
  int most_fingers_ = 0;
  bool moved_ = false;  // beyond the tap slop, or more than one finger: not a tap
  double start_ms_ = 0.0;
  float last_distance_ = 0.0f;
  glm::vec2 last_mid_{0.0f};
  // The last tap, for a double tap.
  std::optional<glm::vec2> last_tap_;
  double last_tap_ms_ = -1e30;
};

}  // namespace pt
