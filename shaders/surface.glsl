// surface.glsl: the one surface step. Every render mode (integrator.glsl, whitted.glsl,
// sh_irradiance.glsl) meets a hit through these two functions and differs only in what
// it does next, so emission, composites, textures, normal maps and mesh shading normals
// mean the same in every mode.
//   surface_hit:     the shape and material records, the side the ray arrived on, the
//                    geometric normal on that side, the emission towards the ray (front
//                    side only) and whether the material ends the path (Emit+Absorb);
//   surface_resolve: what shades there: a FresnelComposite's child (chosen with u_child),
//                    a procedural texture's Diffuse record, a Textured record's values and
//                    normal map, a mesh's interpolated normal; and the shading frame.
// Split in two because the path tracer adds emission with an MIS weight and stops at the
// bounce limit before it draws the random numbers that resolution uses. What a kind does
// here is its own (materials/<kind>.h and .glsl): the generator calls each composite
// kind's choose_<kind> (resolve_composites) and each kind's resolve_hit_<kind>
// (resolve_hit); struct Surface is in surface_types.glsl, so the kinds' snippets see it.

Surface surface_hit(Ray r, Hit h) {
  Surface sf;
  sf.s = load_shape(h.id);
  sf.m = load_material(sf.s.material);
  sf.entering = dot(r.d, h.n) < 0.0;
  sf.n = sf.entering ? h.n : -h.n;
  sf.emission = sf.entering ? sf.m.emission : vec3(0.0);
  emission_hit(sf, r, h);  // a kind whose emission varies over the surface (kEmissionAtHit)
  sf.absorbs = false;
#ifdef HAS_MAT_EMIT
  sf.absorbs = sf.m.kind == MAT_EMIT;
#endif
  sf.fr = frame_from(sf.n);
  sf.wo = to_local(sf.fr, -r.d);
  sf.shading_normal = false;
  return sf;
}

void surface_resolve(inout Surface sf, Ray r, Hit h, float u_child) {
  sf.m = resolve_composites(sf.m, sf.wo.z, sf.entering, u_child);
#ifdef HAS_MEDIA
  sf.medium = material_medium(sf.m, sf.sigma);  // the material's own, before a hit resolution (media.glsl)
#endif
  // A shading normal (a mesh's interpolated vertex normals, a normal map) sets the BSDF's
  // frame; the geometric normal n still decides sides: a direction on different sides
  // of the two carries nothing, and rays leave off the geometric surface.
  // (A shape kind's hook: shading_normal_<kind>, e.g. a mesh's interpolated normals.)
  vec3 ns;
  if (shape_shading_normal(sf.s, h, ns)) {
    ns = dot(ns, sf.n) < 0.0 ? -ns : ns;  // onto the side the ray came from, as n
    if (dot(ns, -r.d) > 0.0) {  // a normal facing away from the viewer is not used
      sf.fr = frame_from(ns);
      sf.wo = to_local(sf.fr, -r.d);
      sf.shading_normal = true;
    }
  }
  // What shades at the hit: a texture's values there (a normal map may set the frame).
  resolve_hit(sf, r, h);
}

// Whether world direction w (unit, leaving the surface) and its shading-frame form wl lie
// on the same side of the geometric and the shading surface; a direction that does not
// carries no light.
bool surface_sides_agree(Surface sf, vec3 w, vec3 wl) {
  return !sf.shading_normal || (dot(w, sf.n) > 0.0) == (wl.z > 0.0);
}
