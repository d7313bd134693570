// tinygltf (Debian's libtinygltf-dev, header-only) without its warnings and with our
// options: it decodes, writes and opens no image (keep_image keeps the bytes for our own
// reader). The options change its declarations, so every glTF file includes it through
// here; scene/gltf_buffers.cpp defines TINYGLTF_IMPLEMENTATION before this.
#pragma once
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wconversion"
#endif
#include <tiny_gltf.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif
