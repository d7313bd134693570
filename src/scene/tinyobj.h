// tinyobjloader (Debian's libtinyobjloader-dev, header-only) without its warnings: the
// OBJ reader's ear clipping of large polygons (scene/mesh_obj.cpp, which defines
// TINYOBJLOADER_IMPLEMENTATION before this) and the OBJ tests' oracle.
#pragma once
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wsign-compare"
#endif
#include <tiny_obj_loader.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
