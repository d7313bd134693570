// Dear ImGui on the page (web_imgui.cpp): its GLFW and OpenGL 3 (WebGL 2) backends, the
// style and font scaled by the device pixel ratio (and made for fingers on a touch screen),
// a touch on a window as its mouse, and one frame's begin, end and draw.
#pragma once

struct GLFWwindow;

namespace pt::web {

void imgui_init(GLFWwindow* window);
// The backend's GL objects belong to a context: made again on a restored one.
void imgui_context_restored();
// Starts an ImGui frame for a drawing buffer of w x h device pixels.
void imgui_begin(int w, int h);
// Ends the ImGui frame (its draw lists); true when they differ from the last frame's
// (then the canvas is drawn again: web.cpp).
bool imgui_render();
void imgui_draw();  // draws the frame's draw lists into the bound framebuffer
// Touch (web_touch.cpp): whether a window of the last frame covers (x, y) (device pixels),
// and a touch on a window as the mouse's left button at (x, y).
bool imgui_window_at(float x, float y);
void imgui_touch(float x, float y, bool down);
bool touch_screen();  // the styles are a finger's: taller rows (imgui_init)

}  // namespace pt::web
