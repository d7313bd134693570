#pragma once
#include <string>

#include "scene/scene.h"

namespace pt {

// Loads a scene in the seed's XML format. Throws InputError naming file and line for
// anything malformed or not understood; never returns a partial scene.
Scene load_scene_file(const std::string& path);
Scene load_scene_text(const std::string& text, const std::string& path);

}  // namespace pt
