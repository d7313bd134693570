// Reading an equirectangular environment map from a file: used by the XML loader
// (<Environment map>), the command line (--env) and the page's environment choice.
#pragma once
#include <memory>
#include <stdexcept>
#include <string>

#include "scene/scene.h"

namespace pt {

// A Radiance .hdr (or PFM) as an EnvImage, rows top (theta = 0) to bottom. Throws
// std::runtime_error naming the file (and the byte or pixel) when it cannot be read,
// has an unusable size, or holds negative, non-finite or absurd (> 1e9) values.
std::shared_ptr<const EnvImage> load_env_map(const std::string& path);

// Sets env to the map in `path` (rotation and intensity kept). Throws like load_env_map.
inline void set_env_map(Environment& env, const std::string& path) {
  env.map = load_env_map(path);
  env.map_path = path;
}

}  // namespace pt
