#include "platform/web_imgui.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>

#include <GLFW/glfw3.h>
#include <emscripten/html5.h>
#include <emscripten.h>
#include <imgui.h>
#include <imgui_internal.h>  // the windows' rectangles, for a touch's start (imgui_window_at)
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "gpu/gl.h"

// A touch screen: the primary pointer is coarse, or the browser reports touch points.
EM_JS(int, pt_js_touch_screen, (), {
  return (window.matchMedia && matchMedia("(pointer: coarse)").matches) || navigator.maxTouchPoints > 0 ? 1 : 0;
});

namespace pt::web {
namespace {

GLFWwindow* g_window = nullptr;
bool g_touch_screen = false;

// A touch that started on a window drives ImGui as the mouse (the backend's mouse is
// overridden while it lasts): a press shorter than a frame is still seen held for one
// frame, then released; afterwards the pointer is nowhere (no hover left behind) until
// the real mouse moves. Dragging a window's background scrolls it, as touch screens do.
struct TouchMouse {
  bool active = false, down = false, pressed = false, hidden = false;
  ImVec2 pos{0, 0}, anchor{0, 0};  // the finger; where it went down
  float scrolled_y = 0;             // the finger's height the scrolling has followed to
  double cursor_x = 0, cursor_y = 0;  // the real mouse's position when the touch came
} g_touch;

// Emscripten 3.1.6's GLFW passes the DOM's deltaY (pixels, positive = down) as the
// scroll offset; GLFW and ImGui expect notches, positive = up.
void scroll_callback(GLFWwindow* window, double dx, double dy) {
  ImGui_ImplGlfw_ScrollCallback(window, -dx / 100.0, -dy / 100.0);
}

}  // namespace

void imgui_init(GLFWwindow* window) {
  g_window = window;
  g_touch_screen = pt_js_touch_screen() != 0;
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini in the page's memory file system
  ImGui::StyleColorsDark();
  ImGuiStyle& style = ImGui::GetStyle();
  style.WindowRounding = 4.0f;
  style.Colors[ImGuiCol_WindowBg].w = 0.85f;
  float font_css = 13.0f;
  if (g_touch_screen) {
    // Rows a finger hits (about 44 CSS pixels, as the platforms' guidelines ask): a 15 px
    // font, frames 15 + 2 x 12 = 39 px high, 6 px between rows; wider grabs and scrollbars.
    font_css = 15.0f;
    style.FramePadding = ImVec2(10.0f, 12.0f);
    style.ItemSpacing = ImVec2(8.0f, 6.0f);
    style.ItemInnerSpacing = ImVec2(8.0f, 6.0f);
    style.GrabMinSize = 24.0f;
    style.ScrollbarSize = 22.0f;
    style.TouchExtraPadding = ImVec2(4.0f, 4.0f);
    io.ConfigWindowsMoveFromTitleBarOnly = true;  // a drag of the background scrolls instead
  }
  // Mouse and display are in device pixels: scale the UI instead of the framebuffer.
  const float scale = std::max(1.0f, float(emscripten_get_device_pixel_ratio()));
  style.ScaleAllSizes(scale);
  ImFontConfig font;
  font.SizePixels = std::round(font_css * scale);
  io.Fonts->AddFontDefault(&font);
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  glfwSetScrollCallback(window, scroll_callback);
  ImGui_ImplOpenGL3_Init("#version 300 es");
}

void imgui_context_restored() {
  ImGui_ImplOpenGL3_Shutdown();  // its deletes of forgotten names do nothing: the
  glGetError();                  // program's and shaders' leave GL_INVALID_VALUE, cleared
  ImGui_ImplOpenGL3_Init("#version 300 es");
}

void imgui_begin(int w, int h) {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGuiIO& io = ImGui::GetIO();
  if (g_touch.active) {
    io.MousePos = g_touch.pos;
    io.MouseDown[ImGuiMouseButton_Left] = g_touch.down || g_touch.pressed;
    // Held on a window's background (no widget took it: nothing active, or the window's
    // move, which ConfigWindowsMoveFromTitleBarOnly leaves still): scroll by the drag, one
    // wheel notch being 5 lines (ImGui's own step); the pointer stays where it went down.
    const ImGuiContext& g = *ImGui::GetCurrentContext();
    const bool background = g.ActiveId == 0 || (g.ActiveIdWindow && g.ActiveId == g.ActiveIdWindow->MoveId);
    if (g_touch.down && !g_touch.pressed && background && io.MouseDownDuration[ImGuiMouseButton_Left] > 0.0f) {
      io.MouseWheel += (g_touch.pos.y - g_touch.scrolled_y) / (5.0f * ImGui::GetFontSize());
      io.MousePos = g_touch.anchor;
      g_touch.scrolled_y = g_touch.pos.y;
    }
    g_touch.pressed = false;
    if (!io.MouseDown[ImGuiMouseButton_Left]) {  // the release frame
      g_touch.active = false;
      g_touch.hidden = true;
    }
  } else if (g_touch.hidden) {
    double x = 0, y = 0;
    glfwGetCursorPos(g_window, &x, &y);
    if (x == g_touch.cursor_x && y == g_touch.cursor_y) io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
    else g_touch.hidden = false;  // the mouse moved: it is the pointer again
  }
  io.DisplaySize = ImVec2(float(w), float(h));  // GLFW's window size is not kept in sync (web.cpp)
  io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
  ImGui::NewFrame();
}

bool imgui_window_at(float x, float y) {
  ImGuiContext* g = ImGui::GetCurrentContext();
  if (!g) return false;
  for (int i = 0; i < g->Windows.Size; ++i) {
    const ImGuiWindow* w = g->Windows[i];
    if (!w->Active || w->Hidden || w->IsFallbackWindow || (w->Flags & ImGuiWindowFlags_NoMouseInputs)) continue;
    ImRect r = w->OuterRectClipped;
    r.Expand(g->Style.TouchExtraPadding);
    if (r.Contains(ImVec2(x, y))) return true;
  }
  return false;
}

void imgui_touch(float x, float y, bool down) {
  if (!g_touch.active) glfwGetCursorPos(g_window, &g_touch.cursor_x, &g_touch.cursor_y);
  g_touch.active = true;
  g_touch.hidden = false;
  if (down && !g_touch.down) {
    g_touch.pressed = true;
    g_touch.anchor = ImVec2(x, y);
    g_touch.scrolled_y = y;
  }
  g_touch.down = down;
  g_touch.pos = ImVec2(x, y);
}

bool touch_screen() { return g_touch_screen; }

bool imgui_render() {
  ImGui::Render();
  // FNV-1a over what the draw lists draw: vertices, indices, and each command's clip,
  // texture and range; the panel changes the canvas only when this does.
  static uint64_t last = 0;
  uint64_t h = 1469598103934665603ull;
  auto mix = [&h](const void* p, size_t n) {
    const unsigned char* b = static_cast<const unsigned char*>(p);
    for (size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  };
  const ImDrawData* d = ImGui::GetDrawData();
  mix(&d->DisplaySize, sizeof(d->DisplaySize));
  for (int l = 0; l < d->CmdListsCount; ++l) {
    const ImDrawList* list = d->CmdLists[l];
    mix(list->VtxBuffer.Data, size_t(list->VtxBuffer.Size) * sizeof(ImDrawVert));
    mix(list->IdxBuffer.Data, size_t(list->IdxBuffer.Size) * sizeof(ImDrawIdx));
    for (const ImDrawCmd& c : list->CmdBuffer) {
      mix(&c.ClipRect, sizeof(c.ClipRect));
      mix(&c.TextureId, sizeof(c.TextureId));
      mix(&c.ElemCount, sizeof(c.ElemCount));
      mix(&c.IdxOffset, sizeof(c.IdxOffset));
      mix(&c.VtxOffset, sizeof(c.VtxOffset));
    }
  }
  const bool changed = h != last;
  last = h;
  return changed;
}

void imgui_draw() { ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData()); }

}  // namespace pt::web
