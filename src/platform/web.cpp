// The web platform: a GLFW window on the page's canvas (WebGL 2), Dear ImGui's GLFW and
// OpenGL 3 backends, the browser's animation-frame loop, and the hooks the page and the
// browser tests call (window.ptStats and friends in web/index.html).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include <GLFW/glfw3.h>
#include <emscripten.h>
#include <emscripten/html5.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "app/app.h"

// A message in place of the canvas (web/index.html defines ptShowError).
EM_JS(void, pt_js_show_error, (const char* message), {
  const text = UTF8ToString(message);
  console.warn("pathtracer: " + text);
  if (typeof ptShowError === "function") ptShowError(text);
});

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

// Keys drive the camera only while the canvas has keyboard focus.
EM_JS(int, pt_js_canvas_focused, (), { return document.activeElement === Module.canvas ? 1 : 0; });

// The page fetches a scene and the files it references, then loads it (web/files.js).
EM_JS(void, pt_js_request_scene, (const char* path), {
  const p = UTF8ToString(path);
  if (typeof ptOpenScene === "function") ptOpenScene(p);
  else Module._pt_load_scene(path);
});

// A scene being prepared gets slices of work between animation frames too, each a task of
// its own (a MessageChannel message: setTimeout would be clamped to 4 ms when nested), so
// input and the next frame run in between and the page never waits long.
EM_JS(void, pt_js_pump_work, (double slice_ms), {
  if (Module.ptWorkPump) return;
  const channel = new MessageChannel();
  Module.ptWorkPump = channel;
  channel.port1.onmessage = () => {
    if (Module._pt_work(slice_ms)) channel.port2.postMessage(0);
    else Module.ptWorkPump = null;
  };
  channel.port2.postMessage(0);
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
std::string g_stats;

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
  g_app->set_keyboard_enabled(pt_js_canvas_focused() != 0);
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
  if (g_app->preparing()) pt_js_pump_work(kWorkSliceMs);
}

// The browser downloads a Blob of the bytes (copied out of the wasm heap first).
EM_JS(void, pt_download, (const uint8_t* data, int size, const char* name, const char* mime), {
  const blob = new Blob([HEAPU8.slice(data, data + size)], {type : UTF8ToString(mime)});
  const a = document.createElement("a");
  a.href = URL.createObjectURL(blob);
  a.download = UTF8ToString(name);
  document.body.appendChild(a);
  a.click();
  setTimeout(() => { URL.revokeObjectURL(a.href); a.remove(); }, 0);
});

pt::AppOptions parse_args(int argc, char** argv) {
  pt::AppOptions o;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--scene") o.scene = value[0] == '/' ? value : o.scene_root + "/" + value;
    if (key == "--size" && std::sscanf(value.c_str(), "%dx%d", &o.width, &o.height) != 2) o.width = o.height = 0;
    if (key == "--limit") o.sample_limit = std::max(0, std::atoi(value.c_str()));
    float v[5];
    if (key == "--cam" && std::sscanf(value.c_str(), "%f,%f,%f,%f,%f", &v[0], &v[1], &v[2], &v[3], &v[4]) == 5 &&
        std::isfinite(v[0] + v[1] + v[2] + v[3] + v[4])) {
      o.camera_position = glm::vec3(v[0], v[1], v[2]);
      o.camera_yaw_pitch = glm::vec2(v[3], v[4]);
    }
    if (key == "--bounces") o.bounces = std::atoi(value.c_str());
    pt::ToneMap tm;
    if (key == "--tonemap" && pt::tonemap_from_name(value.c_str(), &tm)) o.tonemap = tm;
    if (key == "--exposure" && value != "auto") {
      const float e = std::strtof(value.c_str(), nullptr);
      if (e > 0.0f && std::isfinite(e)) o.exposure = e;
    }
  }
  return o;
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

extern "C" {

EMSCRIPTEN_KEEPALIVE const char* pt_stats_json() {
  g_stats = g_app ? g_app->stats_json() : std::string("null");
  return g_stats.c_str();
}

// Loading progress and the sample count, without reading the image back (cheap).
EMSCRIPTEN_KEEPALIVE const char* pt_load_status() {
  g_stats = g_app ? g_app->load_status_json() : std::string("null");
  return g_stats.c_str();
}

// The current view as URL parameters: cheap (no read-back), for keeping the address current.
EMSCRIPTEN_KEEPALIVE const char* pt_view_query() {
  g_stats = g_app ? g_app->view_query() : std::string();
  return g_stats.c_str();
}

EMSCRIPTEN_KEEPALIVE void pt_set_size(int w, int h) {
  if (g_app) g_app->set_fixed_size(w, h);
}

EMSCRIPTEN_KEEPALIVE void pt_set_sample_limit(int n) {
  if (g_app) g_app->set_sample_limit(n);
}

// A slice of the scene preparation in progress; 1 while more remains (pt_js_pump_work).
EMSCRIPTEN_KEEPALIVE int pt_work(double budget_ms) { return g_app && g_app->work(budget_ms) ? 1 : 0; }

EMSCRIPTEN_KEEPALIVE int pt_load_scene(const char* path) { return g_app && g_app->load_scene(path) ? 1 : 0; }

// Loads again keeping the camera: the reload loop after an edit.
EMSCRIPTEN_KEEPALIVE int pt_reload_scene(const char* path) { return g_app && g_app->load_scene(path, true) ? 1 : 0; }

// The current scene's file and the files it references, as a JSON array of paths.
EMSCRIPTEN_KEEPALIVE const char* pt_scene_files() {
  g_stats = g_app ? g_app->scene_files_json() : std::string("[]");
  return g_stats.c_str();
}

// RGBA float radiance of the current estimate; *count receives the number of floats.
EMSCRIPTEN_KEEPALIVE const float* pt_radiance(int* count) {
  if (!g_app) return *count = 0, nullptr;
  const std::vector<float>& px = g_app->radiance_snapshot();
  *count = int(px.size());
  return px.data();
}

// The tone-mapped image as displayed (before scaling to the canvas), RGBA8.
EMSCRIPTEN_KEEPALIVE const uint8_t* pt_display(int* count) {
  if (!g_app) return *count = 0, nullptr;
  const std::vector<uint8_t>& px = g_app->display_snapshot();
  *count = int(px.size());
  return px.data();
}

}  // extern "C"

int main(int argc, char** argv) {
  pt::AppOptions options = parse_args(argc, argv);
  if (!glfwInit()) return pt_js_show_error("GLFW could not start."), 1;
  glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
  glfwWindowHint(GLFW_ALPHA_BITS, 0);  // an opaque canvas: the page behind never shows through
  glfwWindowHint(GLFW_DEPTH_BITS, 0);
  glfwWindowHint(GLFW_STENCIL_BITS, 0);
  int w = 0, h = 0;
  sync_canvas_size(&w, &h);
  g_window = glfwCreateWindow(w, h, "pathtracer", nullptr, nullptr);
  if (!g_window) return pt_js_show_error("This browser or GPU does not support WebGL 2."), 1;
  glfwMakeContextCurrent(g_window);
  sync_canvas_size(&w, &h);
  init_imgui();

  pt_js_enable_extensions();
  char* renderer = pt_js_gl_renderer();
  options.gl_renderer = renderer ? renderer : "";
  options.save_file = [](const std::string& name, const std::vector<uint8_t>& bytes, const char* mime) {
    pt_download(bytes.data(), int(bytes.size()), name.c_str(), mime);
  };
  std::free(renderer);
  options.request_scene = [](const std::string& path) { pt_js_request_scene(path.c_str()); };
  try {
    g_app = std::make_unique<pt::App>(options);
  } catch (const std::exception& e) {
    pt_js_show_error(e.what());
    return 1;
  }
  emscripten_set_main_loop(frame, 0, true);
  return 0;
}
