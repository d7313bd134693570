#include "render/image_maps.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "materials/gltf_map.h"

namespace pt {

std::vector<float> resample_repeat(const ImageMap& src, int width, int height) {
  if (width == src.width && height == src.height) return src.rgba;
  std::vector<float> out(size_t(width) * size_t(height) * 4);
  auto wrap = [](int i, int n) { return ((i % n) + n) % n; };
  for (int y = 0; y < height; ++y) {
    const double sy = (y + 0.5) * src.height / height - 0.5;
    const int y0 = int(std::floor(sy));
    const double fy = sy - y0;
    for (int x = 0; x < width; ++x) {
      const double sx = (x + 0.5) * src.width / width - 0.5;
      const int x0 = int(std::floor(sx));
      const double fx = sx - x0;
      for (int c = 0; c < 4; ++c) {
        auto at = [&](int i, int j) {
          return double(src.rgba[(size_t(wrap(j, src.height)) * size_t(src.width) + size_t(wrap(i, src.width))) * 4 + size_t(c)]);
        };
        const double v = (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) + fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
        out[(size_t(y) * size_t(width) + size_t(x)) * 4 + size_t(c)] = float(v);
      }
    }
  }
  return out;
}

MapArray build_map_array(const Scene& scene, int max_size, int max_layers) {
  MapArray a;
  if (scene.images.empty()) {
    a.texels.assign(4, 1.0f);
    return a;
  }
  auto fail = [&](const ImageMap& m, const std::string& what) { throw InputError(scene.path, m.line, "<Textured>: " + what); };
  a.width = a.height = 0;
  for (const auto& m : scene.images) {
    if (m->width > max_size || m->height > max_size)
      fail(*m, "image '" + m->path + "' is " + std::to_string(m->width) + "x" + std::to_string(m->height) +
                   ", larger than this GPU's GL_MAX_TEXTURE_SIZE (" + std::to_string(max_size) + ")");
    a.width = std::max(a.width, m->width);
    a.height = std::max(a.height, m->height);
  }
  a.layers = int(scene.images.size());
  if (a.layers > max_layers)
    fail(*scene.images[size_t(max_layers)], "the scene has " + std::to_string(a.layers) +
                                                " image maps, more than this GPU's GL_MAX_ARRAY_TEXTURE_LAYERS (" +
                                                std::to_string(max_layers) + ")");
  const double bytes = double(a.width) * a.height * a.layers * 8.0;  // RGBA16F
  if (bytes > 1024.0 * 1024.0 * 1024.0)
    fail(*scene.images.back(), "the scene's " + std::to_string(a.layers) + " image maps at a common size of " +
                                   std::to_string(a.width) + "x" + std::to_string(a.height) + " need " +
                                   std::to_string(int(bytes / 1048576.0)) + " MiB (more than 1024)");
  a.texels.reserve(size_t(a.width) * size_t(a.height) * size_t(a.layers) * 4);
  for (const auto& m : scene.images) {
    const std::vector<float> layer = resample_repeat(*m, a.width, a.height);
    a.texels.insert(a.texels.end(), layer.begin(), layer.end());
  }
  return a;
}

RecordBuffer pack_texinfos(const Scene& scene) {
  RecordBuffer b(texinfo_rec::kTexels);
  for (const Material& m : scene.materials) {
    const int first = b.count();
    for (int k = 0; k < kTexinfosPerMaterial; ++k) b.set(b.add(), texinfo_rec::code, -1.0f);
    std::visit([&](const auto& k) {
      if constexpr (requires { k.pack_texinfos(b, first); }) k.pack_texinfos(b, first);
    }, m.params);
  }
  if (b.count() == 0) b.set(b.add(), texinfo_rec::code, -1.0f);
  return b;
}

RecordBuffer pack_uvs(const Scene& scene) {
  RecordBuffer b(uv_rec::kTexels);
  for (const Shape& s : scene.shapes) {
    const int i = b.add();
    // Kinds with vertex uv (a Triangle's: shapes/triangle.h); the others' stay zero.
    visit_shape(s.params, [&](const auto& k) {
      if constexpr (requires { k.uv0; k.uv1; k.uv2; }) {
        b.set(i, uv_rec::uv0, k.uv0);
        b.set(i, uv_rec::uv1, k.uv1);
        b.set(i, uv_rec::uv2, k.uv2);
      }
    });
  }
  return b;
}

}  // namespace pt
