// GLSL generated only for scenes with a Textured material: the surface parameterisation
// dispatch over the shape kinds present (uv_<kind> and tangent_<kind> of shapes/<kind>.glsl).
#pragma once
#include <string>

#include "shadergen/shadergen.h"

namespace pt {

// struct SurfaceUv { vec2 uv; vec4 tangent; } and
// SurfaceUv surface_uv(ShapeRec s, int id, vec3 p, vec3 n_out), then textured_resolve.glsl.
std::string glsl_textured_support(const Features& f);

}  // namespace pt
