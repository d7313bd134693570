#include "render/packing.h"

#include "render/image_maps.h"

namespace pt {

PackedScene pack_scene(const Scene& scene) {
  PackedScene p;
  for (const Shape& s : scene.shapes) {
    namespace f = shape_rec;
    const int i = p.shapes.add();
    p.shapes.set(i, f::kind, int(s.kind));
    p.shapes.set(i, f::material, s.material);
    // Emitters of samplable kinds become lights for next-event estimation.
    int light = -1;
    if (is_sampled_light(scene, s)) {
      light = p.lights.add();
      p.lights.set(light, light_rec::radiance, scene.materials[size_t(s.material)].emission);
      p.lights.set(light, light_rec::shape, i);
    }
    p.shapes.set(i, f::light, light);
    p.shapes.set(i, f::a, s.a);
    p.shapes.set(i, f::radius, s.radius);
    p.shapes.set(i, f::b, s.kind == ShapeKind::Sphere ? s.velocity : s.b);
    p.shapes.set(i, f::c, s.c);
  }
  for (const Material& m : scene.materials) {
    namespace f = material_rec;
    const int i = p.materials.add();
    p.materials.set(i, f::kind, int(m.kind));
    p.materials.set(i, f::roughness, m.glossiness);
    p.materials.set(i, f::sampling, m.montecarlo);
    p.materials.set(i, f::tint, m.tint);
    p.materials.set(i, f::ior_n, m.ior.x);
    p.materials.set(i, f::ior_k, m.ior.y);
    p.materials.set(i, f::emission, m.emission);
    p.materials.set(i, f::eta_outer, m.outer_ior);
    p.materials.set(i, f::eta_inner, m.inner_ior);
    p.materials.set(i, f::exponent, m.exponent);
    p.materials.set(i, f::child_a, m.child_a);
    p.materials.set(i, f::child_b, m.child_b);
    if (is_procedural_texture(m.kind)) {
      p.materials.set(i, f::color2, m.color2);  // aliases the dielectric fields (see records.h)
      p.materials.set(i, f::scale, m.scale);
    }
    if (m.kind == MaterialKind::Textured) pack_textured(p.materials, i, m);  // aliases too (see records.h)
  }
  return p;
}

}  // namespace pt
