// The one rule for a scene's <Render> (scene/scene.h, SceneRender): each setting it gives
// replaces the current one, unless the user set that one explicitly (a command-line flag,
// a page URL parameter). Used by the CLI (render, bench, watch) and the page's App.
#pragma once
#include "render/renderer.h"

namespace pt {

// What the user set explicitly: these keep their value over the scene's.
struct UserSet {
  bool bounces = false, mode = false, tonemap = false, exposure = false, samples = false;
};

// The settings with the scene's <Render> applied where the user did not set the value.
inline RenderSettings with_scene_render(RenderSettings s, const SceneRender& r, const UserSet& user) {
  if (r.bounces && !user.bounces) s.max_bounces = *r.bounces;
  if (r.mode && !user.mode) s.mode = *r.mode;
  if (r.tonemap && !user.tonemap) s.tonemap = *r.tonemap;
  if (r.exposure && !user.exposure) s.exposure = *r.exposure;
  if (r.samples && !user.samples) s.sample_limit = *r.samples;
  return s;
}

}  // namespace pt
