// The image maps of <Textured> materials on the GPU, and their records.
//
// Storage: one GL_TEXTURE_2D_ARRAY (RGBA16F) holding every image of the scene as a layer,
// all layers resampled to one common size (the largest width and height among the
// images); a material record names its maps by layer index. Chosen over an atlas because
// the hardware then does what the format promises with no shader code: wrap = repeat
// across the image's own edges (an atlas would bleed into its neighbours and need manual
// wrapping and manual bilinear filtering with four fetches), bilinear filtering, and a
// number of images that never changes the shader. The price: a small image stored
// beside a large one is upsampled (bilinearly, with the same wrap, so the lookup barely
// changes) and takes a large layer's memory; scenes here use maps of one size.
// RGBA16F because it is filterable on every WebGL 2 device (RGBA32F filtering needs an
// extension) and keeps the dark end of linear (sRGB-decoded) colours that RGBA8 loses;
// it also holds the signed components of normal maps.
#pragma once
#include <vector>

#include "core/records.h"
#include "scene/scene.h"

namespace pt {

struct MapArray {
  int width = 1, height = 1, layers = 1;
  std::vector<float> texels;  // layer after layer, rows from v = 0, RGBA
};

// Layer i is scene.images[i] (one white texel when the scene has none). Throws
// InputError naming the scene file and the line that referenced the offending image when
// an image is larger than max_size (GL_MAX_TEXTURE_SIZE), when there are more images than
// max_layers (GL_MAX_ARRAY_TEXTURE_LAYERS), or when the array would exceed 1 GiB.
MapArray build_map_array(const Scene& scene, int max_size, int max_layers);

// Bilinear resampling with wrap = repeat at the target's texel centres (what the GPU's
// lookup of the source would return there).
std::vector<float> resample_repeat(const ImageMap& src, int width, int height);

// One uv record per shape (Triangle vertex uv; zero for other kinds).
RecordBuffer pack_uvs(const Scene& scene);
// The maps' texinfo records (materials/gltf_map.h): kTexinfosPerMaterial per material, in
// material order, written by the kinds that have them (pack_texinfos), else "no map".
RecordBuffer pack_texinfos(const Scene& scene);

}  // namespace pt
