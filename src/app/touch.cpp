// The touch gesture recogniser (app/touch.h).
#include "app/touch.h"

#include <algorithm>
#include <cmath>

namespace pt {

TouchRecognizer::Touch* TouchRecognizer::find(int id) {
  for (Touch& t : touches_)
    if (t.id == id) return &t;
  return nullptr;
}

void TouchRecognizer::two_finger_baseline() {
  if (touches_.size() < 2) return;
  last_distance_ = std::max(glm::length(touches_[1].last - touches_[0].last), 1.0f);
  last_mid_ = 0.5f * (touches_[0].last + touches_[1].last);
}

void TouchRecognizer::down(int id, glm::vec2 p, double t_ms) {
  if (find(id)) return;  // a repeated start: keep the first
  if (touches_.empty()) {
    most_fingers_ = 0;
    moved_ = false;
    start_ms_ = t_ms;
  }
  touches_.push_back({id, p, p});
  most_fingers_ = std::max(most_fingers_, int(touches_.size()));
  if (touches_.size() > 1) moved_ = true;  // two fingers are a pinch or a pan, never a tap
  two_finger_baseline();
}

void TouchRecognizer::move(int id, glm::vec2 p, double) {
  Touch* t = find(id);
  if (!t) return;
  if (touches_.size() == 1) {
    // One finger looks once it has left the tap's slop (from there on: a tap that
    // trembles a little leaves the view alone).
    if (!moved_ && glm::length(p - t->start) > kTapSlop * scale_) {
      moved_ = true;
      t->last = p;
      return;
    }
    if (moved_) pending_.look += p - t->last;
    t->last = p;
    return;
  }
  t->last = p;
  if (t != &touches_[0] && t != &touches_[1]) return;  // a third finger does nothing
  const float d = std::max(glm::length(touches_[1].last - touches_[0].last), 1.0f);
  const glm::vec2 mid = 0.5f * (touches_[0].last + touches_[1].last);
  pending_.pinch += std::log(d / last_distance_);
  pending_.pan += mid - last_mid_;
  last_distance_ = d;
  last_mid_ = mid;
}

void TouchRecognizer::up(int id, glm::vec2 p, double t_ms) {
  Touch* t = find(id);
  if (!t) return;
  const bool tap = touches_.size() == 1 && most_fingers_ == 1 && !moved_ && glm::length(p - t->start) <= kTapSlop * scale_ &&
                   t_ms - start_ms_ <= kTapMs;
  const glm::vec2 at = t->start;
  touches_.erase(touches_.begin() + (t - touches_.data()));
  two_finger_baseline();  // the fingers left go on from where they are: no jump
  if (!tap) return;
  if (last_tap_ && t_ms - last_tap_ms_ <= kDoubleTapMs && glm::length(at - *last_tap_) <= kDoubleTapDistance * scale_) {
    pending_.double_tap = true;
    last_tap_.reset();
    return;
  }
  pending_.tap = at;
  last_tap_ = at;
  last_tap_ms_ = t_ms;
}

void TouchRecognizer::cancel(int id) {
  Touch* t = find(id);
  if (!t) return;
  touches_.erase(touches_.begin() + (t - touches_.data()));
  moved_ = true;
  two_finger_baseline();
}

TouchGestures TouchRecognizer::take() {
  TouchGestures g = pending_;
  pending_ = {};
  return g;
}

}  // namespace pt
