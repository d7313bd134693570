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
  pinching_ = panning_ = false;
  pinch_sent_ = 0.0f;
  pan_sent_ = glm::vec2(0.0f);
  if (touches_.size() < 2) return;
  distance0_ = std::max(glm::length(touches_[1].last - touches_[0].last), 1.0f);
  mid0_ = 0.5f * (touches_[0].last + touches_[1].last);
}

void TouchRecognizer::two_finger_update() {
  const float d = std::max(glm::length(touches_[1].last - touches_[0].last), 1.0f);
  const glm::vec2 mid = 0.5f * (touches_[0].last + touches_[1].last);
  // The whole gesture so far, in CSS pixels: positions only, never increments, so it is
  // the same however the moves were grouped.
  const float spread = std::abs(d - distance0_) / scale_;
  const float travel = glm::length(mid - mid0_) / scale_;
  if (!pinching_ && spread > kPinchSlop && spread >= kDominance * travel) {
    pinching_ = true;  // from the dead zone's edge on the side the fingers went
    pinch_from_ = std::max(distance0_ + (d > distance0_ ? 1.0f : -1.0f) * kPinchSlop * scale_, 1.0f);
  }
  if (!panning_ && travel > kPanSlop && travel >= kDominance * spread) {
    panning_ = true;
    pan_from_ = mid0_ + glm::normalize(mid - mid0_) * (kPanSlop * scale_);
  }
  if (pinching_) {
    const float total = std::log(d / pinch_from_);
    pending_.pinch += total - pinch_sent_;
    pinch_sent_ = total;
  }
  if (panning_) {
    const glm::vec2 total = mid - pan_from_;
    pending_.pan += total - pan_sent_;
    pan_sent_ = total;
  }
}

void TouchRecognizer::flush() {
  if (!batch_open_) return;
  batch_open_ = false;
  if (touches_.size() >= 2) two_finger_update();
}

void TouchRecognizer::down(int id, glm::vec2 p, double t_ms) {
  flush();
  if (find(id)) return;  // a repeated start: keep the first
  if (touches_.empty()) {
    most_fingers_ = 0;
    moved_ = false;
    start_ms_ = t_ms;
  }
  touches_.push_back({id, p, p});
  most_fingers_ = std::max(most_fingers_, int(touches_.size()));
  if (touches_.size() > 1) moved_ = true;  // two fingers are a pinch or a pan, never a tap
  if (touches_.size() == 2) two_finger_baseline();  // a third finger leaves the gesture alone
}

void TouchRecognizer::move(int id, glm::vec2 p, double t_ms) {
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
  if (t != &touches_[0] && t != &touches_[1]) {  // a third finger does nothing
    t->last = p;
    return;
  }
  if (batch_open_ && t_ms != batch_ms_) flush();  // the previous event's moves first
  t->last = p;
  batch_open_ = true;
  batch_ms_ = t_ms;
}

void TouchRecognizer::up(int id, glm::vec2 p, double t_ms) {
  if (!find(id)) return;
  move(id, p, t_ms);  // where it lifted counts (a slow page may see no move before the end)
  flush();
  Touch* t = find(id);
  const bool tap = touches_.size() == 1 && most_fingers_ == 1 && !moved_ && glm::length(p - t->start) <= kTapSlop * scale_ &&
                   t_ms - start_ms_ <= kTapMs;
  const glm::vec2 at = t->start;
  touches_.erase(touches_.begin() + (t - touches_.data()));
  two_finger_baseline();  // the fingers left go on from where they are (a new gesture): no jump
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
  flush();
  Touch* t = find(id);
  if (!t) return;
  touches_.erase(touches_.begin() + (t - touches_.data()));
  moved_ = true;
  two_finger_baseline();
}

TouchGestures TouchRecognizer::take() {
  flush();
  TouchGestures g = pending_;
  pending_ = {};
  return g;
}

}  // namespace pt
