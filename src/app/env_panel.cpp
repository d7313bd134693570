#include "app/env_panel.h"

#include <algorithm>
#include <filesystem>

#include <imgui.h>

#include "scene/env_map.h"

namespace pt {

void EnvPanel::scan(const std::string& root) {
  namespace fs = std::filesystem;
  std::error_code ec;
  for (fs::directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file() && it->path().extension() == ".hdr") maps_.push_back(it->path().string());
  std::sort(maps_.begin(), maps_.end());
}

void EnvPanel::scene_loaded(const Environment& own) {
  own_ = own;
  choice_ = 0;
  error_.clear();
}

bool EnvPanel::draw(Environment& env) {
  if (!ImGui::CollapsingHeader("Environment")) return false;
  const auto label = [&](int i) -> std::string {
    if (i == 0) return "the scene's own";
    if (i == 1) return "constant colour";
    return std::filesystem::path(maps_[size_t(i - 2)]).stem().string();
  };
  bool changed = false;
  if (ImGui::BeginCombo("environment", label(choice_).c_str())) {
    for (int i = 0; i < 2 + int(maps_.size()); ++i) {
      if (!ImGui::Selectable(label(i).c_str(), i == choice_) || i == choice_) continue;
      error_.clear();
      if (i == 0) {
        env = own_;
      } else if (i == 1) {
        env.map.reset();
        env.map_path.clear();
        env.color = colour_;
      } else {
        const std::string& path = maps_[size_t(i - 2)];
        try {
          auto& m = loaded_[path];  // read once per page: switching back is instant
          if (!m) m = load_env_map(path);
          env.map = m;
          env.map_path = path;
        } catch (const std::exception& e) {
          error_ = e.what();
          continue;
        }
      }
      choice_ = i;
      changed = true;
    }
    ImGui::EndCombo();
  }
  if (!error_.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", error_.c_str());
  if (env.map) {  // the seed's sliders
    changed |= ImGui::SliderFloat("rotation", &env.rotation, 0.0f, 720.0f, "%.0f deg");
    changed |= ImGui::SliderFloat("energy", &env.intensity, 0.0f, 5.0f);
  } else if (ImGui::ColorEdit3("colour", &env.color.x, ImGuiColorEditFlags_HDR | ImGuiColorEditFlags_Float)) {
    colour_ = env.color;
    changed = true;
  }
  return changed;
}

}  // namespace pt
