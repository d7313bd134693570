// The page's JavaScript hooks: the functions exported to the page and the browser tests
// (`extern "C"`, listed in web/web.cmake's PT_EXPORTS; window.ptStats and friends in
// web/index.html, the scene fetch of web/files.js, tests/browser/*.mjs), the page's
// services the app calls (a download, a scene fetch, an error message), and the page's
// URL parameters as the app's options.
#include "platform/web_hooks.h"
#include "platform/web_touch.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstdint>
#include <string>
#include <vector>

#include <emscripten.h>

// A message in place of the canvas (web/index.html defines ptShowError).
EM_JS(void, pt_js_show_error, (const char* message), {
  const text = UTF8ToString(message);
  console.warn("pathtracer: " + text);
  if (typeof ptShowError === "function") ptShowError(text);
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

namespace {

pt::App* g_app = nullptr;
std::string g_stats;  // the text a hook returns, kept until the next call

}  // namespace

namespace pt::web {

AppOptions page_options(int argc, char** argv) {
  AppOptions o;
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
    if (key == "--coarse") o.coarse = value != "0";
    if (key == "--raw") o.raw_rows = std::max(0, std::atoi(value.c_str()));
    if (key == "--accel") accel_from_name(value.c_str(), &o.accel);  // auto, bvh or flat; else auto stays
    if (key == "--gltfms") o.gltf_ms = value != "off";  // the glTF BSDF's energy compensation (default on)
    if (key == "--adaptive" && (value == "on" || value == "off")) o.adaptive = value == "on";
    if (key == "--denoise" && (value == "on" || value == "off")) o.denoise = value == "on";
    if (key == "--target") o.target_relmse = std::max(0.0f, std::strtof(value.c_str(), nullptr));
    ToneMap tm;
    if (key == "--tonemap" && tonemap_from_name(value.c_str(), &tm)) o.tonemap = tm;
    if (key == "--exposure" && value != "auto") {
      const float e = std::strtof(value.c_str(), nullptr);
      if (e > 0.0f && std::isfinite(e)) o.exposure = e;
    }
  }
  o.save_file = [](const std::string& name, const std::vector<uint8_t>& bytes, const char* mime) {
    pt_download(bytes.data(), int(bytes.size()), name.c_str(), mime);
  };
  o.request_scene = [](const std::string& path) { pt_js_request_scene(path.c_str()); };
  return o;
}

void set_app(App* app) { g_app = app; }
void show_error(const char* message) { pt_js_show_error(message); }
bool canvas_focused() { return pt_js_canvas_focused() != 0; }
void pump_work(double slice_ms) { pt_js_pump_work(slice_ms); }

}  // namespace pt::web

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

// A touch point on the canvas (web/index.html; phase: web_touch.h's TouchPhase).
EMSCRIPTEN_KEEPALIVE void pt_touch(int phase, int id, double x, double y, double t_ms) {
  pt::web::touch_event(g_app, pt::web::TouchPhase(phase), id, float(x), float(y), t_ms);
}

// The panel's state and rectangles, the touch state (App::ui_json; ptUi()).
EMSCRIPTEN_KEEPALIVE const char* pt_ui_json() {
  g_stats = g_app ? g_app->ui_json() : std::string("null");
  if (g_app && g_stats.size() > 1) {  // and where the gestures went (web_touch.h)
    const pt::web::TouchRoutes r = pt::web::touch_routes();
    char j[128];
    std::snprintf(j, sizeof j, ",\"routes\":{\"panel\":%d,\"image\":%d,\"last\":[%g,%g]}}", r.panel, r.image, double(r.x), double(r.y));
    g_stats.pop_back();
    g_stats += j;
  }
  return g_stats.c_str();
}

EMSCRIPTEN_KEEPALIVE void pt_set_size(int w, int h) {
  if (g_app) g_app->set_fixed_size(w, h);
}

EMSCRIPTEN_KEEPALIVE void pt_set_sample_limit(int n) {
  if (g_app) g_app->set_sample_limit(n);
}

// The denoiser's toggle, as the panel's checkbox (ptSetDenoise).
EMSCRIPTEN_KEEPALIVE void pt_set_denoise(int on) {
  if (g_app) g_app->set_denoise(on != 0);
}

// The denoiser's cost on the current image in ms, with or without its regression (ptTimeDenoise).
EMSCRIPTEN_KEEPALIVE double pt_time_denoise(int regression) { return g_app ? g_app->time_denoise(regression != 0) : -1.0; }

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

// The panel's scene list (every .xml, .gltf and .glb under /scenes), as a JSON array of paths.
EMSCRIPTEN_KEEPALIVE const char* pt_scene_list() {
  g_stats = g_app ? g_app->scene_list_json() : std::string("[]");
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
