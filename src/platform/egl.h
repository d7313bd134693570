// Headless GL ES 3 context through EGL, without a window: a real GPU through
// EGL_EXT_platform_device when there is one (NVIDIA's EGL), else Mesa's surfaceless
// platform (llvmpipe). PT_EGL_SOFTWARE=1 forces the software device.
#pragma once
#include <string>

namespace pt {

class HeadlessGl {
 public:
  HeadlessGl();  // throws std::runtime_error when no context can be made
  ~HeadlessGl();
  HeadlessGl(const HeadlessGl&) = delete;
  HeadlessGl& operator=(const HeadlessGl&) = delete;
  // "GL_RENDERER (GL_VERSION) via <platform>"
  const std::string& description() const { return description_; }

 private:
  void* display_ = nullptr;
  void* context_ = nullptr;
  std::string description_;
};

}  // namespace pt
