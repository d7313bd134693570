#include "scene/env_map.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/image.h"

namespace pt {

std::shared_ptr<const EnvImage> load_env_map(const std::string& path) {
  auto img = std::make_shared<EnvImage>();
  std::vector<float> rgba;
  if (!read_hdr(path, &img->width, &img->height, &rgba))
    throw std::runtime_error("cannot read the environment map '" + path + "'");
  if (img->width < 2 || img->height < 1 || img->width > 16384 || img->height > 8192)
    throw std::runtime_error("environment map '" + path + "' has an unusable size");
  // read_hdr gives rows bottom to top; the map is kept top (theta = 0) to bottom.
  const size_t row = size_t(img->width) * 4;
  img->rgba.resize(rgba.size());
  for (int y = 0; y < img->height; ++y)
    std::copy_n(&rgba[size_t(img->height - 1 - y) * row], row, &img->rgba[size_t(y) * row]);
  for (float& v : img->rgba)
    if (!std::isfinite(v) || v < 0.0f)
      throw std::runtime_error("environment map '" + path + "' has negative or non-finite values");
  return img;
}

}  // namespace pt
