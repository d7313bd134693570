#include "platform/web_imgui.h"

#include <algorithm>
#include <cmath>

#include <GLFW/glfw3.h>
#include <emscripten/html5.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "gpu/gl.h"

namespace pt::web {
namespace {

// Emscripten 3.1.6's GLFW passes the DOM's deltaY (pixels, positive = down) as the
// scroll offset; GLFW and ImGui expect notches, positive = up.
void scroll_callback(GLFWwindow* window, double dx, double dy) {
  ImGui_ImplGlfw_ScrollCallback(window, -dx / 100.0, -dy / 100.0);
}

}  // namespace

void imgui_init(GLFWwindow* window) {
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
  io.DisplaySize = ImVec2(float(w), float(h));  // GLFW's window size is not kept in sync (web.cpp)
  io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
  ImGui::NewFrame();
}

void imgui_end() {
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace pt::web
