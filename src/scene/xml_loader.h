#pragma once
#include <string>

#include "scene/scene.h"

namespace pt {

// Loads a scene in the seed's XML format. Throws InputError naming file and line for
// anything malformed or not understood; never returns a partial scene.
constexpr size_t kMaxSceneBytes = size_t(16) << 20;
Scene load_scene_file(const std::string& path);
// allow_files = false refuses every file reference (<Mesh src>, <Environment map>): for
// text from an untrusted source, and for the fuzzer.
Scene load_scene_text(const std::string& text, const std::string& path, bool allow_files = true);

}  // namespace pt
