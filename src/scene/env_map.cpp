#include "scene/env_map.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.h"
#include "core/image_decode.h"
#include "core/xml_attrs.h"

namespace pt {

std::shared_ptr<const EnvImage> load_env_map(const std::string& path) {
  auto img = std::make_shared<EnvImage>();
  std::vector<float> rgba;
  try {
    FloatImage f = load_float_image(path);
    img->width = f.width;
    img->height = f.height;
    rgba = std::move(f.rgba);
  } catch (const InputError& err) {
    throw std::runtime_error(std::string("cannot load the environment map: ") + err.what());
  }
  if (img->width < 2 || img->height < 1 || img->width > 16384 || img->height > 8192)
    throw std::runtime_error("environment map '" + path + "' has an unusable size " + std::to_string(img->width) + "x" +
                             std::to_string(img->height));
  // The decoder gives rows bottom to top; the map is kept top (theta = 0) to bottom.
  const size_t row = size_t(img->width) * 4;
  img->rgba.resize(rgba.size());
  for (int y = 0; y < img->height; ++y)
    std::copy_n(&rgba[size_t(img->height - 1 - y) * row], row, &img->rgba[size_t(y) * row]);
  for (size_t i = 0; i < img->rgba.size(); ++i) {
    const float v = img->rgba[i];
    if (!std::isfinite(v) || v < 0.0f || v > kMaxMagnitude)
      throw std::runtime_error("environment map '" + path + "' pixel (" + std::to_string(i / 4 % size_t(img->width)) + ", " +
                               std::to_string(i / 4 / size_t(img->width)) +
                               ") from the top is negative, non-finite or absurd (> 1e9)");
  }
  return img;
}

}  // namespace pt
