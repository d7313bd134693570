// firefly_mark.glsl: how the error estimate's packed guide (error_guide.glsl) marks a
// firefly: the sign bit of its (non-negative) 3x3 median, so that one float carries both
// and a median of 0 can be marked too. Read by error_scale.glsl and tile_sums.glsl.
float mark_firefly(float median) { return uintBitsToFloat(floatBitsToUint(median) | 0x80000000u); }
bvec4 fireflies(vec4 guide) { return greaterThanEqual(floatBitsToUint(guide), uvec4(0x80000000u)); }
// The median itself, marked or not.
vec4 guide_medians(vec4 guide) { return abs(guide); }
