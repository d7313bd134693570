// The GL ES 3.0 API: the same header natively (libglvnd/EGL) and on the web (Emscripten).
#pragma once
#include <GLES3/gl3.h>
