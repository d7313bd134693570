#pragma once

namespace pt {

// GLSL sources compiled into the binary (see cmake/EmbedGlsl.cmake), keyed by include
// name: "rng.glsl" (shaders/), "shapes/sphere.glsl", "materials/metal.glsl" (src/).
struct EmbeddedFile {
  const char* name;
  const char* text;
};
extern const EmbeddedFile kEmbeddedGlsl[];
extern const int kEmbeddedGlslCount;

const char* find_embedded_glsl(const char* name);  // nullptr when unknown

}  // namespace pt
