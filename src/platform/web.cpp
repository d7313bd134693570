// The web platform: a GLFW window on the page's canvas (WebGL 2) and the browser's
// animation-frame loop, which draws the app's frames and its preparation's slices. The
// context's loss and extensions are in web_context.cpp, Dear ImGui's backends in
// web_imgui.cpp, what the page calls and provides in web_hooks.cpp, where a touch goes in
// web_touch.cpp.
#include <algorithm>
#include <cmath>
#include <memory>

#include <GLFW/glfw3.h>
#include <emscripten.h>
#include <emscripten/html5.h>

#include "app/app.h"
#include "platform/web_context.h"
#include "platform/web_hooks.h"
#include "platform/web_imgui.h"
#include "render/pacing.h"

namespace {

pt::PreparePacer g_prepare;
GLFWwindow* g_window = nullptr;
std::unique_ptr<pt::App> g_app;

// The canvas fills the window through CSS; its drawing buffer follows in device pixels.
// GLFW's own resize path is avoided: it requests fullscreen when the size equals the screen.
void sync_canvas_size(int* w, int* h) {
  double css_w = 0, css_h = 0;
  emscripten_get_element_css_size("#canvas", &css_w, &css_h);
  const double dpr = emscripten_get_device_pixel_ratio();
  *w = std::max(1, int(std::lround(css_w * dpr)));
  *h = std::max(1, int(std::lround(css_h * dpr)));
  int cur_w = 0, cur_h = 0;
  emscripten_get_canvas_element_size("#canvas", &cur_w, &cur_h);
  if (cur_w != *w || cur_h != *h) emscripten_set_canvas_element_size("#canvas", *w, *h);
}

void frame() {
  using pt::web::ContextState;
  const ContextState context = pt::web::context_state();
  if (context == ContextState::Lost) return;  // nothing can be drawn until the browser restores it
  if (context == ContextState::Restored) {
    pt::web::forget_lost_objects();
    pt::web::enable_extensions();
    pt::web::imgui_context_restored();
    g_app->context_restored();
    pt::web::context_rebuilt();
  }
  const double t0 = emscripten_get_now();
  if (!g_prepare.draw_now(g_app->preparing(), t0)) {
    g_app->work(pt::PreparePacer::kSliceMs);  // not drawn: the canvas keeps the last frame
    return;
  }
  g_app->set_keyboard_enabled(pt::web::canvas_focused());
  int w = 0, h = 0;
  sync_canvas_size(&w, &h);
  g_app->set_display(float(emscripten_get_device_pixel_ratio()), pt::web::touch_screen());
  pt::web::imgui_begin(w, h);
  const double now = emscripten_get_now();
  g_app->frame(w, h, now);
  // An unchanged image under an unchanged panel is not drawn again (App::present_due).
  const bool panel_changed = pt::web::imgui_render();
  if (panel_changed || g_app->present_due(now)) {
    g_app->present(w, h, now);
    pt::web::imgui_draw();
  }
  g_prepare.drawn(t0, emscripten_get_now());
  if (g_app->preparing()) pt::web::pump_work(pt::PreparePacer::kSliceMs);
}

}  // namespace

int main(int argc, char** argv) {
  pt::AppOptions options = pt::web::page_options(argc, argv);
  pt::web::reuse_gl_names();
  if (!glfwInit()) return pt::web::show_error("GLFW could not start."), 1;
  glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
  glfwWindowHint(GLFW_ALPHA_BITS, 0);  // an opaque canvas: the page behind never shows through
  glfwWindowHint(GLFW_DEPTH_BITS, 0);
  glfwWindowHint(GLFW_STENCIL_BITS, 0);
  int w = 0, h = 0;
  sync_canvas_size(&w, &h);
  g_window = glfwCreateWindow(w, h, "pathtracer", nullptr, nullptr);
  if (!g_window) return pt::web::show_error("This browser or GPU does not support WebGL 2."), 1;
  glfwMakeContextCurrent(g_window);
  sync_canvas_size(&w, &h);
  pt::web::imgui_init(g_window);

  pt::web::enable_extensions();
  options.gl_renderer = pt::web::gl_renderer();
  try {
    g_app = std::make_unique<pt::App>(options);
  } catch (const std::exception& e) {
    pt::web::show_error(e.what());
    return 1;
  }
  pt::web::set_app(g_app.get());
  emscripten_set_main_loop(frame, 0, true);
  return 0;
}
