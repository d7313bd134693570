// display.glsl: shows the accumulated radiance through the chosen tone map (PT_TONEMAP,
// defined by generate_display: one small program per map).
uniform highp sampler2D u_accum;
uniform float u_exposure;
uniform ivec2 u_offset;  // lower-left corner of the viewport in the target
uniform int u_scale;     // image pixels per texel of u_accum: 1, or a coarse level's divisor (nearest)
out vec4 o_color;

void main() {
  vec3 c = texelFetch(u_accum, (ivec2(gl_FragCoord.xy) - u_offset) / u_scale, 0).rgb;
  o_color = vec4(tone_map(c, PT_TONEMAP, u_exposure), 1.0);
}
