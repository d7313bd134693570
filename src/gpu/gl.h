// The GL ES 3.0 API: the same header natively (libglvnd/EGL) and on the web (Emscripten).
#pragma once
#include <GLES3/gl3.h>
#ifndef __EMSCRIPTEN__
#include <GLES3/gl31.h>  // compute kernels natively (GL ES 3.1+); WebGL 2 has none
#endif
