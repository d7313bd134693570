// Touches on the canvas (web_touch.cpp): web/index.html forwards them (pt_touch in
// web_hooks.cpp) before Emscripten's GLFW sees them, which would turn each into a left
// press at the last mouse position.
#pragma once
#include "app/app.h"

namespace pt::web {

enum class TouchPhase { Start = 0, Move = 1, End = 2, Cancel = 3 };

// One touch point's change; x, y in device pixels of the canvas (y down), t_ms on the
// clock of emscripten_get_now (the event's timeStamp).
void touch_event(App* app, TouchPhase phase, int id, float x, float y, double t_ms);

// Where the gestures went so far (first fingers on a panel, on the image), and the last
// gesture's first point: for the tests' messages (ptUi().routes).
struct TouchRoutes {
  int panel = 0, image = 0;
  float x = 0.0f, y = 0.0f;
};
TouchRoutes touch_routes();

}  // namespace pt::web
