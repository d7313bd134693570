// A whole render of a scene to its sample limit with the given settings, for tests that
// compare traversals (flat_traversal_test.cpp, count_ops_test.cpp): the mean, the
// shader's counters and whether the flat loop was chosen.
#pragma once
#include <vector>

#include "gl_context.h"
#include "render/renderer.h"

namespace pt {

struct AccelRun {
  std::vector<float> rgba;
  Renderer::Counters counters;
  bool flat;
};

inline AccelRun run_render(const Scene& scene, const RenderSettings& st, int width, int height) {
  test_gl();
  Renderer r;
  r.resize(width, height);
  r.set_settings(st);
  r.set_scene(scene);
  while (!r.converged()) r.step();
  return {r.read_radiance(), r.counters(), r.using_flat()};
}

}  // namespace pt
