// The image maps of <Textured> (materials/textured.h): reading and decoding its files.
#pragma once
#include <functional>
#include <string>

#include "core/image.h"
#include "scene/scene.h"
#include "core/xml_attrs.h"

namespace pt {

// The image named by attribute `attr` of `a` (-1 when absent), loaded into scene.images
// once per (file, decoding); its index there. `resolve` turns a path as written into the
// file to open (the scene loader's resolve_path: relative to the scene file, recorded as
// a dependency, refused where file references are off). A file that cannot be read is an
// error naming it and the element's line.
using PathResolver = std::function<std::string(XmlAttrs&, const std::string&)>;
int load_image_map(XmlAttrs& a, Scene& scene, const char* attr, bool normal, const PathResolver& resolve);

// Decoding of a loaded file's code values (core/image.h): sRGB (IEC 61966-2-1) to linear
// for 8/16-bit colour maps, HDR values unchanged; normal maps map the code range onto
// [-1, 1] so that the middle code (128 of 255, 32768 of 65535, 0.5 in a float file) is 0.
float srgb_to_linear(float v);
ImageMap decode_image_map(const LoadedImage& img, bool normal);
// Decodes `img` into scene.images once per (name, normal); a colour map with values
// outside [0, 1] calls `fail` (which throws).
int add_image_map(Scene& scene, const std::string& name, const LoadedImage& img, bool normal, int line,
                  const std::function<void(const std::string&)>& fail);
// The same with the code values kept linear (glTF's metallic-roughness maps): decoded once
// per name under the name "<name>#linear".
int add_linear_image_map(Scene& scene, const std::string& name, LoadedImage img, int line,
                         const std::function<void(const std::string&)>& fail);

}  // namespace pt
