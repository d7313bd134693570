// The chi-square test of a direction sampler against its own density on the production
// GLSL through the harness (Mitsuba's and pbrt's method; tests/sampling_test.cpp says how),
// shared by the tests of every sampler.
#pragma once
#include <functional>
#include <string>

#include "glsl_harness.h"
#include "stats.h"

namespace pt {

struct DirectionCase {
  std::string setup;    // GLSL: constants and make_*() helpers used by the two bodies
  std::string sample;   // GLSL statements: set `vec3 wi` and `bool ok` from rand01()
  std::string density;  // GLSL expression: density of direction `d` (solid angle)
  int dot_weight = 1;
  std::function<void(GlslKernel&)> prepare;  // extra uniforms and textures
  Features features = all_features();        // what the program is generated for
};

// 10^6 samples binned over the sphere against the integrated density; prints the result
// and fails (CHECK) when there is nothing to compare.
Chi2Result direction_chi2(const DirectionCase& c, const char* name);

// GLSL: const vec3 WO at incidence cos_theta (in the xz plane).
std::string incident(double cos_theta);

// The BSDF's own sampler and density, of make_material() at WO (material_sample, material_eval).
extern const char* const kBsdfSample;
extern const char* const kBsdfDensity;
extern const char* const kBsdfPdfHelper;

}  // namespace pt
