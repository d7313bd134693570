// Where a touch goes (web_touch.h). The first finger decides for the whole gesture: one
// that starts on a Dear ImGui window (as last drawn) drives ImGui as the mouse until it is
// lifted, and other fingers meanwhile do nothing; one that starts on the image goes, with
// every finger that joins it, to the app's gesture recogniser (app/touch.h), which looks,
// moves, picks and resets the view. Emscripten's own touch callbacks (html5.h) would do as
// well; the page's listener is needed anyway to keep the touches from GLFW's listeners.
#include "platform/web_touch.h"

#include <algorithm>
#include <vector>

#include "platform/web_imgui.h"

namespace pt::web {
namespace {

enum class Route { None, Panel, Image };
Route g_route = Route::None;
int g_panel_finger = -1;
std::vector<int> g_fingers;  // down on the canvas now
TouchRoutes g_routes;

}  // namespace

void touch_event(App* app, TouchPhase phase, int id, float x, float y, double t_ms) {
  if (!app) return;
  const glm::vec2 p(x, y);
  const auto known = std::find(g_fingers.begin(), g_fingers.end(), id);
  if (phase == TouchPhase::Start) {
    if (known != g_fingers.end()) return;
    if (g_fingers.empty()) {
      g_route = imgui_window_at(x, y) ? Route::Panel : Route::Image;
      g_panel_finger = g_route == Route::Panel ? id : -1;
      ++(g_route == Route::Panel ? g_routes.panel : g_routes.image);
      g_routes.x = x;
      g_routes.y = y;
    }
    g_fingers.push_back(id);
    if (g_route == Route::Panel && id == g_panel_finger) imgui_touch(x, y, true);
    if (g_route == Route::Image) app->touch().down(id, p, t_ms);
    return;
  }
  if (known == g_fingers.end()) return;
  const bool ends = phase != TouchPhase::Move;
  if (g_route == Route::Panel && id == g_panel_finger) imgui_touch(x, y, !ends);
  if (g_route == Route::Image) {
    if (phase == TouchPhase::Move) app->touch().move(id, p, t_ms);
    if (phase == TouchPhase::End) app->touch().up(id, p, t_ms);
    if (phase == TouchPhase::Cancel) app->touch().cancel(id);
  }
  if (ends) g_fingers.erase(known);
  if (g_fingers.empty()) g_route = Route::None;
}

TouchRoutes touch_routes() { return g_routes; }

}  // namespace pt::web
