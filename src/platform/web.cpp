// The web platform: a GLFW window on the page's canvas (WebGL 2) and its context's loss
// and restoration, Dear ImGui's GLFW and OpenGL 3 backends, and the browser's
// animation-frame loop. What the page calls and provides is in web_hooks.cpp.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>

#include <GLFW/glfw3.h>
#include <emscripten.h>
#include <emscripten/html5.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "app/app.h"
#include "platform/web_hooks.h"

// The GPU's name: the unmasked renderer when the browser tells it, else GL_RENDERER.
// Returns a malloc'ed string.
EM_JS(char*, pt_js_gl_renderer, (), {
  const gl = Module.ctx;
  const info = gl.getExtension("WEBGL_debug_renderer_info");
  const name = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  const size = lengthBytesUTF8(name) + 1;
  const ptr = _malloc(size);
  stringToUTF8(name, ptr, size);
  return ptr;
});

// WebGL context loss (web/index.html tracks the events): 0 usable, 1 lost, 2 restored
// and not yet rebuilt.
EM_JS(int, pt_js_context_state, (), { return Module.ptContextState | 0; });
EM_JS(void, pt_js_context_rebuilt, (), { Module.ptContextState = 0; });

// WebGL extensions are off until asked for: ask again on a restored context (Emscripten
// enables its defaults only when it creates one). KHR_parallel_shader_compile lets the
// driver compile in the background (gpu/program.cpp polls it).
EM_JS(void, pt_js_enable_extensions, (), {
  const gl = Module.ctx;
  for (const name of ["EXT_color_buffer_float", "EXT_color_buffer_half_float", "EXT_float_blend",
                      "OES_texture_float_linear", "KHR_parallel_shader_compile", "WEBGL_debug_renderer_info",
                      "EXT_disjoint_timer_query_webgl2"])
    gl.getExtension(name);
});

namespace {

constexpr double kWorkSliceMs = 8.0;  // one slice of scene preparation between frames
// While a scene is being prepared, a frame is drawn only once the preparation has had
// this many times the time the last drawn frame took: with a software GPU a frame costs
// the page's thread tens of milliseconds, which would otherwise leave the preparation a
// small share of it (2 gave about 1.6x the preparation's own time from request to swap
// with SwiftShader, 4 about 1.3-1.5x; docs/benchmarks.md). With a fast GPU every frame is
// still drawn.
constexpr double kPrepareShare = 4.0;
double g_last_draw_end = 0.0, g_last_draw_ms = 0.0;

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

// Emscripten 3.1.6's GLFW passes the DOM's deltaY (pixels, positive = down) as the
// scroll offset; GLFW and ImGui expect notches, positive = up.
void scroll_callback(GLFWwindow* window, double dx, double dy) {
  ImGui_ImplGlfw_ScrollCallback(window, -dx / 100.0, -dy / 100.0);
}

void frame() {
  const int context = pt_js_context_state();
  if (context == 1) return;  // lost: nothing can be drawn until the browser restores it
  if (context == 2) {
    pt_js_enable_extensions();
    ImGui_ImplOpenGL3_Shutdown();  // its objects belong to the lost context
    ImGui_ImplOpenGL3_Init("#version 300 es");
    g_app->context_restored();
    pt_js_context_rebuilt();
  }
  const double t0 = emscripten_get_now();
  if (g_app->preparing() && t0 - g_last_draw_end < kPrepareShare * g_last_draw_ms) {
    g_app->work(kWorkSliceMs);  // not drawn: the canvas keeps the last frame
    return;
  }
  g_app->set_keyboard_enabled(pt::web::canvas_focused());
  int w = 0, h = 0;
  sync_canvas_size(&w, &h);
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(float(w), float(h));  // GLFW's window size is not kept in sync (see above)
  io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
  ImGui::NewFrame();
  g_app->frame(w, h, emscripten_get_now());
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  g_last_draw_end = emscripten_get_now();
  g_last_draw_ms = g_last_draw_end - t0;
  if (g_app->preparing()) pt::web::pump_work(kWorkSliceMs);
}

void init_imgui() {
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini in the page's memory file system
  ImGui::StyleColorsDark();
  ImGui::GetStyle().WindowRounding = 4.0f;
  ImGui::GetStyle().Colors[ImGuiCol_WindowBg].w = 0.85f;
  // Mouse and display are in device pixels: scale the UI instead of the framebuffer.
  const float scale = std::max(1.0f, float(emscripten_get_device_pixel_ratio()));
  ImGui::GetStyle().ScaleAllSizes(scale);
  ImFontConfig font;
  font.SizePixels = std::round(13.0f * scale);
  io.Fonts->AddFontDefault(&font);
  ImGui_ImplGlfw_InitForOpenGL(g_window, true);
  glfwSetScrollCallback(g_window, scroll_callback);
  ImGui_ImplOpenGL3_Init("#version 300 es");
}

}  // namespace

int main(int argc, char** argv) {
  pt::AppOptions options = pt::web::page_options(argc, argv);
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
  init_imgui();

  pt_js_enable_extensions();
  char* renderer = pt_js_gl_renderer();
  options.gl_renderer = renderer ? renderer : "";
  std::free(renderer);
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
