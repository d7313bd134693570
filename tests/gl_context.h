// One headless GL context for the whole test process (llvmpipe in CI, a GPU if present).
#pragma once
#include "platform/egl.h"

inline pt::HeadlessGl& test_gl() {
  static pt::HeadlessGl gl;
  return gl;
}
