// surface_types.glsl: what a hit is to the surface step (surface.glsl), defined before
// the kinds' snippets so that their resolve_hit_<kind> hooks can take it.
struct Surface {
  ShapeRec s;
  MaterialRec m;        // after surface_resolve: the record that shades (never a composite)
  bool entering;        // the ray arrived on the side the outward normal points to
  vec3 n;               // geometric unit normal on the side the ray came from
  vec3 emission;        // radiance emitted back along the ray
  bool absorbs;         // Emit+Absorb: nothing scatters, the path ends
  Frame fr;             // shading frame: z is the shading normal on the ray's side
  vec3 wo;              // unit direction to the viewer in fr
  bool shading_normal;  // fr is not the geometric frame: sides are decided by n
#ifdef HAS_MEDIA
  bool medium;          // after surface_resolve: the material bounds a medium (media.glsl)
  vec3 sigma;           // its absorption per unit length
#endif
};
