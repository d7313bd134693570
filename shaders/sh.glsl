// sh.glsl: irradiance from the 9 order-2 spherical-harmonic coefficients of the
// environment (Ramamoorthi and Hanrahan 2001), computed on the CPU by render/sh.cpp
// (same basis and order): E(n) = sum_lm A_l L_lm Y_lm(n), A = (pi, 2 pi / 3, pi / 4).
uniform vec3 u_sh[9];

vec3 sh_irradiance(vec3 n) {
  const float A0 = 3.14159265, A1 = 2.09439510, A2 = 0.78539816;
  float x = n.x, y = n.y, z = n.z;
  return A0 * 0.282094792 * u_sh[0]
       + A1 * 0.488602512 * (u_sh[1] * y + u_sh[2] * z + u_sh[3] * x)
       + A2 * (1.092548431 * (u_sh[4] * x * y + u_sh[5] * y * z + u_sh[7] * x * z)
               + 0.315391565 * u_sh[6] * (3.0 * z * z - 1.0)
               + 0.546274215 * u_sh[8] * (x * x - y * y));
}
