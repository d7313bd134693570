#include "scene/textured_loader.h"

#include <cmath>
#include <stdexcept>

#include "core/file_io.h"

namespace pt {

float srgb_to_linear(float v) {
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

ImageMap decode_image_map(const LoadedImage& img, bool normal) {
  ImageMap m;
  m.normal = normal;
  m.width = img.width;
  m.height = img.height;
  m.rgba = img.rgba;
  // Integer codes: 0 .. M with M = 255 or 65535; the middle code (M + 1) / 2 maps to 0 and
  // M to 1 (a flat map of (128, 128, 255) is exactly (0, 0, 1)).
  const float max_code = img.bits == 16 ? 65535.0f : 255.0f;
  for (size_t i = 0; i < m.rgba.size(); ++i) {
    float& v = m.rgba[i];
    if (i % 4 == 3) {
      if (normal) v = 1.0f;  // colour maps keep their alpha (linear: glTF's base colour alpha)
    } else if (normal) {
      v = img.bits == 0 ? 2.0f * v - 1.0f
                        : std::max(-1.0f, (std::round(v * max_code) - 0.5f * (max_code + 1.0f)) / (0.5f * (max_code - 1.0f)));
    } else if (img.bits != 0) {
      v = srgb_to_linear(v);
    }
  }
  return m;
}


int add_image_map(Scene& scene, const std::string& name, const LoadedImage& img, bool normal, int line,
                  const std::function<void(const std::string&)>& fail) {
  for (size_t i = 0; i < scene.images.size(); ++i)
    if (scene.images[i]->path == name && scene.images[i]->normal == normal) return int(i);
  auto m = std::make_shared<ImageMap>(decode_image_map(img, normal));
  m->path = name;
  m->line = line;
  for (float v : m->rgba)
    if (!std::isfinite(v) || (!normal && (v < 0.0f || v > 1.0f))) {
      fail("has values outside [0, 1]: a reflectance map cannot add energy");
      throw std::logic_error("add_image_map: fail returned");
    }
  scene.images.push_back(std::move(m));
  return int(scene.images.size()) - 1;
}

int add_linear_image_map(Scene& scene, const std::string& name, LoadedImage img, int line,
                         const std::function<void(const std::string&)>& fail) {
  img.bits = 0;  // code values as they are: no sRGB decoding
  return add_image_map(scene, name + "#linear", img, false, line, fail);
}

int load_image_map(XmlAttrs& a, Scene& scene, const char* attr, bool normal, const PathResolver& resolve) {
  if (!a.has(attr)) return -1;
  const std::string given = a.text(attr);
  const std::string path = resolve(a, given);
  for (size_t i = 0; i < scene.images.size(); ++i)
    if (scene.images[i]->path == path && scene.images[i]->normal == normal) return int(i);
  LoadedImage img;
  std::string why;
  if (!read_image(path, &img, &why)) a.fail("cannot read '" + given + "': " + why);
  return add_image_map(scene, path, img, normal, a.line(), [&](const std::string& what) { a.fail("'" + given + "' " + what); });
}

}  // namespace pt
