#include "render/light_select.h"

#include <algorithm>
#include <cmath>

namespace pt {

AliasTable alias_table(const std::vector<double>& w) {
  const size_t n = w.size();
  AliasTable t;
  t.pmf.assign(n, 0.0f);
  t.keep.assign(n, 1.0f);
  t.alias.resize(n);
  double sum = 0.0;
  for (double x : w) sum += x;
  for (size_t i = 0; i < n; ++i) t.alias[i] = int(i);
  if (!(sum > 0.0)) {
    std::fill(t.keep.begin(), t.keep.end(), 0.0f);  // pmf 0: never kept (and never aliased to)
    return t;
  }
  // Vose: slots whose scaled weight is below 1 are topped up by one above 1.
  std::vector<double> q(n);
  std::vector<size_t> small, large;
  for (size_t i = 0; i < n; ++i) {
    t.pmf[i] = float(w[i] / sum);
    q[i] = w[i] / sum * double(n);
    (q[i] < 1.0 ? small : large).push_back(i);
  }
  while (!small.empty() && !large.empty()) {
    const size_t s = small.back(), l = large.back();
    small.pop_back();
    large.pop_back();
    t.keep[s] = float(q[s]);
    t.alias[s] = int(l);
    q[l] = (q[l] + q[s]) - 1.0;
    (q[l] < 1.0 ? small : large).push_back(l);
  }
  // What is left is 1 up to rounding: kept always.
  for (size_t i : small) t.keep[i] = 1.0f;
  for (size_t i : large) t.keep[i] = 1.0f;
  return t;
}

float scene_radius(const Scene& scene) {
  ShapeBounds b;
  const ShapeContext ctx{&scene.meshes, std::max(1.0f, scene.camera.shutter)};
  for (const Shape& s : scene.shapes) {
    if (info(s.kind()).bvh == BvhRole::Unbounded) continue;
    const ShapeBounds k = bounds(s.params, ctx);
    b.grow(k.lo);
    b.grow(k.hi);
  }
  // Only unbounded shapes (planes): the camera's distance from the origin sets the scale.
  if (!(b.lo.x <= b.hi.x)) return std::max(1.0f, glm::length(scene.camera.position));
  return std::max(0.5f * glm::length(b.hi - b.lo), 1e-3f);
}

std::vector<double> light_powers(const Scene& scene, const std::vector<int>& shapes) {
  std::vector<double> w;
  w.reserve(shapes.size() + scene.punctual.size());
  for (int i : shapes) {
    const Shape& s = scene.shapes[size_t(i)];
    const glm::vec3 L = scene.materials[size_t(s.material)].emission;
    w.push_back(double(L.x + L.y + L.z) / 3.0 * double(area(s.params)) * 3.141592653589793);
  }
  if (!scene.punctual.empty()) {
    const LightContext ctx{scene_radius(scene)};
    for (const PunctualLight& l : scene.punctual) w.push_back(double(l.power(ctx)));
  }
  return w;
}

Sealed sealed_lights(const Scene& scene, const std::vector<int>& shapes) {
  Sealed out;
  out.sealed.assign(shapes.size(), 0);
  const ShapeContext ctx{&scene.meshes, std::max(1.0f, scene.camera.shutter)};
  for (const Shape& c : scene.shapes) {
    glm::vec3 lo, hi;
    if (scene.materials[size_t(c.material)].kind() != MaterialKind::Emit || !solid(c.params, lo, hi)) continue;
    bool used = false;
    for (size_t k = 0; k < shapes.size(); ++k)
      if (&scene.shapes[size_t(shapes[k])] != &c && inside_box(scene.shapes[size_t(shapes[k])].params, lo, hi, ctx)) out.sealed[k] = 1, used = true;
    if (used) out.lo.push_back(lo), out.hi.push_back(hi);
  }
  return out;
}

bool camera_sealed_off(const std::vector<glm::vec3>& lo, const std::vector<glm::vec3>& hi, glm::vec3 p, float aperture) {
  for (size_t i = 0; i < lo.size(); ++i) {
    // The box grown by the lens radius and a relative margin: conservative for any lens point.
    const glm::vec3 m = glm::vec3(aperture) + 1e-4f * (glm::abs(lo[i]) + glm::abs(hi[i]) + glm::vec3(1.0f));
    if (glm::all(glm::greaterThan(p, lo[i] - m)) && glm::all(glm::lessThan(p, hi[i] + m))) return true;
  }
  return false;
}

void pack_lights(const Scene& scene, const std::vector<int>& shapes, RecordBuffer& lights, std::vector<glm::vec3>& seal_lo,
                 std::vector<glm::vec3>& seal_hi) {
  std::vector<double> w = light_powers(scene, shapes);
  const Sealed sealed = sealed_lights(scene, shapes);
  for (size_t k = 0; k < shapes.size(); ++k)
    if (sealed.sealed[k]) w[k] = 0.0;
  seal_lo = sealed.lo;
  seal_hi = sealed.hi;
  const AliasTable t = alias_table(w);
  size_t k = 0;
  auto table = [&](int r) {
    lights.set(r, light_rec::pmf, t.pmf[k]);
    lights.set(r, light_rec::alias_p, t.keep[k]);
    lights.set(r, light_rec::alias, t.alias[k]);
    ++k;
  };
  for (int i : shapes) {
    const int r = lights.add();
    lights.set(r, light_rec::radiance, scene.materials[size_t(scene.shapes[size_t(i)].material)].emission);
    lights.set(r, light_rec::shape, i);
    table(r);
  }
  for (const PunctualLight& l : scene.punctual) {
    const int r = lights.add();
    l.pack(lights, r);
    table(r);
  }
}

}  // namespace pt
