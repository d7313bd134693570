// The panel's environment choice: the scene's own environment, a constant colour, or one
// of the shipped HDR maps (*.hdr under a folder, /assets/env on the page). Choosing edits
// the app's Scene::environment; the caller re-packs the scene (a map where there was none,
// or none where there was one, selects another cached program).
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace pt {

class EnvPanel {
 public:
  void scan(const std::string& root);
  // A new scene: its environment becomes "the scene's own", and the choice returns to it.
  void scene_loaded(const Environment& own);
  // ImGui widgets; true when `env` changed.
  bool draw(Environment& env);

 private:
  std::vector<std::string> maps_;  // paths
  int choice_ = 0;                 // 0: the scene's own, 1: constant colour, 2 + i: maps_[i]
  Environment own_;
  glm::vec3 colour_{0.5f};
  std::map<std::string, std::shared_ptr<const EnvImage>> loaded_;
  std::string error_;
};

}  // namespace pt
